#include "study/tangent_spline_resampler.hpp"

#include <cmath>
#include <stdexcept>

#include "aloft/dynamics/rotation.hpp"

namespace aloft::host {
namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

// log(a^-1 b): the rotation vector that carries a into b, in a's body axes.
Eigen::Vector3d chart(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return aloft::quat_log(Eigen::Quaterniond(a.conjugate() * b));
}

// Body rate at knot i: derivative at t_i of the parabola through the neighbouring poses
// in the chart of q_i (three-point formula; one-sided at the two ends).
Eigen::Vector3d knot_rate(const std::vector<double>& t, const std::vector<Eigen::Quaterniond>& q,
                          std::size_t i) {
  const std::size_t n = t.size();
  if (i == 0) {
    const double h0 = t[1] - t[0], big = t[2] - t[0], h1 = t[2] - t[1];
    const Eigen::Vector3d b1 = chart(q[0], q[1]), b2 = chart(q[0], q[2]);
    return (b1 * big * big - b2 * h0 * h0) / (h0 * big * h1);
  }
  if (i == n - 1) {
    const double h0 = t[n - 1] - t[n - 2], big = t[n - 1] - t[n - 3], h1 = t[n - 2] - t[n - 3];
    const Eigen::Vector3d a1 = chart(q[n - 1], q[n - 2]), a2 = chart(q[n - 1], q[n - 3]);
    return -(a1 * big * big - a2 * h0 * h0) / (h0 * big * h1);
  }
  const double h0 = t[i] - t[i - 1], h1 = t[i + 1] - t[i];
  const Eigen::Vector3d a = chart(q[i], q[i - 1]), b = chart(q[i], q[i + 1]);
  return (b * h0 * h0 - a * h1 * h1) / (h0 * h1 * (h0 + h1));
}

}  // namespace

Eigen::Matrix3d so3_right_jacobian(const Eigen::Vector3d& p) {
  const double theta_sq = p.squaredNorm();
  double a, b;  // (1 - cos θ)/θ², (θ - sin θ)/θ³
  if (theta_sq < 1e-8) {
    a = 0.5 - theta_sq / 24.0;
    b = 1.0 / 6.0 - theta_sq / 120.0;
  } else {
    const double theta = std::sqrt(theta_sq);
    a = (1.0 - std::cos(theta)) / theta_sq;
    b = (theta - std::sin(theta)) / (theta_sq * theta);
  }
  const Eigen::Matrix3d s = skew(p);
  return Eigen::Matrix3d::Identity() - a * s + b * s * s;
}

Eigen::Matrix3d so3_right_jacobian_inverse(const Eigen::Vector3d& p) {
  const double theta_sq = p.squaredNorm();
  double c;  // 1/θ² - (1 + cos θ)/(2 θ sin θ)
  if (theta_sq < 1e-8) {
    c = 1.0 / 12.0 + theta_sq / 720.0;
  } else {
    const double theta = std::sqrt(theta_sq);
    c = 1.0 / theta_sq - (1.0 + std::cos(theta)) / (2.0 * theta * std::sin(theta));
  }
  const Eigen::Matrix3d s = skew(p);
  return Eigen::Matrix3d::Identity() + 0.5 * s + c * s * s;
}

ResampledPoses resample_poses(const std::vector<double>& time_s,
                              const std::vector<Eigen::Quaterniond>& orientation, double rate_hz) {
  const std::size_t n = time_s.size();
  if (n < 3 || orientation.size() != n) {
    throw std::invalid_argument("resampling needs at least 3 poses");
  }
  if (!(rate_hz > 0.0)) throw std::invalid_argument("resampling rate must be positive");
  for (std::size_t i = 1; i < n; ++i) {
    if (!(time_s[i] > time_s[i - 1])) {
      throw std::invalid_argument("pose times must increase strictly");
    }
  }
  std::vector<Eigen::Vector3d> knot_omega(n);
  for (std::size_t i = 0; i < n; ++i) knot_omega[i] = knot_rate(time_s, orientation, i);

  ResampledPoses out;
  const double t0 = time_s.front();
  const auto count = static_cast<std::size_t>(std::floor((time_s.back() - t0) * rate_hz + 1e-6)) + 1;
  out.time_s.reserve(count);
  out.orientation.reserve(count);
  out.omega_body.reserve(count);
  std::size_t k = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const double t = std::min(t0 + static_cast<double>(i) / rate_hz, time_s.back());
    while (k + 2 < n && t >= time_s[k + 1]) ++k;
    const double h = time_s[k + 1] - time_s[k];
    const double s = (t - time_s[k]) / h;
    const Eigen::Vector3d target = chart(orientation[k], orientation[k + 1]);
    const Eigen::Vector3d m0 = knot_omega[k];
    const Eigen::Vector3d m1 = so3_right_jacobian_inverse(target) * knot_omega[k + 1];
    const double s2 = s * s, s3 = s2 * s;
    const Eigen::Vector3d p =
        (-2.0 * s3 + 3.0 * s2) * target + h * ((s3 - 2.0 * s2 + s) * m0 + (s3 - s2) * m1);
    const Eigen::Vector3d dp =
        (-6.0 * s2 + 6.0 * s) / h * target + (3.0 * s2 - 4.0 * s + 1.0) * m0 + (3.0 * s2 - 2.0 * s) * m1;
    out.time_s.push_back(t);
    out.orientation.push_back((orientation[k] * aloft::quat_exp(p)).normalized());
    out.omega_body.push_back(so3_right_jacobian(p) * dp);
  }
  return out;
}

}  // namespace aloft::host
