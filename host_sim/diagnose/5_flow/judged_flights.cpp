#include "diagnose/5_flow/judged_flights.hpp"

namespace aloft::host::diagnose {

void JudgedFlights::add(const Flight& flight, const Eigen::Vector3d& inverse) {
  flights.push_back(&flight);
  inverse_sigma.push_back(inverse);
  all.push_back(FlightData{&flight, all_samples(flight.size()), inverse});
  folds.push_back(interleaved_folds(flight.size()));
  train.push_back({FlightData{&flight, folds.back().train[0], inverse},
                   FlightData{&flight, folds.back().train[1], inverse}});
}

std::vector<Eigen::Vector3d> JudgedFlights::judge_folds(std::size_t j, const NominalInertia& nominal,
                                                        const FoldFit& fit_fold, GapSums& sums) const {
  const Flight& flight = *flights[j];
  std::vector<Eigen::Vector3d> heldout(flight.size(), Eigen::Vector3d::Zero()), readings;
  for (std::size_t f = 0; f < 2; ++f) {
    predict(fit_fold(f), nominal, 0, flight, readings);
    for (std::size_t k = 0; k < flight.size(); ++k) {
      if (!folds[j].judge[f][k]) continue;
      heldout[k] = readings[k];
      if (flight.usable[k]) sums.add(readings[k], flight.omega[k], inverse_sigma[j]);
    }
  }
  return heldout;
}

void set_heldout_gap(Candidate& c, const std::vector<GapSums>& per_flight) {
  GapSums total;
  for (const GapSums& s : per_flight) {
    total.chi_square += s.chi_square;
    total.residuals += s.residuals;
    total.da_sq += s.da_sq;
    total.rel_sq += s.rel_sq;
    total.samples += s.samples;
  }
  c.heldout_chi_square = total.chi_square;
  c.heldout_residuals = total.residuals;
  c.heldout_rms_da_deg = total.rms_da_deg();
  c.heldout_rms_rel_err = total.rms_rel_err();
}

RankingContext JudgedFlights::ranking_context(const NominalInertia& nominal, double resolution) const {
  double speed_sum = 0.0, duration_sum = 0.0;
  for (const Flight* f : flights) {
    speed_sum += f->mean_speed();
    duration_sum += f->end_s() - f->start_s();
  }
  // Shared parameters are informed by every flight's data: the whole duration counts.
  return RankingContext{flights.front()->gyro_input,
                        flights,
                        inverse_sigma,
                        speed_sum / static_cast<double>(flights.size()),
                        duration_sum,
                        &nominal,
                        resolution,
                        {}};  // a session sets its flights' own analyses
}

}  // namespace aloft::host::diagnose
