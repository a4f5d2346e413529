// diagnose/effect_descriptor: every registered effect is described completely, under its
// SPEC §4 name and `params` keys, and its model hook does what its descriptor claims.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/2_model/flight_model.hpp"
#include "diagnose/2_model/spin_up_profile.hpp"
#include "diagnose/6_report/effect_words.hpp"

using namespace aloft::host::diagnose;

namespace {

// SPEC §4: each effect's fixed name, whether it describes the sensor, and the required
// `params` keys; written out here, apart from the registry, so that a descriptor under the
// wrong name or of the wrong kind shows.
struct SpecEffect {
  Effect effect;
  std::string name;
  bool sensor;
  std::vector<std::string> keys;
};
const std::vector<SpecEffect> kSpec = {
    {Effect::none, "none", false, {}},
    {Effect::inertia_moments, "inertia_moments", false, {"principal_kg_m2"}},
    {Effect::inertia_axes, "inertia_axes", false, {"angle_deg", "rotation"}},
    {Effect::aero_torque, "aero_torque", false, {"k_N_m_s2"}},
    {Effect::internal_damping, "internal_damping", false, {}},  // model-specific
    {Effect::impulse, "impulse", false, {"time_s", "angular_impulse_N_m_s"}},
    {Effect::gyro_bias, "gyro_bias", true, {"bias_rad_s"}},
    {Effect::gyro_scale, "gyro_scale", true, {"scale_error"}},
    {Effect::sensor_misalignment, "sensor_misalignment", true, {"angle_deg", "rotation"}},
    {Effect::clock_drift, "clock_drift", true, {"rate_error"}},
    {Effect::internal_momentum, "internal_momentum", false, {"h_N_m_s"}},
};

// A variant (descriptor variant_of: a rotor spun up by a motor) answers to the SPEC name
// of the effect it varies.
const SpecEffect* spec_of(Effect effect) {
  const Effect of = describe(effect).variant_of;
  for (const SpecEffect& s : kSpec) {
    if (s.effect == (of != Effect::none ? of : effect)) return &s;
  }
  return nullptr;
}

// A tumbling flight of an asymmetric body, read by a gyro turned from the body axes.
Flight tumbling_flight() {
  Flight f;
  f.sensor_to_body = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()));
  for (int k = 0; k < 200; ++k) {
    f.time_s.push_back(0.005 * k);
    f.omega.emplace_back(1.0, 8.0, 0.5);
    f.usable.push_back(1);
  }
  return f;
}

NominalInertia asymmetric_body() {
  Eigen::Matrix3d tensor = Eigen::Vector3d(0.002, 0.004, 0.005).asDiagonal();
  return NominalInertia::of_tensor(tensor);
}

std::vector<Eigen::Vector3d> predict(Effect effect, const Eigen::VectorXd& theta) {
  const Flight flight = tumbling_flight();
  const EffectModel model(effect, asymmetric_body(), 0.42);
  std::vector<Eigen::Vector3d> readings;
  predict_readings(model, flight, reference_index(effect, flight), Eigen::Vector3d(1.0, 8.0, 0.5), theta,
                   readings);
  return readings;
}

double largest_difference(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double largest = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) largest = std::max(largest, (a[k] - b[k]).norm());
  return largest;
}

}  // namespace

TEST_CASE("every registered effect is complete, under a SPEC §4 name, none left out", "[effect_descriptor]") {
  std::set<std::string> names;
  for (Effect e : registered_effects()) {
    const EffectDescriptor& d = describe(e);
    REQUIRE(d.name != nullptr);
    CAPTURE(d.name);
    if (d.variant_of == Effect::none) CHECK(names.insert(d.name).second);  // unique, but for variants
    if (d.variant_of != Effect::none) CHECK(describe(d.variant_of).variant_of == Effect::none);
    const SpecEffect* spec = spec_of(e);
    REQUIRE(spec != nullptr);
    CHECK(std::string(d.name) == spec->name);
    CHECK(std::string(effect_name(e)) == spec->name);  // the name the reports write
    CHECK(d.sensor == spec->sensor);
    CHECK((d.parameter_count > 0) == (e != Effect::none));
    const EffectHooks& h = d.hooks;
    CHECK(h.tolerance != nullptr);
    CHECK(h.apply != nullptr);
    CHECK(h.parameters != nullptr);
    CHECK(h.too_small != nullptr);
    CHECK(h.senseless != nullptr);
    CHECK(h.unphysical != nullptr);
    for (Effect q : d.gyro_equivalents) CHECK((q != e || e == Effect::none));  // padding is `none`
    // A one-way equivalence names another effect and says when it holds.
    CHECK((e == Effect::none || d.one_way_equivalent.stands_in_for != e));
    CHECK((d.one_way_equivalent.stands_in_for == Effect::none) == (d.one_way_equivalent.holds == nullptr));
  }
  CHECK(names.size() == kSpec.size());
  CHECK(registered_effects().front() == Effect::none);
}

TEST_CASE("each effect's JSON has its SPEC §4 keys, and none has none; its text is empty for none only",
          "[effect_descriptor]") {
  for (Effect e : registered_effects()) {
    const EffectDescriptor& d = describe(e);
    CAPTURE(d.name);
    const nlohmann::json params = params_json(e, EffectParameters());
    REQUIRE(params.is_object());
    const SpecEffect* spec = spec_of(e);
    REQUIRE(spec != nullptr);
    for (const std::string& key : spec->keys) CHECK(params.contains(key));
    CHECK(params.empty() == (e == Effect::none));
    CHECK(params_text(e, EffectParameters()).empty() == (e == Effect::none));
  }
}

// The words of a session's spin-up, flight by flight: each flight's number, start, time constant
// and |h| where the text says they are (printf_text's format is checked by the compiler; a
// flight's number once came out as another value's bits).
TEST_CASE("a session's spin-up is worded flight by flight", "[effect_descriptor]") {
  EffectParameters p;
  p.vector = Eigen::Vector3d(0.0, 0.0, 0.06);
  p.spin_up_profile = {0.065, 0.040};
  // The second flight's log gives its rotor (a body file's rotor and rotor_rad_s): 3-4-5,
  // 36.9 degrees off the found h, which is 1.2 times its size.
  p.spin_up_flights = {
      {Eigen::Vector3d(0.0, 0.0, 0.05), {0.046, 0.059}, 0.0, std::nullopt},
      {Eigen::Vector3d(0.0, 0.0, 0.06), {0.065, 0.040}, 0.0, Eigen::Vector3d(0.0, 0.03, 0.04)}};
  const std::string text = params_text(Effect::internal_momentum_spin_up, p);
  CAPTURE(text);
  CHECK(text.rfind("in the longest flight, a wheel spun up 65 ms after the first sample", 0) == 0);
  CHECK(text.find("flight 1 from 46 ms, ramp 0 ms, time constant 59 ms, |h| 0.05 N m s") !=
        std::string::npos);
  CHECK(
      text.find("flight 2 from 65 ms, ramp 0 ms, time constant 40 ms, |h| 0.06 N m s, 0.06 N m s at its end, "
                "the log's rotor 0.05 N m s there: found 1.20 x it, 36.9 deg apart") != std::string::npos);
  CHECK(text.find("log's rotor") == text.rfind("log's rotor"));  // flight 2's only
  const nlohmann::json json = params_json(Effect::internal_momentum_spin_up, p);
  CHECK(!json["flights"][0].contains("logged_h_N_m_s"));
  CHECK(json["flights"][1]["logged_h_N_m_s"] == nlohmann::json::array({0.0, 0.03, 0.04}));
  // A flight whose own spin-up the fit put before its data (at speed from its first sample,
  // e^(-205/0.6) of the way): a steady rotor there, worded so, its time constant unmeasured.
  p.spin_up_flights.front().profile = {-0.205, 0.0006};
  const std::string steady = params_text(Effect::internal_momentum_spin_up, p);
  CAPTURE(steady);
  CHECK(steady.find("flight 1 at speed from its first sample, |h| 0.05 N m s;") != std::string::npos);
  CHECK(steady.find("-205 ms") == std::string::npos);
  p.spin_up_profile = {-0.205, 0.0006};
  CHECK(params_text(Effect::internal_momentum_spin_up, p)
            .rfind("in the longest flight, a wheel at speed from the first sample, h = (0, 0, 0.06) N m s",
                   0) == 0);
}

TEST_CASE("a start grid is complete: starts and a joining start of the effect's size, minima told apart",
          "[effect_descriptor]") {
  int grids = 0;
  for (Effect e : registered_effects()) {
    const EffectDescriptor& d = describe(e);
    CAPTURE(d.name);
    if (d.start_grid == nullptr) continue;
    ++grids;
    REQUIRE(d.start_grid->starts != nullptr);
    REQUIRE(d.start_grid->joining != nullptr);
    CHECK(d.start_grid->distinct > 0.0);
    const std::vector<Eigen::VectorXd> starts = d.start_grid->starts();
    CHECK(starts.size() >= 2);
    // Where theta = 0 is the nominal model, the grid starts there first and joins there,
    // so a flight whose nominal is right starts as it would without a grid.
    if (d.neutral_at_zero) {
      CHECK(starts.front().isZero());
      CHECK(d.start_grid->joining().isZero());
    }
    for (const Eigen::VectorXd& s : starts) {
      CHECK(s.size() == d.parameter_count);
      CHECK(s.allFinite());
    }
    CHECK(d.start_grid->joining().size() == d.parameter_count);
    CHECK(d.start_grid->joining().allFinite());
  }
  CHECK(grids >= 2);                                         // the damping rotor's, the moments'
  CHECK_FALSE(describe(Effect::impulse).shared_by_flights);  // a knock belongs to one flight
}

TEST_CASE("SPEC §4's classes a gyro cannot split, and no sensor effect for motion capture",
          "[effect_descriptor]") {
  using V = std::vector<Effect>;
  CHECK(always_equivalent(Effect::inertia_axes, true) ==
        V{Effect::inertia_axes, Effect::sensor_misalignment});
  CHECK(always_equivalent(Effect::sensor_misalignment, true) ==
        V{Effect::sensor_misalignment, Effect::inertia_axes});
  CHECK(always_equivalent(Effect::clock_drift, true) == V{Effect::clock_drift, Effect::gyro_scale});
  CHECK(always_equivalent(Effect::inertia_axes, false) == V{Effect::inertia_axes});
  // Every registered effect is a candidate for IMU input, the rotor too; a variant is
  // tried by variant_candidates.hpp instead.
  std::vector<Effect> primary;
  for (Effect e : registered_effects())
    if (describe(e).variant_of == Effect::none) primary.push_back(e);
  CHECK(candidate_effects(true) == primary);
  CHECK(primary.size() + 1 == registered_effects().size());
  CHECK(describe(Effect::internal_momentum).named_only_when_told_apart);
  for (Effect e : candidate_effects(false)) CHECK_FALSE(is_sensor_effect(e));
  CHECK(effect_penalty_count(Effect::impulse) == effect_parameter_count(Effect::impulse) + 1);
}

TEST_CASE(
    "the model hook: theta = 0 is the nominal model where the descriptor says so, and "
    "every parameter moves the readings",
    "[effect_descriptor]") {
  const std::vector<Eigen::Vector3d> nominal = predict(Effect::none, Eigen::VectorXd());
  for (Effect e : registered_effects()) {
    if (e == Effect::none) continue;
    const EffectDescriptor& d = describe(e);
    CAPTURE(d.name);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(d.parameter_count);
    // The reference sample differs for an effect that starts at release; compare with the
    // nominal model fitted at the same sample.
    const std::vector<Eigen::Vector3d> at_zero = predict(e, zero);
    if (d.neutral_at_zero && !d.starts_at_release) {
      CHECK(largest_difference(at_zero, nominal) < 1e-12);
    } else if (!d.neutral_at_zero) {
      CHECK(largest_difference(at_zero, nominal) > 1e-3);
    }
    // A variant's parameters beyond its parent's (a spin-up's timing) move the readings
    // only where its parent's do: they are moved about a parent part of 0.05.
    const int parent = d.variant_of != Effect::none ? describe(d.variant_of).parameter_count : 0;
    Eigen::VectorXd base = zero;
    base.head(parent).setConstant(0.05);
    const std::vector<Eigen::Vector3d> at_base = parent > 0 ? predict(e, base) : at_zero;
    for (int i = 0; i < d.parameter_count; ++i) {
      CAPTURE(i);
      Eigen::VectorXd theta = i < parent ? zero : base;
      theta(i) += 0.05;
      CHECK(largest_difference(predict(e, theta), i < parent ? at_zero : at_base) > 1e-4);
    }
  }
}

TEST_CASE("physical parameters: the impulse keeps its time, drag is p times the mean moment",
          "[effect_descriptor]") {
  const NominalInertia body = asymmetric_body();
  const EffectParameters jump =
      describe(Effect::impulse).hooks.parameters(Eigen::Vector3d(0.1, 0.0, 0.0), body, 0.42);
  CHECK(jump.time_s == 0.42);
  CHECK(jump.vector.isApprox(body.tensor * Eigen::Vector3d(0.1, 0.0, 0.0)));
  Eigen::VectorXd p(1);
  p << 2.0;
  CHECK(describe(Effect::aero_torque).hooks.parameters(p, body, 0.0).k_N_m_s2 == Approx(2.0 * 0.011 / 3.0));
}

// A spun-up wheel's rise and time constant are judged pinned by their sizes' errors, not
// their logarithms': a rise fitted at 2.5 ms whose logarithm is loose by 2 is pinned to 5 ms.
TEST_CASE("a spin-up's rise and time constant are pinned as sizes", "[effect_descriptor]") {
  const EffectDescriptor& d = describe(Effect::internal_momentum_spin_up);
  REQUIRE(d.pinned_errors != nullptr);
  Eigen::VectorXd theta(kSpinUpParameters), se(kSpinUpParameters);
  theta << 1.0, 2.0, 3.0, 0.6, std::log(0.04 / kSpinUpTimeConstantUnit_s),
      std::log(0.0025 / kSpinUpTimeConstantUnit_s);
  se << 0.1, 0.2, 0.3, 0.01, 0.5, 2.0;
  const Eigen::VectorXd pinned = d.pinned_errors(theta, se);
  CHECK(pinned.head<4>() == se.head<4>());
  CHECK(pinned(4) * kSpinUpTimeConstantUnit_s == Approx(0.5 * 0.04));
  CHECK(pinned(5) * kSpinUpTimeConstantUnit_s == Approx(2.0 * 0.0025));
  for (Effect e : registered_effects()) {
    if (e != Effect::internal_momentum_spin_up) CHECK(describe(e).pinned_errors == nullptr);
  }
}
