// A free body's joint from an OpenSim model (.osim, XML; OpenSim 3 and 4 layouts), so that
// an inverse-kinematics result of any free body reads right with --osim MODEL --joint NAME.
//
// Read with pugixml (Debian libpugixml-dev). Two joint types hold a free body:
//   - FreeJoint: coordinates 0..2 rotate about x, y, z (body-fixed), 3..5 translate along
//     the parent's x, y, z;
//   - CustomJoint: its SpatialTransform's rotation1..3 and translation1..3, each an axis,
//     at most one coordinate, and a LinearFunction (scale, offset) or a Constant.
// The joint's parent must be ground; its parent and child offset frames (OpenSim 4
// PhysicalOffsetFrame, OpenSim 3 location/orientation[_in_parent], orientations as
// body-fixed X-Y-Z angles in radians) are applied (free_joint.hpp).
// Anything else — another joint type, a spline, a joint on another body — is refused
// with Error "MODEL: problem", never guessed.
#pragma once

#include <string>

#include "readers/free_joint.hpp"

namespace aloft::host {

FreeJointColumns read_osim_joint(const std::string& osim_path, const std::string& joint_name);

}  // namespace aloft::host
