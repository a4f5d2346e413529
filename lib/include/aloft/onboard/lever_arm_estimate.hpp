// The accelerometer's position r (body axes, m, from the centre of mass) by least squares
// over free-flight samples: each gives a = K(w, w_dot) r (aloft/dynamics/free_flight_residual.hpp),
// so r solves (sum K^T K) r = sum K^T a, a 3x3 system kept as running sums: no samples are
// stored. A spin about one fixed axis cannot see r's component along that axis (it moves
// nothing); a small ridge (ridge_rad_s2² per sample) sets that component to zero instead
// of leaving it to noise, and shrinks r of a body that hardly turns to nothing, where a
// is then its own residual (a drop).
#pragma once

#include <cstdint>
#include <limits>

#include "aloft/cold_path.hpp"
#include "aloft/dynamics/free_flight_residual.hpp"

namespace aloft {

// K^T K is symmetric: its six distinct entries (the upper triangle). Summing six, not
// nine, takes a third of the additions out of every sample the fits take.
template <typename Scalar>
struct SymmetricMat3 {
  Scalar xx = Scalar(0), xy = Scalar(0), xz = Scalar(0), yy = Scalar(0), yz = Scalar(0), zz = Scalar(0);

  SymmetricMat3& operator+=(const SymmetricMat3& o) {
    xx += o.xx;
    xy += o.xy;
    xz += o.xz;
    yy += o.yy;
    yz += o.yz;
    zz += o.zz;
    return *this;
  }
  void scale(Scalar f) {
    xx *= f;
    xy *= f;
    xz *= f;
    yy *= f;
    yz *= f;
    zz *= f;
  }
  // Entry (i, j), i <= j.
  Scalar& upper(int i, int j) {
    Scalar* const rows[3][3] = {{&xx, &xy, &xz}, {&xy, &yy, &yz}, {&xz, &yz, &zz}};
    return *rows[i][j];
  }
  // trace((this + d I)^-1), from the adjugate's diagonal and the determinant; infinite
  // where the matrix is singular (or, by rounding, not positive definite).
  Scalar trace_of_inverse(Scalar d) const {
    const Scalar a = xx + d, b = yy + d, c = zz + d;
    const Scalar cofactor_x = b * c - yz * yz, cofactor_y = a * c - xz * xz, cofactor_z = a * b - xy * xy;
    const Scalar det = a * cofactor_x - xy * (xy * c - yz * xz) + xz * (xy * yz - b * xz);
    return det > Scalar(0) ? (cofactor_x + cofactor_y + cofactor_z) / det
                           : std::numeric_limits<Scalar>::infinity();
  }
  Mat3<Scalar> full() const {
    Mat3<Scalar> m;
    m << xx, xy, xz, xy, yy, yz, xz, yz, zz;
    return m;
  }
};

// One sample's terms of the sums, formed once when the sample joins several fits.
template <typename Scalar>
struct LeverArmTerms {
  explicit LeverArmTerms(const BodyKinematics<Scalar>& k) {
    const Mat3<Scalar> m = lever_arm_matrix(k.w, k.w_dot);
    // Column i of K dotted with column j, summed as x0 + (x1 + x2) as Eigen sums m^T m.
    for (int i = 0; i < 3; ++i) {
      for (int j = i; j < 3; ++j)
        ktk.upper(i, j) = m(0, i) * m(0, j) + (m(1, i) * m(1, j) + m(2, i) * m(2, j));
    }
    kta = m.transpose() * k.a;
    ata = k.a.squaredNorm();
  }
  SymmetricMat3<Scalar> ktk;
  Vec3<Scalar> kta;
  Scalar ata;
};

template <typename Scalar>
class LeverArmFit {
 public:
  void add(const BodyKinematics<Scalar>& k) { add(LeverArmTerms<Scalar>(k)); }
  ALOFT_OUT_OF_LINE void add(const LeverArmTerms<Scalar>& t) { accumulate(t); }
  // The same, in line: the terms stay in registers rather than stored for a call (a
  // flight's fit takes every airborne sample; out of line, the STM32F405 image's deepest
  // stack path grew by 8 B and each sample took 25 instructions more, for 88 B less flash).
  void add_in_line(const LeverArmTerms<Scalar>& t) { accumulate(t); }
  // n samples summarised by their mean K and mean a (a block mean: what varies within
  // the block, as a structural mode does, is left out).
  // Written out rather than as Eigen products, whose temporaries made this the deepest
  // frame of the firmware's stack; the same sums to the bit as w * (K^T K) and w * (K^T a)
  // are in Eigen (the weight taken into K^T, the sum of three as x0 + (x1 + x2)).
  ALOFT_COLD void add_mean(const Mat3<Scalar>& k_mean, const Vec3<Scalar>& a_mean, std::uint32_t n) {
    const Scalar w = static_cast<Scalar>(n);
    for (int i = 0; i < 3; ++i) {
      const Scalar w0 = w * k_mean(0, i), w1 = w * k_mean(1, i), w2 = w * k_mean(2, i);
      for (int j = i; j < 3; ++j)
        ktk_.upper(i, j) += w0 * k_mean(0, j) + (w1 * k_mean(1, j) + w2 * k_mean(2, j));
      kta_(i) += w0 * a_mean(0) + (w1 * a_mean(1) + w2 * a_mean(2));
    }
    ata_ += w * a_mean.squaredNorm();
    count_ += n;
  }
  ALOFT_COLD void merge(const LeverArmFit& other) {
    ktk_ += other.ktk_;
    kta_ += other.kta_;
    ata_ += other.ata_;
    count_ += other.count_;
  }
  void reset() { *this = LeverArmFit(); }

  // r minimising sum |a - K r|² + ridge² n |r|² (zero when there are no samples).
  ALOFT_OUT_OF_LINE Vec3<Scalar> solve(Scalar ridge_rad_s2) const {
    if (count_ == 0) return Vec3<Scalar>::Zero();
    const Scalar lambda = ridge_rad_s2 * ridge_rad_s2 * static_cast<Scalar>(count_);
    const Mat3<Scalar> m = ktk_.full() + lambda * Mat3<Scalar>::Identity();
    return m.inverse() * kta_;  // positive definite: the ridge keeps it invertible
  }

  // Root mean square of |a - K r| over the samples (m/s²).
  ALOFT_COLD Scalar rms_residual(const Vec3<Scalar>& r) const {
    if (count_ == 0) return Scalar(0);
    const Scalar sse = ata_ - Scalar(2) * r.dot(kta_) + r.dot(ktk_.full() * r);
    return std::sqrt((sse > Scalar(0) ? sse : Scalar(0)) / static_cast<Scalar>(count_));
  }

  // A bound on how far r (this fit's, at the ridge) can lie from the true one, from the
  // smallest eigenvalue mu of the mean ridged K^T K (M = K^T K / n + ridge² I):
  //  - a misfit as large as the fit's rms residual at r, laid along the direction K sees
  //    worst, moves r by rms / sqrt(mu): a flight that turns little about one axis sees r's
  //    part along it weakly, and a hand's last touch or a ringing body moves that part;
  //  - the ridge pulls r's part along that direction towards zero by ridge² / mu of it, at
  //    most ridge² / mu * max_r_m.
  // mu is bounded below through trace(M^-1) >= 1 / mu (so the bound is at most sqrt 3 and
  // 3 times the exact terms).
  ALOFT_COLD Scalar worst_error_m(const Vec3<Scalar>& r, Scalar ridge_rad_s2, Scalar max_r_m) const {
    if (count_ == 0) return std::numeric_limits<Scalar>::infinity();
    // Per sample: the sums of a long flight would overflow a float's determinant.
    SymmetricMat3<Scalar> mean = ktk_;
    mean.scale(Scalar(1) / static_cast<Scalar>(count_));
    const Scalar ridge2 = ridge_rad_s2 * ridge_rad_s2;
    const Scalar inverse_mu = mean.trace_of_inverse(ridge2);
    return rms_residual(r) * std::sqrt(inverse_mu) + ridge2 * inverse_mu * max_r_m;
  }

  std::uint32_t count() const { return count_; }

 private:
  // By value: the sums written cannot alias the terms read, so these are read once.
  void accumulate(LeverArmTerms<Scalar> t) {
    ktk_ += t.ktk;
    kta_ += t.kta;
    ata_ += t.ata;
    ++count_;
  }

  SymmetricMat3<Scalar> ktk_;
  Vec3<Scalar> kta_ = Vec3<Scalar>::Zero();
  Scalar ata_ = Scalar(0);
  std::uint32_t count_ = 0;
};

}  // namespace aloft
