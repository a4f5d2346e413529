// The torque-free invariants of the measured motion, computed with the nominal tensor:
// kinetic energy 1/2 w.Iw and |L| = |Iw|. A body left alone keeps both; an external or
// dissipative torque makes them trend, a wrong tensor or a sensor error makes them
// oscillate (the measured rate is then not a motion the nominal body can make).
#pragma once

#include <string>
#include <vector>

#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/1_input/flight.hpp"
#include "diagnose/4_judge/noise_floor.hpp"

namespace aloft::host::diagnose {

struct InvariantBehaviour {
  std::string name;                   // "kinetic_energy" or "angular_momentum"
  double mean = 0.0;                  // J or N·m·s
  double relative_change = 0.0;       // fitted linear change over the flight / mean
  double relative_oscillation = 0.0;  // RMS about the line / mean
  // "constant", "trend", "oscillation" or "trend_and_oscillation", each judged against
  // what the noise floor alone would give.
  std::string behaviour = "constant";
  std::vector<double> series;  // per sample (unusable samples: NaN)
};

struct Invariants {
  InvariantBehaviour energy;
  InvariantBehaviour momentum;
};

Invariants measured_invariants(const Flight& flight, const NominalInertia& nominal, const NoiseFloor& noise);

}  // namespace aloft::host::diagnose
