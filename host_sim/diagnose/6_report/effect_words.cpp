// The report's words for each effect's parameters (effect_words.hpp), in registry order.
#include "diagnose/6_report/effect_words.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "common/printf_text.hpp"
#include "diagnose/6_report/json_values.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

struct EffectWords {
  std::string (*text)(const EffectParameters& p) = nullptr;
  nlohmann::json (*json)(const EffectParameters& p) = nullptr;
};

// `none`
std::string none_text(const EffectParameters&) { return ""; }

nlohmann::json none_json(const EffectParameters&) { return nlohmann::json::object(); }

// `inertia_moments`
// Torque-free motion fixes only the ratios of the moments, so a change is said of one
// moment relative to the other two (their geometric mean), which does not depend on how
// the fitted moments were scaled: "the body file's Iy is 3.0 % high relative to Ix and
// Iz (the data's Iy is 2.9 % below the file's); moments about body x, y, z: ...".
std::string inertia_moments_text(const EffectParameters& p) {
  const Vec3 m = p.principal_body_order_kg_m2, n = p.nominal_body_order_kg_m2;
  if (!(n.minCoeff() > 0.0) || !(m.minCoeff() > 0.0)) {
    return printf_text("principal moments about body x, y, z %.4g, %.4g, %.4g kg m^2", m(0), m(1), m(2));
  }
  const Vec3 factor = m.cwiseQuotient(n);  // the data's moment over the file's
  Vec3 relative = Vec3::Zero();            // each factor over the other two's geometric mean
  for (int i = 0; i < 3; ++i) relative(i) = factor(i) / std::sqrt(factor((i + 1) % 3) * factor((i + 2) % 3));
  Eigen::Index most = 0;
  relative.array().log().abs().maxCoeff(&most);
  const char* name[] = {"Ix", "Iy", "Iz"};
  const int a = (static_cast<int>(most) + 1) % 3, b = (static_cast<int>(most) + 2) % 3;
  const double file_off = 100.0 * (1.0 / relative(most) - 1.0), data_off = 100.0 * (relative(most) - 1.0);
  return std::string("the body file's ") + name[most] + printf_text(" is %.1f %% ", std::abs(file_off)) +
         (file_off > 0 ? "high" : "low") + " relative to " + name[std::min(a, b)] + " and " +
         name[std::max(a, b)] + " (the data's " + name[most] +
         printf_text(" is %.1f %% ", std::abs(data_off)) + (data_off < 0 ? "below" : "above") +
         " the file's); " +
         printf_text(
             "principal moments about body x, y, z %.4g, %.4g, %.4g kg m^2 (scaled to the file's sum)", m(0),
             m(1), m(2));
}

nlohmann::json inertia_moments_json(const EffectParameters& p) {
  return {{"principal_kg_m2", json_vec(p.principal_body_order_kg_m2)},
          {"nominal_principal_kg_m2", json_vec(p.nominal_body_order_kg_m2)},
          {"principal_axes_order",
           "body file axes x, y, z (each principal axis by the body axis it lies nearest)"},
          {"principal_ascending_kg_m2", json_vec(p.principal_kg_m2)},
          {"tensor_kg_m2", json_matrix(p.tensor_kg_m2)}};
}

// `inertia_axes`
std::string inertia_axes_text(const EffectParameters& p) {
  return printf_text("rotated by %.2f deg", p.angle_deg);
}

nlohmann::json inertia_axes_json(const EffectParameters& p) {
  return {{"angle_deg", p.angle_deg},
          {"rotation", json_quat(p.rotation)},
          {"tensor_kg_m2", json_matrix(p.tensor_kg_m2)}};
}

// `aero_torque`
std::string aero_torque_text(const EffectParameters& p) {
  return printf_text("k = %.3g N m s^2", p.k_N_m_s2);
}

nlohmann::json aero_torque_json(const EffectParameters& p) { return {{"k_N_m_s2", p.k_N_m_s2}}; }

// `internal_damping`
std::string internal_damping_text(const EffectParameters& p) {
  return printf_text("rotor J = %.3g kg m^2, c = %.3g N m s", p.rotor_J_kg_m2, p.c_N_m_s);
}

nlohmann::json internal_damping_json(const EffectParameters& p) {
  return {{"model", "spherical_rotor_in_viscous_cavity"},
          {"rotor_J_kg_m2", p.rotor_J_kg_m2},
          {"c_N_m_s", p.c_N_m_s}};
}

// `impulse`
std::string impulse_text(const EffectParameters& p) {
  return printf_text("at %.3f s, |dL| %.3g N m s", p.time_s, p.vector.norm());
}

nlohmann::json impulse_json(const EffectParameters& p) {
  return {{"time_s", p.time_s}, {"angular_impulse_N_m_s", json_vec(p.vector)}};
}

// `gyro_bias`
std::string gyro_bias_text(const EffectParameters& p) {
  return printf_text("bias %.4f, %.4f, %.4f rad/s", p.vector(0), p.vector(1), p.vector(2));
}

nlohmann::json gyro_bias_json(const EffectParameters& p) { return {{"bias_rad_s", json_vec(p.vector)}}; }

// `gyro_scale`
std::string gyro_scale_text(const EffectParameters& p) {
  return printf_text("scale errors %.4f, %.4f, %.4f", p.vector(0), p.vector(1), p.vector(2));
}

nlohmann::json gyro_scale_json(const EffectParameters& p) { return {{"scale_error", json_vec(p.vector)}}; }

// `sensor_misalignment`
std::string sensor_misalignment_text(const EffectParameters& p) {
  return printf_text("rotated by %.2f deg", p.angle_deg);
}

nlohmann::json sensor_misalignment_json(const EffectParameters& p) {
  return {{"angle_deg", p.angle_deg}, {"rotation", json_quat(p.rotation)}};
}

// `clock_drift`
std::string clock_drift_text(const EffectParameters& p) {
  return printf_text("rate error %.4f", p.rate_error);
}

nlohmann::json clock_drift_json(const EffectParameters& p) { return {{"rate_error", p.rate_error}}; }

// `internal_momentum`
std::string internal_momentum_text(const EffectParameters& p) {
  return printf_text("h = (%.3g, %.3g, %.3g) N m s in body axes, |h| %.3g N m s", p.vector(0), p.vector(1),
                     p.vector(2), p.vector.norm());
}

nlohmann::json internal_momentum_json(const EffectParameters& p) { return {{"h_N_m_s", json_vec(p.vector)}}; }

// Where the body file has a rotor and the log its speed: the log's h beside the h found at
// the same end, the found one's size over it and the angle between them.
std::string logged_rotor_words(const Eigen::Vector3d& found, const std::optional<Eigen::Vector3d>& logged) {
  if (!logged) return {};
  if (!(logged->norm() > 0.0)) return ", the log's rotor at rest there";
  const double angle = std::atan2(found.cross(*logged).norm(), found.dot(*logged));
  return printf_text(", the log's rotor %.3g N m s there: found %.2f x it, %.1f deg apart", logged->norm(),
                     found.norm() / logged->norm(), angle * 180.0 / 3.141592653589793);
}

// `internal_momentum` spun up by a motor: the final h, the profile, and h at the end of the
// data (SPEC §4: h_N_m_s is h at the flight's end).
// A session's flights share the wheel's axis and each has its own profile: the longest
// flight's above, then each flight's.
std::string internal_momentum_spin_up_text(const EffectParameters& p) {
  const Eigen::Vector3d end = p.spin_up_h_at_end();
  const std::string profile =
      p.spin_up_profile.at_speed_before_data()
          ? std::string("a wheel at speed from the first sample, ")
          : printf_text(
                "a wheel spun up %.0f ms after the first sample, set-point ramp %.0f ms, time constant "
                "%.0f ms, to ",
                1000.0 * p.spin_up_profile.start_s, 1000.0 * p.spin_up_profile.rise_s,
                1000.0 * p.spin_up_profile.time_constant_s);
  std::string out = std::string(p.spin_up_flights.empty() ? "" : "in the longest flight, ") + profile +
                    printf_text(
                        "h = (%.3g, %.3g, %.3g) N m s in body axes (|h| %.3g N m s; %.3g N m s at the "
                        "end of the data%s)",
                        p.vector(0), p.vector(1), p.vector(2), p.vector.norm(), end.norm(),
                        logged_rotor_words(end, p.spin_up_logged_h).c_str());
  if (p.spin_up_flights.empty()) return out;
  const Eigen::Vector3d axis = p.vector.normalized();
  out += printf_text("; the flights share its axis (%.3f, %.3f, %.3f), each its own profile:", axis(0),
                     axis(1), axis(2));
  for (std::size_t j = 0; j < p.spin_up_flights.size(); ++j) {
    const EffectParameters::SpinUpFlight& f = p.spin_up_flights[j];
    if (f.profile.at_speed_before_data()) {
      out += printf_text(" flight %zu at speed from its first sample, |h| %.3g N m s%s;", j + 1,
                         f.final_h.norm(), logged_rotor_words(f.h_at_end(), f.logged_h).c_str());
      continue;
    }
    out += printf_text(
        " flight %zu from %.0f ms, ramp %.0f ms, time constant %.0f ms, |h| %.3g N m s, %.3g N m s "
        "at its end%s;",
        j + 1, 1000.0 * f.profile.start_s, 1000.0 * f.profile.rise_s, 1000.0 * f.profile.time_constant_s,
        f.final_h.norm(), f.h_at_end().norm(), logged_rotor_words(f.h_at_end(), f.logged_h).c_str());
  }
  out.pop_back();
  return out;
}

nlohmann::json internal_momentum_spin_up_json(const EffectParameters& p) {
  nlohmann::json out = {{"h_N_m_s", json_vec(p.spin_up_h_at_end())},
                        {"profile", "ramped_first_order_spin_up"},
                        {"final_h_N_m_s", json_vec(p.vector)},
                        {"start_s", p.spin_up_profile.start_s},
                        {"time_constant_s", p.spin_up_profile.time_constant_s},
                        {"rise_s", p.spin_up_profile.rise_s},
                        {"end_s", p.spin_up_end_s}};
  if (p.spin_up_logged_h) out["logged_h_N_m_s"] = json_vec(*p.spin_up_logged_h);
  if (p.spin_up_flights.empty()) return out;
  out["axis"] = json_vec(p.vector.normalized());
  nlohmann::json flights = nlohmann::json::array();
  for (const EffectParameters::SpinUpFlight& f : p.spin_up_flights) {
    flights.push_back({{"h_N_m_s", json_vec(f.h_at_end())},
                       {"final_h_N_m_s", json_vec(f.final_h)},
                       {"start_s", f.profile.start_s},
                       {"time_constant_s", f.profile.time_constant_s},
                       {"rise_s", f.profile.rise_s},
                       {"end_s", f.end_s}});
    if (f.logged_h) flights.back()["logged_h_N_m_s"] = json_vec(*f.logged_h);
  }
  out["flights"] = flights;
  return out;
}

constexpr std::array kWords = {
#define ALOFT_EFFECT(name) EffectWords{name##_text, name##_json},
#include "diagnose/2_model/effects/effect_list.def"
#undef ALOFT_EFFECT
};

}  // namespace

std::string params_text(Effect effect, const EffectParameters& params) {
  return kWords[static_cast<std::size_t>(effect)].text(params);
}

nlohmann::json params_json(Effect effect, const EffectParameters& params) {
  return kWords[static_cast<std::size_t>(effect)].json(params);
}

std::string note_text(const Note& note) {
  return note.params_of ? note.text + params_text(*note.params_of, note.params) : note.text;
}

}  // namespace aloft::host::diagnose
