// One list per settings struct. Every settings struct of the onboard chain (the stream
// clock's, the release detector's, the release window's, the lever-arm estimator's, the
// check's and the pipeline's own) lists its fields once, in
//   template <class Self, class Visitor> static void visit(Self& s, Visitor&& v)
// which calls v(field, describe) for each setting in a fixed order, and visit_settings()
// on the settings structs it holds. That one list is walked by the records' settings hash
// (aloft/records/settings_hash.hpp), by the test that changes every setting and checks the
// hash changes (tests/core/test_settings_hash.cpp), and by the test that writes the docs
// table (docs/onboard-settings.md) and compares it with the page.
//
// `describe` is an empty function object returning the setting's SettingInfo. Only a
// visitor that wants the words calls it, so a firmware that hashes its settings carries
// none of them. Self is the struct, const or not: the same list reads the settings (the
// hash, the table) and writes them (the test).
#pragma once

#include <type_traits>

namespace aloft {

struct SettingInfo {
  const char* name;  // as written on OnboardPipelineSettings, e.g. "release.confirm_us"
  const char* unit;  // "" for a plain number
  const char* why;   // what it decides, and the measurement (or the constant) behind its value
};

template <typename Settings, typename Visitor>
void visit_settings(Settings& settings, Visitor&& visitor) {
  std::remove_const_t<Settings>::visit(settings, visitor);
}

}  // namespace aloft
