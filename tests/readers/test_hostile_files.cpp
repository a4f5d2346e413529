// Large and hostile inputs: every reader refuses 100 MB of something else within
// seconds, from what it reads first, with one line naming the file (issue 12, item 7).
#include <chrono>

#include <catch2/catch.hpp>

#include "common/body_file.hpp"
#include "one_line_error.hpp"
#include "readers/c3d_reader.hpp"
#include "readers/imu_csv_reader.hpp"
#include "readers/pose_reader.hpp"
#include "readers/segments.hpp"
#include "readers/trc_reader.hpp"
#include "readers/trial_file.hpp"
#include "scratch_files.hpp"

using aloft::test::ScratchDir;

namespace {

// 100 MiB of printable garbage in lines of 80 characters, or one line without end.
std::string garbage(bool with_newlines) {
  std::string text(100u << 20, 'q');
  for (std::size_t i = 0; i < text.size(); ++i) {
    text[i] = static_cast<char>('!' + (i * 7919u) % 90u);
    if (with_newlines && i % 81 == 80) text[i] = '\n';
  }
  return text;
}

template <typename Read>
double seconds_to_refuse(const std::string& path, Read&& read) {
  const auto start = std::chrono::steady_clock::now();
  const std::string message = aloft::test::error_message_of([&] { read(path); });
  CHECK(message.find(path) == 0);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

TEST_CASE("100 MB of garbage is refused in well under a second by every reader", "[readers][bad][large]") {
  ScratchDir dir;
  for (bool with_newlines : {true, false}) {
    INFO("garbage with newlines: " << with_newlines);
    const std::string text = garbage(with_newlines);
    const auto imu = dir.write("g.csv", text);
    // The bar is generous for sanitizer builds; a reader that reads the whole file first
    // takes several seconds and far more memory.
    constexpr double kBar = 1.0;
    CHECK(seconds_to_refuse(imu, [](const std::string& p) { aloft::host::read_imu_csv(p); }) < kBar);
    CHECK(seconds_to_refuse(imu, [](const std::string& p) { aloft::host::read_segments_csv(p); }) < kBar);
    CHECK(seconds_to_refuse(imu, [](const std::string& p) { aloft::host::read_pose_csv(p); }) < kBar);
    CHECK(seconds_to_refuse(imu, [](const std::string& p) { aloft::host::detect_trial_format(p); }) < kBar);
    const auto trc = dir.write("g.trc", text);
    CHECK(seconds_to_refuse(trc, [](const std::string& p) { aloft::host::read_trc(p); }) < kBar);
    const auto c3d = dir.write("g.c3d", text);
    CHECK(seconds_to_refuse(c3d, [](const std::string& p) { aloft::host::read_c3d(p); }) < kBar);
  }
}

TEST_CASE("binary garbage is refused as binary", "[readers][bad]") {
  ScratchDir dir;
  std::string bytes(3u << 20, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>((i * 2654435761u) >> 13);
  const auto p = dir.write("b.csv", bytes);
  CHECK_ONE_LINE_ERROR(aloft::host::read_imu_csv(p), p, "binary");
  CHECK_ONE_LINE_ERROR(aloft::host::read_mot(p), p, "binary");
}
