// The settings hash a flight record carries (aloft/records/flight_record.hpp), so that a
// result can be matched to the settings it was checked with: CRC-32 (aloft/records/crc32.hpp)
// of every setting's bytes in the order of the settings' one list (aloft/settings.hpp),
// the build constants first (K, the history's samples, the release window's blocks), then
// OnboardPipelineSettings. Numbers are little-endian: a real number as IEEE-754 binary32
// whatever Scalar is (a firmware checks in float), an integer in its own width, a flag one
// byte, a quaternion w x y z, a vector x y z. docs/onboard-settings.md lists the settings
// in that order. Records of version 1 carry the hash of an earlier, hand-written list
// (without the build constants and the two level factors); records of version 2 that of the
// list before the rotor and the tensor estimate's settings joined it.
#pragma once

#include <cstdint>
#include <cstring>

#include "aloft/cold_path.hpp"
#include "aloft/onboard/onboard_pipeline.hpp"
#include "aloft/records/crc32.hpp"
#include "aloft/records/little_endian.hpp"
#include "aloft/settings.hpp"

namespace aloft {

// A settings visitor that hashes each setting as it comes: no buffer whose size must
// follow the list.
class SettingsHasher {
 public:
  template <typename Value, typename Describe>
  void operator()(const Value& value, Describe) {
    add(value);
  }
  std::uint32_t value() const { return crc_; }

 private:
  void add(bool v) { add_bytes(v ? 1u : 0u, 1); }
  void add(std::uint16_t v) { add_bytes(v, 2); }
  void add(std::uint32_t v) { add_bytes(v, 4); }
  void add(double v) { add(static_cast<float>(v)); }
  void add(float v) {
    static_assert(sizeof(float) == 4, "binary32 float");
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, 4);
    add_bytes(bits, 4);
  }
  template <typename Scalar>
  void add(const Quat<Scalar>& q) {
    for (const Scalar c : {q.w(), q.x(), q.y(), q.z()}) add(c);
  }
  template <typename Scalar>
  void add(const Vec3<Scalar>& r) {
    for (int i = 0; i < 3; ++i) add(r[i]);
  }
  // Out of line: every setting calls it, with one load and one call each.
  ALOFT_OUT_OF_LINE void add_bytes(std::uint32_t value, std::size_t count) {
    std::uint8_t bytes[4];
    le::put_u32(bytes, value);
    crc_ = crc32(bytes, count, crc_);
  }

  std::uint32_t crc_ = 0;
};

template <typename Scalar>
ALOFT_COLD std::uint32_t settings_hash(const OnboardPipelineSettings<Scalar>& settings,
                                       const OnboardBuildConstants& constants) {
  SettingsHasher hasher;
  visit_settings(constants, hasher);
  visit_settings(settings, hasher);
  return hasher.value();
}

// The hash of the settings of a pipeline with K live simulations (computed once, at
// start-up).
template <typename Scalar>
std::uint32_t settings_hash(const OnboardPipelineSettings<Scalar>& settings, int live_simulations) {
  return settings_hash(settings, onboard_build_constants(live_simulations));
}

}  // namespace aloft
