// The practical-significance bar of the diagnosis (issue 8): an effect that shrinks the
// held-out gap beyond noise can still be too small to matter, e.g. on near-perfect data
// where the noise floor is tiny and any parameter "explains" a rounding error. Such an
// effect is not reported: the verdict is `none` (or the stepwise selection stops).
//
// Too small to matter, for the effect an addition brings (its own parameters):
//   the held-out gap it starts from (RMS relative error times the mean |ω|) is below
//   twice the data's resolution (noise_floor.hpp): nothing the sensor resolves is left;
//   it closes less than 1 % of that gap (kSmallestShrink): with thousands of correlated
//   samples (a filtered phone gyro) a test against noise passes on an effect that
//   explains next to nothing, e.g. a 0.3 % gyro scale that mimics a 15 Hz low-pass
//   (0.5 % of the gap); the weakest real effect of the withheld tests closes 1.1 % (drag
//   from marker-derived rates), so the bar sits between them, and 2 % loses that case;
//   otherwise the effect's own bar (its descriptor's `too_small`, effects/<name>.cpp):
//   inertia_moments      every moment within 0.5 % of nominal;
//   inertia_axes, sensor_misalignment   turned by less than 0.25°;
//   aero_torque          |ω| would fall by less than 0.5 % over the data;
//   impulse              |Δω| below 0.5 % of the mean |ω|;
//   gyro_bias            |b| below 0.1 % of the mean |ω|;
//   gyro_scale, clock_drift   every error below 0.1 %;
//   internal_damping     no threshold of its own (the shrink decides).
#pragma once

#include <string>

#include "diagnose/4_judge/candidate_ranking.hpp"
#include "diagnose/4_judge/confidence.hpp"

namespace aloft::host::diagnose {

// Whether the effect `c` adds (c.effect, with c.base already in the model) is large
// enough to matter; when not, `why` says what fell short.
bool matters(const Candidate& c, const RankingContext& context, std::string* why = nullptr);

}  // namespace aloft::host::diagnose
