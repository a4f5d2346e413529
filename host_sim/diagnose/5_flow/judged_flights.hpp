// The flights one analysis judges, each with the noise that weighs it and the samples its
// fits may see: all of them, or one of two interleaved folds (3_fit/held_out.hpp). A
// flight is judged as a session of one (judge_candidates.hpp); only the held-out rule
// differs.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/3_fit/effect_fit.hpp"
#include "diagnose/3_fit/flight_data.hpp"
#include "diagnose/3_fit/held_out.hpp"
#include "diagnose/4_judge/candidate_ranking.hpp"

namespace aloft::host::diagnose {

struct JudgedFlights {
  std::vector<const Flight*> flights;
  std::vector<Eigen::Vector3d> inverse_sigma;    // per flight: 1 / noise floor
  std::vector<FlightData> all;                   // every sample of each flight
  std::vector<Folds> folds;                      // each flight's interleaved folds
  std::vector<std::array<FlightData, 2>> train;  // each flight's fold training data

  void add(const Flight& flight, const Eigen::Vector3d& inverse_sigma);
  std::size_t size() const { return flights.size(); }

  // The one held-out fold loop: flight j predicted on each fold's judged samples by
  // `fit_fold(f)`, a fit that never saw them. Returns the held-out readings of the whole
  // flight and adds their gap (usable samples) to `sums`.
  using FoldFit = std::function<EffectFit(std::size_t fold)>;
  std::vector<Eigen::Vector3d> judge_folds(std::size_t j, const NominalInertia& nominal,
                                           const FoldFit& fit_fold, GapSums& sums) const;

  // What the ranking needs to know of these flights; `resolution` the coarsest of their
  // noise floors' (noise_floor.hpp).
  RankingContext ranking_context(const NominalInertia& nominal, double resolution) const;
};

// Sets c.heldout_* from the held-out gaps of every flight, summed in flight order.
void set_heldout_gap(Candidate& c, const std::vector<GapSums>& per_flight);

}  // namespace aloft::host::diagnose
