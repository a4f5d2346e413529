// Flight records: the CRC-32 against its standard check value, the byte layout of
// aloft/records/flight_record.hpp field by field, how a slot is classified (version 1 and 2
// records still read, with their first seeds), the tensor hash against a value computed independently
// (Python's struct and zlib.crc32 over the bytes the header defines; the settings hash:
// test_settings_hash.cpp), the adapter from the pipeline's result, and the ring on a device full of garbage
// and after several wraps.
#include <cmath>
#include <cstdint>

#include "aloft/records/flight_record_from_result.hpp"
#include "aloft/records/record_ring.hpp"
#include "fake_flash.hpp"
#include "test_api.hpp"

namespace {

using aloft::FlightRecord;
using aloft::SlotState;
using aloft::Status;

FlightRecord sample_record() {
  FlightRecord r;
  r.sequence = 0x01020304u;
  r.flight_number = 7;
  r.release_us = 0x1122334455667788ull;
  r.landing_us = 2500000;
  r.samples = 812;
  r.gaps = 2;
  r.clipped_samples = 5;
  r.landed = true;
  r.turned = true;
  r.comparisons = 6000;
  r.rms_da_rad = 1.0f;
  r.rms_rel_err = 0.5f;
  r.max_da_rad = 2.0f;
  r.max_rel_err = -2.0f;
  r.tensor.determined = true;
  r.tensor.absolute = true;
  r.tensor.note = 0;
  r.tensor.principal[0] = 0.001f;
  r.tensor.principal[1] = 0.002f;
  r.tensor.principal[2] = 0.003f;
  r.tensor.axes_xyz[0] = 0.5f;
  r.tensor.axes_xyz[1] = -0.25f;
  r.tensor.axes_xyz[2] = 0.125f;
  r.tensor.ratios_95[0] = 0.5f;  // bf16 holds these exactly
  r.tensor.ratios_95[1] = 0.25f;
  r.tensor.principal_95[0] = 0.0078125f;
  r.tensor.principal_95[1] = 0.015625f;
  r.tensor.principal_95[2] = 0.03125f;
  r.tensor.axes_95_rad[0] = 0.0625f;
  r.tensor.axes_95_rad[1] = 1.5f;
  r.tensor.axes_95_rad[2] = 3.0f;
  r.tensor_hash = 0xDEADBEEFu;
  r.settings_hash = 0x0BADF00Du;
  return r;
}

// Exact equality of two floats, bit for bit (-Wfloat-equal forbids ==).
bool same_bits(float a, float b) {
  std::uint8_t x[4], y[4];
  aloft::le::put_f32(x, a);
  aloft::le::put_f32(y, b);
  return aloft::bytes_equal(x, y, 4);
}

}  // namespace

ALOFT_TEST_CASE("crc32: the standard check value, chaining, and the empty input", "[records]") {
  const std::uint8_t digits[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  ALOFT_CHECK(aloft::crc32(digits, 9) == 0xCBF43926u);
  ALOFT_CHECK(aloft::crc32(digits + 4, 5, aloft::crc32(digits, 4)) == 0xCBF43926u);
  ALOFT_CHECK(aloft::crc32(digits, 0) == 0u);
}

ALOFT_TEST_CASE("flight record: every field at its offset, little-endian", "[records]") {
  std::uint8_t b[aloft::flight_record_size];
  aloft::encode_flight_record(sample_record(), b);
  const std::uint8_t head[16] = {0x41, 0x4C, 0x46, 0x52, 4, 0, 128, 0, 4, 3, 2, 1, 7, 0, 0, 0};
  ALOFT_CHECK(aloft::bytes_equal(b, head, 16));
  const std::uint8_t release[8] = {0x88, 0x77, 0x66, 0x55, 0x44, 0x33, 0x22, 0x11};
  ALOFT_CHECK(aloft::bytes_equal(b + 16, release, 8));
  ALOFT_CHECK(aloft::le::get_u64(b + 24) == 2500000u);
  ALOFT_CHECK((b[32] == 0x2C && b[33] == 0x03 && b[36] == 2 && b[40] == 5));  // 812 = 0x032C
  ALOFT_CHECK(aloft::le::get_u32(b + 44) == 3u + 8u + 16u);  // landed, turned; tensor determined, absolute
  ALOFT_CHECK(aloft::le::get_u32(b + 48) == 6000u);
  const std::uint8_t one[4] = {0x00, 0x00, 0x80, 0x3F};  // 1.0f
  ALOFT_CHECK(aloft::bytes_equal(b + 52, one, 4));
  const std::uint8_t minus_two[4] = {0x00, 0x00, 0x00, 0xC0};  // -2.0f
  ALOFT_CHECK(aloft::bytes_equal(b + 64, minus_two, 4));
  ALOFT_CHECK(same_bits(aloft::le::get_f32(b + 76), 0.003f));
  ALOFT_CHECK(same_bits(aloft::le::get_f32(b + 84), -0.25f));
  ALOFT_CHECK(aloft::le::get_u16(b + 92) == 0x3F00u);   // 0.5 as bf16
  ALOFT_CHECK(aloft::le::get_u16(b + 100) == 0x3D00u);  // 0.03125
  ALOFT_CHECK(aloft::le::get_u16(b + 102) == 0x3D80u);  // 0.0625
  ALOFT_CHECK(aloft::le::get_u16(b + 114) == 0x4040u);  // 3.0
  ALOFT_CHECK(aloft::le::get_u32(b + 104) == 0xDEADBEEFu);
  ALOFT_CHECK(aloft::le::get_u32(b + 108) == 0x0BADF00Du);
  ALOFT_CHECK(aloft::le::get_u32(b + 116) == aloft::crc32(b, 116));
  const std::uint8_t commit[8] = {0x43, 0x4F, 0x4D, 0x54, 0xFF, 0xFF, 0xFF, 0xFF};
  ALOFT_CHECK(aloft::bytes_equal(b + 120, commit, 8));
}

ALOFT_TEST_CASE("flight record: decoded as written; torn, corrupt, foreign and other versions named",
                "[records]") {
  std::uint8_t b[aloft::flight_record_size];
  aloft::encode_flight_record(sample_record(), b);
  FlightRecord back;
  ALOFT_REQUIRE(aloft::decode_flight_record(b, back) == SlotState::valid);
  std::uint8_t again[aloft::flight_record_size];
  aloft::encode_flight_record(back, again);
  ALOFT_CHECK(aloft::bytes_equal(b, again, aloft::flight_record_size));
  ALOFT_CHECK(back.release_us == 0x1122334455667788ull);
  ALOFT_CHECK(back.version == 4u);
  ALOFT_CHECK((back.tensor.determined && back.tensor.absolute && back.tensor.note == 0u));
  ALOFT_CHECK(same_bits(back.tensor.principal[1], 0.002f));
  ALOFT_CHECK(same_bits(back.tensor.axes_95_rad[1], 1.5f));
  ALOFT_CHECK(same_bits(back.tensor.principal_95[0], 0.0078125f));
  ALOFT_CHECK(back.seeds_stored == 0u);

  // Version 3, written before the settings hash's list lost a setting, has this layout:
  // it reads, tensor and all, and says it is version 3.
  std::uint8_t v3[aloft::flight_record_size];
  for (std::uint32_t i = 0; i < aloft::flight_record_size; ++i) v3[i] = b[i];
  aloft::le::put_u16(v3 + 4, 3);
  aloft::le::put_u32(v3 + aloft::flight_record_crc_offset, aloft::crc32(v3, aloft::flight_record_crc_offset));
  FlightRecord old;
  ALOFT_REQUIRE(aloft::decode_flight_record(v3, old) == SlotState::valid);
  ALOFT_CHECK(old.version == 3u);
  ALOFT_CHECK(same_bits(old.tensor.principal[1], 0.002f));

  std::uint8_t s[aloft::flight_record_size];
  const auto state_with = [&](std::uint32_t offset, std::uint8_t value) {
    for (std::uint32_t i = 0; i < aloft::flight_record_size; ++i) s[i] = b[i];
    s[offset] = value;
    FlightRecord r;
    return aloft::decode_flight_record(s, r);
  };
  ALOFT_CHECK(state_with(60, static_cast<std::uint8_t>(b[60] ^ 0x10)) == SlotState::crc_mismatch);
  ALOFT_CHECK(state_with(116, static_cast<std::uint8_t>(b[116] ^ 1)) == SlotState::crc_mismatch);
  ALOFT_CHECK(state_with(123, 0xFF) == SlotState::not_committed);
  ALOFT_CHECK(state_with(4, 5) == SlotState::unknown_version);
  ALOFT_CHECK(state_with(4, 0) == SlotState::unknown_version);
  ALOFT_CHECK(state_with(6, 64) == SlotState::unknown_version);
  ALOFT_CHECK(state_with(0, 0x42) == SlotState::no_magic);
  for (std::uint8_t& x : s) x = 0xFF;
  FlightRecord r;
  ALOFT_CHECK(aloft::decode_flight_record(s, r) == SlotState::erased);
}

// Records written before the tensor estimate (versions 1 and 2: the first seeds where
// version 3 keeps the estimate, bytes 112..115 reserved) still read, and say which they are.
ALOFT_TEST_CASE("flight record: version 1 and 2 records still read, with their seeds", "[records]") {
  for (const std::uint16_t version : {std::uint16_t(1), std::uint16_t(2)}) {
    std::uint8_t b[aloft::flight_record_size];
    aloft::encode_flight_record(sample_record(), b);
    aloft::le::put_u16(b + 4, version);
    aloft::le::put_u32(b + 44, 3u);  // landed, turned: no tensor bits before version 3
    aloft::le::put_u32(b + 68, 2u);
    for (std::uint32_t i = 72; i < 104; i += 4) aloft::le::put_f32(b + i, 0.0f);
    aloft::le::put_f32(b + 72, 0.25f);
    aloft::le::put_f32(b + 84, 8.0f);
    aloft::le::put_u32(b + 112, 0u);
    aloft::le::put_u32(b + aloft::flight_record_crc_offset, aloft::crc32(b, aloft::flight_record_crc_offset));
    FlightRecord back;
    ALOFT_REQUIRE(aloft::decode_flight_record(b, back) == SlotState::valid);
    ALOFT_CHECK(back.version == version);
    ALOFT_CHECK(back.settings_hash == 0x0BADF00Du);
    ALOFT_CHECK(back.release_us == 0x1122334455667788ull);
    ALOFT_CHECK(back.seeds_stored == 2u);
    ALOFT_CHECK(same_bits(back.seeds[0].rms_da_rad, 0.25f));
    ALOFT_CHECK(same_bits(back.seeds[1].rms_rel_err, 8.0f));
    ALOFT_CHECK(!back.tensor.determined);
  }
}

ALOFT_TEST_CASE("flight record: the tensor hash is the CRC-32 of the bytes defined", "[records]") {
  aloft::Mat3<double> tensor;
  tensor << 0.01, 0.001, -0.002, 0.001, 0.02, 0.0005, -0.002, 0.0005, 0.03;
  ALOFT_CHECK(aloft::tensor_hash(tensor) == 0xFABCA080u);  // zlib.crc32(struct.pack('<6f', ...))
  ALOFT_CHECK(aloft::tensor_hash<float>(tensor.cast<float>()) == 0xFABCA080u);
  aloft::Mat3<double> other = tensor;
  other(2, 2) = 0.0301;
  ALOFT_CHECK(aloft::tensor_hash(other) != 0xFABCA080u);
}

ALOFT_TEST_CASE("flight record: made from the pipeline's result", "[records]") {
  aloft::FlightResult<float> result;
  result.flight_number = 3;
  result.release_us = 1500000;
  result.landing_us = 2300000;
  result.landed = true;
  result.samples = 800;
  result.gaps = 1;
  result.clipped_samples = 4;
  result.turned = true;
  result.overall.add_values(0.3f, 0.04f);  // RMS of (0.3, 0.4) is sqrt(0.125)
  result.overall.add_values(0.4f, 0.03f);
  result.tensor.determined = true;
  result.tensor.note = aloft::TensorEstimateNote::determined;
  result.tensor.principal = aloft::Vec3<float>(0.5f, 0.75f, 1.0f);
  result.tensor.ratios_95[1] = 0.01f;
  result.tensor.axes = aloft::Quat<float>(-0.6f, 0.0f, 0.8f, 0.0f);  // w < 0: kept as its negative
  result.tensor.axes_95_rad = aloft::Vec3<float>(0.1f, 0.2f, 0.3f);
  const FlightRecord r = aloft::make_flight_record(result, 11u, 22u);
  ALOFT_CHECK(r.flight_number == 3u);
  ALOFT_CHECK((r.release_us == 1500000u && r.landing_us == 2300000u && r.landed && r.turned));
  ALOFT_CHECK((r.samples == 800u && r.gaps == 1u && r.clipped_samples == 4u && r.comparisons == 2u));
  ALOFT_CHECK(std::abs(r.rms_da_rad - std::sqrt(0.125f)) < 1e-6f);
  ALOFT_CHECK(same_bits(r.max_da_rad, 0.4f));
  ALOFT_CHECK((r.tensor.determined && !r.tensor.absolute && r.tensor.note == 0u));
  ALOFT_CHECK(same_bits(r.tensor.principal[1], 0.75f));
  ALOFT_CHECK(same_bits(r.tensor.ratios_95[1], 0.01f));
  ALOFT_CHECK(same_bits(r.tensor.axes_xyz[1], -0.8f));
  ALOFT_CHECK(same_bits(r.tensor.axes_95_rad[2], 0.3f));
  ALOFT_CHECK((r.tensor_hash == 11u && r.settings_hash == 22u));
}

ALOFT_TEST_CASE("record ring: starts on a device full of garbage, keeps the newest after wraps",
                "[records]") {
  aloft::testing::FakeFlash<512, 3> flash;
  std::uint32_t x = 12345;
  for (std::uint32_t i = 0; i < flash.size(); ++i) {
    x ^= x << 13, x ^= x >> 17, x ^= x << 5;
    flash.bytes()[i] = static_cast<std::uint8_t>(x);
  }
  aloft::RecordRing ring(flash.device());
  ALOFT_REQUIRE(ring.mount() == Status::ok);
  for (std::uint32_t i = 0; i < 40; ++i) {
    FlightRecord r = sample_record();
    r.flight_number = i;
    ALOFT_REQUIRE(ring.append(r) == Status::ok);
    ALOFT_CHECK(r.sequence == i + 1);
  }
  ALOFT_CHECK(flash.violations() == 0u);
  aloft::RecordRing again(flash.device());
  ALOFT_REQUIRE(again.mount() == Status::ok);
  ALOFT_CHECK(again.next_sequence() == 41u);
  std::uint32_t found = 0, lowest = 0xFFFFFFFFu, highest = 0;
  ALOFT_CHECK(again.for_each_record([&](const FlightRecord& r, std::uint32_t, std::uint32_t) {
    ++found;
    lowest = r.sequence < lowest ? r.sequence : lowest;
    highest = r.sequence > highest ? r.sequence : highest;
    if (r.flight_number + 1 != r.sequence) found += 1000;
  }) == Status::ok);
  // Capacity between (3 - 2) * 4 + 1 and (3 - 1) * 4: the newest, without holes.
  ALOFT_CHECK((found >= 5u && found <= 8u));
  ALOFT_CHECK(highest == 40u);
  ALOFT_CHECK(highest - lowest + 1 == found);
}

ALOFT_TEST_CASE("record ring: refuses a geometry it cannot use, and appends only when mounted", "[records]") {
  aloft::testing::FakeFlash<512, 3> flash;
  aloft::BlockDevice one_block = flash.device();
  one_block.block_count = 1;
  ALOFT_CHECK(aloft::RecordRing(one_block).mount() == Status::invalid_dimension);
  aloft::BlockDevice odd_unit = flash.device();
  odd_unit.program_size = 16;
  ALOFT_CHECK(aloft::RecordRing(odd_unit).mount() == Status::invalid_dimension);
  aloft::RecordRing ring(flash.device());
  FlightRecord r = sample_record();
  ALOFT_CHECK(ring.append(r) == Status::storage_full);
}
