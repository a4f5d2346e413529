#include "study/built_in_study.hpp"

#include <string>

#include "common/commands.hpp"
#include "readers/marker_pose_fit.hpp"
#include "study/paper_cylinder.hpp"
#include "study/tangent_spline_resampler.hpp"

namespace aloft::host {

InertiaTensor<double> compound_pendulum_inertia() {
  InertiaTensor<double> cp;
  const Eigen::Vector3d moments(paper::kCompoundPendulumKgM2[0], paper::kCompoundPendulumKgM2[1],
                                paper::kCompoundPendulumKgM2[2]);
  const Status made = InertiaTensor<double>::make_from_principal(moments, Eigen::Quaterniond::Identity(), cp);
  if (made != Status::ok) throw Error(std::string("the paper's CP tensor: ") + describe(made));
  return cp;
}

BuiltInTrial make_built_in_trial(const SyntheticThrowSettings& settings) {
  const SyntheticThrow sim = make_synthetic_throw(settings);
  const PoseTrial fitted = fit_poses(sim.markers, sim.body);
  const ResampledPoses poses = resample_poses(fitted.time_s, fitted.orientation, paper::kResampleRateHz);

  BuiltInTrial out;
  out.body = sim.body;
  out.flight = make_pose_flight("built-in throw", poses);

  nlohmann::json& d = out.description;
  d["kind"] = "built-in synthetic throw of the paper's cylinder";
  d["body"] = {{"mass_kg", paper::kMassKg}, {"height_m", paper::kHeightM}, {"diameter_m", paper::kDiameterM}};
  nlohmann::json markers = nlohmann::json::object();
  for (const auto& [name, p] : sim.body.markers_m) markers[name] = {p.x(), p.y(), p.z()};
  d["markers_body_m"] = markers;
  const Eigen::Vector3d w = settings.initial_omega_body_rad_s();
  const Eigen::Quaterniond& q = settings.initial_orientation;
  d["spin_rate_rev_s"] = settings.spin_rate_rev_s;
  d["spin_tilt_deg"] = settings.spin_tilt_deg;
  d["spin_azimuth_deg"] = settings.spin_azimuth_deg;
  d["initial_omega_body_rad_s"] = {w.x(), w.y(), w.z()};
  d["initial_orientation_wxyz"] = {q.w(), q.x(), q.y(), q.z()};
  d["flight_time_s"] = settings.flight_time_s;
  d["camera_rate_hz"] = settings.camera_rate_hz;
  d["camera_frames"] = sim.markers.time_s.size();
  d["marker_noise_m"] = settings.marker_noise_m;
  d["marker_layout"] = marker_layout_name(settings.marker_layout);
  d["noise_seed"] = settings.noise_seed;
  d["pose_fit"] = "least-squares rigid fit of the body's marker set per frame (readers/marker_pose_fit)";
  d["resampling"] =
      "C1 cubic Hermite spline in the tangent space of SO(3), knot rates from three-point "
      "derivatives, to 1000 Hz";
  d["samples"] = out.flight.samples();
  d["omega_measured"] =
      "log(q_j^-1 q_{j+1}) / dt between consecutive resampled orientations (body axes); "
      "q_j times it in world axes";
  return out;
}

}  // namespace aloft::host
