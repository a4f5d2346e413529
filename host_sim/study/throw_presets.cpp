#include "study/throw_presets.hpp"

#include "common/commands.hpp"

namespace aloft::host {

SyntheticThrowSettings throw_preset(const std::string& name) {
  SyntheticThrowSettings s;
  if (name == "built-in") return s;
  throw Error("study: --throw must be built-in, not '" + name + "'");
}

}  // namespace aloft::host
