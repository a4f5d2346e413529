// Length units as marker files state them (TRC `Units`, C3D `POINT:UNITS`), matched the
// way C3D tools match them: trimmed, case-folded, and by prefix, because C3D stores the
// unit in a fixed-width character array that writers fill with whatever fits — Peak
// Performance exports write "mete" for metres.
#pragma once

#include <string>

namespace aloft::host {

// Metres per unit: 1e-3 for "mm" or a prefix of "millimeters"/"millimetres" (at least
// "mil"), 1e-2 for "cm" or a prefix of "centimeters"/"centimetres" (at least "cen"), 1
// for "m" or a prefix of "meters"/"metres" (at least "me"); 0 for anything else.
double metres_per_unit(const std::string& unit);

}  // namespace aloft::host
