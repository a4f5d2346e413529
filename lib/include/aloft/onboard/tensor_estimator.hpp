// The tensor a flight itself shows, estimated as it flies, in O(1) memory and O(1) work per
// sample. Euler's equations integrated over a piece [t_a, t_b] of the flight
// (aloft/dynamics/euler_equations.hpp),
//   I (w_b - w_a) + ∫ w x (I w) dt = -(h_b - h_a) - ∫ w x h dt,
// are linear in the tensor's six entries and need no derivative of the gyro. Per sample the
// estimator adds the six products w_i w_j (and, with a rotor, its speed times w) to the
// open piece's integrals (the trapezoid rule); at a piece's end it forms the piece's three
// rows and rotates them into the flight's least-squares problem
// (aloft/onboard/tensor_estimate.hpp), which at the flight's end gives the estimate.
//  - The rows are in rate units: multiplied by the nominal tensor's inverse (the body
//    file's, which the pipeline checks the flight against), so that a row's noise, the
//    gyro's at the piece's two ends, is about the same on each axis whatever the body.
//  - Pieces do not share samples, and the next piece starts a few noise correlation times
//    (the gyro filter's time constant) after the last one ended: the pieces' residuals are
//    then independent, which the intervals assume.
// docs/tensor-estimate.md has the derivation and the measurements behind the settings.
#pragma once

#include <cstdint>

#include "aloft/cold_path.hpp"
#include "aloft/dynamics/euler_equations.hpp"
#include "aloft/dynamics/inertia_tensor.hpp"
#include "aloft/dynamics/rotor.hpp"
#include "aloft/onboard/tensor_estimate.hpp"
#include "aloft/settings.hpp"

namespace aloft {

template <typename Scalar>
struct TensorEstimatorSettings {
  // 16 bits: at most 65,535 µs each (the settings' struct in float stays a multiple of
  // its 16-byte alignment: 32 bits each made it 16 bytes longer).
  std::uint16_t piece_us = 40000;
  std::uint16_t gyro_filter_us = 640;
  std::uint16_t min_pieces = 4;
  Scalar min_rms_rate_rad_s = Scalar(2);
  Scalar max_relative_sd = Scalar(0.05);

  // The one list of these settings (aloft/settings.hpp).
  template <typename Self, typename Visitor>
  static void visit(Self& s, Visitor&& v) {
    v(s.piece_us, [] {
      return SettingInfo{"tensor.piece_us", "µs",
                         "pieces over which Euler's equations are integrated. Chosen among 10-60 ms on "
                         "generated flights (seeds 1-300, docs/tensor-estimate.md): 40 ms narrowed the "
                         "ratios' intervals from 0.17 % (20 ms) to 0.13 % and covered 97 %; 60 ms narrowed "
                         "them 13 % more but needs 0.26 s of flight for 4 pieces"};
    });
    v(s.gyro_filter_us, [] {
      return SettingInfo{"tensor.gyro_filter_us", "µs",
                         "time constant of the gyro's first-order low-pass, 0 for none: the ICM-42688-P's UI "
                         "filter at ODR/4 = 250 Hz, as aloft's driver sets it at 1 kHz. Sets the filter's "
                         "correction and the waits after a release (8 of it) and between pieces (3). A "
                         "property of the firmware"};
    });
    v(s.min_pieces, [] {
      return SettingInfo{"tensor.min_pieces", "pieces",
                         "fewer pieces: too short to estimate the tensor. 4: 6 degrees of freedom at least "
                         "for the residuals' variance (Student's t at most 2.45). Not swept"};
    });
    v(s.min_rms_rate_rad_s, [] {
      return SettingInfo{"tensor.min_rms_rate_rad_s", "rad/s",
                         "the pieces' rms rate below which the body turned too little (a drop, whose rows "
                         "are noise alone). Not swept: throws turn at 5-30 rad/s"};
    });
    v(s.max_relative_sd, [] {
      return SettingInfo{"tensor.max_relative_sd", "",
                         "the tensor's weakest direction may be this uncertain (standard deviation relative "
                         "to it); more: the rates do not fix it (a spin about one axis). Chosen among "
                         "0.02-0.1 on the same seeds: 0.1 kept 2 % more flights and covered up to 2 % less"};
    });
  }
};

// The next piece starts this many gyro filter time constants after the last one ended:
// behind a first-order low-pass the noise is correlated e^(-t/tau), so the two pieces'
// residuals correlate by about -e^-3 / 2 = -2.5 %, which leaves a variance 5 % small, and
// their intervals 2.5 % narrow, against independent pieces (derived).
constexpr std::uint32_t piece_gap_filter_times = 3;
// After a release or a break the first piece starts this many filter time constants in:
// a hand's torque that stops at the release leaves the filtered rate a transient
// e^(-t/tau) off a torque-free motion, which enters the first piece's equations to first
// order in tau. Noise-free throws behind a 0.5 ms filter at 2 kHz (tests/core/
// test_tensor_estimator.cpp): ratios 1.5e-3 off without the wait, 1.6e-4 after 5 time
// constants, 4e-6 after 12; e^-8 leaves 3e-4 of the transient.
constexpr std::uint32_t settle_filter_times = 8;

// What the estimator reads and does not keep (a firmware's RAM holds them once, in the
// pipeline): its settings, the nominal tensor that weighs the rows, the rotor.
template <typename Scalar>
struct TensorEstimatorInputs {
  const TensorEstimatorSettings<Scalar>& settings;
  const InertiaTensor<Scalar>& nominal;
  const Rotor<Scalar>& rotor;
};

namespace detail {
// The rotor's share of the open piece: its filtered speed, the speed at the piece's start
// and ∫ s w dt. Nothing without rotor support (a firmware without it keeps 20 B less).
template <typename Scalar, bool Rotor>
struct RotorPieceIntegrals {
  Scalar speed_f = Scalar(0);                       // the rotor's speed, filtered
  Scalar speed_a = Scalar(0);                       // the filtered speed at the open piece's first sample
  Vec3<Scalar> speed_omega = Vec3<Scalar>::Zero();  // ∫ s w dt
  // For the telemetry delay's column: ∫ s' w dt, the speed's slope over the piece's first
  // rotor_slope_us, and the speed and time where its last rotor_slope_us begin.
  Vec3<Scalar> slope_omega = Vec3<Scalar>::Zero();
  Scalar slope_a = Scalar(0);
  Scalar speed_late = Scalar(0);
  std::uint32_t late_us = 0;
};
template <typename Scalar>
struct RotorPieceIntegrals<Scalar, false> {};
}  // namespace detail

// The rotor's speed's slope at a piece's ends, for the delay's column, over this long (at
// most a quarter of the piece): an ESC's telemetry holds its speed 0.125-2 ms between
// frames, so a slope over one sample would be its steps. Chosen among 2, 5 and 10 ms on
// the generated rotor throws of tests/host/test_tensor_on_rotor_throws.cpp (seeds 42x):
// moments covered in 66, 71, 66 of 76-77 flights, their errors 1.09, 1.07, 1.11 %.
constexpr std::uint32_t rotor_slope_us = 5000;

// Rotor: whether a rotor's speed may come with the samples (a pipeline's RotorSupport);
// without, the rotor's terms are not compiled in.
template <typename Scalar, bool Rotor = true>
class TensorEstimator : detail::RotorPieceIntegrals<Scalar, Rotor> {
 public:
  using Inputs = TensorEstimatorInputs<Scalar>;

  // A new flight.
  void start() {
    ls_ = TensorLeastSquares<Scalar, Rotor>();
    piece_count_ = 0;
    scaled_ = false;
    phase_ = Phase::idle;
  }

  // One airborne sample: the body rate (body axes), the rate of the sample before it (the
  // caller holds it: a pipeline's history), the rotor's speed relative to the body (0
  // without one), and the time since the sample before. The sample before is not read
  // after start() or interrupt().
  void add(const Vec3<Scalar>& w, const Vec3<Scalar>& w_before, Scalar rotor_speed, std::uint32_t dt_us,
           const Inputs& in) {
    if (phase_ == Phase::idle) {
      // The filters start here: the first piece waits for their transient.
      if constexpr (Rotor) this->speed_f = rotor_speed;
      elapsed_us_ = 0;
      phase_ = Phase::settle;
      return;
    }
    const Scalar dt = static_cast<Scalar>(dt_us) * Scalar(1e-6);
    const Scalar tau = static_cast<Scalar>(in.settings.gyro_filter_us) * Scalar(1e-6);
    // The rotor's speed through a filter like the gyro's, so that both lag alike (without a
    // rotor it stays 0, and the sample's work has no rotor terms).
    const bool rotor = Rotor && in.rotor.present();
    Scalar ds = Scalar(0);  // the filtered speed's change over the interval
    if constexpr (Rotor) {
      const Scalar speed_before = this->speed_f;
      if (rotor) this->speed_f += (dt / (tau + dt)) * (rotor_speed - this->speed_f);
      ds = this->speed_f - speed_before;
    }
    const bool first_step = elapsed_us_ == 0;
    elapsed_us_ += dt_us;
    if (phase_ != Phase::piece) {
      const std::uint32_t filter_times = phase_ == Phase::gap ? piece_gap_filter_times : settle_filter_times;
      if (elapsed_us_ >= filter_times * in.settings.gyro_filter_us) start_piece(w);
      return;
    }
    // The filter's own term over this interval (docs/tensor-estimate.md): the true rate is
    // w + tau (w - w_before) / dt, which adds tau (tau + dt) ∫ w_dot w_dot^T dt to the
    // gyroscopic integral, w_dot from the difference (midpoint rule).
    const Vec3<Scalar> dw = w - w_before;
    // Trapezoid rule on the rates: each sample weighs dt, the piece's first and last half
    // of theirs (exact on evenly spaced samples, without keeping the sample before), and
    // Euler-Maclaurin's end correction -dt²/12 (f'(t_b) - f'(t_a)), f' from the first and
    // last differences: the trapezoid's error goes from (dt Ω)² to (dt Ω)⁴ at no cost per
    // sample (a throw at 28 rad/s sampled at 1 kHz: ratios 1.6e-4 off without it).
    if (first_step) integrate_end(omega_a_, dw, speed_at_start(), ds, dt);
    integrate_sample(w, dw, ds, dt, tau * (tau + dt) / dt, rotor);
    if constexpr (Rotor) {
      if (rotor) track_slopes(w, ds, dt_us, in.settings.piece_us);
    }
    if (elapsed_us_ >= in.settings.piece_us) {
      integrate_end(w, dw, filtered_speed(), ds, -dt);
      close_piece(w, filtered_speed(), in);
    }
  }

  // The samples break here (a gap, a clipped gyro, a rotor speed missing): the open piece
  // is dropped and the next sample starts a new one.
  void interrupt() { phase_ = Phase::idle; }

  // The flight's estimate (cold: once per flight).
  ALOFT_COLD void finish(const Inputs& in, TensorEstimate<Scalar>& out) const {
    const TensorDetermination<Scalar> d{in.settings.min_pieces, in.settings.min_rms_rate_rad_s,
                                        in.settings.max_relative_sd,
                                        static_cast<std::uint32_t>(in.settings.piece_us)};
    estimate_tensor<Scalar, Rotor>(ls_, pieces(), nominal_scale(in.nominal), d, out);
  }

  const TensorLeastSquares<Scalar, Rotor>& least_squares() const { return ls_; }
  TensorPieces pieces() const { return TensorPieces{piece_count_, scaled_}; }

 private:
  enum class Phase : std::uint8_t {
    idle,    // the next sample starts the filters
    settle,  // waiting for the filters' transient after a start or a break
    piece,   // integrating a piece
    gap,     // between pieces
  };

  Scalar filtered_speed() const {
    if constexpr (Rotor) return this->speed_f;
    return Scalar(0);
  }
  Scalar speed_at_start() const {
    if constexpr (Rotor) return this->speed_a;
    return Scalar(0);
  }

  // theta's unit: the nominal tensor's mean moment.
  static Scalar nominal_scale(const InertiaTensor<Scalar>& nominal) {
    return nominal.tensor().trace() / Scalar(3);
  }

  ALOFT_COLD void start_piece(const Vec3<Scalar>& w) {
    phase_ = Phase::piece;
    elapsed_us_ = 0;
    omega_a_ = w;
    if constexpr (Rotor) this->speed_a = this->speed_f;
    for (Scalar& p : products_) p = Scalar(0);
    if constexpr (Rotor) {
      this->speed_omega.setZero();
      this->slope_omega.setZero();
      this->slope_a = Scalar(0);
      this->speed_late = this->speed_f;
      this->late_us = 0;
    }
  }

  // The delay column's integrals: ∫ s' w dt as the sum of ds w, and the speed where the
  // piece's first rotor_slope_us end and its last begin.
  void track_slopes(const Vec3<Scalar>& w, Scalar ds, std::uint32_t dt_us, std::uint32_t piece_us) {
    this->slope_omega += ds * w;
    // From the settings each sample: a shift and a compare, cheaper than 4 B more state.
    const std::uint32_t window = piece_us / 4 < rotor_slope_us ? piece_us / 4 : rotor_slope_us;
    const std::uint32_t before = elapsed_us_ - dt_us;
    if (before < window && elapsed_us_ >= window)
      this->slope_a = (this->speed_f - this->speed_a) / (static_cast<Scalar>(elapsed_us_) * Scalar(1e-6));
    if (before < piece_us - window && elapsed_us_ >= piece_us - window) {
      this->speed_late = this->speed_f;
      this->late_us = elapsed_us_;
    }
  }

  void integrate(const Vec3<Scalar>& w, Scalar rotor_speed, Scalar weight) {
    const Vec3<Scalar> ww = weight * w;
    products_[0] += ww.x() * w.x();
    products_[1] += ww.y() * w.y();
    products_[2] += ww.z() * w.z();
    products_[3] += ww.x() * w.y();
    products_[4] += ww.x() * w.z();
    products_[5] += ww.y() * w.z();
    if constexpr (Rotor) this->speed_omega += rotor_speed * ww;
  }

  // One sample's share, in one pass over the integrals: dt w w^T and the filter's term
  // c dw dw^T (c = tau (tau + dt) / dt), and the rotor's dt s w and c ds dw.
  void integrate_sample(const Vec3<Scalar>& w, const Vec3<Scalar>& dw, Scalar ds, Scalar dt, Scalar c,
                        bool rotor) {
    const Vec3<Scalar> a = dt * w, b = c * dw;
    products_[0] += a.x() * w.x() + b.x() * dw.x();
    products_[1] += a.y() * w.y() + b.y() * dw.y();
    products_[2] += a.z() * w.z() + b.z() * dw.z();
    products_[3] += a.x() * w.y() + b.x() * dw.y();
    products_[4] += a.x() * w.z() + b.x() * dw.z();
    products_[5] += a.y() * w.z() + b.y() * dw.z();
    if constexpr (Rotor) {
      if (rotor) this->speed_omega += this->speed_f * a + ds * b;
    }
  }

  // A piece's end (dt > 0 its first, dt < 0 its last): half the sample's weight, and the
  // end correction. Out of line: twice a piece, not on every sample's code path.
  ALOFT_COLD void integrate_end(const Vec3<Scalar>& w, const Vec3<Scalar>& dw, Scalar speed, Scalar ds,
                                Scalar dt) {
    integrate(w, speed, Scalar(0.5) * dt);
    integrate_slope(w, dw, speed, ds, dt / Scalar(12));
  }

  // weight (dw w^T + w dw^T) and weight (ds w + s dw): dt² f' of the integrands, times
  // weight / dt.
  void integrate_slope(const Vec3<Scalar>& w, const Vec3<Scalar>& dw, Scalar rotor_speed, Scalar ds,
                       Scalar weight) {
    const Vec3<Scalar> a = weight * w, b = weight * dw;
    products_[0] += Scalar(2) * a.x() * dw.x();
    products_[1] += Scalar(2) * a.y() * dw.y();
    products_[2] += Scalar(2) * a.z() * dw.z();
    products_[3] += a.x() * dw.y() + b.x() * w.y();
    products_[4] += a.x() * dw.z() + b.x() * w.z();
    products_[5] += a.y() * dw.z() + b.y() * w.z();
    if constexpr (Rotor) this->speed_omega += ds * a + rotor_speed * b;
  }

  // The piece's three rows: column m is the body's side of the integrated equations for
  // the m-th unit tensor (theta's entries), the right side the rotor's; with rotor support
  // the nuisances' columns follow (TensorLeastSquares): the rotor's side per ms of delay
  // (its speed's slope in place of the speed), minus the rows' sensitivities to the
  // gyro's scale.
  ALOFT_COLD void close_piece(const Vec3<Scalar>& w_b, Scalar speed_b, const Inputs& in) {
    Mat3<Scalar> p;
    p << products_[0], products_[3], products_[4], products_[3], products_[1], products_[5], products_[4],
        products_[5], products_[2];
    const Vec3<Scalar> delta_omega = w_b - omega_a_;
    const Mat3<Scalar>& to_rates = in.nominal.inverse();
    const Scalar scale = nominal_scale(in.nominal);
    const Eigen::Matrix<Scalar, 3, 6> torque = integrated_body_torque_per_entry(delta_omega, p);
    Vec3<Scalar> b = Vec3<Scalar>::Zero();
    if constexpr (Rotor) {
      Eigen::Matrix<Scalar, 3, 4> nuisance = Eigen::Matrix<Scalar, 3, 4>::Zero();
      if (in.rotor.present()) {
        b = -(to_rates * integrated_rotor_torque(in.rotor, speed_b - this->speed_a, this->speed_omega));
        if (b.squaredNorm() > Scalar(0)) scaled_ = true;
        const Scalar late_s = static_cast<Scalar>(elapsed_us_ - this->late_us) * Scalar(1e-6);
        const Scalar slope_b = late_s > Scalar(0) ? (speed_b - this->speed_late) / late_s : this->slope_a;
        nuisance.col(0) =
            Scalar(1e-3) *
            (to_rates * integrated_rotor_torque(in.rotor, slope_b - this->slope_a, this->slope_omega));
      }
      nuisance.template rightCols<3>() =
          -(to_rates * integrated_torque_gyro_scale_sensitivity(in.nominal.tensor(), delta_omega, p, in.rotor,
                                                                this->speed_omega));
      add_rows(to_rates, scale, torque, b, nuisance.data());
    } else {
      add_rows(to_rates, scale, torque, b, nullptr);
    }
    ls_.rate_squared_s += products_[0] + products_[1] + products_[2];
    ++piece_count_;
    phase_ = Phase::gap;
    elapsed_us_ = 0;
  }

  // Row r of (scale to_rates) torque, then with rotor support the nuisances' columns
  // (`nuisance`: 3 x 4, column-major), as a plain loop: Eigen's unrolled 3 x 6 product took
  // 730 B of the flight image's flash for a path run once a piece.
  void add_rows(const Mat3<Scalar>& to_rates, Scalar scale, const Eigen::Matrix<Scalar, 3, 6>& torque,
                const Vec3<Scalar>& b, [[maybe_unused]] const Scalar* nuisance) {
    for (int r = 0; r < 3; ++r) {
      Scalar row[TensorLeastSquares<Scalar, Rotor>::columns];
      for (int m = 0; m < 6; ++m) row[m] = scale * to_rates.row(r).dot(torque.col(m));
      if constexpr (Rotor) {
        for (int m = 0; m < 4; ++m) row[6 + m] = nuisance[r + 3 * m];
      }
      ls_.add_row(row, b(r));
    }
  }

  TensorLeastSquares<Scalar, Rotor> ls_;
  // The open piece: its first sample, and the integrals so far.
  Vec3<Scalar> omega_a_ = Vec3<Scalar>::Zero();
  Scalar products_[6] = {};       // ∫ w_i w_j dt: xx yy zz xy xz yz
  std::uint32_t elapsed_us_ = 0;  // in the open piece, or since the last one ended
  // Packed in one word (196 B in float with a TensorPieces here, 192 without).
  std::uint16_t piece_count_ = 0;
  bool scaled_ = false;  // some piece had a rotor's momentum
  Phase phase_ = Phase::idle;
};

// What a pipeline built without the estimate (TensorEstimation::off) holds in its place:
// nothing, so that the estimate's cost can be measured against it.
template <typename Scalar, bool Rotor = true>
class NoTensorEstimator {
 public:
  void start() {}
  void add(const Vec3<Scalar>&, const Vec3<Scalar>&, Scalar, std::uint32_t,
           const TensorEstimatorInputs<Scalar>&) {}
  void interrupt() {}
  void finish(const TensorEstimatorInputs<Scalar>&, TensorEstimate<Scalar>&) const {}
};

}  // namespace aloft
