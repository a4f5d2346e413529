#include "flight_generator.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "aloft/dynamics/inertia_tensor.hpp"
#include "body_catalogue.hpp"
#include "gyro_filter.hpp"
#include "perturbed_rigid_body.hpp"
#include "seeded_random.hpp"

namespace aloft::generator {
namespace {

using nlohmann::json;

constexpr double kPi = SeededRandom::kPi;
constexpr double kDegree = kPi / 180.0;
const Eigen::Vector3d kGravity(0.0, -9.81, 0.0);  // world y up, as OpenSim/Vicon exports

// Independent streams of one seed (splitmix64 of the seed and the stream number), so
// the throw, the effect and the noise never consume each other's draws.
enum class Stream : std::uint64_t { throw_ = 1, effect = 2, noise = 3 };
std::uint64_t stream_seed(std::uint64_t seed, Stream stream) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * static_cast<std::uint64_t>(stream);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

json to_json(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }
json to_json(const Eigen::Quaterniond& q) { return json::array({q.w(), q.x(), q.y(), q.z()}); }
json to_json(const Eigen::Matrix3d& m) {
  json rows = json::array();
  for (int r = 0; r < 3; ++r) rows.push_back(json::array({m(r, 0), m(r, 1), m(r, 2)}));
  return rows;
}

// Principal moments (ascending) and axes (columns, right-handed) as lib/ computes them,
// so "along the nominal principal axes" means what the diagnosis reads from body.json.
struct Principal {
  Eigen::Vector3d moments;
  Eigen::Matrix3d axes;
};
Principal principal_of(const Eigen::Matrix3d& tensor) {
  InertiaTensor<double> inertia;
  if (InertiaTensor<double>::make_from_tensor(tensor, inertia) != Status::ok) {
    throw std::logic_error("generator body has an invalid inertia tensor");
  }
  return {inertia.principal_moments(), inertia.principal_axes().toRotationMatrix()};
}

// The throw: everything about a flight that does not depend on the effect.
struct Throw {
  double duration_s = 1.0;
  Eigen::Vector3d omega0_body;
  Eigen::Quaterniond orientation0;
  Eigen::Vector3d com0_m;
  Eigen::Vector3d velocity0_m_s;
  std::vector<Eigen::Vector3d> markers_m;  // body axes
  // A rotor spun up after release (FlightSpec::rotor_spin_up): this throw's profile.
  double spin_up_start_s = 0.0, spin_up_time_constant_s = 0.0, spin_up_speed = 1.0;
};

Throw draw_throw(const BodyModel& body, const FlightSpec& spec, SeededRandom& rng) {
  Throw t;
  t.duration_s = spec.duration_s > 0.0 ? spec.duration_s : rng.uniform(0.8, 1.2);
  // Generic spin axis: >= 20° from each principal axis, so every effect has a lever.
  const Principal p = principal_of(body.inertia_kg_m2);
  Eigen::Vector3d axis;
  for (;;) {
    axis = rng.unit_vector();
    bool generic = true;
    for (int i = 0; i < 3; ++i)
      generic = generic && std::abs(axis.dot(p.axes.col(i))) <= std::cos(20 * kDegree);
    if (generic) break;
  }
  t.omega0_body = rng.uniform(5.0, 15.0) * axis;
  Eigen::Vector4d q;
  do {
    q = Eigen::Vector4d(rng.normal(), rng.normal(), rng.normal(), rng.normal());
  } while (q.norm() < 1e-6);
  q.normalize();
  t.orientation0 = Eigen::Quaterniond(q(0), q(1), q(2), q(3));  // uniform on SO(3)
  t.com0_m = Eigen::Vector3d(rng.uniform(-0.1, 0.1), rng.uniform(0.9, 1.2), rng.uniform(-0.1, 0.1));
  t.velocity0_m_s = Eigen::Vector3d(rng.uniform(1.5, 3.0), rng.uniform(2.5, 4.5), rng.uniform(-1.5, 1.5));
  // Six markers on the body's surface ellipsoid, spread out (no two within 40 % of the
  // mean semi-axis), as a marker set is designed for a well-conditioned pose fit.
  const double min_gap = 0.4 * body.marker_semi_axes_m.mean();
  while (t.markers_m.size() < 6) {
    const Eigen::Vector3d m = body.marker_semi_axes_m.cwiseProduct(rng.unit_vector());
    bool spread = true;
    for (const auto& other : t.markers_m) spread = spread && (m - other).norm() >= min_gap;
    if (spread) t.markers_m.push_back(m);
  }
  // Drawn last, and only for a spun-up rotor, so that every other throw keeps its draws.
  if (spec.rotor_spin_up) {
    t.spin_up_start_s = rng.uniform(spec.spin_up_start_low_s, spec.spin_up_start_high_s);
    t.spin_up_time_constant_s =
        rng.uniform(spec.spin_up_time_constant_low_s, spec.spin_up_time_constant_high_s);
    t.spin_up_speed = 1.0 + rng.uniform(-spec.spin_up_speed_spread, spec.spin_up_speed_spread);
  }
  return t;
}

// A rotation of angle in [3°, 15°] about a random axis; normal to the symmetry axis
// for a body of revolution (a turn about that axis is unobservable).
Eigen::Quaterniond draw_misrotation(const Principal& p, SeededRandom& rng) {
  const double angle = rng.uniform(3.0, 15.0) * kDegree;
  Eigen::Vector3d axis = rng.unit_vector();
  const int symmetry = symmetry_axis_index(p.moments);
  if (symmetry >= 0) {
    const Eigen::Vector3d e = p.axes.col(symmetry);
    while ((axis - axis.dot(e) * e).norm() < 0.1) axis = rng.unit_vector();
    axis = (axis - axis.dot(e) * e).normalized();
  }
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis));
}

double rotation_angle_deg(const Eigen::Quaterniond& q) {
  return 2.0 * std::atan2(q.vec().norm(), std::abs(q.w())) / kDegree;
}

// Fraction of kinetic energy a rotor of relaxation time `relaxation_s` takes out of
// this throw by its end.
double energy_loss(FlightPhysics physics, const Throw& thrown, double relaxation_s) {
  physics.rotor_damping_N_m_s = physics.rotor_inertia_kg_m2 / relaxation_s;
  const PerturbedRigidBody body(physics);
  FlightState start;
  start.omega_body = thrown.omega0_body;
  start.rotor_omega_body = thrown.omega0_body;
  const FlightState end = body.sample(start, {thrown.duration_s}, 2e-4).back();
  return 1.0 - body.kinetic_energy(end) / body.kinetic_energy(start);
}

// The rotor's relaxation time J/c that takes `target` of the energy out over the
// flight: the smallest on [10, 500] ms (the loss rises with it, peaks where it matches
// the rate at which the body rate turns in the body, then falls), found on a log grid
// and refined by bisection; the time of the largest loss when the throw cannot reach
// the target (a slowly precessing, near-symmetric body).
double relaxation_for_energy_loss(const FlightPhysics& physics, const Throw& thrown, double target,
                                  bool& reached) {
  reached = true;
  constexpr int kGrid = 13;
  double previous = 0.0, best = 0.0, best_loss = -1.0;
  for (int i = 0; i < kGrid; ++i) {
    const double tau = 0.01 * std::pow(50.0, double(i) / (kGrid - 1));
    const double loss = energy_loss(physics, thrown, tau);
    if (loss >= target) {
      double low = previous > 0.0 ? previous : tau / 2, high = tau;
      for (int b = 0; b < 30; ++b) {
        const double mid = std::sqrt(low * high);
        (energy_loss(physics, thrown, mid) < target ? low : high) = mid;
      }
      return high;
    }
    if (loss > best_loss) {
      best_loss = loss;
      best = tau;
    }
    previous = tau;
  }
  reached = false;
  return best;
}

// The injected effect: the true physics and sensor, and the params of SPEC §4.
struct InjectedEffect {
  FlightPhysics physics;
  Eigen::Quaterniond imu_to_body = Eigen::Quaterniond::Identity();
  Eigen::Vector3d bias = Eigen::Vector3d::Zero();
  Eigen::Vector3d scale_error = Eigen::Vector3d::Zero();
  double rate_error = 0.0;
  json params = json::object();
  std::optional<double> onset_s;
  bool full_size = true;  // false: this throw cannot show the drawn magnitude
};

// Each principal moment off by 5-20 % (random sign), rescaled to the nominal sum, until
// one is off by >= 5 % and the body stays physical.
Eigen::Vector3d draw_wrong_moments(const Principal& p, const BodyModel& body, SeededRandom& rng) {
  Eigen::Vector3d moments;
  for (int attempt = 0;; ++attempt) {
    if (attempt > 10000) throw std::logic_error("no valid moment perturbation for " + body.name);
    for (int i = 0; i < 3; ++i) moments(i) = p.moments(i) * (1.0 + rng.signed_uniform(0.05, 0.20));
    moments *= p.moments.sum() / moments.sum();
    const double largest_change = (moments.cwiseQuotient(p.moments).array() - 1.0).abs().maxCoeff();
    // Keep 0.5 % of slack on the triangle inequality so the body stays physical.
    const double slack = 0.005 * moments.sum();
    const bool physical = moments(0) + slack <= moments(1) + moments(2) &&
                          moments(1) + slack <= moments(0) + moments(2) &&
                          moments(2) + slack <= moments(0) + moments(1);
    if (largest_change >= 0.05 && physical) return moments;
  }
}

// The effects that live in the sensor model (is_sensor_effect): the physics stays nominal.
void draw_sensor_effect(const std::string& effect, const Principal& p, SeededRandom& rng, InjectedEffect& e) {
  if (effect == "gyro_bias") {
    e.bias = rng.uniform(0.05, 0.3) * rng.unit_vector();
    e.params = {{"bias_rad_s", to_json(e.bias)}};
  } else if (effect == "gyro_scale") {
    do {
      for (int i = 0; i < 3; ++i) e.scale_error(i) = rng.signed_uniform(0.02, 0.08);
    } while (e.scale_error.maxCoeff() - e.scale_error.minCoeff() < 0.03);
    e.params = {{"scale_error", to_json(e.scale_error)}};
  } else if (effect == "sensor_misalignment") {
    e.imu_to_body = draw_misrotation(p, rng);
    e.params = {{"angle_deg", rotation_angle_deg(e.imu_to_body)}, {"rotation", to_json(e.imu_to_body)}};
  } else if (effect == "clock_drift") {
    e.rate_error = rng.signed_uniform(0.01, 0.05);
    e.params = {{"rate_error", e.rate_error}};
  }
}

InjectedEffect draw_effect(const std::string& effect, const BodyModel& body, const Throw& thrown,
                           const FlightSpec& spec, SeededRandom& rng) {
  InjectedEffect e;
  const Eigen::Matrix3d& nominal = body.inertia_kg_m2;
  e.physics.inertia_kg_m2 = nominal;
  const Principal p = principal_of(nominal);
  const Eigen::Vector3d w0 = thrown.omega0_body;
  const Eigen::Vector3d l0 = nominal * w0;
  const double energy0 = 0.5 * w0.dot(l0);

  if (effect == "none") {
  } else if (is_sensor_effect(effect)) {
    draw_sensor_effect(effect, p, rng, e);
  } else if (effect == "inertia_moments") {
    const Eigen::Vector3d moments = draw_wrong_moments(p, body, rng);
    e.physics.inertia_kg_m2 = p.axes * moments.asDiagonal() * p.axes.transpose();
    e.params = {{"principal_kg_m2", to_json(moments)},
                {"principal_nominal_kg_m2", to_json(p.moments)},
                {"tensor_kg_m2", to_json(e.physics.inertia_kg_m2)}};
  } else if (effect == "inertia_axes") {
    const Eigen::Quaterniond r = draw_misrotation(p, rng);
    const Eigen::Matrix3d rm = r.toRotationMatrix();
    e.physics.inertia_kg_m2 = rm * nominal * rm.transpose();
    e.params = {{"angle_deg", rotation_angle_deg(r)},
                {"rotation", to_json(r)},
                {"tensor_kg_m2", to_json(e.physics.inertia_kg_m2)}};
  } else if (effect == "aero_torque") {
    // d ln|L|/dt = -k |w| 2E / |L|² at release: pick k for a 4-12 % fall of |L|.
    const double fall = rng.uniform(0.04, 0.12);
    e.physics.aero_k_N_m_s2 = fall * l0.squaredNorm() / (thrown.duration_s * w0.norm() * 2.0 * energy0);
    e.params = {{"k_N_m_s2", e.physics.aero_k_N_m_s2}};
  } else if (effect == "internal_damping") {
    e.physics.rotor_inertia_kg_m2 = rng.uniform(0.08, 0.15) * p.moments(0);
    const double relaxation =
        relaxation_for_energy_loss(e.physics, thrown, rng.uniform(0.015, 0.06), e.full_size);
    e.physics.rotor_damping_N_m_s = e.physics.rotor_inertia_kg_m2 / relaxation;
    e.params = {{"model", "spherical_rotor_viscous_cavity"},
                {"rotor_J", e.physics.rotor_inertia_kg_m2},
                {"c", e.physics.rotor_damping_N_m_s},
                {"relaxation_time_s", relaxation}};
  } else if (effect == "impulse") {
    const double fraction = rng.uniform(0.05, 0.20);
    e.physics.has_impulse = true;
    e.physics.angular_impulse_N_m_s = fraction * l0.norm() * rng.unit_vector();
    e.physics.impulse_time_s = rng.uniform(0.3, 0.7) * thrown.duration_s;
    e.physics.impulse_duration_s = spec.impulse_duration_s;
    e.onset_s = e.physics.impulse_time_s;
    e.params = {{"time_s", e.physics.impulse_time_s},
                {"angular_impulse_N_m_s", to_json(e.physics.angular_impulse_N_m_s)},
                {"duration_s", e.physics.impulse_duration_s}};
  } else if (effect == "internal_momentum") {
    const double typical_l = p.moments.mean() * 10.0;
    const Eigen::Vector3d h =
        rng.uniform(spec.rotor_fraction_low, spec.rotor_fraction_high) * typical_l * rng.unit_vector();
    if (spec.rotor_spin_up) {
      e.physics.spin_up = {thrown.spin_up_speed * h, thrown.spin_up_start_s, thrown.spin_up_time_constant_s,
                           spec.spin_up_shape, 3.0 * thrown.spin_up_time_constant_s};
      const Eigen::Vector3d at_end = e.physics.spin_up.momentum(thrown.duration_s);
      e.params = {{"h_N_m_s", to_json(at_end)},
                  {"final_h_N_m_s", to_json(e.physics.spin_up.final_momentum_N_m_s)},
                  {"start_s", thrown.spin_up_start_s},
                  {"time_constant_s", thrown.spin_up_time_constant_s},
                  {"shape", spin_up_shape_name(spec.spin_up_shape)},
                  {"h_fraction_of_L", at_end.norm() / l0.norm()}};
      if (spec.spin_up_shape != SpinUpShape::first_order) e.params["rise_s"] = e.physics.spin_up.rise_s;
    } else {
      e.physics.internal_momentum_N_m_s = h;
      e.params = {{"h_N_m_s", to_json(h)}, {"h_fraction_of_L", h.norm() / l0.norm()}};
    }
  } else {
    throw std::invalid_argument("unknown effect '" + effect + "'");
  }
  return e;
}

// `scale_mimics_moments`: the gyro's axes are the body's principal axes and the three
// moments differ, where a non-uniform gyro scale reproduces wrong moments that keep their
// order exactly (not the reverse; and never on a body of revolution).
std::vector<std::string> equivalent_class(const std::string& effect, DataKind kind,
                                          bool scale_mimics_moments = false) {
  std::vector<std::string> out = {effect};
  if (kind == DataKind::imu) {
    if (effect == "inertia_moments" && scale_mimics_moments) out.push_back("gyro_scale");
    if (effect == "inertia_axes") out.push_back("sensor_misalignment");
    if (effect == "sensor_misalignment") out.push_back("inertia_axes");
    if (effect == "clock_drift") out.push_back("gyro_scale");
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Runs a gyro's low-pass over the motion before release, so that at release it is in the
// steady state of a gyro that has been running (not settled on one rate, whose transient
// would look like an impulse at the start): the flight's own dynamics backwards in time,
// 10 / cutoff seconds of it. Backwards, w(-t) = -u(t) where u obeys the same equations with
// -h; only the torque-free body and the rotor are reversed (drag, damping and an impulse
// act later in the flight, or change so little over the pre-roll that the filter does not
// see it).
template <typename Reading>
void settle_on_motion_before(GyroFilter& filter, const FlightPhysics& physics, const Eigen::Vector3d& omega0,
                             double cutoff_hz, double rate_hz, const Reading& reading) {
  FlightPhysics backwards;
  backwards.inertia_kg_m2 = physics.inertia_kg_m2;
  backwards.internal_momentum_N_m_s = -physics.internal_momentum_N_m_s;
  const int samples = static_cast<int>(std::ceil(10.0 / cutoff_hz * rate_hz));
  std::vector<double> times;
  for (int k = samples; k >= 1; --k) times.push_back(k / rate_hz);
  std::reverse(times.begin(), times.end());
  FlightState start;
  start.omega_body = -omega0;
  const std::vector<FlightState> before = PerturbedRigidBody(backwards).sample(start, times);
  filter.settle(reading(-before.back().omega_body));
  for (std::size_t k = before.size(); k-- > 0;) filter(reading(-before[k].omega_body));
}

// A rotor along a body of revolution's axis is, within one flight, an axial moment
// changed by h / w_axis (docs/diagnose.md, "A rotor inside"); within 15° of the axis its
// transverse part stays below a quarter of |h|.
bool rotor_along_symmetry_axis(const Principal& p, const FlightPhysics& physics) {
  const int symmetry = symmetry_axis_index(p.moments);
  const Eigen::Vector3d h = physics.internal_momentum_N_m_s + physics.spin_up.final_momentum_N_m_s;
  if (symmetry < 0 || h.norm() == 0.0) return false;
  return std::abs(h.normalized().dot(p.axes.col(symmetry))) >= std::cos(15.0 * kDegree);
}

std::string nominal_body_json(const BodyModel& body, const Throw& thrown, DataKind kind) {
  json j = {
      {"name", body.name}, {"mass", body.mass_kg}, {"inertia", {{"tensor", to_json(body.inertia_kg_m2)}}}};
  if (kind == DataKind::markers) {
    json markers = json::object();
    for (std::size_t i = 0; i < thrown.markers_m.size(); ++i) {
      markers["M" + std::to_string(i + 1)] = to_json(thrown.markers_m[i]);
    }
    j["markers"] = markers;
  }
  return j.dump(2) + "\n";
}

// Two effects at once (FlightSpec::second_effect): the second's physics and sensor
// model are laid over the first's. Only a rotation of the axes acts on a tensor the
// first effect already changed (moments), and it turns that tensor.
InjectedEffect combine(InjectedEffect first, const InjectedEffect& second, const std::string& second_name,
                       const Eigen::Matrix3d& nominal) {
  if (second_name == "inertia_axes") {
    const Eigen::Matrix3d r = Eigen::Quaterniond(second.params["rotation"][0].get<double>(),
                                                 second.params["rotation"][1].get<double>(),
                                                 second.params["rotation"][2].get<double>(),
                                                 second.params["rotation"][3].get<double>())
                                  .toRotationMatrix();
    first.physics.inertia_kg_m2 = r * first.physics.inertia_kg_m2 * r.transpose();
  } else if (!second.physics.inertia_kg_m2.isApprox(nominal)) {
    first.physics.inertia_kg_m2 = second.physics.inertia_kg_m2;
  }
  first.physics.aero_k_N_m_s2 += second.physics.aero_k_N_m_s2;
  first.physics.internal_momentum_N_m_s += second.physics.internal_momentum_N_m_s;
  if (second.physics.spin_up.present()) first.physics.spin_up = second.physics.spin_up;
  if (second.physics.rotor_inertia_kg_m2 > 0.0) {
    first.physics.rotor_inertia_kg_m2 = second.physics.rotor_inertia_kg_m2;
    first.physics.rotor_damping_N_m_s = second.physics.rotor_damping_N_m_s;
  }
  if (second.physics.has_impulse) {
    first.physics.has_impulse = true;
    first.physics.impulse_time_s = second.physics.impulse_time_s;
    first.physics.impulse_duration_s = second.physics.impulse_duration_s;
    first.physics.angular_impulse_N_m_s = second.physics.angular_impulse_N_m_s;
    first.onset_s = second.onset_s;
  }
  first.imu_to_body = first.imu_to_body * second.imu_to_body;
  first.bias += second.bias;
  first.scale_error += second.scale_error;
  first.rate_error += second.rate_error;
  first.full_size = first.full_size && second.full_size;
  return first;
}

// A blow from outside that gives angular impulse L acts at a point c of the surface with
// a linear impulse P, c x P = L: c is taken on the marker ellipsoid, perpendicular to L
// (no draw: the flights stay as they were), and P = (L x c) / |c|^2. Over the pulse the
// centre of mass then accelerates by P/m times the torque's half-sine profile, which the
// accelerometer reads. Zero outside the pulse and for an instantaneous impulse.
Eigen::Vector3d blow_acceleration(const FlightPhysics& physics, const BodyModel& body, double t) {
  const double d = physics.impulse_duration_s;
  if (!physics.has_impulse || !(d > 0.0)) return Eigen::Vector3d::Zero();
  const double u = (t - physics.impulse_time_s) / d;
  if (u < 0.0 || u > 1.0) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d& L = physics.angular_impulse_N_m_s;
  if (!(L.norm() > 0.0)) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d l = L.normalized();
  Eigen::Index least = 0;
  l.cwiseAbs().minCoeff(&least);
  const Eigen::Vector3d e = Eigen::Vector3d::Unit(least);
  const Eigen::Vector3d dir = (e - e.dot(l) * l).normalized();
  const Eigen::Vector3d c = dir / dir.cwiseQuotient(body.marker_semi_axes_m).norm();
  const Eigen::Vector3d P = L.cross(c) / c.squaredNorm();
  return P / body.mass_kg * (kPi / (2.0 * d)) * std::sin(kPi * u);
}

void check_spec(const FlightSpec& spec) {
  if (!known_effect(spec.effect)) throw std::invalid_argument("unknown effect '" + spec.effect + "'");
  if (!spec.second_effect.empty() && !known_effect(spec.second_effect)) {
    throw std::invalid_argument("unknown effect '" + spec.second_effect + "'");
  }
  if (spec.data == DataKind::markers &&
      (is_sensor_effect(spec.effect) || is_sensor_effect(spec.second_effect))) {
    throw std::invalid_argument("sensor effect '" + spec.effect + "' needs IMU data");
  }
}

bool is_compound(const FlightSpec& spec) {
  return !spec.second_effect.empty() && spec.second_effect != "none";
}

// The spec's effect (and its second one, laid over it) drawn for `thrown`.
InjectedEffect draw_effects(const FlightSpec& spec, const BodyModel& body, const Throw& thrown,
                            SeededRandom& effect_rng) {
  InjectedEffect e = draw_effect(spec.effect, body, thrown, spec, effect_rng);
  if (!is_compound(spec)) return e;
  const InjectedEffect second = draw_effect(spec.second_effect, body, thrown, spec, effect_rng);
  json both = json::object();
  both[spec.effect] = e.params;
  both[spec.second_effect] = second.params;
  e = combine(e, second, spec.second_effect, body.inertia_kg_m2);
  e.params = both;
  return e;
}

struct ThrownEffect {
  Throw thrown;
  InjectedEffect effect;
};

ThrownEffect draw_throw_and_effects(const FlightSpec& spec, const BodyModel& body, SeededRandom& throw_rng,
                                    SeededRandom& effect_rng) {
  ThrownEffect out;
  out.thrown = draw_throw(body, spec, throw_rng);
  out.effect = draw_effects(spec, body, out.thrown, effect_rng);
  // Internal damping shows only when the body rate turns within the body fast enough;
  // a throw that cannot lose the drawn energy fraction is thrown again (up to 20
  // times: a near-symmetric body may never manage, and then keeps its last throw).
  for (int retry = 0; !out.effect.full_size && retry < 20; ++retry) {
    out.thrown = draw_throw(body, spec, throw_rng);
    out.effect = draw_effects(spec, body, out.thrown, effect_rng);
  }
  return out;
}

// The flight as it truly went, at each data sample.
struct TrueFlight {
  std::vector<double> recorded_s;  // on the sensor's clock: recorded = true × (1 + eps)
  std::vector<double> true_s;
  std::vector<FlightState> states;
};

TrueFlight fly(const FlightSpec& spec, const Throw& thrown, const InjectedEffect& effect,
               const PerturbedRigidBody& dynamics) {
  TrueFlight flight;
  const double rate = spec.data == DataKind::imu ? spec.imu_rate_hz : spec.marker_rate_hz;
  const int count = static_cast<int>(std::floor(thrown.duration_s * rate + 1e-9)) + 1;
  flight.recorded_s.resize(static_cast<std::size_t>(count));
  flight.true_s.resize(flight.recorded_s.size());
  for (int k = 0; k < count; ++k) {
    flight.recorded_s[std::size_t(k)] = k / rate;
    flight.true_s[std::size_t(k)] = flight.recorded_s[std::size_t(k)] / (1.0 + effect.rate_error);
  }
  FlightState initial;
  initial.orientation = thrown.orientation0;
  initial.omega_body = thrown.omega0_body;
  initial.rotor_omega_body = thrown.omega0_body;  // the rotor co-rotates at release
  flight.states = dynamics.sample(initial, flight.true_s);
  return flight;
}

std::vector<TrueSample> true_samples_of(const FlightSpec& spec, const Throw& thrown, const TrueFlight& flight,
                                        const PerturbedRigidBody& dynamics) {
  std::vector<TrueSample> samples(flight.states.size());
  for (std::size_t k = 0; k < flight.states.size(); ++k) {
    TrueSample& s = samples[k];
    const FlightState& state = flight.states[k];
    s.t_s = flight.true_s[k];
    s.orientation = state.orientation;
    s.omega_body = state.omega_body;
    s.kinetic_energy_J = dynamics.kinetic_energy(state);
    s.angular_momentum_world = state.orientation * dynamics.angular_momentum(state, s.t_s);
    if (spec.data == DataKind::markers) {
      s.com_position_m = thrown.com0_m + thrown.velocity0_m_s * s.t_s + 0.5 * kGravity * s.t_s * s.t_s;
    }
  }
  return samples;
}

// How big the dissipative effects turned out, from the truth, for reports and tests.
void add_dissipation_measured(const FlightSpec& spec, const std::vector<TrueSample>& samples, json& params) {
  if (is_compound(spec)) return;
  if (spec.effect == "aero_torque") {
    params["L_drop_fraction"] =
        1.0 - samples.back().angular_momentum_world.norm() / samples.front().angular_momentum_world.norm();
  }
  if (spec.effect == "internal_damping") {
    params["energy_loss_fraction"] = 1.0 - samples.back().kinetic_energy_J / samples.front().kinetic_energy_J;
  }
}

// Readings per independent sample of white noise behind the spec's filter: (sum h)^2 /
// sum h^2 of its impulse response, summed until the response has died away (40 time
// constants of the cutoff).
double filter_correlation(const FlightSpec& spec) {
  if (!(spec.gyro_cutoff_hz > 0.0)) return 1.0;
  GyroFilter filter = gyro_filter_of(spec);
  const int steps = static_cast<int>(std::ceil(40.0 * spec.imu_rate_hz / spec.gyro_cutoff_hz)) + 10;
  double sum = 0.0, squares = 0.0;
  for (int k = 0; k < steps; ++k) {
    const double h = filter(Eigen::Vector3d(k == 0 ? 1.0 : 0.0, 0.0, 0.0)).x();
    sum += h;
    squares += h * h;
  }
  return sum * sum / squares;
}

// The gyro's readings in sensor axes, low-passed if the spec says so, with their noise,
// quantised if it says so; returns the spread of the noise as it is in the readings
// (quantisation included).
Eigen::Vector3d record_gyro(const FlightSpec& spec, const Throw& thrown, const InjectedEffect& effect,
                            const TrueFlight& flight, SeededRandom& noise_rng, host::ImuLog& log) {
  const Eigen::Matrix3d body_to_sensor = effect.imu_to_body.conjugate().toRotationMatrix();
  const Eigen::Vector3d gain = Eigen::Vector3d::Ones() + effect.scale_error;
  // The filter is linear: the readings' noise is the filtered noise sequence, kept
  // apart to measure its spread; filtering reading and noise separately adds up to
  // filtering their sum.
  GyroFilter signal_filter = gyro_filter_of(spec), noise_filter = gyro_filter_of(spec);
  if (spec.gyro_cutoff_hz > 0.0) {
    settle_on_motion_before(
        signal_filter, effect.physics, thrown.omega0_body, spec.gyro_cutoff_hz, spec.imu_rate_hz,
        [&](const Eigen::Vector3d& w) { return gain.cwiseProduct(body_to_sensor * w) + effect.bias; });
  }
  Eigen::Vector3d noise_squares = Eigen::Vector3d::Zero();
  for (const FlightState& state : flight.states) {
    const Eigen::Vector3d w_sensor = body_to_sensor * state.omega_body;
    Eigen::Vector3d reading = gain.cwiseProduct(w_sensor) + effect.bias;
    Eigen::Vector3d noise = noise_rng.normal_vector(spec.gyro_noise_rad_s);
    if (spec.gyro_cutoff_hz > 0.0) {
      reading = signal_filter(reading);
      noise = noise_filter(noise);
    }
    const Eigen::Vector3d logged = quantised_reading(spec, reading + noise);
    if (spec.gyro_quantum_rad_s > 0.0) noise = logged - reading;
    noise_squares += noise.cwiseAbs2();
    log.gyro_rad_s.push_back(logged);
  }
  return (noise_squares / static_cast<double>(flight.states.size())).cwiseSqrt();
}

// Free fall: the specific force at the sensor is only its acceleration relative to the
// centre of mass, w' × r + w × (w × r) (aerodynamic force neglected), and an impulse's blow.
void record_accelerometer(const FlightSpec& spec, const BodyModel& body, const InjectedEffect& effect,
                          const TrueFlight& flight, const PerturbedRigidBody& dynamics,
                          SeededRandom& noise_rng, host::ImuLog& log) {
  const Eigen::Matrix3d body_to_sensor = effect.imu_to_body.conjugate().toRotationMatrix();
  const Eigen::Vector3d& r = body.imu_offset_m;
  for (std::size_t k = 0; k < flight.states.size(); ++k) {
    const Eigen::Vector3d& w = flight.states[k].omega_body;
    const Eigen::Vector3d w_dot = dynamics.shell_angular_acceleration(flight.true_s[k], flight.states[k]);
    const Eigen::Vector3d a =
        w_dot.cross(r) + w.cross(w.cross(r)) + blow_acceleration(effect.physics, body, flight.true_s[k]);
    log.accel_m_s2.push_back(body_to_sensor * a + noise_rng.normal_vector(spec.accel_noise_m_s2));
  }
}

// Now and then one marker drops out for a few frames; never two at once, so at least
// five markers are always visible.
void occlude_markers(int marker_count, SeededRandom& noise_rng, host::MarkerTrial& trial) {
  const int count = static_cast<int>(trial.positions_m.size());
  std::vector<bool> busy(trial.positions_m.size(), false);
  const int events = noise_rng.index(4);
  for (int e = 0; e < events; ++e) {
    const int marker = noise_rng.index(marker_count);
    const int length = 2 + noise_rng.index(5);
    const int start = noise_rng.index(count - length);
    bool free = true;
    for (int k = start; k < start + length; ++k) free = free && !busy[std::size_t(k)];
    if (!free) continue;
    for (int k = start; k < start + length; ++k) {
      busy[std::size_t(k)] = true;
      trial.positions_m[std::size_t(k)][std::size_t(marker)].setConstant(
          std::numeric_limits<double>::quiet_NaN());
    }
  }
}

void record_markers(const FlightSpec& spec, const Throw& thrown, const TrueFlight& flight,
                    const std::vector<TrueSample>& samples, SeededRandom& noise_rng,
                    host::MarkerTrial& trial) {
  trial.path = "markers.trc";
  trial.format = "trc";
  trial.units_in_file = "mm";
  trial.rate_hz = spec.marker_rate_hz;
  trial.time_s = flight.recorded_s;
  for (std::size_t i = 0; i < thrown.markers_m.size(); ++i) {
    trial.marker_names.push_back("M" + std::to_string(i + 1));
  }
  for (std::size_t k = 0; k < flight.states.size(); ++k) {
    std::vector<Eigen::Vector3d> frame;
    const Eigen::Matrix3d r = flight.states[k].orientation.toRotationMatrix();
    for (const auto& m : thrown.markers_m) {
      frame.push_back(samples[k].com_position_m + r * m + noise_rng.normal_vector(spec.marker_noise_m));
    }
    trial.positions_m.push_back(frame);
  }
  if (spec.occlusions) occlude_markers(static_cast<int>(thrown.markers_m.size()), noise_rng, trial);
}

FlightTruth truth_of(const FlightSpec& spec, const BodyModel& body, const Throw& thrown,
                     const InjectedEffect& effect) {
  FlightTruth t;
  t.effect = spec.effect;
  const Principal principal = principal_of(body.inertia_kg_m2);
  const bool aligned = principal.axes.cwiseAbs().isApprox(Eigen::Matrix3d::Identity(), 1e-9) ||
                       (principal.axes.cwiseAbs().array() > 1.0 - 1e-9).count() == 3;
  const bool distinct = symmetry_axis_index(principal.moments, 1e-6) < 0 &&
                        principal.moments(2) - principal.moments(0) > 1e-6 * principal.moments(2);
  const bool mimics =
      aligned && distinct && effect.imu_to_body.angularDistance(Eigen::Quaterniond::Identity()) < 1e-12;
  t.equivalent = equivalent_class(spec.effect, spec.data, mimics);
  if (spec.effect == "internal_momentum" && rotor_along_symmetry_axis(principal, effect.physics)) {
    t.equivalent.push_back("inertia_moments");
    std::sort(t.equivalent.begin(), t.equivalent.end());
  }
  t.effects = {spec.effect};
  t.equivalents = {t.equivalent};
  if (is_compound(spec)) {
    t.effects.push_back(spec.second_effect);
    t.equivalents.push_back(equivalent_class(spec.second_effect, spec.data, mimics));
  }
  t.params = effect.params;
  t.onset_s = effect.onset_s;
  t.omega0_body = thrown.omega0_body;
  t.body = body.name;
  t.kind = spec.data;
  t.duration_s = thrown.duration_s;
  return t;
}

}  // namespace

GyroFilter gyro_filter_of(const FlightSpec& spec) {
  return GyroFilter(spec.gyro_filter_order, spec.gyro_cutoff_hz, 1.0 / spec.imu_rate_hz, spec.gyro_pt1_stages,
                    spec.gyro_later_stage_ratio);
}

Eigen::Vector3d quantised_reading(const FlightSpec& spec, const Eigen::Vector3d& reading) {
  const double q = spec.gyro_quantum_rad_s;
  return q > 0.0 ? Eigen::Vector3d((reading / q).array().round().matrix() * q) : reading;
}

const std::vector<std::string>& effect_names() {
  static const std::vector<std::string> names = {
      "none",    "inertia_moments", "inertia_axes", "aero_torque",         "internal_damping",
      "impulse", "gyro_bias",       "gyro_scale",   "sensor_misalignment", "clock_drift"};
  return names;
}

bool known_effect(const std::string& effect) {
  const auto& names = effect_names();
  return effect == "internal_momentum" || std::find(names.begin(), names.end(), effect) != names.end();
}

bool is_sensor_effect(const std::string& effect) {
  return effect == "gyro_bias" || effect == "gyro_scale" || effect == "sensor_misalignment" ||
         effect == "clock_drift";
}

const char* to_string(DataKind kind) { return kind == DataKind::imu ? "imu" : "mocap"; }

GeneratedFlight generate_flight(const FlightSpec& spec, std::uint64_t seed) {
  check_spec(spec);
  const BodyModel body = body_model(spec.body);

  const std::uint64_t throw_seed = spec.throw_seed != 0 ? spec.throw_seed : seed;
  SeededRandom throw_rng(stream_seed(throw_seed, Stream::throw_));
  SeededRandom effect_rng(stream_seed(seed, Stream::effect));
  SeededRandom noise_rng(stream_seed(throw_seed, Stream::noise));
  ThrownEffect drawn = draw_throw_and_effects(spec, body, throw_rng, effect_rng);
  const Throw& thrown = drawn.thrown;
  InjectedEffect& effect = drawn.effect;

  GeneratedFlight f;
  f.spec = spec;
  f.seed = seed;
  f.body_json = nominal_body_json(body, thrown, spec.data);
  f.body = host::parse_body_json(f.body_json, body.name + " (generated body.json)");
  f.true_inertia_kg_m2 = effect.physics.inertia_kg_m2;
  f.true_imu_to_body = effect.imu_to_body;

  const PerturbedRigidBody dynamics(effect.physics);
  const TrueFlight flight = fly(spec, thrown, effect, dynamics);
  f.true_samples = true_samples_of(spec, thrown, flight, dynamics);
  add_dissipation_measured(spec, f.true_samples, effect.params);

  if (spec.data == DataKind::imu) {
    f.imu.path = "imu.csv";
    f.imu.format = "imu_csv";
    f.imu.time_s = flight.recorded_s;
    f.gyro_noise_in_readings_rad_s = record_gyro(spec, thrown, effect, flight, noise_rng, f.imu);
    f.gyro_noise_correlation = filter_correlation(spec);
    if (spec.accelerometer) record_accelerometer(spec, body, effect, flight, dynamics, noise_rng, f.imu);
  } else {
    record_markers(spec, thrown, flight, f.true_samples, noise_rng, f.markers);
  }
  f.truth = truth_of(spec, body, thrown, effect);
  return f;
}

json truth_to_json(const FlightTruth& truth) {
  json j = {{"kind", to_string(truth.kind)},    {"body", truth.body},     {"duration_s", truth.duration_s},
            {"w0", to_json(truth.omega0_body)}, {"effect", truth.effect}, {"params", truth.params},
            {"equivalent", truth.equivalent}};
  if (truth.onset_s) j["onset_s"] = *truth.onset_s;
  if (truth.effects.size() > 1) {
    j["effects"] = truth.effects;
    j["equivalents"] = truth.equivalents;
  }
  return j;
}

}  // namespace aloft::generator
