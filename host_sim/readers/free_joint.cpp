#include "readers/free_joint.hpp"

#include <map>
#include <set>

#include "common/commands.hpp"
#include "readers/osim_joint.hpp"
#include "readers/text_cells.hpp"

namespace aloft::host {

namespace {

// A recognised column: the joint it belongs to and its slot (0..2 rotation about x, y, z;
// 3..5 translation along x, y, z).
struct NamedSlot {
  std::string joint;
  int slot = 0;
};

// "/jointset/<joint>/<coordinate>/value" -> "<coordinate>"; nullopt for other paths
// (speeds, accelerations, forces) and for plain names.
std::optional<std::string> coordinate_of_value_path(const std::string& column) {
  if (column.empty() || column.front() != '/') return std::nullopt;
  std::vector<std::string> parts;
  std::size_t start = 1;
  while (start <= column.size()) {
    std::size_t slash = column.find('/', start);
    if (slash == std::string::npos) slash = column.size();
    parts.push_back(column.substr(start, slash - start));
    start = slash + 1;
  }
  if (parts.size() == 4 && to_lower(parts[0]) == "jointset" && to_lower(parts[3]) == "value") {
    return parts[2];
  }
  return std::nullopt;
}

std::optional<NamedSlot> free_joint_slot(const std::string& column) {
  std::string name = column;
  if (!column.empty() && column.front() == '/') {
    const auto coordinate = coordinate_of_value_path(column);
    if (!coordinate) return std::nullopt;
    name = *coordinate;
  }
  name = to_lower(name);
  const std::string coord = "_coord_";
  const std::size_t at = name.rfind(coord);
  if (at != std::string::npos && at + coord.size() + 1 == name.size()) {
    const char digit = name.back();
    if (digit >= '0' && digit <= '5') return NamedSlot{name.substr(0, at), digit - '0'};
  }
  const std::size_t underscore = name.rfind('_');
  const std::string joint = underscore == std::string::npos ? "" : name.substr(0, underscore);
  const std::string suffix = underscore == std::string::npos ? name : name.substr(underscore + 1);
  const char* axes = "xyz";
  for (int a = 0; a < 3; ++a) {
    const std::string x(1, axes[a]);
    if (suffix == "r" + x || suffix == "rot" + x || suffix == "rotation" + x || suffix == x + "rotation") {
      return NamedSlot{joint, a};
    }
    if (suffix == "t" + x || suffix == "trans" + x || suffix == "translation" + x ||
        suffix == x + "translation") {
      return NamedSlot{joint, 3 + a};
    }
  }
  return std::nullopt;
}

Eigen::Vector3d unit_axis(char axis) {
  switch (axis) {
    case 'x': return Eigen::Vector3d::UnitX();
    case 'y': return Eigen::Vector3d::UnitY();
    default: return Eigen::Vector3d::UnitZ();
  }
}

std::string shown_joint(const std::string& joint) { return joint.empty() ? "(no prefix)" : joint; }

}  // namespace

std::string how_to_name_the_pose() {
  return "name the pose with --pose-columns RX,RY,RZ[,TX,TY,TZ] (with --pose-sequence, default "
         "xyz) or --osim MODEL.osim --joint NAME";
}

int coordinate_column(const std::vector<std::string>& names, const std::string& coordinate) {
  const std::string wanted = to_lower(coordinate);
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (to_lower(names[i]) == wanted) return static_cast<int>(i);
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto path_coordinate = coordinate_of_value_path(names[i]);
    if (path_coordinate && to_lower(*path_coordinate) == wanted) return static_cast<int>(i);
  }
  return -1;
}

std::optional<FreeJointColumns> recognise_free_joint(const std::vector<std::string>& names,
                                                     const std::string& path, std::size_t line) {
  // Per joint name, the column of each slot.
  std::map<std::string, std::array<int, 6>> joints;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto named = free_joint_slot(names[i]);
    if (!named) continue;
    auto [it, fresh] = joints.try_emplace(named->joint);
    if (fresh) it->second.fill(-1);
    int& column = it->second[static_cast<std::size_t>(named->slot)];
    if (column >= 0) {
      throw Error(at_line(path, line,
                          "columns " + names[static_cast<std::size_t>(column)] + " and " + names[i] +
                              " name the same free-joint coordinate; " + how_to_name_the_pose()));
    }
    column = static_cast<int>(i);
  }
  std::vector<std::string> complete;
  for (const auto& [joint, slots] : joints) {
    if (slots[0] >= 0 && slots[1] >= 0 && slots[2] >= 0) complete.push_back(joint);
  }
  if (complete.empty()) return std::nullopt;
  if (complete.size() > 1) {
    std::string list;
    for (const std::string& j : complete) list += (list.empty() ? "" : ", ") + shown_joint(j);
    throw Error(at_line(path, line,
                        "the columns hold " + std::to_string(complete.size()) + " free joints (" + list +
                            "); " + how_to_name_the_pose()));
  }
  const std::array<int, 6>& slots = joints[complete.front()];
  const int translations = (slots[3] >= 0) + (slots[4] >= 0) + (slots[5] >= 0);
  if (translations != 0 && translations != 3) {
    throw Error(at_line(path, line,
                        "free joint " + shown_joint(complete.front()) +
                            " has some but not all of its three translation columns"));
  }
  FreeJointColumns joint;
  joint.source = "free joint " + shown_joint(complete.front()) + " recognised by column names";
  for (int a = 0; a < 3; ++a) {
    joint.rotations[static_cast<std::size_t>(a)] = JointAxis{
        unit_axis("xyz"[a]), names[static_cast<std::size_t>(slots[static_cast<std::size_t>(a)])], 1.0, 0.0};
  }
  if (translations == 3) {
    for (int a = 0; a < 3; ++a) {
      joint.translations.push_back(
          JointAxis{unit_axis("xyz"[a]),
                    names[static_cast<std::size_t>(slots[static_cast<std::size_t>(3 + a)])], 1.0, 0.0});
    }
  }
  return joint;
}

FreeJointColumns free_joint_from_user_columns(const std::vector<std::string>& columns,
                                              const std::string& sequence) {
  if (columns.size() != 3 && columns.size() != 6) {
    throw Error(
        "--pose-columns needs 3 rotation columns, optionally followed by 3 translation "
        "columns (x, y, z), not " +
        std::to_string(columns.size()) + " names");
  }
  const std::string axes = to_lower(sequence);
  if (axes.size() != 3 || axes.find_first_not_of("xyz") != std::string::npos || axes[0] == axes[1] ||
      axes[1] == axes[2]) {
    throw Error(
        "--pose-sequence must be three axes of x, y, z, no axis twice in a row (such as "
        "xyz, zxy or zxz), not '" +
        sequence + "'");
  }
  FreeJointColumns joint;
  joint.source = "--pose-columns with body-fixed sequence " + axes;
  for (std::size_t a = 0; a < 3; ++a)
    joint.rotations[a] = JointAxis{unit_axis(axes[a]), columns[a], 1.0, 0.0};
  if (columns.size() == 6) {
    for (std::size_t a = 0; a < 3; ++a) {
      joint.translations.push_back(JointAxis{unit_axis("xyz"[a]), columns[3 + a], 1.0, 0.0});
    }
  }
  return joint;
}

Eigen::Isometry3d free_joint_pose(const FreeJointColumns& joint, const std::array<double, 3>& rotation_values,
                                  const std::array<double, 3>& translation_values) {
  Eigen::Isometry3d across = Eigen::Isometry3d::Identity();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  for (std::size_t i = 0; i < 3; ++i) {
    const JointAxis& r = joint.rotations[i];
    const double angle = r.coordinate.empty() ? r.offset : r.scale * rotation_values[i] + r.offset;
    rotation = rotation * Eigen::AngleAxisd(angle, r.axis).toRotationMatrix();
  }
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < joint.translations.size() && i < 3; ++i) {
    const JointAxis& t = joint.translations[i];
    const double distance = t.coordinate.empty() ? t.offset : t.scale * translation_values[i] + t.offset;
    translation += distance * t.axis;
  }
  across.linear() = rotation;
  across.translation() = translation;
  return joint.parent_offset * across * joint.child_offset.inverse();
}

std::optional<FreeJointColumns> free_joint_from_naming(const PoseNaming& naming) {
  if (naming.empty()) return std::nullopt;
  if (!naming.columns.empty() && !(naming.osim_path.empty() && naming.joint.empty())) {
    throw Error("--pose-columns and --osim/--joint both name the pose: give one");
  }
  if (!naming.columns.empty()) return free_joint_from_user_columns(naming.columns, naming.sequence);
  if (naming.osim_path.empty() || naming.joint.empty()) {
    throw Error("--osim MODEL.osim and --joint NAME go together");
  }
  return read_osim_joint(naming.osim_path, naming.joint);
}

}  // namespace aloft::host
