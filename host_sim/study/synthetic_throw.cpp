#include "study/synthetic_throw.hpp"

#include <boost/random/normal_distribution.hpp>

#include <cmath>
#include <stdexcept>

#include "aloft/dynamics/rk4_integrator.hpp"
#include "study/paper_cylinder.hpp"
#include "study/simulation_random.hpp"

namespace aloft::host {

const char* marker_layout_name(MarkerLayout layout) {
  return layout == MarkerLayout::side ? "side" : "side-and-end";
}

Body paper_cylinder_body(MarkerLayout layout) {
  Body body;
  body.name = "paper steel cylinder (GF)";
  body.mass_kg = paper::kMassKg;
  const double radius = paper::kDiameterM / 2.0;
  const double half_height = paper::kHeightM / 2.0;
  if (InertiaTensor<double>::make_cylinder(paper::kMassKg, radius, paper::kHeightM, body.inertia) !=
      Status::ok) {
    throw std::logic_error("paper cylinder: invalid dimensions");
  }
  // Marker centres sit one marker radius off the surface.
  const double proud = paper::kMarkerDiameterM / 2.0;
  const auto on_side = [&](double azimuth_deg, double z) {
    const double a = azimuth_deg * M_PI / 180.0;
    return Eigen::Vector3d((radius + proud) * std::cos(a), (radius + proud) * std::sin(a), z);
  };
  if (layout == MarkerLayout::side) {
    body.markers_m["M1"] = on_side(15.0, 0.035);
    body.markers_m["M2"] = on_side(110.0, -0.030);
    body.markers_m["M3"] = on_side(200.0, 0.015);
    body.markers_m["M4"] = on_side(285.0, -0.010);
    return body;
  }
  body.markers_m["M1"] = on_side(20.0, 0.030);
  body.markers_m["M2"] = on_side(140.0, -0.025);
  body.markers_m["M3"] = on_side(250.0, 0.010);
  body.markers_m["M4"] = Eigen::Vector3d(0.030, -0.020, half_height + proud);  // top face
  return body;
}

SyntheticThrow make_synthetic_throw(const SyntheticThrowSettings& settings) {
  SyntheticThrow out;
  out.body = paper_cylinder_body(settings.marker_layout);

  const double frame_dt = 1.0 / settings.camera_rate_hz;
  const auto frames =
      static_cast<std::size_t>(std::llround(settings.flight_time_s * settings.camera_rate_hz)) + 1;
  // The truth is integrated with 16 RK4 sub-steps per frame (62.5 µs): its own error,
  // below 1e-12 rad, is nothing beside the marker noise.
  constexpr int kSubsteps = 16;
  const Rk4Integrator<double> integrator(out.body.inertia);
  RigidBodyState<double> state{settings.initial_orientation.normalized(),
                               settings.initial_omega_body_rad_s()};

  MarkerTrial& m = out.markers;
  m.path = "built-in throw";
  m.format = "synthetic";
  m.units_in_file = "m";
  m.rate_hz = settings.camera_rate_hz;
  for (const auto& [name, position] : out.body.markers_m) m.marker_names.push_back(name);
  out.true_poses.path = m.path;
  out.true_poses.format = "synthetic";

  SimulationRandom random(settings.noise_seed, 0, 0);
  boost::random::normal_distribution<double> noise(0.0, settings.marker_noise_m);
  const Eigen::Vector3d gravity(0.0, 0.0, -9.81);
  const Eigen::Vector3d launch_velocity(settings.launch_horizontal_velocity_m_s.x(),
                                        settings.launch_horizontal_velocity_m_s.y(),
                                        -gravity.z() * settings.flight_time_s / 2.0);
  for (std::size_t i = 0; i < frames; ++i) {
    if (i > 0) {
      for (int s = 0; s < kSubsteps; ++s) {
        const Status stepped = integrator.step(state, frame_dt / kSubsteps, TimeDirection::forward);
        if (stepped != Status::ok)
          throw std::logic_error(std::string("built-in throw: ") + describe(stepped));
      }
    }
    const double t = static_cast<double>(i) * frame_dt;
    const Eigen::Vector3d centre = settings.launch_position_m + launch_velocity * t + 0.5 * gravity * t * t;
    const Eigen::Matrix3d r = state.orientation.toRotationMatrix();
    std::vector<Eigen::Vector3d> seen;
    for (const auto& [name, position] : out.body.markers_m) {
      seen.push_back(centre + r * position + Eigen::Vector3d(noise(random), noise(random), noise(random)));
    }
    m.time_s.push_back(t);
    m.positions_m.push_back(std::move(seen));
    out.true_poses.time_s.push_back(t);
    out.true_poses.orientation.push_back(state.orientation);
    out.true_poses.position_m.push_back(centre);
    out.true_omega_body.push_back(state.omega_body);
  }
  return out;
}

}  // namespace aloft::host
