// `aloft records` (SPEC §5) on dumps of the record area: the good one and the example,
// and hostile ones — torn, flipped bits, truncated, random bytes, empty, another version.
// Intact records are always listed, each bad slot is named by its offset and reason,
// and a file that holds no record it can read is refused with one line naming it.
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <catch2/catch.hpp>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "example_flights.hpp"
#include "one_line_error.hpp"
#include "records/record_dump.hpp"
#include "run_aloft.hpp"

namespace {

using aloft::test::program_scratch;
using aloft::test::run_aloft;

std::string good_dump_bytes() {
  const std::string path = program_scratch().path("good.bin");
  REQUIRE(aloft::test::write_example_dump(path) == aloft::Status::ok);
  return aloft::test::read_file(path);
}

std::string write_dump(const std::string& name, const std::string& bytes) {
  return program_scratch().write(name, bytes);
}

std::uint32_t xorshift(std::uint32_t& x) {
  x ^= x << 13, x ^= x >> 17, x ^= x << 5;
  return x;
}

}  // namespace

TEST_CASE("crc32 agrees with zlib's on random buffers, whole and chained", "[records]") {
  std::uint32_t x = 2463534242u;
  for (std::size_t size : {0u, 1u, 3u, 4u, 7u, 116u, 128u, 1000u, 4096u}) {
    std::string bytes(size, '\0');
    for (char& c : bytes) c = static_cast<char>(xorshift(x));
    const auto* p = reinterpret_cast<const std::uint8_t*>(bytes.data());
    const std::uint32_t z = static_cast<std::uint32_t>(::crc32(0L, p, static_cast<uInt>(size)));
    CHECK(aloft::crc32(p, size) == z);
    CHECK(aloft::crc32(p + size / 2, size - size / 2, aloft::crc32(p, size / 2)) == z);
  }
}

TEST_CASE("aloft records lists the flights of a good dump as a table, JSON and CSV", "[records]") {
  const std::string path = write_dump("listed.bin", good_dump_bytes());
  const auto table = run_aloft("records '" + path + "'");
  CHECK(table.exit_code == 0);
  CHECK(table.err.empty());
  CHECK(aloft::test::count_lines(table.out) == 7);  // header, 5 flights, count
  CHECK(table.out.find("5 flights") != std::string::npos);

  const auto json_run = run_aloft("records --json '" + path + "'");
  REQUIRE(json_run.exit_code == 0);
  const auto report = nlohmann::json::parse(json_run.out);
  REQUIRE(report["flights"].size() == 5);
  CHECK(report["problems"].empty());
  for (std::size_t i = 0; i < 5; ++i) CHECK(report["flights"][i]["sequence"] == i + 1);
  for (std::size_t i = 0; i < 5; ++i)
    CHECK(report["flights"][i]["record_version"] == aloft::flight_record_version);
  const auto& f = report["flights"];
  CHECK(f[0]["landed"] == true);
  CHECK(f[0]["rms_da_deg"].get<double>() < 0.1);  // the right tensor, exact motion
  CHECK(f[1]["gaps"] == 1);
  CHECK(f[1]["clipped_samples"] == 3);
  CHECK(f[2]["turned"] == false);
  CHECK(f[2]["rms_da_deg"].is_null());
  CHECK(f[3]["rms_da_deg"].get<double>() > 10 * f[0]["rms_da_deg"].get<double>());
  CHECK(f[3]["tensor_hash"] != f[0]["tensor_hash"]);
  CHECK(f[4]["landed"] == false);
  CHECK(f[4]["landing_s"].is_null());
  // Version 3 keeps the flight's own tensor estimate (no first seeds): the top's ratios
  // 1/3 and 2/3 within their intervals, also for the throw checked with a wrong tensor
  // (the estimate is the flight's, not the body file's); the drop determines nothing.
  CHECK(f[0]["first_seeds"].empty());
  for (const int i : {0, 1, 3}) {
    const auto& t = f[i]["tensor_estimate"];
    INFO("flight " << i << ": " << t.dump());
    REQUIRE(t["determined"] == true);
    CHECK(std::abs(t["principal_ratios"][0].get<double>() - 1.0 / 3.0) < 1e-3);
    CHECK(std::abs(t["principal_ratios"][1].get<double>() - 2.0 / 3.0) < 1e-3);
    CHECK(t["principal_ratios_95"][0][0].get<double>() <= t["principal_ratios"][0].get<double>());
    CHECK(t["principal_kg_m2"].is_null());
  }
  CHECK(f[2]["tensor_estimate"]["determined"] == false);
  CHECK(f[2]["tensor_estimate"]["note"].get<std::string>().find("turning") != std::string::npos);

  const auto csv = run_aloft("records --csv '" + path + "'");
  CHECK(csv.exit_code == 0);
  CHECK(aloft::test::count_lines(csv.out) == 6);
  CHECK(csv.out.rfind("sequence,flight,release_s,landing_s,", 0) == 0);
  CHECK(csv.out.find("\n5,4,") != std::string::npos);

  CHECK(run_aloft("records --json --csv '" + path + "'").exit_code == 2);
}

TEST_CASE("the example dump is what its generator writes, and lists its flights", "[records]") {
  const std::string example = std::string(ALOFT_SOURCE_DIR) + "/examples/flight_records.bin";
  // The same flights as the generator makes now (the floats to rounding: another compiler
  // may round the pipeline's last bits otherwise).
  const std::string fresh = write_dump("fresh.bin", good_dump_bytes());
  const aloft::host::RecordDump stored = aloft::host::read_record_dump(example);
  const aloft::host::RecordDump made = aloft::host::read_record_dump(fresh);
  REQUIRE(stored.records.size() == made.records.size());
  CHECK(stored.problems.empty());
  for (std::size_t i = 0; i < made.records.size(); ++i) {
    const aloft::FlightRecord& a = stored.records[i].record;
    const aloft::FlightRecord& b = made.records[i].record;
    CHECK((a.sequence == b.sequence && a.flight_number == b.flight_number && a.release_us == b.release_us &&
           a.landing_us == b.landing_us && a.samples == b.samples && a.gaps == b.gaps &&
           a.clipped_samples == b.clipped_samples && a.landed == b.landed && a.turned == b.turned));
    CHECK(std::abs(a.rms_da_rad - b.rms_da_rad) < 1e-5f);
    CHECK(std::abs(a.rms_rel_err - b.rms_rel_err) < 1e-5f);
    // The committed example was written as version 1, before the settings hash walked the
    // settings' one list: it still reads, and says so; the generator writes the current one.
    CHECK(a.version == 1u);
    CHECK(b.version == aloft::flight_record_version);
  }
  const auto r = run_aloft("records '" + example + "'");
  CHECK(r.exit_code == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find("5 flights") != std::string::npos);
}

TEST_CASE("aloft records: a torn record is named, the others listed", "[records]") {
  std::string bytes = good_dump_bytes();
  for (int i = 120; i < 124; ++i) bytes[4 * 128 + i] = static_cast<char>(0xFF);  // marker not programmed
  for (int i = 60; i < 120; ++i) bytes[3 * 128 + i] = static_cast<char>(0xFF);   // body cut at byte 60
  const auto r = run_aloft("records --json '" + write_dump("torn.bin", bytes) + "'");
  CHECK(r.exit_code == 0);
  const auto report = nlohmann::json::parse(r.out);
  CHECK(report["flights"].size() == 3);
  REQUIRE(report["problems"].size() == 2);
  CHECK(report["problems"][0]["offset"] == 384);
  CHECK(report["problems"][1]["offset"] == 512);
  CHECK(report["problems"][1]["reason"] == "torn record (no commit marker)");
  CHECK(r.err.find("offset 512: torn record") != std::string::npos);
}

TEST_CASE("aloft records: every single flipped bit in a record is caught, never listed", "[records]") {
  const std::string good = good_dump_bytes();
  const std::string path = program_scratch().path("flipped.bin");
  for (int byte = 0; byte < 128; ++byte) {
    for (int bit = 0; bit < 8; ++bit) {
      std::string bytes = good;
      bytes[128 + byte] = static_cast<char>(bytes[128 + byte] ^ (1 << bit));
      aloft::test::write_file(path, bytes);
      const aloft::host::RecordDump dump = aloft::host::read_record_dump(path);
      INFO("byte " << byte << " bit " << bit);
      if (byte < 124) {  // bytes 124..127 are unused padding
        CHECK(dump.records.size() == 4);
        REQUIRE(dump.problems.size() == 1);
        CHECK(dump.problems[0].offset == 128);
      } else {
        CHECK(dump.records.size() == 5);
      }
    }
  }
  std::string bytes = good;
  bytes[128 + 60] = static_cast<char>(bytes[128 + 60] ^ 4);
  const auto r = run_aloft("records '" + write_dump("flip.bin", bytes) + "'");
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("4 flights") != std::string::npos);
  CHECK(r.err.find("offset 128: CRC-32 mismatch") != std::string::npos);
}

TEST_CASE("aloft records: a truncated dump lists the whole records before the cut", "[records]") {
  const std::string good = good_dump_bytes();
  const std::string path = program_scratch().path("cut.bin");
  for (std::size_t size = 4; size < good.size(); ++size) {
    aloft::test::write_file(path, good.substr(0, size));
    const aloft::host::RecordDump dump = aloft::host::read_record_dump(path);
    INFO("size " << size);
    CHECK(dump.records.size() == std::min<std::size_t>(size / 128, 5));
    const bool partial_record = size % 128 != 0 && size < 5 * 128;
    CHECK(dump.problems.size() == (partial_record ? 1u : 0u));
  }
  const auto r = run_aloft("records '" + write_dump("cut300.bin", good.substr(0, 300)) + "'");
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("2 flights") != std::string::npos);
  CHECK(r.err.find("offset 256: truncated record (44 of 128 bytes)") != std::string::npos);
}

TEST_CASE("aloft records refuses random bytes, an empty file, another version, in one line", "[records]") {
  std::uint32_t x = 99;
  std::string noise(4096, '\0');
  for (char& c : noise) c = static_cast<char>(xorshift(x));
  const std::string noise_path = write_dump("noise.bin", noise);
  CHECK_ONE_LINE_ERROR(aloft::host::read_record_dump(noise_path), noise_path, "not a flight record dump");
  const std::string empty_path = write_dump("empty.bin", "");
  CHECK_ONE_LINE_ERROR(aloft::host::read_record_dump(empty_path), empty_path, "empty file");
  CHECK_ONE_LINE_ERROR(aloft::host::read_record_dump(noise_path + ".missing"), "cannot be opened");
  CHECK_ONE_LINE_ERROR(aloft::host::read_record_dump(program_scratch().path("")), "a folder");

  std::string v5 = good_dump_bytes();
  for (int slot = 0; slot < 5; ++slot) v5[slot * 128 + 4] = 5;
  const std::string v5_path = write_dump("v5.bin", v5);
  CHECK_ONE_LINE_ERROR(aloft::host::read_record_dump(v5_path), v5_path, "record version 5 at offset 0",
                       "versions 1 to 4");
  for (const std::string& p : {noise_path, empty_path, v5_path}) {
    const auto r = run_aloft("records '" + p + "'");
    CHECK(r.exit_code == 2);
    CHECK(aloft::test::count_lines(r.err) == 1);
    CHECK(r.err.find(p) != std::string::npos);
    CHECK(r.out.empty());
  }
}

TEST_CASE("aloft records on an erased record area: no flights, no problems", "[records]") {
  const auto r = run_aloft("records '" + write_dump("erased.bin", std::string(3072, '\xFF')) + "'");
  CHECK(r.exit_code == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find("0 flights") != std::string::npos);
}
