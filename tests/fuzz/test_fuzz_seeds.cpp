// Every seed of the fuzz corpora is a file its reader accepts: a fuzzer that starts from
// refused inputs explores little beyond the first check.
#include <catch2/catch.hpp>

#include "common/body_file.hpp"
#include "fuzz_seeds.hpp"
#include "readers/c3d_reader.hpp"
#include "readers/imu_csv_reader.hpp"
#include "readers/osim_joint.hpp"
#include "readers/pose_reader.hpp"
#include "readers/segments.hpp"
#include "readers/trc_reader.hpp"
#include "readers/trial_file.hpp"
#include "replay/fifo_recording.hpp"
#include "records/record_dump.hpp"
#include "scratch_files.hpp"

TEST_CASE("every fuzz seed is read by its reader", "[fuzz][seeds]") {
  aloft::test::ScratchDir dir;
  const auto corpus = aloft::fuzz::seed_corpus();
  REQUIRE(corpus.size() == 11);
  for (const auto& [harness, seeds] : corpus) {
    REQUIRE_FALSE(seeds.empty());
    for (const auto& seed : seeds) {
      INFO(harness << "/" << seed.name);
      const std::string path = dir.write(seed.name, seed.bytes);
      if (harness == "imu_csv") CHECK_NOTHROW(aloft::host::read_imu_csv(path));
      if (harness == "segments") CHECK_NOTHROW(aloft::host::read_segments_csv(path));
      if (harness == "trc") CHECK_NOTHROW(aloft::host::read_trc(path));
      if (harness == "c3d") CHECK_NOTHROW(aloft::host::read_c3d(path));
      if (harness == "mot") CHECK_NOTHROW(aloft::host::read_mot(path));
      if (harness == "pose_csv") CHECK_NOTHROW(aloft::host::read_pose_csv(path));
      if (harness == "body_json") CHECK_NOTHROW(aloft::host::read_body_file(path));
      if (harness == "osim") CHECK_NOTHROW(aloft::host::read_osim_joint(path, "j"));
      if (harness == "trial_dispatch") CHECK_NOTHROW(aloft::host::detect_trial_format(path));
      if (harness == "icm42688p_fifo") CHECK_NOTHROW(aloft::host::read_fifo_recording(path, 1000));
      if (harness == "records") CHECK_NOTHROW(aloft::host::read_record_dump(path));
    }
  }
}
