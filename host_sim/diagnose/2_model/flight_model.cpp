#include "diagnose/2_model/flight_model.hpp"

#include <algorithm>

#include "diagnose/2_model/flight_dynamics.hpp"
#include "diagnose/2_model/gyro_filter_bend.hpp"
#include "diagnose/2_model/reading_walks.hpp"
#include "diagnose/2_model/spin_up_walk.hpp"
#include "diagnose/2_model/walk_layout.hpp"

namespace aloft::host::diagnose {
namespace {

// Samples this close share one step, the readings between interpolated (ReadingWalks):
// 1 kHz data takes one step every 5 samples instead of one a sample (case00: 2.10 G
// instructions -> 1.33 G). Not for a model with a rotor: the internal damping fits reach
// coupling rates of ~200 /s, where a 5 ms step misjudges the rotor and the fitted rotor
// moved (practice2/A02 then named internal_damping instead of inertia_axes).
constexpr double kMaxSegment = kMaxStep;

WalkLayoutKey layout_key(const EffectModel& model, const Flight& flight, std::size_t ref,
                         SampleStepping stepping, const FlightDynamics& dynamics) {
  WalkLayoutKey key;
  key.ref = ref;
  key.max_segment = stepping == SampleStepping::shared_steps ? kMaxSegment : 0.0;
  key.single_samples = dynamics.has_rotor();
  key.has_jump = dynamics.has_jump();
  key.time_factor = dynamics.time_factor();
  const double t_ref = flight.time_s[ref];
  key.jump_time = key.has_jump ? t_ref + (model.impulse_time_s - t_ref) * key.time_factor : 0.0;
  return key;
}

Motion start_at(const Eigen::Vector3d& omega_ref) {
  Motion start;
  start.x.head<3>() = omega_ref;
  start.x.tail<3>() = omega_ref;  // rotor co-rotating at the reference (damping only)
  return start;
}

// FlightDynamics::advance_pair of one body, for walk_together.
auto paired_steps(const FlightDynamics& dynamics) {
  return [&dynamics](Motion& x, int x_steps, double hx, Motion& y, int y_steps, double hy) {
    dynamics.advance_pair(x, x_steps, hx, y, y_steps, hy);
  };
}

}  // namespace

void predict_readings(const EffectModel& model, const Flight& flight, std::size_t ref,
                      const Eigen::Vector3d& omega_ref, const Eigen::VectorXd& theta,
                      std::vector<Eigen::Vector3d>& readings, SampleStepping stepping,
                      Eigen::Vector3d* rate_at_impulse, ReadSamples read) {
  const std::size_t n = flight.size();
  readings.resize(n);
  if (n == 0) return;
  const ModelTerms terms = model_terms(model, theta);
  FlightDynamics dynamics(terms, flight);
  dynamics.set_impulse_scale(model.nominal.tensor);
  const WalkLayoutKey key = layout_key(model, flight, ref, stepping, dynamics);
  if (has_spin_up(terms)) {
    predict_spin_up_readings(dynamics, terms, flight, ref, omega_ref, key.jump_time, readings, read);
  } else {
    const WalkLayout& layout = walk_layout(flight.time_s, key);
    const ReadingWalks walks(dynamics, key.jump_time, readings, layout.weights, rate_at_impulse, read);
    const Motion start = start_at(omega_ref);
    readings[ref] = dynamics.reading(start.x);
    // Forwards from the reference and backwards from it, independent of each other.
    ReadingWalks::Walk up{start, ref}, down{start, ref};
    walk_together(paired_steps(dynamics), walks, up, layout.up, walks, down, layout.down);
  }
  bend_by_gyro_filter(flight, readings, read);
}

namespace {

// predict_readings of (omega_a, theta_a), then of (omega_b, theta_b): where the two
// cannot step side by side.
void predict_one_after_the_other(const EffectModel& model, const Flight& flight, std::size_t ref,
                                 const Eigen::Vector3d& omega_a, const Eigen::VectorXd& theta_a,
                                 const Eigen::Vector3d& omega_b, const Eigen::VectorXd& theta_b,
                                 std::vector<Eigen::Vector3d>& readings_a,
                                 std::vector<Eigen::Vector3d>& readings_b, ReadSamples read) {
  predict_readings(model, flight, ref, omega_a, theta_a, readings_a, SampleStepping::shared_steps, nullptr,
                   read);
  predict_readings(model, flight, ref, omega_b, theta_b, readings_b, SampleStepping::shared_steps, nullptr,
                   read);
}

// The one walk of each of two predictions from `ref`, the first or last sample (the
// layout's other direction has no segments), side by side: advance_pair steps them
// together (walk_together), each in its own body's terms; then both are read through the
// flight's gyro filter, as predict_readings reads one.
template <class AdvancePair>
void one_walks_side_by_side(const AdvancePair& advance_pair, const FlightDynamics& dynamics_a,
                            const FlightDynamics& dynamics_b, const WalkLayout& layout, double jump_time,
                            std::size_t ref, const Eigen::Vector3d& omega_a, const Eigen::Vector3d& omega_b,
                            std::vector<Eigen::Vector3d>& readings_a,
                            std::vector<Eigen::Vector3d>& readings_b, const Flight& flight,
                            ReadSamples read) {
  const std::size_t n = flight.size();
  readings_a.resize(n);
  readings_b.resize(n);
  const ReadingWalks walks_a(dynamics_a, jump_time, readings_a, layout.weights, nullptr, read),
      walks_b(dynamics_b, jump_time, readings_b, layout.weights, nullptr, read);
  const Motion start_a = start_at(omega_a), start_b = start_at(omega_b);
  readings_a[ref] = dynamics_a.reading(start_a.x);
  readings_b[ref] = dynamics_b.reading(start_b.x);
  ReadingWalks::Walk a{start_a, ref}, b{start_b, ref};
  const std::vector<WalkSegment>& segments = layout.up.empty() ? layout.down : layout.up;
  walk_together(advance_pair, walks_a, a, segments, walks_b, b, segments);
  bend_by_gyro_filter(flight, readings_a, read);
  bend_by_gyro_filter(flight, readings_b, read);
}

}  // namespace

void predict_readings_pair(const EffectModel& model, const Flight& flight, std::size_t ref,
                           const Eigen::Vector3d& omega_a, const Eigen::Vector3d& omega_b,
                           const Eigen::VectorXd& theta, std::vector<Eigen::Vector3d>& readings_a,
                           std::vector<Eigen::Vector3d>& readings_b, ReadSamples read) {
  const std::size_t n = flight.size();
  const ModelTerms terms = model_terms(model, theta);
  if (n == 0 || (ref != 0 && ref + 1 != n) || has_spin_up(terms)) {
    predict_one_after_the_other(model, flight, ref, omega_a, theta, omega_b, theta, readings_a, readings_b,
                                read);
    return;
  }
  FlightDynamics dynamics(terms, flight);
  dynamics.set_impulse_scale(model.nominal.tensor);
  const WalkLayoutKey key = layout_key(model, flight, ref, SampleStepping::shared_steps, dynamics);
  one_walks_side_by_side(paired_steps(dynamics), dynamics, dynamics, walk_layout(flight.time_s, key),
                         key.jump_time, ref, omega_a, omega_b, readings_a, readings_b, flight, read);
}

void predict_readings_two(const EffectModel& model, const Flight& flight, std::size_t ref,
                          const Eigen::Vector3d& omega_a, const Eigen::VectorXd& theta_a,
                          const Eigen::Vector3d& omega_b, const Eigen::VectorXd& theta_b,
                          std::vector<Eigen::Vector3d>& readings_a, std::vector<Eigen::Vector3d>& readings_b,
                          ReadSamples read) {
  if (theta_a.size() == theta_b.size() && (theta_a.array() == theta_b.array()).all()) {
    predict_readings_pair(model, flight, ref, omega_a, omega_b, theta_a, readings_a, readings_b, read);
    return;
  }
  const std::size_t n = flight.size();
  const ModelTerms terms_a = model_terms(model, theta_a), terms_b = model_terms(model, theta_b);
  if (has_spin_up(terms_a) || has_spin_up(terms_b)) {
    predict_one_after_the_other(model, flight, ref, omega_a, theta_a, omega_b, theta_b, readings_a,
                                readings_b, read);
    return;
  }
  FlightDynamics dynamics_a(terms_a, flight), dynamics_b(terms_b, flight);
  dynamics_a.set_impulse_scale(model.nominal.tensor);
  dynamics_b.set_impulse_scale(model.nominal.tensor);
  const WalkLayoutKey key = layout_key(model, flight, ref, SampleStepping::shared_steps, dynamics_a);
  if (n == 0 || (ref != 0 && ref + 1 != n) || !FlightDynamics::same_kind(dynamics_a, dynamics_b) ||
      !(layout_key(model, flight, ref, SampleStepping::shared_steps, dynamics_b) == key)) {
    predict_one_after_the_other(model, flight, ref, omega_a, theta_a, omega_b, theta_b, readings_a,
                                readings_b, read);
    return;
  }
  // Each lane with its own body's terms.
  const FlightDynamics::LaneTerms lanes = FlightDynamics::lane_terms(dynamics_a, dynamics_b);
  const auto advance_two = [&](Motion& x, int x_steps, double hx, Motion& y, int y_steps, double hy) {
    FlightDynamics::advance_two(lanes, dynamics_a, x, x_steps, hx, dynamics_b, y, y_steps, hy);
  };
  one_walks_side_by_side(advance_two, dynamics_a, dynamics_b, walk_layout(flight.time_s, key), key.jump_time,
                         ref, omega_a, omega_b, readings_a, readings_b, flight, read);
}

}  // namespace aloft::host::diagnose
