#include "perturbed_rigid_body.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aloft::generator {
namespace {

constexpr double kPi = 3.14159265358979323846;

// dq/dt = ½ q ⊗ (0, w), q in Eigen coefficient order (x, y, z, w).
Eigen::Vector4d quaternion_rate(const Eigen::Vector4d& q, const Eigen::Vector3d& w) {
  const double x = q(0), y = q(1), z = q(2), s = q(3);
  return 0.5 * Eigen::Vector4d(s * w.x() + y * w.z() - z * w.y(), s * w.y() + z * w.x() - x * w.z(),
                               s * w.z() + x * w.y() - y * w.x(), -x * w.x() - y * w.y() - z * w.z());
}

}  // namespace

PerturbedRigidBody::PerturbedRigidBody(const FlightPhysics& physics)
    : physics_(physics), has_rotor_(physics.rotor_inertia_kg_m2 > 0.0) {
  shell_inertia_ = physics.inertia_kg_m2;
  if (has_rotor_) {
    shell_inertia_ -= physics.rotor_inertia_kg_m2 * Eigen::Matrix3d::Identity();
    if (!(physics.rotor_damping_N_m_s > 0.0)) {
      throw std::invalid_argument("internal damping needs a positive damping coefficient");
    }
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(shell_inertia_);
  if (!(solver.eigenvalues().minCoeff() > 0.0)) {
    throw std::invalid_argument("rotor inertia leaves the shell without positive inertia");
  }
  shell_inverse_ = shell_inertia_.inverse();
}

Eigen::Vector3d PerturbedRigidBody::external_torque(double t, const Eigen::Vector3d& w) const {
  Eigen::Vector3d tau = -physics_.aero_k_N_m_s2 * w.norm() * w;
  if (physics_.has_impulse && physics_.impulse_duration_s > 0.0) {
    const double d = physics_.impulse_duration_s;
    const double u = (t - physics_.impulse_time_s) / d;
    if (u >= 0.0 && u <= 1.0) {
      // Half-sine of unit integral over the pulse.
      tau += physics_.angular_impulse_N_m_s * (kPi / (2.0 * d)) * std::sin(kPi * u);
    }
  }
  return tau;
}

PerturbedRigidBody::Derivative PerturbedRigidBody::derivative(double t, const Eigen::Vector4d& q,
                                                              const Eigen::Vector3d& w,
                                                              const Eigen::Vector3d& wr,
                                                              double side_s) const {
  Derivative d;
  d.q_dot = quaternion_rate(q, w);
  Eigen::Vector3d torque =
      external_torque(t, w) - w.cross(shell_inertia_ * w + physics_.internal_momentum_N_m_s);
  if (physics_.spin_up.present())
    torque -= w.cross(physics_.spin_up.momentum(t)) +
              physics_.spin_up.momentum_rate(t, std::isnan(side_s) ? t : side_s);
  if (has_rotor_) {
    const Eigen::Vector3d viscous = physics_.rotor_damping_N_m_s * (wr - w);
    torque += viscous;
    d.wr_dot = -w.cross(wr) - viscous / physics_.rotor_inertia_kg_m2;
  } else {
    d.wr_dot.setZero();
  }
  d.w_dot = shell_inverse_ * torque;
  return d;
}

void PerturbedRigidBody::rk4_step(double t, double h, FlightState& s) const {
  const Eigen::Vector4d q0 = s.orientation.coeffs();
  const Eigen::Vector3d w0 = s.omega_body;
  const Eigen::Vector3d r0 = s.rotor_omega_body;
  // Steps never straddle the rotor's rate steps (breaks of sample()): the step's middle
  // says on which side of them the step lies.
  const double middle = t + 0.5 * h;
  const Derivative k1 = derivative(t, q0, w0, r0, middle);
  const Derivative k2 = derivative(t + 0.5 * h, q0 + 0.5 * h * k1.q_dot, w0 + 0.5 * h * k1.w_dot,
                                   r0 + 0.5 * h * k1.wr_dot, middle);
  const Derivative k3 = derivative(t + 0.5 * h, q0 + 0.5 * h * k2.q_dot, w0 + 0.5 * h * k2.w_dot,
                                   r0 + 0.5 * h * k2.wr_dot, middle);
  const Derivative k4 = derivative(t + h, q0 + h * k3.q_dot, w0 + h * k3.w_dot, r0 + h * k3.wr_dot, middle);
  Eigen::Vector4d q = q0 + h / 6.0 * (k1.q_dot + 2.0 * (k2.q_dot + k3.q_dot) + k4.q_dot);
  s.orientation.coeffs() = q / q.norm();
  s.omega_body = w0 + h / 6.0 * (k1.w_dot + 2.0 * (k2.w_dot + k3.w_dot) + k4.w_dot);
  s.rotor_omega_body = r0 + h / 6.0 * (k1.wr_dot + 2.0 * (k2.wr_dot + k3.wr_dot) + k4.wr_dot);
}

void PerturbedRigidBody::advance(double t0, double t1, double max_step_s, FlightState& s) const {
  if (!(t1 > t0)) return;
  const int steps = std::max(1, static_cast<int>(std::ceil((t1 - t0) / max_step_s - 1e-9)));
  const double h = (t1 - t0) / steps;
  for (int i = 0; i < steps; ++i) rk4_step(t0 + i * h, h, s);
}

std::vector<FlightState> PerturbedRigidBody::sample(const FlightState& initial,
                                                    const std::vector<double>& times_s,
                                                    double max_step_s) const {
  // Breakpoints where the right-hand side is not smooth: the ends of the pulse (or
  // the instant of an instantaneous impulse).
  std::vector<double> breaks;
  if (physics_.has_impulse) {
    breaks.push_back(physics_.impulse_time_s);
    if (physics_.impulse_duration_s > 0.0) {
      breaks.push_back(physics_.impulse_time_s + physics_.impulse_duration_s);
    }
  }
  // The motor's start (its reaction torque steps from zero there) and a ramp's end.
  for (const double step : physics_.spin_up.rate_steps_s()) breaks.push_back(step);
  std::sort(breaks.begin(), breaks.end());
  bool jump_pending = physics_.has_impulse && !(physics_.impulse_duration_s > 0.0);
  std::size_t next_break = 0;

  std::vector<FlightState> out;
  out.reserve(times_s.size());
  FlightState s = initial;
  if (!has_rotor_) s.rotor_omega_body = s.omega_body;
  double t = 0.0;
  for (double target : times_s) {
    if (target < t) throw std::invalid_argument("sample times must be ascending from 0");
    while (next_break < breaks.size() && breaks[next_break] <= target) {
      advance(t, breaks[next_break], max_step_s, s);
      t = std::max(t, breaks[next_break]);
      if (jump_pending && breaks[next_break] == physics_.impulse_time_s) {
        s.omega_body += shell_inverse_ * physics_.angular_impulse_N_m_s;
        jump_pending = false;
      }
      ++next_break;
    }
    advance(t, target, max_step_s, s);
    t = target;
    out.push_back(s);
  }
  return out;
}

Eigen::Vector3d PerturbedRigidBody::angular_momentum(const FlightState& s, double t) const {
  Eigen::Vector3d l =
      shell_inertia_ * s.omega_body + physics_.internal_momentum_N_m_s + physics_.spin_up.momentum(t);
  if (has_rotor_) l += physics_.rotor_inertia_kg_m2 * s.rotor_omega_body;
  return l;
}

double PerturbedRigidBody::kinetic_energy(const FlightState& s) const {
  double e = 0.5 * s.omega_body.dot(shell_inertia_ * s.omega_body);
  if (has_rotor_) e += 0.5 * physics_.rotor_inertia_kg_m2 * s.rotor_omega_body.squaredNorm();
  return e;
}

Eigen::Vector3d PerturbedRigidBody::shell_angular_acceleration(double t, const FlightState& s) const {
  return derivative(t, s.orientation.coeffs(), s.omega_body, s.rotor_omega_body).w_dot;
}

}  // namespace aloft::generator
