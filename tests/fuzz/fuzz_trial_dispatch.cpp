// libFuzzer harness: the file-type dispatch on arbitrary bytes. The file has no
// extension, so the content decides (C3D key, TRC first line, OpenSim endheader, CSV
// header), and the reader the dispatch picks then reads it (see fuzz_input.hpp).
#include "fuzz_input.hpp"
#include "readers/c3d_reader.hpp"
#include "readers/imu_csv_reader.hpp"
#include "readers/segments.hpp"
#include "readers/trial_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  aloft::fuzz::read_input(data, size, "", [](const std::string& path) {
    using aloft::host::TrialKind;
    switch (aloft::host::detect_trial_format(path).kind) {
      case TrialKind::markers: aloft::host::read_marker_file(path); break;
      case TrialKind::poses: aloft::host::read_pose_file(path); break;
      case TrialKind::imu: aloft::host::read_imu_csv(path); break;
      case TrialKind::segments: aloft::host::read_segments_csv(path); break;
    }
  });
  return 0;
}
