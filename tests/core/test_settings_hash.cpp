// The onboard settings' one list (aloft/settings.hpp) and the records' settings hash it
// drives (aloft/records/settings_hash.hpp): the list names every field of every settings
// struct, every setting it names changes the hash, and the hash is the CRC-32 of the
// bytes the list defines.
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>

#include "aloft/records/flight_record.hpp"
#include "aloft/records/settings_hash.hpp"
#include "test_api.hpp"

namespace {

using Settings = aloft::OnboardPipelineSettings<float>;
using aloft::OnboardBuildConstants;

// How many fields an aggregate has: the most initialisers it takes (each converts to any
// member's type). A nested settings struct counts as one field.
struct AnyField {
  template <typename T>
  operator T() const;  // NOLINT: only in unevaluated operands
};
template <typename T, typename Indices, typename = void>
struct TakesInitialisers : std::false_type {};
template <typename T, std::size_t... I>
struct TakesInitialisers<T, std::index_sequence<I...>, std::void_t<decltype(T{(void(I), AnyField{})...})>>
    : std::true_type {};
template <typename T, std::size_t N = 0>
constexpr std::size_t field_count() {
  if constexpr (TakesInitialisers<T, std::make_index_sequence<N + 1>>::value) {
    return field_count<T, N + 1>();
  } else {
    return N;
  }
}

// Settings the list names, nested structs' included.
template <typename S>
int listed_settings() {
  S s{};
  int n = 0;
  aloft::visit_settings(s, [&n](auto&, auto) { ++n; });
  return n;
}

// A value unlike the one given, of the setting's type.
void change(bool& v) { v = !v; }
void change(std::uint16_t& v) { v = static_cast<std::uint16_t>(v + 1u); }
void change(std::uint32_t& v) { v += 1u; }
void change(float& v) { v = v * 1.5f + 0.25f; }
void change(aloft::Quat<float>& q) { q = aloft::Quat<float>(0.6f, 0.8f, 0.0f, 0.0f) * q; }
void change(aloft::Vec3<float>& r) { r.x() += 0.001f; }

// Changes setting `index` of the list (in the list's order) and nothing else.
template <typename S>
void change_setting(S& s, int index) {
  int n = 0;
  aloft::visit_settings(s, [&](auto& value, auto) {
    if (n++ == index) change(value);
  });
}

// The hash of the defaults with setting `index` of `settings` (else of `constants`) changed.
std::uint32_t hash_with_changed(int index) {
  Settings s;
  OnboardBuildConstants c = aloft::onboard_build_constants(8);
  const int constants = listed_settings<OnboardBuildConstants>();
  if (index < constants) {
    change_setting(c, index);
  } else {
    change_setting(s, index - constants);
  }
  return aloft::settings_hash(s, c);
}

// The bytes the list defines, written out whole (not hashed as they come, as the hasher does).
struct SettingBytes {
  std::uint8_t bytes[512] = {};
  std::size_t size = 0;
  void put(std::uint32_t v, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) bytes[size++] = static_cast<std::uint8_t>(v >> (8 * i));
  }
  void put_float(float v) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, 4);
    put(bits, 4);
  }
  template <typename Describe>
  void operator()(const bool& v, Describe) {
    put(v ? 1u : 0u, 1);
  }
  template <typename Describe>
  void operator()(const std::uint16_t& v, Describe) {
    put(v, 2);
  }
  template <typename Describe>
  void operator()(const std::uint32_t& v, Describe) {
    put(v, 4);
  }
  template <typename Describe>
  void operator()(const float& v, Describe) {
    put_float(v);
  }
  template <typename Describe>
  void operator()(const aloft::Quat<float>& q, Describe) {
    for (const float c : {q.w(), q.x(), q.y(), q.z()}) put_float(c);
  }
  template <typename Describe>
  void operator()(const aloft::Vec3<float>& r, Describe) {
    for (int i = 0; i < 3; ++i) put_float(r[i]);
  }
};

}  // namespace

ALOFT_TEST_CASE("settings list: names every field of every onboard settings struct", "[settings]") {
  // A struct's settings are its own fields, plus those of the settings structs it holds.
  using aloft::FreeFlightSettings, aloft::ReleaseDetectorSettings, aloft::ReleaseWindowSettings;
  using aloft::StreamClockSettings, aloft::LeverArmEstimatorSettings, aloft::OnboardCheckSettings;
  ALOFT_CHECK(listed_settings<StreamClockSettings<float>>() ==
              static_cast<int>(field_count<StreamClockSettings<float>>()));
  ALOFT_CHECK(listed_settings<FreeFlightSettings<float>>() ==
              static_cast<int>(field_count<FreeFlightSettings<float>>()));
  ALOFT_CHECK(listed_settings<ReleaseDetectorSettings<float>>() ==
              static_cast<int>(field_count<ReleaseDetectorSettings<float>>()) - 1 +
                  listed_settings<FreeFlightSettings<float>>());
  ALOFT_CHECK(listed_settings<ReleaseWindowSettings<float>>() ==
              static_cast<int>(field_count<ReleaseWindowSettings<float>>()));
  ALOFT_CHECK(listed_settings<LeverArmEstimatorSettings<float>>() ==
              static_cast<int>(field_count<LeverArmEstimatorSettings<float>>()));
  ALOFT_CHECK(listed_settings<OnboardCheckSettings<float>>() ==
              static_cast<int>(field_count<OnboardCheckSettings<float>>()));
  ALOFT_CHECK(listed_settings<OnboardBuildConstants>() ==
              static_cast<int>(field_count<OnboardBuildConstants>()));
  const int held =
      listed_settings<OnboardCheckSettings<float>>() + listed_settings<StreamClockSettings<float>>() +
      listed_settings<ReleaseDetectorSettings<float>>() + listed_settings<ReleaseWindowSettings<float>>() +
      listed_settings<LeverArmEstimatorSettings<float>>() + listed_settings<aloft::Rotor<float>>() +
      listed_settings<aloft::TensorEstimatorSettings<float>>();
  ALOFT_CHECK(listed_settings<aloft::Rotor<float>>() == static_cast<int>(field_count<aloft::Rotor<float>>()));
  ALOFT_CHECK(listed_settings<aloft::TensorEstimatorSettings<float>>() ==
              static_cast<int>(field_count<aloft::TensorEstimatorSettings<float>>()));
  ALOFT_CHECK(listed_settings<Settings>() == static_cast<int>(field_count<Settings>()) - 7 + held);
  // The counting itself: a struct of three plain fields has three.
  struct Three {
    int a, b, c;
  };
  ALOFT_CHECK(field_count<Three>() == 3u);
}

// Every setting that can change a decision changes the hash, the build constants too, and
// no two changes give the same hash: a record can be matched to the settings it was
// checked with.
ALOFT_TEST_CASE("settings hash: changing any setting of the list changes it", "[settings][records]") {
  const std::uint32_t default_hash = aloft::settings_hash(Settings(), 8);
  const int count = listed_settings<OnboardBuildConstants>() + listed_settings<Settings>();
  ALOFT_REQUIRE(count <= 80);
  std::uint32_t hashes[80] = {};
  int unchanged = -1, same_as_another = -1;
  for (int i = 0; i < count; ++i) {
    hashes[i] = hash_with_changed(i);
    if (unchanged < 0 && hashes[i] == default_hash) unchanged = i;
    for (int j = 0; j < i; ++j)
      if (same_as_another < 0 && hashes[j] == hashes[i]) same_as_another = i;
  }
  ALOFT_CHECK(unchanged == -1);
  ALOFT_CHECK(same_as_another == -1);
  ALOFT_CHECK(count == 3 + 57);  // the build constants and the pipeline's settings listed today
}

ALOFT_TEST_CASE("settings hash: the CRC-32 of the bytes the list defines, build constants first",
                "[settings][records]") {
  SettingBytes written;
  const OnboardBuildConstants constants = aloft::onboard_build_constants(8);
  aloft::visit_settings(constants, written);
  const Settings defaults;
  aloft::visit_settings(defaults, written);
  ALOFT_CHECK(written.size == 3u * 2u + 217u);
  const std::uint32_t default_hash = aloft::settings_hash(Settings(), 8);
  ALOFT_CHECK(default_hash == aloft::crc32(written.bytes, written.size));
  ALOFT_CHECK(aloft::settings_hash(aloft::OnboardPipelineSettings<double>(), 8) == default_hash);
  ALOFT_CHECK(aloft::settings_hash(Settings(), 4) != default_hash);
  // The defaults' hash, pinned: a change here changes what a record's settings hash means,
  // and flight_record_version must change with it (aloft/records/flight_record.hpp).
  ALOFT_CHECK(default_hash == 0x819A9A86u);
  ALOFT_CHECK(aloft::flight_record_version == 4u);
}
