#include "diagnose/6_report/corrected_body.hpp"

#include <fstream>
#include <sstream>

#include "common/json_text.hpp"
#include "common/atomic_file.hpp"
#include "common/commands.hpp"

namespace aloft::host::diagnose {

nlohmann::json fitted_tensor(const nlohmann::json& report) {
  if (!report.contains("verdict") || !report["verdict"].contains("effects")) return nullptr;
  for (const nlohmann::json& effect : report["verdict"]["effects"]) {
    if (effect.contains("params") && effect["params"].contains("tensor_kg_m2")) {
      return effect["params"]["tensor_kg_m2"];
    }
  }
  return nullptr;
}

bool write_corrected_body(const std::string& body_path, const nlohmann::json& report,
                          const std::string& out_path) {
  if (fitted_tensor(report).is_null()) return false;
  std::ifstream in(body_path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return write_corrected_body_from_text(text.str(), report, out_path);
}

bool write_corrected_body_from_text(const std::string& body_text, const nlohmann::json& report,
                                    const std::string& out_path) {
  const nlohmann::json tensor = fitted_tensor(report);
  if (tensor.is_null()) return false;
  // The body file was read and checked before the diagnosis: it parses.
  nlohmann::json body = nlohmann::json::parse(body_text);
  body["inertia"] = {{"tensor", tensor}};
  write_file_atomically(out_path, [&](std::ostream& out) { out << json_text(body) << "\n"; });
  return true;
}

}  // namespace aloft::host::diagnose
