// The power gain of the digital low-passes a gyro's noise passes, as the noise floor fits
// them to the readings' spectrum (noise_floor.cpp):
// - a 2nd-order Butterworth (bilinear, a MEMS gyro's and a phone's DLPF, PX4's and
//   ArduPilot's gyro filter: 1 / (1 + (tan(pi f / fs) / tan(pi fc / fs))^4));
// - a flight controller's first-order PT1 (y += k (x - y), k = dt / (RC + dt),
//   RC = 1 / (2 pi fc): k^2 / (1 + a^2 - 2 a cos(2 pi f / fs)), a = 1 - k; Betaflight's
//   default, and the ICM-42688's UI filter at order 1);
// - two PT1 stages at one cutoff in series (Betaflight's and INAV's PT2: the PT1's gain
//   squared). Betaflight's default pair, a PT1 and a second at about twice its cutoff, has
//   nearly this shape at a cutoff between the two.
// Past the cutoff a Butterworth's and a PT2's noise fall as 1/f^4, a PT1's as 1/f^2, so a
// PT1's noise stays correlated over fs / (pi fc) readings, a Butterworth's at the same
// cutoff over about fs / (2.2 fc), a PT2's (a softer knee: a quarter of the power at its
// cutoff) over about 2 fs / (pi fc).
//
// Split in two so that a search over cutoffs takes each frequency's trigonometric function
// once (`abscissa`) and each cutoff's once (the constructor).
#pragma once

namespace aloft::host::diagnose {

class LowPassShape {
 public:
  enum class Kind { butterworth, first_order, two_first_order };

  // cutoff_hz <= 0: no filter (gain 1 everywhere).
  LowPassShape(Kind kind, double cutoff_hz, double sample_hz);

  // What a frequency enters the gain through: tan(pi f / fs) for the Butterworth,
  // cos(2 pi f / fs) for the PT1 and PT2 (f held below the Nyquist rate).
  static double abscissa(Kind kind, double f_hz, double sample_hz);
  double gain_at(double abscissa) const;
  double gain(double f_hz) const { return gain_at(abscissa(kind_, f_hz, sample_hz_)); }

  Kind kind() const { return kind_; }
  int order() const { return kind_ == Kind::first_order ? 1 : 2; }
  // "butterworth", "pt1" or "pt2" (the reports' noise_floor.low_pass_shape).
  const char* name() const;
  double cutoff_hz() const { return cutoff_hz_; }
  // Half the variance of the filter's impulse response (s^2): a slow signal x comes out as
  // x(t - mean) + (variance / 2) x'' to second order. A PT1's response k (1 - k)^n dt has
  // variance RC (RC + dt), n stages in series n times that; a 2nd-order Butterworth's
  // (Q = 1 / sqrt 2: 1 - sqrt 2 s / w0 + s^2 / w0^2 + ...) has none, to this order.
  double bend_s2() const;

 private:
  Kind kind_;
  double cutoff_hz_, sample_hz_;
  double cutoff_abscissa_ = 0.0;  // Butterworth: tan(pi fc / fs)
  double k_ = 1.0;                // PT1, PT2: each stage's gain k, and a = 1 - k
};

}  // namespace aloft::host::diagnose
