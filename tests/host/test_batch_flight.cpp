// The batch integrator (aloft/lanes/batch_flight.hpp) in xsimd lanes against an independent
// scalar reference: Rk4Integrator on body states, ω from consecutive orientations with
// Eigen quaternions, and the C library's atan2. Also: the lanes' atan2 against
// std::atan2, and no heap.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "aloft/lanes/batch_flight.hpp"
#include "aloft/dynamics/rk4_integrator.hpp"
#include "aloft/lanes/xsimd_lanes.hpp"
#include "heap_counter.hpp"

namespace {

using Lanes = xsimd::batch<double>;
constexpr double kDegrees = 180.0 / 3.14159265358979323846;

// A pose flight: 500 samples at 1 kHz of a tumbling asymmetric body (integrated finely),
// measured rates with 0.01 rad/s of noise so that the deviations are not all zero.
struct TestFlight {
  std::vector<double> time, orientation, state_omega, measured_body, measured_world;
  aloft::InertiaTensor<double> inertia;
  aloft::FlightArrays<double> arrays(bool pose) const {
    aloft::FlightArrays<double> f;
    f.samples = time.size();
    f.time_s = time.data();
    f.state_omega_body = state_omega.data();
    if (pose) {
      f.orientation_wxyz = orientation.data();
      f.measured_body = measured_body.data();
      f.measured_world = measured_world.data();
    } else {
      f.measured_body = state_omega.data();  // rate flight: the gyro is the rate
    }
    return f;
  }
};

TestFlight make_flight() {
  TestFlight f;
  REQUIRE(aloft::InertiaTensor<double>::make_from_principal(
              {0.011, 0.019, 0.027}, aloft::quat_wxyz(0.9, 0.1, -0.3, 0.3).normalized(), f.inertia) ==
          aloft::Status::ok);
  const aloft::Rk4Integrator<double> truth(f.inertia);
  aloft::RigidBodyState<double> s;
  s.omega_body = {3.0, -7.0, 9.0};
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  const int n = 500;
  // Uneven sampling, as a resampled recording need not be even.
  double t = 0.0;
  for (int i = 0; i < n; ++i) {
    f.time.push_back(t);
    const aloft::Quat<double>& q = s.orientation;
    f.orientation.insert(f.orientation.end(), {q.w(), q.x(), q.y(), q.z()});
    const aloft::Vec3<double> w =
        s.omega_body + aloft::Vec3<double>(noise(random), noise(random), noise(random));
    f.state_omega.insert(f.state_omega.end(), {w.x(), w.y(), w.z()});
    if (i + 1 < n) {
      const aloft::Vec3<double> ww = q * w;
      f.measured_body.insert(f.measured_body.end(), {w.x(), w.y(), w.z()});
      f.measured_world.insert(f.measured_world.end(), {ww.x(), ww.y(), ww.z()});
    }
    const double dt = 1e-3 * (1.0 + 0.2 * std::sin(i * 0.1));
    for (int sub = 0; sub < 10; ++sub) truth.step_unchecked(s, dt / 10.0);
    t += dt;
  }
  return f;
}

double reference_da(const aloft::Vec3<double>& a, const aloft::Vec3<double>& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

aloft::Vec3<double> short_side(const aloft::Quat<double>& d) {
  return d.w() < 0.0 ? aloft::Vec3<double>(-d.vec()) : aloft::Vec3<double>(d.vec());
}

// The scalar reference of one pose-flight simulation: RMS DA (degrees), body and world.
void reference_pose(const TestFlight& f, const aloft::InertiaTensor<double>& inertia, std::size_t k,
                    double& body, double& world) {
  const aloft::Rk4Integrator<double> integrator(inertia);
  const std::size_t n = f.time.size();
  const auto q_at = [&](std::size_t i) {
    return aloft::quat_wxyz(f.orientation[4 * i], f.orientation[4 * i + 1], f.orientation[4 * i + 2],
                            f.orientation[4 * i + 3]);
  };
  const auto v3 = [](const std::vector<double>& v, std::size_t i) {
    return aloft::Vec3<double>(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
  };
  const aloft::RigidBodyState<double> seed{q_at(k), v3(f.state_omega, k)};
  double sb = 0.0, sw = 0.0;
  const auto add = [&](const aloft::Quat<double>& a, const aloft::Quat<double>& b, std::size_t j) {
    const double db = reference_da(short_side(a.conjugate() * b), v3(f.measured_body, j));
    const double dw = reference_da(short_side(b * a.conjugate()), v3(f.measured_world, j));
    sb += db * db;
    sw += dw * dw;
  };
  aloft::RigidBodyState<double> s = seed;
  for (std::size_t j = k; j + 1 < n; ++j) {
    const aloft::Quat<double> before = s.orientation;
    integrator.step_unchecked(s, f.time[j + 1] - f.time[j]);
    add(before, s.orientation, j);
  }
  s = seed;
  for (std::size_t j = k; j-- > 0;) {
    const aloft::Quat<double> after = s.orientation;
    integrator.step_unchecked(s, -(f.time[j + 1] - f.time[j]));
    add(s.orientation, after, j);
  }
  body = std::sqrt(sb / double(n - 1)) * kDegrees;
  world = std::sqrt(sw / double(n - 1)) * kDegrees;
}

double reference_rate(const TestFlight& f, const aloft::InertiaTensor<double>& inertia, std::size_t k) {
  const std::size_t n = f.time.size();
  const auto v3 = [&](std::size_t i) {
    return aloft::Vec3<double>(f.state_omega[3 * i], f.state_omega[3 * i + 1], f.state_omega[3 * i + 2]);
  };
  double sum = 0.0;
  aloft::Vec3<double> w = v3(k);
  for (std::size_t j = k; j + 1 < n; ++j) {
    w = aloft::body_rate_rk4_step(inertia, w, f.time[j + 1] - f.time[j]);
    const double da = reference_da(w, v3(j + 1));
    sum += da * da;
  }
  w = v3(k);
  for (std::size_t j = k; j-- > 0;) {
    w = aloft::body_rate_rk4_step(inertia, w, -(f.time[j + 1] - f.time[j]));
    const double da = reference_da(w, v3(j));
    sum += da * da;
  }
  return std::sqrt(sum / double(n)) * kDegrees;
}

// Tensors a few per cent and degrees off the flight's, one per simulation.
std::vector<aloft::InertiaTensor<double>> perturbed_tensors(const aloft::InertiaTensor<double>& nominal,
                                                            int count) {
  std::vector<aloft::InertiaTensor<double>> out;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < count; ++i) {
    const aloft::Vec3<double> m = nominal.principal_moments().cwiseProduct(
        aloft::Vec3<double>(1 + 0.05 * u(random), 1 + 0.05 * u(random), 1 + 0.05 * u(random)));
    const aloft::Quat<double> axes =
        nominal.principal_axes() *
        aloft::quat_exp(aloft::Vec3<double>(0.1 * u(random), 0.1 * u(random), 0.1 * u(random)));
    aloft::InertiaTensor<double> t;
    REQUIRE(aloft::InertiaTensor<double>::make_from_principal(m, axes, t) == aloft::Status::ok);
    out.push_back(t);
  }
  return out;
}

}  // namespace

TEST_CASE("batched full flights match the scalar reference within 1e-9 degrees", "[batch]") {
  const TestFlight f = make_flight();
  const std::size_t n = f.time.size();
  constexpr int L = aloft::LaneTraits<Lanes>::count;
  const std::vector<aloft::InertiaTensor<double>> tensors = perturbed_tensors(f.inertia, 4 * L);
  // Seeds spread over the flight, the first and last samples included.
  std::vector<aloft::FlightSimulation<double>> sims;
  for (int i = 0; i < 4 * L; ++i) {
    const std::size_t k = i == 0 ? 0 : (i == 1 ? n - 1 : (std::size_t(i) * 97) % n);
    sims.push_back(aloft::flight_simulation(tensors[std::size_t(i)], k));
  }
  for (bool pose : {true, false}) {
    std::vector<aloft::SquaredDeviations<double>> lanes(sims.size()), single(sims.size());
    const aloft::FlightArrays<double> arrays = f.arrays(pose);
    const std::size_t before = aloft_test::heap_allocations();
    for (std::size_t i = 0; i < sims.size(); i += L) {
      aloft::BatchFlight<Lanes>::run(arrays, &sims[i], &lanes[i]);
    }
    for (std::size_t i = 0; i < sims.size(); ++i) {
      aloft::BatchFlight<double>::run(arrays, &sims[i], &single[i]);
    }
    CHECK(aloft_test::heap_allocations() == before);
    for (std::size_t i = 0; i < sims.size(); ++i) {
      const double count = double(lanes[i].comparisons);
      const double body = std::sqrt(lanes[i].body / count) * kDegrees;
      const double world = std::sqrt(lanes[i].world / count) * kDegrees;
      CHECK(lanes[i].comparisons == (pose ? n - 1 : n));
      // One lane or many: the same arithmetic.
      CHECK(std::abs(body - std::sqrt(single[i].body / count) * kDegrees) < 1e-12);
      if (pose) {
        double ref_body = 0.0, ref_world = 0.0;
        reference_pose(f, tensors[i], sims[i].seed_sample, ref_body, ref_world);
        CHECK(body > 0.1);  // a real deviation, not a trivially equal zero
        CHECK(std::abs(body - ref_body) < 1e-9);
        CHECK(std::abs(world - ref_world) < 1e-9);
      } else {
        CHECK(std::abs(body - reference_rate(f, tensors[i], sims[i].seed_sample)) < 1e-9);
      }
    }
  }
}

TEST_CASE("the deviation angle in lanes is within 1e-9 rad of atan2", "[batch]") {
  constexpr int L = aloft::LaneTraits<Lanes>::count;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 100000; ++i) {
    double a[3][L], b[3][L];
    for (int c = 0; c < 3; ++c) {
      for (int l = 0; l < L; ++l) {
        a[c][l] = u(random);
        // Every other vector nearly parallel or anti-parallel to a.
        b[c][l] = (i % 2 == 0) ? u(random) : (i % 4 == 1 ? 1.0 : -1.0) * a[c][l] + 1e-6 * u(random);
      }
    }
    const aloft::LaneVec3<Lanes> va{Lanes::load_unaligned(a[0]), Lanes::load_unaligned(a[1]),
                                    Lanes::load_unaligned(a[2])};
    const aloft::LaneVec3<Lanes> vb{Lanes::load_unaligned(b[0]), Lanes::load_unaligned(b[1]),
                                    Lanes::load_unaligned(b[2])};
    double da[L];
    aloft::lane_deviation_angle(va, vb).store_unaligned(da);
    for (int l = 0; l < L; ++l) {
      const aloft::Vec3<double> x(a[0][l], a[1][l], a[2][l]), y(b[0][l], b[1][l], b[2][l]);
      worst = std::max(worst, std::abs(da[l] - reference_da(x, y)));
    }
  }
  CHECK(worst <= 1e-9);  // the bound
  CHECK(worst < 1e-14);  // what fdlibm's polynomial gives
}
