#include "diagnose/3_fit/flight_jacobian.hpp"

#include <algorithm>
#include <vector>

#include "diagnose/2_model/reading_derivatives.hpp"
#include "diagnose/2_model/spin_up_walk.hpp"
#include "diagnose/3_fit/levenberg_marquardt.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

// [theta | local] moved by the fitter's forward-difference step along entry i.
struct Shift {
  Eigen::VectorXd theta, local;
  double h = 0.0;
};
Shift shifted(const Eigen::VectorXd& theta, const Eigen::VectorXd& local, Eigen::Index i) {
  Shift out{theta, local, 0.0};
  const Eigen::Index p = theta.size();
  double& value = i < p ? out.theta(i) : out.local(i - p);
  out.h = forward_difference_step(value);
  value += out.h;
  return out;
}

// A Jacobian column of reading derivatives weighted in place as the residuals are: zero
// for the samples the fit leaves out.
void weight_column(const FlightData& d, Eigen::MatrixXd& jacobian, Eigen::Index column) {
  for (std::size_t k = 0; k < d.flight->size(); ++k) {
    const Eigen::Index row = static_cast<Eigen::Index>(3 * k);
    jacobian.block<3, 1>(row, column) =
        d.compared(k) ? Vec3(jacobian.block<3, 1>(row, column).cwiseProduct(d.inverse_sigma)) : Vec3::Zero();
  }
}

}  // namespace

bool flight_jacobian(const FitSetup& setup, int block, const Eigen::VectorXd& theta,
                     const Eigen::VectorXd& local, Eigen::VectorXd& r, Eigen::MatrixXd& jacobian,
                     Eigen::Matrix3d* rate_derivative) {
  if (setup.own() != nullptr) return false;  // each flight's own parameters: differenced, as the rest
  const EffectModel model = setup.model();
  const std::vector<char> sensor = sensor_directions(model, theta);
  std::vector<char> impulse = impulse_directions(model, theta);
  const auto none = [](const std::vector<char>& v) { return std::find(v.begin(), v.end(), 1) == v.end(); };
  // The impulse's columns through the flow map assume the time-free walks; beside a
  // spinning-up rotor (spin_up_walk.hpp) they are differenced like the rest.
  if (!none(impulse) && has_spin_up(model_terms(model, theta))) std::fill(impulse.begin(), impulse.end(), 0);
  const FlightData& d = (*setup.data)[static_cast<std::size_t>(block)];
  const Flight& flight = *d.flight;
  const std::size_t ref = setup.refs[static_cast<std::size_t>(block)];
  const Eigen::Index p = theta.size(), m = local.size();
  const bool paired_rates = (ref == 0 || ref + 1 == flight.size()) && none(impulse) && m == 3;
  if (none(sensor) && none(impulse) && !paired_rates) return false;
  std::vector<Vec3> readings, readings_b;
  Vec3 at_impulse = Vec3::Zero(), moved_at_impulse = Vec3::Zero();
  const ReadSamples read = compared_samples(d);
  if (!none(sensor) || !none(impulse) || r.size() == 0) {
    predict_readings(model, flight, ref, Vec3(local), theta, readings, SampleStepping::shared_steps,
                     &at_impulse, read);
    residuals_of(d, readings, r);
  }
  jacobian.resize(r.size(), p + m);
  if (!none(sensor)) sensor_reading_derivatives(model, flight, theta, readings, sensor, jacobian);
  Eigen::Matrix3d impulse_rate_derivative = Eigen::Matrix3d::Identity();
  Eigen::VectorXd moved;
  Eigen::Index differenced = p + m;
  if (paired_rates) {  // the last two rate columns side by side
    Eigen::VectorXd local_a = local, local_b = local;
    const double h_a = forward_difference_step(local_a(m - 1)), h_b = forward_difference_step(local_b(m - 2));
    local_a(m - 1) += h_a;
    local_b(m - 2) += h_b;
    predict_readings_pair(model, flight, ref, Vec3(local_a), Vec3(local_b), theta, readings, readings_b,
                          read);
    residuals_of(d, readings, moved);
    jacobian.col(p + m - 1) = (moved - r) / h_a;
    residuals_of(d, readings_b, moved);
    jacobian.col(p + m - 2) = (moved - r) / h_b;
    differenced = p + m - 2;
  }
  // Differenced columns, the rates' first: the impulse's columns are made from them.
  std::vector<Eigen::Index> columns;
  for (Eigen::Index i = differenced; i-- > 0;) {
    if (i >= p || !(sensor[static_cast<std::size_t>(i)] || impulse[static_cast<std::size_t>(i)])) {
      columns.push_back(i);
    }
  }
  std::size_t next = 0;
  // With one walk a prediction (and no impulse), two at a time side by side, each lane
  // with its own theta (predict_readings_two): a rotor's (case00 377.0 -> 367.9 M).
  for (; paired_rates && next + 1 < columns.size(); next += 2) {
    const Shift a = shifted(theta, local, columns[next]), b = shifted(theta, local, columns[next + 1]);
    predict_readings_two(model, flight, ref, Vec3(a.local), a.theta, Vec3(b.local), b.theta, readings,
                         readings_b, read);
    residuals_of(d, readings, moved);
    jacobian.col(columns[next]) = (moved - r) / a.h;
    residuals_of(d, readings_b, moved);
    jacobian.col(columns[next + 1]) = (moved - r) / b.h;
  }
  for (; next < columns.size(); ++next) {
    const Eigen::Index i = columns[next];
    const Shift a = shifted(theta, local, i);
    predict_readings(model, flight, ref, Vec3(a.local), a.theta, readings, SampleStepping::shared_steps,
                     &moved_at_impulse, read);
    residuals_of(d, readings, moved);
    jacobian.col(i) = (moved - r) / a.h;
    if (i >= p) impulse_rate_derivative.col(i - p) = (moved_at_impulse - at_impulse) / a.h;
  }
  if (!none(impulse)) {
    impulse_reading_derivatives(model, flight, ref, theta, impulse_rate_derivative, impulse, jacobian);
    if (rate_derivative != nullptr) *rate_derivative = impulse_rate_derivative;
  }
  for (Eigen::Index i = 0; i < p; ++i) {
    if (sensor[static_cast<std::size_t>(i)]) weight_column(d, jacobian, i);
  }
  return true;
}

}  // namespace aloft::host::diagnose
