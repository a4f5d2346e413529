#include "diagnose/3_fit/initial_state_fit.hpp"

#include <algorithm>

#include "diagnose/3_fit/levenberg_marquardt.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

// The first span: about a tenth of a second each side of the reference (at least 4
// samples), short enough that a flip's timing cannot yet be mistaken.
constexpr double kFirstHalfSpan_s = 0.1;
constexpr std::size_t kFirstHalfSpanSamples = 4;

// Samples [from, to) of a flight, with the mask folded into `usable`.
Flight span_of(const FlightData& data, std::size_t from, std::size_t to) {
  const Flight& f = *data.flight;
  Flight out;
  out.name = f.name;
  out.gyro_input = f.gyro_input;
  out.rates_from_differences = f.rates_from_differences;
  out.sensor_to_body = f.sensor_to_body;
  for (std::size_t k = from; k < to; ++k) {
    out.time_s.push_back(f.time_s[k]);
    out.omega.push_back(f.omega[k]);
    out.usable.push_back(static_cast<char>(data.compared(k)));
  }
  return out;
}

InitialState fit_on(const EffectModel& model, const Flight& flight, std::size_t ref,
                    const Vec3& inverse_sigma, const Eigen::VectorXd& theta, const Vec3& start) {
  ArrowProblem problem;
  problem.shared_count = 0;
  problem.local_count = 3;
  problem.block_count = 1;
  problem.residuals = [&](int, const Eigen::VectorXd&, const Eigen::VectorXd& local, Eigen::VectorXd& r) {
    std::vector<Vec3> readings;
    predict_readings(model, flight, ref, Vec3(local), theta, readings);
    r.resize(static_cast<Eigen::Index>(3 * flight.size()));  // each sample written once
    for (std::size_t k = 0; k < flight.size(); ++k) {
      auto out = r.segment<3>(static_cast<Eigen::Index>(3 * k));
      if (!flight.usable[k]) {
        out.setZero();
      } else {
        out = (readings[k] - flight.omega[k]).cwiseProduct(inverse_sigma);
      }
    }
  };
  LeastSquaresOptions options;
  options.normal_at_solution = false;  // only the rate and its cost are wanted
  const LeastSquaresResult r = minimise(problem, Eigen::VectorXd(), {Eigen::VectorXd(start)}, options);
  return {Vec3(r.local[0]), r.cost};
}

}  // namespace

InitialState fit_initial_state(const EffectModel& model, const FlightData& data, std::size_t ref,
                               const Eigen::VectorXd& theta, const Vec3* start) {
  const Flight& flight = *data.flight;
  const std::size_t n = flight.size();
  const Flight whole = span_of(data, 0, n);
  const Vec3 from_reading = body_rate_for_reading(model, flight, theta, flight.omega[ref]);
  InitialState plain = fit_on(model, whole, ref, data.inverse_sigma, theta, start ? *start : from_reading);

  const double duration = std::max(flight.end_s() - flight.start_s(), 1e-9);
  std::size_t half = std::max<std::size_t>(
      kFirstHalfSpanSamples, static_cast<std::size_t>(kFirstHalfSpan_s / duration * static_cast<double>(n)));
  Vec3 rate = from_reading;
  while (true) {
    const std::size_t lo = ref > half ? ref - half : 0;
    const std::size_t hi = std::min(n, ref + half + 1);
    if (lo == 0 && hi == n) break;
    const Flight span = span_of(data, lo, hi);
    rate = fit_on(model, span, ref - lo, data.inverse_sigma, theta, rate).omega_ref;
    half *= 2;
  }
  const InitialState continued = fit_on(model, whole, ref, data.inverse_sigma, theta, rate);
  return continued.cost < plain.cost ? continued : plain;
}

}  // namespace aloft::host::diagnose
