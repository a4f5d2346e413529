#include "readers/length_units.hpp"

#include "readers/text_cells.hpp"

namespace aloft::host {

namespace {

// True when `text` is a prefix of `word` at least `shortest` characters long.
bool abbreviates(const std::string& text, const std::string& word, std::size_t shortest) {
  return text.size() >= shortest && text.size() <= word.size() && word.compare(0, text.size(), text) == 0;
}

}  // namespace

double metres_per_unit(const std::string& unit) {
  const std::string u = to_lower(trim(unit));
  if (u == "mm" || abbreviates(u, "millimeters", 3) || abbreviates(u, "millimetres", 3)) return 1e-3;
  if (u == "cm" || abbreviates(u, "centimeters", 3) || abbreviates(u, "centimetres", 3)) return 1e-2;
  if (u == "m" || abbreviates(u, "meters", 2) || abbreviates(u, "metres", 2)) return 1.0;
  return 0.0;
}

}  // namespace aloft::host
