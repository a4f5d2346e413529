#include <catch2/catch.hpp>

#include "one_line_error.hpp"
#include "readers/segments.hpp"
#include "scratch_files.hpp"

using aloft::host::read_segments_csv;
using aloft::test::ScratchDir;

TEST_CASE("segments: keep=false rows skipped, spaces trimmed, comments kept", "[readers][segments]") {
  ScratchDir dir;
  const auto segments =
      read_segments_csv(dir.write("s.csv",
                                  "segment, start, end, keep, comment\n"
                                  "0, 4.8, 6.2, false, Not a trial\n"
                                  " 1 , 12.0 , 13.0 , , Intermediate axis rotation\n"
                                  "2,18.65,19.84,true,fast, then slow\n"
                                  "3,20,21,\" FALSE\",\"quoted, with comma\"\n"
                                  "4,25.2,26.25"));  // no keep/comment cells, no final newline
  REQUIRE(segments.size() == 3);
  CHECK(segments[0].name == "1");
  CHECK(segments[0].start_s == 12.0);
  CHECK(segments[0].end_s == 13.0);
  CHECK(segments[0].comment == "Intermediate axis rotation");
  CHECK(segments[1].comment == "fast, then slow");
  CHECK(segments[2].name == "4");
  CHECK(segments[2].end_s == 26.25);
}

TEST_CASE("segments: a keep=false row is skipped before its cells are read", "[readers][segments]") {
  ScratchDir dir;
  // phyphox users leave start and end blank on rows they do not keep (SPEC §3).
  const auto segments = read_segments_csv(dir.write("s.csv",
                                                    "segment,start,end,keep,comment\n"
                                                    "0,,,false,warm-up\n"
                                                    "1,1.0,2.0,true,\n"
                                                    "x, later , ?, FALSE, dropped, with a comma\n"
                                                    "2,3.0,4.0\n"));
  REQUIRE(segments.size() == 2);
  CHECK(segments[0].name == "1");
  CHECK(segments[1].name == "2");
  CHECK(segments[1].start_s == 3.0);
}

TEST_CASE("racquet sessions' segments", "[readers][segments][shared]") {
  ALOFT_REQUIRE_SHARED_DATA(data);
  const auto first = read_segments_csv(data + "/real/racquet/2025-01-16_17-10-11/segments.csv");
  REQUIRE(first.size() == 6);  // row 0 is keep=false
  CHECK(first.front().name == "1");
  CHECK(first.front().start_s == 12.0);
  CHECK(first.back().end_s == 53.45);
  const auto second = read_segments_csv(data + "/real/racquet/2025-01-23_18-29-01/segments.csv");
  CHECK(second.size() == 5);
}

TEST_CASE("bad segments files", "[readers][segments][bad]") {
  ScratchDir dir;
  SECTION("wrong header") {
    const auto p = dir.write("s.csv", "name,from,to\n1,2,3\n");
    CHECK_ONE_LINE_ERROR(read_segments_csv(p), p + ":1:", "segment,start,end");
  }
  SECTION("end before start") {
    const auto p = dir.write("s.csv", "segment,start,end\n1,2,3\n2,5,4\n");
    CHECK_ONE_LINE_ERROR(read_segments_csv(p), p + ":3:", "ends before it starts");
  }
  SECTION("unknown keep value") {
    const auto p = dir.write("s.csv", "segment,start,end,keep\n1,2,3,maybe\n");
    CHECK_ONE_LINE_ERROR(read_segments_csv(p), p + ":2:", "maybe");
  }
  SECTION("missing end") {
    const auto p = dir.write("s.csv", "segment,start,end\n1,2\n");
    CHECK_ONE_LINE_ERROR(read_segments_csv(p), p + ":2:", "end");
  }
  SECTION("NaN start") {
    const auto p = dir.write("s.csv", "segment,start,end\n1,nan,3\n");
    CHECK_ONE_LINE_ERROR(read_segments_csv(p), p + ":2:", "finite");
  }
  SECTION("nothing kept") {
    const auto p = dir.write("s.csv", "segment,start,end,keep\n1,2,3,false\n");
    CHECK_ONE_LINE_ERROR(read_segments_csv(p), p, "keep=false");
  }
  SECTION("empty file") {
    const auto p = dir.write("s.csv", "\n\n");
    CHECK_ONE_LINE_ERROR(read_segments_csv(p), p, "empty");
  }
}
