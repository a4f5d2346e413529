#include "diagnose/2_model/spin_up_from_readings.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "diagnose/2_model/effect_model.hpp"
#include "diagnose/2_model/spin_up_profile.hpp"

namespace aloft::host::diagnose {
namespace {

// dw/dt from readings 2 ms either side (at least one sample), as momentum_from_readings.
constexpr double kDerivativeHalfSpan_s = 0.002;
// Samples used per flight at most (every k-th beyond): the balance is a sum, and a
// flight controller's 8 kHz adds cost, not information, to a start.
constexpr std::size_t kMostSamples = 1000;
constexpr double kStartStep_s = 0.01, kEarliestStart_s = -0.1;
constexpr double kTimeConstants_s[] = {0.02, 0.04, 0.08, 0.16};
// Set-point ramps: 5 ms, next to a first-order step (the fit lowers it where the data ask,
// R = 0 itself lies at ln R = -infinity), to 200 ms, the real wheels' rise (issue 44).
constexpr double kRises_s[] = {0.005, 0.05, 0.1, 0.2};

// One sample of the balance: the body rate, and the torque the Euler equations leave.
struct Balance {
  double t = 0.0;  // from the flight's first sample
  Eigen::Vector3d w, torque;
};

std::vector<Balance> balances(const Flight& flight, const Eigen::Matrix3d& inertia) {
  std::vector<Balance> out;
  const std::size_t n = flight.size();
  if (n < 3) return out;
  const double step_s = (flight.time_s.back() - flight.time_s.front()) / static_cast<double>(n - 1);
  if (!(step_s > 0.0)) return out;
  const std::size_t d =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(kDerivativeHalfSpan_s / step_s)));
  const std::size_t stride = std::max<std::size_t>(1, n / kMostSamples);
  for (std::size_t k = d; k + d < n; k += stride) {
    if (!flight.usable[k - d] || !flight.usable[k] || !flight.usable[k + d]) continue;
    const double span_s = flight.time_s[k + d] - flight.time_s[k - d];
    if (!(span_s > 0.0) || span_s > 3.0 * static_cast<double>(d) * step_s) continue;
    Balance b;
    b.t = flight.time_s[k] - flight.time_s.front();
    b.w = body_rate_of_reading(flight, flight.omega[k]);
    const Eigen::Vector3d dw = (body_rate_of_reading(flight, flight.omega[k + d]) -
                                body_rate_of_reading(flight, flight.omega[k - d])) /
                               span_s;
    b.torque = -(inertia * dw + b.w.cross(inertia * b.w));
    out.push_back(b);
  }
  return out;
}

struct Solved {
  Eigen::Vector3d h = Eigen::Vector3d::Zero();
  double misfit = 0.0;
};

// h_inf for (t0, tau) by least squares over every flight's balance, and what it leaves.
Solved solve(const std::vector<std::vector<Balance>>& flights, const SpinUpProfile& profile) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  double total = 0.0;
  for (const std::vector<Balance>& samples : flights) {
    for (const Balance& s : samples) {
      total += s.torque.squaredNorm();
      const double u = s.t - profile.start_s;
      if (u <= 0.0) continue;
      const double f = profile.level(u), rate = profile.slope(u);
      // torque = (f [w]x + rate I) h
      Eigen::Matrix3d m;
      m << rate, -f * s.w.z(), f * s.w.y(), f * s.w.z(), rate, -f * s.w.x(), -f * s.w.y(), f * s.w.x(), rate;
      a += m.transpose() * m;
      b += m.transpose() * s.torque;
    }
  }
  Solved out;
  out.misfit = total;
  if (!(a.trace() > 0.0)) return out;
  a += 1e-9 * a.trace() * Eigen::Matrix3d::Identity();
  out.h = a.ldlt().solve(b);
  out.misfit = total - b.dot(out.h);
  return out;
}

}  // namespace

Eigen::VectorXd spin_up_theta_from_readings(const std::vector<const Flight*>& flights,
                                            const NominalInertia& nominal) {
  std::vector<std::vector<Balance>> samples;
  double shortest = 1e300;
  for (const Flight* f : flights) {
    samples.push_back(balances(*f, nominal.tensor));
    if (f->size() > 1) shortest = std::min(shortest, f->time_s.back() - f->time_s.front());
  }
  Solved best;
  SpinUpProfile best_profile;
  bool any = false;
  for (double t0 = kEarliestStart_s; t0 <= 0.5 * shortest; t0 += kStartStep_s) {
    for (double tau : kTimeConstants_s) {
      for (double rise : kRises_s) {
        const SpinUpProfile profile{t0, tau, rise};
        const Solved s = solve(samples, profile);
        if (!any || s.misfit < best.misfit) {
          best = s;
          best_profile = profile;
          any = true;
        }
      }
    }
  }
  Eigen::VectorXd theta = Eigen::VectorXd::Zero(kSpinUpParameters);
  if (!any) return theta;
  theta.head<3>() = nominal.tensor.ldlt().solve(best.h);
  write_spin_up_profile(best_profile, theta);
  return theta;
}

}  // namespace aloft::host::diagnose
