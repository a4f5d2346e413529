#include <cmath>
#include <limits>
#include <random>

#include <catch2/catch.hpp>

#include "c3d_test_writer.hpp"
#include "one_line_error.hpp"
#include "readers/c3d_reader.hpp"
#include "scratch_files.hpp"

using aloft::host::C3dDetails;
using aloft::host::MarkerTrial;
using aloft::host::read_c3d;
using aloft::test::C3dContent;
using aloft::test::Processor;
using aloft::test::ScratchDir;

namespace {

std::string as_text(const std::vector<std::uint8_t>& bytes) {
  return std::string(bytes.begin(), bytes.end());
}

C3dContent two_marker_trial(Processor p, bool float_data) {
  C3dContent c;
  c.processor = p;
  c.float_data = float_data;
  c.scale = 0.1;
  c.rate_hz = 250.0f;
  c.units = "mm";
  c.labels = {"M1", "Subject:M2"};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  c.coordinates = {{{{100.0, -200.5, 30.2}}, {{-1.5, 2.0, 3000.0}}},
                   {{{101.0, -201.5, 31.2}}, {{nan, 0.0, 0.0}}},
                   {{{102.0, -202.5, 32.2}}, {{-3.5, 4.0, 3002.0}}}};
  return c;
}

// Largest coordinate difference between two trials with the same occlusions, metres.
double max_difference(const MarkerTrial& a, const MarkerTrial& b) {
  REQUIRE(a.positions_m.size() == b.positions_m.size());
  double worst = 0.0;
  for (std::size_t f = 0; f < a.positions_m.size(); ++f) {
    REQUIRE(a.positions_m[f].size() == b.positions_m[f].size());
    for (std::size_t m = 0; m < a.positions_m[f].size(); ++m) {
      const auto& p = a.positions_m[f][m];
      const auto& q = b.positions_m[f][m];
      REQUIRE(p.allFinite() == q.allFinite());
      if (p.allFinite()) worst = std::max(worst, (p - q).cwiseAbs().maxCoeff());
    }
  }
  return worst;
}

}  // namespace

TEST_CASE("C3D written in each processor format, integer and float, reads back", "[readers][c3d]") {
  ScratchDir dir;
  for (Processor p : {Processor::intel, Processor::dec, Processor::mips}) {
    for (bool float_data : {false, true}) {
      INFO("processor " << aloft::host::c3d::processor_name(p) << ", float " << float_data);
      const auto content = two_marker_trial(p, float_data);
      C3dDetails details;
      const auto trial =
          read_c3d(dir.write("t.c3d", as_text(aloft::test::write_c3d_bytes(content))), &details);
      CHECK(details.processor == aloft::host::c3d::processor_name(p));
      CHECK(details.float_data == float_data);
      CHECK(details.parameter_damage.empty());
      CHECK(trial.format == "c3d");
      CHECK(trial.units_in_file == "mm");
      CHECK(trial.rate_hz == 250.0);
      CHECK(trial.marker_names == std::vector<std::string>{"M1", "Subject:M2"});
      REQUIRE(trial.time_s.size() == 3);
      CHECK(trial.time_s[2] == Approx(2.0 / 250.0));
      // Integer data are exact to the scale step (0.1 mm); float data to float rounding.
      const double tolerance = float_data ? 1e-7 : 0.05e-3 + 1e-12;
      CHECK(std::abs(trial.positions_m[0][0].y() - -0.2005) <= tolerance);
      CHECK(std::abs(trial.positions_m[2][1].z() - 3.002) <= tolerance);
      CHECK_FALSE(trial.positions_m[1][1].allFinite());  // residual -1: occluded
      CHECK(trial.positions_m[1][0].allFinite());
    }
  }
}

TEST_CASE("C3D units m and cm are converted to metres", "[readers][c3d]") {
  ScratchDir dir;
  auto content = two_marker_trial(Processor::intel, true);
  content.units = "m";
  auto trial = read_c3d(dir.write("m.c3d", as_text(aloft::test::write_c3d_bytes(content))));
  CHECK(trial.positions_m[0][0].x() == Approx(100.0));
  content.units = "cm";
  trial = read_c3d(dir.write("cm.c3d", as_text(aloft::test::write_c3d_bytes(content))));
  CHECK(trial.positions_m[0][0].x() == Approx(1.0));
}

TEST_CASE("c3d.org samples: the six versions of each trial give the same points", "[readers][c3d][shared]") {
  ALOFT_REQUIRE_SHARED_DATA(data);
  struct Trial {
    std::string folder;
    std::vector<std::string> integer_files;
    std::vector<std::string> float_files;
    std::size_t frames;
    std::size_t points;
  };
  const std::vector<Trial> trials = {
      {"sample01",
       {"Eb015pi.c3d", "Eb015vi.c3d", "Eb015si.c3d"},
       {"Eb015pr.c3d", "Eb015vr.c3d", "Eb015sr.c3d"},
       450,
       26},
      {"sample02",
       {"pc_int.c3d", "DEC_INT.C3D", "sgi_int.c3d"},
       {"pc_real.c3d", "Dec_real.c3d", "sgi_real.c3d"},
       89,
       36},
  };
  for (const Trial& t : trials) {
    INFO(t.folder);
    const std::string folder = data + "/c3d/" + t.folder + "/";
    C3dDetails d;
    const MarkerTrial reference = read_c3d(folder + t.float_files[0], &d);
    CHECK(reference.time_s.size() == t.frames);
    CHECK(reference.marker_names.size() == t.points);
    CHECK(reference.rate_hz == 50.0);
    const double step_m = std::abs(d.point_scale) * 1e-3;  // one integer step, metres
    std::size_t occluded = 0;
    for (const auto& frame : reference.positions_m) {
      for (const auto& p : frame) occluded += p.allFinite() ? 0 : 1;
    }
    CHECK(occluded > 0);  // the samples have gaps: they must agree on them too
    for (const auto& name : t.float_files) {
      INFO(name);
      const MarkerTrial other = read_c3d(folder + name);
      CHECK(other.marker_names == reference.marker_names);
      CHECK(max_difference(other, reference) == 0.0);  // same floats, decoded exactly
    }
    for (const auto& name : t.integer_files) {
      INFO(name);
      const MarkerTrial other = read_c3d(folder + name);
      CHECK(other.marker_names == reference.marker_names);
      CHECK(max_difference(other, reference) <= step_m);
    }
  }
}

TEST_CASE("c3d.org golf swing: float data, parameter block count understated", "[readers][c3d][shared]") {
  ALOFT_REQUIRE_SHARED_DATA(data);
  C3dDetails d;
  const auto trial = read_c3d(data + "/c3d/sample13/golfswing.c3d", &d);
  CHECK(d.parameter_damage.empty());
  CHECK(d.float_data);
  CHECK(trial.time_s.size() == 514);
  CHECK(trial.marker_names.size() == 29);
  CHECK(trial.marker_names[0] == "Channel103");
  CHECK(trial.rate_hz == Approx(107.527).epsilon(1e-4));
}

TEST_CASE("c3d.org damaged parameter section: partial parse, no crash", "[readers][c3d][shared][bad]") {
  ALOFT_REQUIRE_SHARED_DATA(data);
  // Its parameter records run on into the data section. The reader keeps the records
  // before that point (POINT and ANALOG are intact) and reads the points.
  C3dDetails d;
  const auto trial = read_c3d(data + "/c3d/sample18/bad_parameter_section.c3d", &d);
  CHECK_FALSE(d.parameter_damage.empty());
  CHECK(trial.marker_names.size() == 45);
  CHECK(trial.time_s.size() == 332);
  CHECK(trial.rate_hz == 120.0);
}

TEST_CASE("damaged C3D files never crash: random corruption of real files", "[readers][c3d][bad]") {
  // Every outcome is either a trial or aloft::host::Error; an out-of-bounds read would
  // show under the sanitizers or as a crash here.
  ScratchDir dir;
  std::vector<std::vector<std::uint8_t>> originals = {
      aloft::test::write_c3d_bytes(two_marker_trial(Processor::intel, false)),
      aloft::test::write_c3d_bytes(two_marker_trial(Processor::dec, true)),
      aloft::test::write_c3d_bytes(two_marker_trial(Processor::mips, false))};
  std::mt19937 rng(20240611);
  std::size_t read_ok = 0;
  std::size_t rejected = 0;
  for (int trial = 0; trial < 600; ++trial) {
    std::vector<std::uint8_t> bytes = originals[static_cast<std::size_t>(trial) % originals.size()];
    // Corrupt the header and parameter section, where lengths and offsets live.
    const std::size_t limit = std::min<std::size_t>(bytes.size(), 3 * 512);
    std::uniform_int_distribution<std::size_t> where(0, limit - 1);
    std::uniform_int_distribution<int> value(0, 255);
    const int hits = 1 + trial % 8;
    for (int h = 0; h < hits; ++h) bytes[where(rng)] = static_cast<std::uint8_t>(value(rng));
    if (trial % 5 == 0) bytes.resize(where(rng));  // and truncate some
    const std::string path = dir.write("fuzz.c3d", as_text(bytes));
    try {
      C3dDetails details;  // given, so damage is reported here rather than on stderr
      read_c3d(path, &details);
      ++read_ok;
    } catch (const aloft::host::Error& e) {
      ++rejected;
      CHECK(std::string(e.what()).find('\n') == std::string::npos);
    }
  }
  CHECK(read_ok + rejected == 600);
  CHECK(read_ok > 0);
  CHECK(rejected > 0);
}

TEST_CASE("bad C3D files: one-line errors", "[readers][c3d][bad]") {
  ScratchDir dir;
  const auto good = aloft::test::write_c3d_bytes(two_marker_trial(Processor::intel, false));
  SECTION("empty") {
    const auto p = dir.write("e.c3d", "");
    CHECK_ONE_LINE_ERROR(read_c3d(p), p, "empty");
  }
  SECTION("shorter than a header") {
    const auto p = dir.write("s.c3d", as_text(good).substr(0, 100));
    CHECK_ONE_LINE_ERROR(read_c3d(p), p, "too short");
  }
  SECTION("not a C3D file") {
    auto bytes = good;
    bytes[1] = 0x51;
    const auto p = dir.write("n.c3d", as_text(bytes));
    CHECK_ONE_LINE_ERROR(read_c3d(p), p, "not a C3D file");
  }
  SECTION("unknown processor type") {
    auto bytes = good;
    bytes[512 + 3] = 99;
    const auto p = dir.write("u.c3d", as_text(bytes));
    CHECK_ONE_LINE_ERROR(read_c3d(p), p, "processor type 99");
  }
  SECTION("truncated data section") {
    auto bytes = good;
    bytes.resize(3 * 512 + 10);  // header, parameters, and 10 bytes of data
    const auto p = dir.write("t.c3d", as_text(bytes));
    CHECK_ONE_LINE_ERROR(read_c3d(p), p, "truncated");
  }
  SECTION("unknown units") {
    auto content = two_marker_trial(Processor::intel, false);
    content.units = "in";
    const auto p = dir.write("i.c3d", as_text(aloft::test::write_c3d_bytes(content)));
    CHECK_ONE_LINE_ERROR(read_c3d(p), p, "unknown POINT:UNITS 'in'");
  }
  SECTION("parameter section beyond the end of the file") {
    auto bytes = good;
    bytes[0] = 200;
    const auto p = dir.write("b.c3d", as_text(bytes));
    CHECK_ONE_LINE_ERROR(read_c3d(p), p, "beyond the end");
  }
}

TEST_CASE("C3D POINT:UNITS matched as C3D tools match them", "[readers][c3d][units]") {
  ScratchDir dir;
  auto content = two_marker_trial(Processor::intel, true);
  for (const char* metres : {"mete", "meters", " METRES", "m"}) {
    INFO("units '" << metres << "'");
    content.units = metres;
    const auto trial = read_c3d(dir.write("m.c3d", as_text(aloft::test::write_c3d_bytes(content))));
    CHECK(trial.positions_m[0][0].x() == Approx(100.0));
  }
  content.units = "millimeters";
  const auto mm = read_c3d(dir.write("mm.c3d", as_text(aloft::test::write_c3d_bytes(content))));
  CHECK(mm.positions_m[0][0].x() == Approx(0.1));
  content.units = "feet";
  const auto p = dir.write("ft.c3d", as_text(aloft::test::write_c3d_bytes(content)));
  CHECK_ONE_LINE_ERROR(read_c3d(p), p, "unknown POINT:UNITS 'feet'");
}

TEST_CASE("C3D long trial: frame count over 65,535 from TRIAL:ACTUAL_*_FIELD", "[readers][c3d]") {
  ScratchDir dir;
  C3dContent c;
  c.float_data = false;
  c.scale = 0.1;
  c.rate_hz = 1000.0f;
  c.labels = {"M1"};
  c.trial_fields = true;
  constexpr std::size_t kFrames = 70000;
  for (std::size_t f = 0; f < kFrames; ++f) {
    c.coordinates.push_back({{{static_cast<double>(f % 3000), 1.0, -2.0}}});
  }
  C3dDetails details;
  const auto trial = read_c3d(dir.write("long.c3d", as_text(aloft::test::write_c3d_bytes(c))), &details);
  REQUIRE(trial.time_s.size() == kFrames);
  CHECK(details.first_frame == 1);
  CHECK(trial.time_s.back() == Approx((kFrames - 1) / 1000.0));
  CHECK(trial.positions_m[69999][0].x() == Approx((69999 % 3000) * 1e-3));
  CHECK(trial.positions_m[65536][0].x() == Approx((65536 % 3000) * 1e-3));
  // Without the TRIAL fields the header's 16-bit count says 65,535 frames: read as such.
  c.trial_fields = false;
  const auto capped = read_c3d(dir.write("capped.c3d", as_text(aloft::test::write_c3d_bytes(c))));
  CHECK(capped.time_s.size() == 65535);
}

TEST_CASE("C3D numbers out of range are refused before they are used", "[readers][c3d][bad]") {
  ScratchDir dir;
  auto content = two_marker_trial(Processor::intel, true);
  SECTION("a rate of 1e30 in both the parameter and the header") {
    content.rate_hz = 1e30f;
    const auto p = dir.write("r.c3d", as_text(aloft::test::write_c3d_bytes(content)));
    CHECK_ONE_LINE_ERROR(read_c3d(p), p, "POINT:RATE");
  }
  SECTION("a long trial claiming more frames than the file holds: the claim and the truth") {
    content.trial_fields = true;
    auto bytes = aloft::test::write_c3d_bytes(content);
    // ACTUAL_END_FIELD's high word sits 2 bytes before the end of its record; make it
    // claim 2^31 frames.
    const std::string name = "ACTUAL_END_FIELD";
    const auto at = as_text(bytes).find(name);
    REQUIRE(at != std::string::npos);
    const std::size_t high_word = at + name.size() + 2 + 2 + 1 + 2;  // offset, type, dims, dim, low
    bytes[high_word] = 0x00;
    bytes[high_word + 1] = 0x80;
    const auto p = dir.write("c.c3d", as_text(bytes));
    // 2^31 + 3 frames claimed; one 512-byte data block of 32-byte frames holds 16.
    CHECK_ONE_LINE_ERROR(read_c3d(p), p, "claims 2147483651 frames", "holds 16");
  }
  SECTION("a 100 MB file of something else is refused from its first block") {
    std::string garbage(100u << 20, 'x');
    const auto p = dir.write("g.c3d", garbage);
    CHECK_ONE_LINE_ERROR(read_c3d(p), p, "not a C3D file");
  }
}
