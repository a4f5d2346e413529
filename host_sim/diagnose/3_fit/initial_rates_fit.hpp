// The flights' initial rates refitted with a fitted effect's parameters held: how a
// fitted effect is carried over to a flight (or a fold of one) it never saw.
#pragma once

#include <cstddef>
#include <vector>

#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/3_fit/effect_fit_result.hpp"
#include "diagnose/3_fit/flight_data.hpp"

namespace aloft::host::diagnose {

// fit_initial_rates_near: how far the refit of a fold's rate from the all-samples fit's
// rate may end before the separatrix-safe start is tried too: at most this many times the
// all-samples fit's cost on the fold's samples, and at most this misfit (chi-square per
// residual). Measured with both refits made on every left-out fold of the diagnose,
// session, phone and rotor tests (9,502 folds) and of a 10-flight aero_torque log (340):
// where the refit from the all-samples rate ended more than 1e-5 above the safe one (36
// folds, by up to 2,400 times: a candidate that misses the flight by far, whose rate the
// pooled fit cannot guide), its misfit was 622 per residual or more. Of the tests' folds
// these bounds keep 5,718, each within 4e-6 of the safe fit's cost; on the log it ended
// at the safe fit's cost on every fold, at up to 2.07 times the all-samples cost (a wrong
// effect fitted without the flight) and up to 444 per residual.
constexpr double kNearRateCostRatio = 3.0;
constexpr double kNearRateMaxMisfit = 300.0;
// Refits only the flights' initial rates with the effect parameters of `fixed` held: how a
// fitted effect is carried over to a flight it never saw.
EffectFit fit_initial_rates(const EffectFit& fixed, const NominalInertia& nominal,
                            const std::vector<FlightData>& data, const EffectFit* nominal_fit);

// A fold's refit of one flight's initial rate (fit_initial_rates, `data` one flight)
// where the rate is already known near here: `near` is a fit of all of this flight's
// samples (flight `index` of it), with effect parameters close to `fixed`'s (a pooled fit,
// `fixed` the same effect without this flight). The rate-only fit starts from near's rate,
// skipping the separatrix-safe start (initial_state_fit.hpp) that costs twice the fit
// itself. It is kept when it explains the fold's samples about as well as `near` does
// (its cost at most kNearRateCostRatio times near's cost on them) and near the noise
// (kNearRateMaxMisfit): a start in the basin of a wrong motion cannot. Otherwise the
// separatrix-safe fit is made too and the lower of the two kept.
EffectFit fit_initial_rates_near(const EffectFit& fixed, const NominalInertia& nominal,
                                 const FlightData& data, const EffectFit& near, std::size_t index,
                                 const EffectFit* nominal_fit);
}  // namespace aloft::host::diagnose
