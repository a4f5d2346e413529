// Where a free body's pose lies among the columns of an OpenSim .mot/.sto file, and how
// the columns' values make it (OpenSim's joint model, written once here):
//
//   X_ground_body = parent_offset · X_joint(q) · child_offset⁻¹
//   X_joint(q)    = ( R1(f1(q)) · R2(f2(q)) · R3(f3(q)),  Σ axis_i · g_i(q) )
//
// The rotations are a body-fixed sequence, each about its axis in the frame the previous
// rotations left (R = R1·R2·R3, as an OpenSim SpatialTransform applies rotation1..3);
// translations are along axes of the joint's parent frame. Each f/g is scale·q + offset
// of one column q (OpenSim's LinearFunction), or a constant. Rotational columns are in
// degrees when the file says inDegrees=yes; translations are in metres.
//
// A pose comes from column names only (never from column positions): the names OpenSim
// gives a free joint (see recognise_free_joint), or names the user gives
// (--pose-columns, --pose-sequence), or a joint of an OpenSim model (--osim, --joint:
// osim_joint.hpp).
#pragma once

#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace aloft::host {

struct JointAxis {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();  // unit vector
  std::string coordinate;                           // the column it follows; empty: constant `offset`
  double scale = 1.0;
  double offset = 0.0;
};

struct FreeJointColumns {
  std::string source;  // how the pose was named, for messages and `inspect`
  std::array<JointAxis, 3> rotations;
  std::vector<JointAxis> translations;  // none (orientation only) or three
  Eigen::Isometry3d parent_offset = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d child_offset = Eigen::Isometry3d::Identity();
};

// The user's naming of the pose, from the command line; empty: recognise by name.
struct PoseNaming {
  std::vector<std::string> columns;  // --pose-columns R1,R2,R3[,TX,TY,TZ]
  std::string sequence = "xyz";      // --pose-sequence: axes of R1, R2, R3 (body-fixed)
  std::string osim_path;             // --osim MODEL.osim
  std::string joint;                 // --joint NAME
  bool empty() const { return columns.empty() && osim_path.empty() && joint.empty(); }
};

// OpenSim's spellings of a free joint among `names` (time excluded by the caller):
// <joint>_coord_0..5 (FreeJoint), <joint>_rx/_ry/_rz with _tx/_ty/_tz (also rotx,
// rotationx, xRotation, tx, transx, translationx, xTranslation), and OpenSim 4's
// /jointset/<joint>/<coordinate>/value paths. The three rotations (and, when present,
// the three translations) must share a joint name. nullopt when no joint is complete;
// throws aloft::host::Error ("FILE:LINE: ...") when the names hold several free joints
// or a joint with some but not all translations.
std::optional<FreeJointColumns> recognise_free_joint(const std::vector<std::string>& names,
                                                     const std::string& path, std::size_t line);

// --pose-columns and --pose-sequence (e.g. "zxy"); throws Error on a wrong count or sequence.
FreeJointColumns free_joint_from_user_columns(const std::vector<std::string>& columns,
                                              const std::string& sequence);

// The joint from the user's naming (--pose-columns or --osim/--joint), or nullopt when
// the user named nothing. Throws Error for an incomplete naming (--osim without --joint).
std::optional<FreeJointColumns> free_joint_from_naming(const PoseNaming& naming);

// The column of a coordinate: the column named exactly so (case-insensitive), or the
// OpenSim 4 path /jointset/<joint>/<coordinate>/value. -1 when absent.
int coordinate_column(const std::vector<std::string>& names, const std::string& coordinate);

// Body-to-ground pose from one row: `values` holds each JointAxis's column value (in
// radians for rotations, metres for translations), in the order rotations, translations.
Eigen::Isometry3d free_joint_pose(const FreeJointColumns& joint, const std::array<double, 3>& rotation_values,
                                  const std::array<double, 3>& translation_values);

// The one-line hint appended to refusals: how a user names the pose.
std::string how_to_name_the_pose();

}  // namespace aloft::host
