// docs/onboard-settings.md's table is the settings' one list (aloft/settings.hpp), written
// out: each setting in the order the records' settings hash takes it, with its default,
// unit and what chose its value. On a mismatch the test prints the table the code gives,
// to paste between the page's two markers.
#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "aloft/records/settings_hash.hpp"

namespace {

const char* const kBegin =
    "<!-- settings table: generated from the code, tests/records/test_settings_table.cpp -->\n";
const char* const kEnd = "<!-- end of settings table -->";

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

std::string value(bool v) { return v ? "true" : "false"; }
std::string value(std::uint16_t v) { return std::to_string(v); }
std::string value(std::uint32_t v) { return std::to_string(v); }
std::string value(float v) { return number(static_cast<double>(v)); }
std::string value(const aloft::Quat<float>& q) {
  if (q.isApprox(aloft::Quat<float>::Identity(), 0.0f)) return "identity";
  return "w " + value(q.w()) + ", x " + value(q.x()) + ", y " + value(q.y()) + ", z " + value(q.z());
}
std::string value(const aloft::Vec3<float>& r) {
  return "(" + value(r.x()) + ", " + value(r.y()) + ", " + value(r.z()) + ")";
}

// A table cell: a '|' of the text (|K r|) escaped.
std::string cell(const char* text) {
  std::string out;
  for (const char* c = text; *c != '\0'; ++c) out += *c == '|' ? std::string("\\|") : std::string(1, *c);
  return out;
}

struct TableRows {
  std::string text;
  template <typename Value, typename Describe>
  void operator()(const Value& v, Describe describe) {
    const aloft::SettingInfo info = describe();
    text += "| `" + std::string(info.name) + "` | " + value(v) + " | " + cell(info.unit) + " | " +
            cell(info.why) + " |\n";
  }
};

std::string settings_table() {
  TableRows rows;
  rows.text = "| setting | default | unit | what it decides, and what chose its value |\n|---|---|---|---|\n";
  const aloft::OnboardBuildConstants constants = aloft::onboard_build_constants(8);
  const aloft::OnboardPipelineSettings<float> defaults;
  aloft::visit_settings(constants, rows);
  aloft::visit_settings(defaults, rows);
  return rows.text;
}

std::string page_table() {
  std::ifstream in(std::string(ALOFT_SOURCE_DIR) + "/docs/onboard-settings.md");
  std::stringstream page;
  page << in.rdbuf();
  const std::string text = page.str();
  const std::size_t begin = text.find(kBegin);
  const std::size_t end = text.find(kEnd);
  if (begin == std::string::npos || end == std::string::npos || end < begin)
    return "(no table between the markers)";
  return text.substr(begin + std::string(kBegin).size(), end - begin - std::string(kBegin).size());
}

}  // namespace

TEST_CASE("docs/onboard-settings.md's table is the settings' one list", "[records][docs]") {
  const std::string table = settings_table();
  const std::string page = page_table();
  INFO("docs/onboard-settings.md, between its markers, should read:\n" << table);
  CHECK(page == table);
}
