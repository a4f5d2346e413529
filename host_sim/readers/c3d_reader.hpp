// Vicon/C3D marker files (.c3d): the 3D POINT data of the C3D format (c3d.org, "The C3D
// File Format User Guide"). Reads all three processor formats (Intel, DEC/VAX,
// SGI/MIPS; see c3d_numbers.hpp), integer data (scaled by POINT:SCALE) and floating-
// point data (negative scale), POINT:LABELS (and LABELS2...), POINT:RATE and
// POINT:UNITS (mm, cm or m; mm when absent), converting to metres. Analog data are
// skipped. A point whose residual word is negative is invalid (occluded) and becomes NaN.
//
// Written by hand: Debian packages no C3D library (`apt-cache search c3d` finds none;
// ezc3d and BTK are not packaged).
//
// Damaged files never crash the reader: all reads are bounded (c3d_numbers.hpp). A
// parameter section that breaks off part-way is used as far as it goes, with the
// header's copies of point count, scale, rate and data start standing in for
// parameters that are lost (C3dDetails::parameter_damage says what happened; without
// `details`, a one-line warning goes to stderr); a file
// whose data section is shorter than its frames need is an error, as is anything whose
// header or layout cannot be trusted. Errors: aloft::host::Error "FILE: problem".
#pragma once

#include <string>
#include <vector>

#include "common/trial.hpp"

namespace aloft::host {

// What the file says about itself beyond the MarkerTrial, for `inspect` and tests.
struct C3dDetails {
  std::string processor;  // "intel", "dec" or "mips"
  bool float_data = false;
  double point_scale = 0.0;  // POINT:SCALE as stored (negative: float data)
  long first_frame = 1;      // up to 65535·65536 in long trials
  int analog_samples_per_frame = 0;
  std::string parameter_damage;                // empty when the parameter section read cleanly
  std::vector<std::string> parameter_repairs;  // bad offset words worked around
};

MarkerTrial read_c3d(const std::string& path, C3dDetails* details = nullptr);

}  // namespace aloft::host
