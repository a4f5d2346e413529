#include "verdict_score.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace aloft::generator {
namespace {

using nlohmann::json;

bool has_vector(const json& params, const char* key) {
  return params.is_object() && params.contains(key) && params[key].is_array() && params[key].size() == 3 &&
         params[key][0].is_number() && params[key][1].is_number() && params[key][2].is_number();
}
Eigen::Vector3d vector_of(const json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}
bool has_number(const json& params, const char* key) {
  return params.is_object() && params.contains(key) && params[key].is_number();
}

}  // namespace

VerdictScore score_verdict(const FlightTruth& truth, const json& verdict) {
  VerdictScore s;
  std::ostringstream d;
  const std::string said = verdict.is_object() && verdict.contains("effect") && verdict["effect"].is_string()
                               ? verdict["effect"].get<std::string>()
                               : std::string("(no effect)");
  const json params = verdict.is_object() && verdict.contains("params") ? verdict["params"] : json::object();
  s.class_right = std::find(truth.equivalent.begin(), truth.equivalent.end(), said) != truth.equivalent.end();
  d << "truth " << truth.effect << ", verdict " << said;
  if (!s.class_right) {
    s.detail = d.str() + ": wrong class";
    return s;
  }
  const json& p = truth.params;
  s.params_checked = true;
  if (said == "gyro_bias") {
    if (!has_vector(params, "bias_rad_s")) {
      d << ": no bias_rad_s";
    } else {
      const Eigen::Vector3d b = vector_of(p["bias_rad_s"]);
      const double error = (vector_of(params["bias_rad_s"]) - b).norm();
      s.params_right = error <= 0.2 * b.norm();
      d << ": bias error " << error << " rad/s vs 20 % of " << b.norm();
    }
  } else if (said == "gyro_scale") {
    if (!has_vector(params, "scale_error")) {
      d << ": no scale_error";
    } else {
      const Eigen::Vector3d truth_scale = truth.effect == "clock_drift"
                                              ? Eigen::Vector3d::Constant(p["rate_error"].get<double>())
                                              : vector_of(p["scale_error"]);
      const double error = (vector_of(params["scale_error"]) - truth_scale).cwiseAbs().maxCoeff();
      s.params_right = error <= 0.01;
      d << ": scale error " << error << " vs 0.01";
    }
  } else if (said == "clock_drift") {
    if (!has_number(params, "rate_error")) {
      d << ": no rate_error";
    } else {
      const double error = std::abs(params["rate_error"].get<double>() - p["rate_error"].get<double>());
      s.params_right = error <= 0.01;
      d << ": rate error " << error << " vs 0.01";
    }
  } else if (said == "inertia_axes" || said == "sensor_misalignment") {
    if (!has_number(params, "angle_deg")) {
      d << ": no angle_deg";
    } else {
      const double error = std::abs(params["angle_deg"].get<double>() - p["angle_deg"].get<double>());
      s.params_right = error <= 2.0;
      d << ": angle error " << error << " deg vs 2";
    }
  } else if (said == "aero_torque") {
    if (!has_number(params, "k_N_m_s2")) {
      d << ": no k_N_m_s2";
    } else {
      const double k = p["k_N_m_s2"].get<double>();
      const double error = std::abs(params["k_N_m_s2"].get<double>() - k);
      s.params_right = error <= 0.25 * k;
      d << ": k error " << error / k * 100.0 << " % vs 25 %";
    }
  } else if (said == "impulse") {
    if (!has_number(params, "time_s")) {
      d << ": no time_s";
    } else {
      const double error = std::abs(params["time_s"].get<double>() - p["time_s"].get<double>());
      s.params_right = error <= 0.030;
      d << ": impulse time error " << error * 1000.0 << " ms vs 30";
    }
  } else {
    s.params_checked = false;
    s.params_right = true;
    d << ": no parameter threshold";
  }
  s.detail = d.str();
  return s;
}

}  // namespace aloft::generator
