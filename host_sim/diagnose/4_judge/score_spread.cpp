#include "diagnose/4_judge/score_spread.hpp"

#include <cmath>

#include "diagnose/3_fit/held_out.hpp"
#include "diagnose/4_judge/analysis.hpp"

namespace aloft::host::diagnose {

std::vector<double> chunk_chi_squares(const Candidate& c, const std::vector<const Flight*>& flights,
                                      const std::vector<Eigen::Vector3d>& inverse_sigma) {
  std::vector<double> out;
  for (std::size_t f = 0; f < flights.size() && f < c.heldout_readings.size() && f < inverse_sigma.size();
       ++f) {
    const Flight& flight = *flights[f];
    const std::vector<Eigen::Vector3d>& predicted = c.heldout_readings[f];
    const std::size_t chunk = chunk_length(flight.size());
    for (std::size_t from = 0; from < flight.size() && from < predicted.size(); from += chunk) {
      double sum = 0.0;
      for (std::size_t k = from; k < from + chunk && k < flight.size() && k < predicted.size(); ++k) {
        if (flight.usable[k])
          sum += (predicted[k] - flight.omega[k]).cwiseProduct(inverse_sigma[f]).squaredNorm();
      }
      out.push_back(sum);
    }
  }
  return out;
}

double spread_of_sum(const std::vector<double>& parts) {
  const std::size_t n = parts.size();
  if (n < 2) return 0.0;
  double mean = 0.0;
  for (double p : parts) mean += p;
  mean /= static_cast<double>(n);
  double squares = 0.0;
  for (double p : parts) squares += (p - mean) * (p - mean);
  // sqrt(N) * standard deviation = sqrt(N * squares / (N - 1)).
  return std::sqrt(static_cast<double>(n) * squares / static_cast<double>(n - 1));
}

double spread_of_difference(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return 0.0;
  std::vector<double> difference(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) difference[i] = a[i] - b[i];
  return spread_of_sum(difference);
}

}  // namespace aloft::host::diagnose
