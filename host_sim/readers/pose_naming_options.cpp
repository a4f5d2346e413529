#include "readers/pose_naming_options.hpp"

namespace aloft::host {

void add_pose_naming_options(CLI::App& command, PoseNaming& naming) {
  command
      .add_option("--pose-columns", naming.columns,
                  "pose columns of a .mot/.sto: R1,R2,R3[,TX,TY,TZ] (rotations in the order of "
                  "--pose-sequence, translations along x, y, z)")
      ->delimiter(',');
  command.add_option("--pose-sequence", naming.sequence,
                     "axes of the --pose-columns rotations, a body-fixed sequence (default xyz)");
  command.add_option("--osim", naming.osim_path,
                     "OpenSim model whose --joint gives the pose columns of a .mot/.sto");
  command.add_option("--joint", naming.joint, "FreeJoint or CustomJoint of the --osim model");
}

}  // namespace aloft::host
