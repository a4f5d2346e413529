// The power gain of the digital low-passes a gyro's noise passes, as the noise floor fits
// them to the readings' spectrum (noise_floor.cpp): a 2nd-order Butterworth (bilinear, a
// MEMS gyro's and a phone's DLPF: 1 / (1 + (tan(pi f / fs) / tan(pi fc / fs))^4)) and a
// flight controller's first-order PT1 (y += k (x - y), k = dt / (RC + dt), RC = 1 / (2 pi fc):
// k^2 / (1 + a^2 - 2 a cos(2 pi f / fs)), a = 1 - k; Betaflight's default, and the ICM-42688's
// UI filter at order 1). Past the cutoff a Butterworth's noise falls as 1/f^4, a PT1's as
// 1/f^2, so a PT1's noise stays correlated over fs / (pi fc) readings, where a Butterworth's
// at the same cutoff spans about fs / (2.2 fc).
//
// Split in two so that a search over cutoffs takes each frequency's trigonometric function
// once (`abscissa`) and each cutoff's once (the constructor).
#pragma once

namespace aloft::host::diagnose {

class LowPassShape {
 public:
  static constexpr int kButterworth = 2;  // the order of each shape
  static constexpr int kFirstOrder = 1;

  // cutoff_hz <= 0: no filter (gain 1 everywhere).
  LowPassShape(int order, double cutoff_hz, double sample_hz);

  // What a frequency enters the gain through: tan(pi f / fs) for the Butterworth,
  // cos(2 pi f / fs) for the PT1 (f held below the Nyquist rate).
  static double abscissa(int order, double f_hz, double sample_hz);
  double gain_at(double abscissa) const;
  double gain(double f_hz) const { return gain_at(abscissa(order_, f_hz, sample_hz_)); }

  int order() const { return order_; }
  double cutoff_hz() const { return cutoff_hz_; }

 private:
  int order_;
  double cutoff_hz_, sample_hz_;
  double cutoff_abscissa_ = 0.0;  // Butterworth: tan(pi fc / fs)
  double k_ = 1.0;                // PT1: the step's gain k, and a = 1 - k
};

}  // namespace aloft::host::diagnose
