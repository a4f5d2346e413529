// Exact torque-free motions the integrators are checked against (double precision):
//  - the symmetric top (I1 = I2): closed form for body rate and orientation;
//  - the asymmetric top: body rate from Jacobi's elliptic functions (Landau & Lifshitz,
//    Mechanics §37), including motion near the separatrix, where the body flips about
//    its intermediate axis.
// Written by hand (AGM method of Abramowitz & Stegun 16.4) rather than taken from Boost,
// so the same bodies run on bare metal; tests/host cross-checks them against Boost.
#pragma once

#include <cmath>

#include "aloft/dynamics/rotation.hpp"

namespace aloft_test {

// sn, cn, dn of (u | m), m = k^2 in [0, 1), by the arithmetic-geometric mean.
struct JacobiElliptic {
  double sn, cn, dn;
};

inline JacobiElliptic jacobi_elliptic(double u, double m) {
  constexpr int max_terms = 16;
  double a[max_terms + 1];
  double c[max_terms + 1];
  a[0] = 1.0;
  double b = std::sqrt(1.0 - m);
  c[0] = std::sqrt(m);
  int n = 0;
  while (std::abs(c[n]) > 1e-16 && n < max_terms) {
    a[n + 1] = 0.5 * (a[n] + b);
    c[n + 1] = 0.5 * (a[n] - b);
    b = std::sqrt(a[n] * b);
    ++n;
  }
  double phi = std::ldexp(a[n] * u, n);
  double previous = phi;
  for (int i = n; i > 0; --i) {
    previous = phi;
    phi = 0.5 * (phi + std::asin(c[i] / a[i] * std::sin(phi)));
  }
  const double dn = n > 0 ? std::cos(phi) / std::cos(previous - phi) : 1.0;
  return {std::sin(phi), std::cos(phi), dn};
}

// Complete elliptic integral of the first kind K(m).
inline double complete_elliptic_k(double m) {
  double a = 1.0;
  double b = std::sqrt(1.0 - m);
  for (int i = 0; i < 16 && std::abs(a - b) > 1e-16 * a; ++i) {
    const double next_a = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next_a;
  }
  return 3.14159265358979323846 / (2.0 * a);
}

// Asymmetric top in its principal frame, moments i1 < i2 < i3, with
// w(tau = 0) = (a, 0, c), a, c > 0 and i3 c^2 (i3 - i2) > i1 a^2 (i2 - i1) (the branch
// L^2 > 2 E i2, where w3 keeps its sign). t_offset shifts the start of the motion.
struct AsymmetricTop {
  double i1, i2, i3, a, c, t_offset;

  double modulus_squared() const { return (i2 - i1) * i1 * a * a / ((i3 - i2) * i3 * c * c); }
  double lambda() const { return c * std::sqrt((i3 - i2) * (i3 - i1) / (i1 * i2)); }
  // Time between two flips about the intermediate axis: half the period of w2.
  double flip_interval() const { return 2.0 * complete_elliptic_k(modulus_squared()) / lambda(); }

  aloft::Vec3<double> omega(double t) const {
    const JacobiElliptic j = jacobi_elliptic(lambda() * (t + t_offset), modulus_squared());
    const double b = a * std::sqrt(i1 * (i3 - i1) / (i2 * (i3 - i2)));
    return {a * j.cn, b * j.sn, c * j.dn};
  }
};

// Symmetric top: transverse moment it (about body x and y), axial moment i3 (body z).
struct SymmetricTop {
  double it, i3;
  aloft::Vec3<double> omega0;
  aloft::Quat<double> q0;

  // Body rate: the transverse part turns about z at Omega = (i3 - it)/it * w3.
  aloft::Vec3<double> omega(double t) const {
    const double rate = (i3 - it) / it * omega0.z();
    const double c = std::cos(rate * t);
    const double s = std::sin(rate * t);
    return {c * omega0.x() - s * omega0.y(), s * omega0.x() + c * omega0.y(), omega0.z()};
  }

  // q(t) = exp(t |L|/it * l_world) * q0 * exp(-t Omega e_z): precession about the fixed
  // angular momentum composed with the body's spin relative to it.
  aloft::Quat<double> orientation(double t) const {
    const aloft::Vec3<double> l_body(it * omega0.x(), it * omega0.y(), i3 * omega0.z());
    const aloft::Vec3<double> l_world = q0 * l_body;
    const double rate = (i3 - it) / it * omega0.z();
    const aloft::Quat<double> precession = aloft::quat_exp(aloft::Vec3<double>(l_world * (t / it)));
    const aloft::Quat<double> spin = aloft::quat_exp(aloft::Vec3<double>(0.0, 0.0, -rate * t));
    return precession * q0 * spin;
  }
};

}  // namespace aloft_test
