// Full-flight simulations side by side in lanes (aloft/lanes/lanes.hpp): the seed study's
// "a simulation from a sampled state, forward to the end of the flight and backward to
// its start, compared with the measured angular velocity at every sample", for as many
// simulations at once as the lane type T holds, each with its own tensor and seed sample.
// Heap-free: the flight is read through plain pointers and every buffer is on the stack.
//
// Each simulation takes n - 1 steps: forward from its seed sample k to the end, then,
// back at the seed state, backward to the start. Lane l is at sample k_l + s or below
// k_l at step s, so the per-sample inputs (step, measured rate) are gathered lane by
// lane; everything else (stepping in the principal frame, ω from consecutive
// orientations, the deviation angle, its square summed) runs in the lanes.
//   pose flight: orientation and rate integrated; ω of interval j from the two simulated
//     orientations that bound it, against measured_body[j] (body axes, rotated into the
//     lane's principal axes) and measured_world[j] (world axes: the principal and body
//     orientations differ by a fixed rotation on the right, which b a^-1 cancels);
//   rate flight: the body rate alone against measured_body at every sample, the seed
//     sample included (where the deviation is zero).
#pragma once

#include <cstddef>

#include "aloft/dynamics/inertia_tensor.hpp"
#include "aloft/lanes/lane_angle.hpp"
#include "aloft/lanes/lane_rotation.hpp"
#include "aloft/dynamics/principal_dynamics.hpp"

namespace aloft {

// A flight in plain arrays (n samples).
template <typename Scalar>
struct FlightArrays {
  std::size_t samples = 0;                   // n >= 2
  const Scalar* time_s = nullptr;            // n, increasing
  const Scalar* orientation_wxyz = nullptr;  // 4n (body to world); null: a rate flight
  const Scalar* state_omega_body = nullptr;  // 3n: the rate a simulation seeded at k starts with
  const Scalar* measured_body = nullptr;     // 3(n-1) for a pose flight, 3n for a rate flight
  const Scalar* measured_world = nullptr;    // 3(n-1) for a pose flight, or null
};

// One simulation: its seed sample and its tensor in principal form.
template <typename Scalar>
struct FlightSimulation {
  std::size_t seed_sample = 0;
  Scalar moments[3] = {};              // principal moments
  Scalar principal_axes_wxyz[4] = {};  // A: principal axes into body axes, unit
  Scalar principal_to_body[9] = {};    // R(A), row-major: column i is principal axis i
};

// The simulation of `inertia` seeded at sample k.
template <typename Scalar>
inline FlightSimulation<Scalar> flight_simulation(const InertiaTensor<Scalar>& inertia, std::size_t k) {
  FlightSimulation<Scalar> sim;
  sim.seed_sample = k;
  const Quat<Scalar>& a = inertia.principal_axes();
  const Mat3<Scalar> r = a.toRotationMatrix();
  for (int i = 0; i < 3; ++i) sim.moments[i] = inertia.principal_moments()(i);
  const Scalar wxyz[4] = {a.w(), a.x(), a.y(), a.z()};
  for (int i = 0; i < 4; ++i) sim.principal_axes_wxyz[i] = wxyz[i];
  for (int i = 0; i < 9; ++i) sim.principal_to_body[i] = r(i / 3, i % 3);
  return sim;
}

// What one simulation accumulated: sums of squared DA (radians squared) and how many.
template <typename Scalar>
struct SquaredDeviations {
  Scalar body = Scalar(0);
  Scalar world = Scalar(0);
  std::size_t comparisons = 0;
};

template <typename T>
class BatchFlight {
 public:
  using Scalar = LaneScalar<T>;
  static constexpr int lanes = LaneTraits<T>::count;

  // Runs sims[0 .. lanes) on `flight` and writes out[0 .. lanes).
  static void run(const FlightArrays<Scalar>& flight, const FlightSimulation<Scalar>* sims,
                  SquaredDeviations<Scalar>* out) {
    BatchFlight batch(flight, sims);
    batch.run_all(out);
  }

 private:
  BatchFlight(const FlightArrays<Scalar>& flight, const FlightSimulation<Scalar>* sims)
      : f_(flight), sims_(sims) {
    Scalar i[3][lanes], r[3][3][lanes];
    for (int l = 0; l < lanes; ++l) {
      for (int a = 0; a < 3; ++a) i[a][l] = sims[l].moments[a];
      for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) r[a][b][l] = sims[l].principal_to_body[3 * a + b];
      }
    }
    c_ = euler_coefficients(load(i[0]), load(i[1]), load(i[2]));
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) to_body_.m[a][b] = load(r[a][b]);
    }
    seed_all();
  }

  static T load(const Scalar* p) { return LaneTraits<T>::load(p); }

  // Seed state of lane l in principal axes: q_b(k) A and R(A)^T w_b(k).
  void seed_lane(int l) {
    const std::size_t k = sims_[l].seed_sample;
    const Scalar* r = sims_[l].principal_to_body;
    const Scalar* w = f_.state_omega_body + 3 * k;
    for (int a = 0; a < 3; ++a) seed_w_[a][l] = r[a] * w[0] + r[3 + a] * w[1] + r[6 + a] * w[2];
    if (f_.orientation_wxyz == nullptr) return;
    const Scalar* q = f_.orientation_wxyz + 4 * k;
    const Scalar* p = sims_[l].principal_axes_wxyz;
    // Hamilton product q_b(k) * A.
    seed_q_[0][l] = q[0] * p[0] - q[1] * p[1] - q[2] * p[2] - q[3] * p[3];
    seed_q_[1][l] = q[0] * p[1] + q[1] * p[0] + q[2] * p[3] - q[3] * p[2];
    seed_q_[2][l] = q[0] * p[2] - q[1] * p[3] + q[2] * p[0] + q[3] * p[1];
    seed_q_[3][l] = q[0] * p[3] + q[1] * p[2] - q[2] * p[1] + q[3] * p[0];
  }

  void seed_all() {
    for (int l = 0; l < lanes; ++l) seed_lane(l);
    state_.w = {load(seed_w_[0]), load(seed_w_[1]), load(seed_w_[2])};
    state_.q = {load(seed_q_[0]), load(seed_q_[1]), load(seed_q_[2]), load(seed_q_[3])};
  }

  // Puts lane l back at its seed state (the turn from forward to backward).
  void reset_lane(int l) {
    Scalar q[4][lanes], w[3][lanes];
    LaneTraits<T>::store(state_.q.w, q[0]);
    LaneTraits<T>::store(state_.q.x, q[1]);
    LaneTraits<T>::store(state_.q.y, q[2]);
    LaneTraits<T>::store(state_.q.z, q[3]);
    LaneTraits<T>::store(state_.w.x, w[0]);
    LaneTraits<T>::store(state_.w.y, w[1]);
    LaneTraits<T>::store(state_.w.z, w[2]);
    for (int a = 0; a < 4; ++a) q[a][l] = seed_q_[a][l];
    for (int a = 0; a < 3; ++a) w[a][l] = seed_w_[a][l];
    state_.q = {load(q[0]), load(q[1]), load(q[2]), load(q[3])};
    state_.w = {load(w[0]), load(w[1]), load(w[2])};
  }

  void run_all(SquaredDeviations<Scalar>* out) {
    const std::size_t n = f_.samples;
    const bool pose = f_.orientation_wxyz != nullptr;
    const bool world = pose && f_.measured_world != nullptr;
    T sum_body = T(Scalar(0));
    T sum_world = T(Scalar(0));
    Scalar h[lanes] = {}, direction[lanes] = {}, mb[3][lanes] = {}, mw[3][lanes] = {};
    for (std::size_t s = 0; s + 1 < n; ++s) {
      for (int l = 0; l < lanes; ++l) {
        const std::size_t k = sims_[l].seed_sample;
        const std::size_t forward_steps = n - 1 - k;
        const bool forward = s < forward_steps;
        if (s == forward_steps && s > 0) reset_lane(l);
        const std::size_t j = forward ? k + s : k - 1 - (s - forward_steps);  // interval
        const Scalar dt = f_.time_s[j + 1] - f_.time_s[j];
        direction[l] = forward ? Scalar(1) : Scalar(-1);
        h[l] = forward ? dt : -dt;
        // Pose flights compare interval j; rate flights the sample stepped to.
        const std::size_t m = pose ? j : (forward ? j + 1 : j);
        for (int a = 0; a < 3; ++a) mb[a][l] = f_.measured_body[3 * m + static_cast<std::size_t>(a)];
        if (world) {
          for (int a = 0; a < 3; ++a) mw[a][l] = f_.measured_world[3 * m + static_cast<std::size_t>(a)];
        }
      }
      const T step = load(h);
      const LaneVec3<T> body_p =
          lane_rotate_transposed(to_body_, LaneVec3<T>{load(mb[0]), load(mb[1]), load(mb[2])});
      if (!pose) {
        state_.w = principal_rate_rk4_step(c_, state_.w, step);
        const T da = lane_deviation_angle(state_.w, body_p);
        sum_body += da * da;
        continue;
      }
      const LaneQuat<T> before = state_.q;
      principal_rk4_step(c_, state_, step);
      const T dir = load(direction);
      const T da = lane_deviation_angle(lane_body_rotation_axis(before, state_.q, dir), body_p);
      sum_body += da * da;
      if (world) {
        const T dw = lane_deviation_angle(lane_world_rotation_axis(before, state_.q, dir),
                                          LaneVec3<T>{load(mw[0]), load(mw[1]), load(mw[2])});
        sum_world += dw * dw;
      }
    }
    Scalar b[lanes], w[lanes];
    LaneTraits<T>::store(sum_body, b);
    LaneTraits<T>::store(sum_world, w);
    for (int l = 0; l < lanes; ++l) out[l] = {b[l], w[l], pose ? n - 1 : n};
  }

  const FlightArrays<Scalar>& f_;
  const FlightSimulation<Scalar>* sims_;
  EulerCoefficients<T> c_;
  LaneMat3<T> to_body_;
  Scalar seed_q_[4][lanes] = {};
  Scalar seed_w_[3][lanes] = {};
  PrincipalState<T> state_;
};

}  // namespace aloft
