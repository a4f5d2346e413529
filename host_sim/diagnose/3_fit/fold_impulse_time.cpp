#include "diagnose/3_fit/fold_impulse_time.hpp"

#include <algorithm>
#include <cstddef>

namespace aloft::host::diagnose {
namespace {

// The fold's fit or the all-data solution moved onto the fold, by training cost; the
// search's own unless it lies outside the window of the other minima (a clearly other
// basin), so that fits of one basin keep the searched time.
EffectFit lower_training_cost(const EffectFit& searched, const EffectFit& all_data,
                              const NominalInertia& nominal, const FlightData& train,
                              SharedLinearisation* at_all_data) {
  const double all_data_time = all_data.flights[0].impulse_time_s;
  if (searched.flights[0].impulse_time_s == all_data_time) return searched;
  EffectFit moved = refit_from_solution(all_data, nominal, train, all_data_time,
                                        at_all_data != nullptr ? at_all_data->at(all_data_time) : nullptr);
  const double window = std::max(kOtherMinimumWindow, kOtherMinimumWindowShare * moved.cost);
  return searched.cost - moved.cost > window ? moved : searched;
}

// `fit` with its jump in the middle of the gap between the training samples either side.
EffectFit jump_centred_in_unseen_gap(const EffectFit& fit, const NominalInertia& nominal,
                                     const FlightData& train) {
  const SampleRange gap = unseen_jump_gap(fit, train);
  if (gap.first == gap.end) return fit;
  // A jump just before any sample from gap.first to gap.end fits alike; the middle one of
  // them (the earlier of two middles: a fixed rule).
  const Flight& flight = *train.flight;
  const std::size_t middle = (gap.first + gap.end) / 2;
  if (middle < 2 || flight.time_s[middle - 1] < flight.settling_until_s) return fit;
  const double middle_s = 0.5 * (flight.time_s[middle - 1] + flight.time_s[middle]);
  if (middle_s == fit.flights[0].impulse_time_s) return fit;
  return refit_from_solution(fit, nominal, train, middle_s);
}

}  // namespace

SampleRange unseen_jump_gap(const EffectFit& fit, const FlightData& train) {
  const Flight& flight = *train.flight;
  const std::size_t n = flight.size();
  const double jump_s = fit.flights[0].impulse_time_s;
  const auto seen = [&](std::size_t k) { return train.compared(k); };
  // The jump lies just before sample `after`: the first sample later than it.
  std::size_t after = 0;
  while (after < n && flight.time_s[after] < jump_s) ++after;
  if (after == 0 || after >= n) return {};
  // The nearest training samples: `last_seen` before the jump, `next_seen` after it.
  std::size_t last_seen = after - 1;
  while (last_seen > 0 && !seen(last_seen)) --last_seen;
  std::size_t next_seen = after;
  while (next_seen < n && !seen(next_seen)) ++next_seen;
  if (!seen(last_seen) || next_seen >= n) return {};
  return {last_seen + 1, next_seen};
}

EffectFit fold_impulse_fit(const EffectFit& searched, const EffectFit& all_data,
                           const NominalInertia& nominal, const FlightData& train,
                           SharedLinearisation* at_all_data) {
  return jump_centred_in_unseen_gap(lower_training_cost(searched, all_data, nominal, train, at_all_data),
                                    nominal, train);
}

}  // namespace aloft::host::diagnose
