// Flights with one withheld effect, for checking `aloft diagnose` (issue 5, SPEC §4).
//
// generate_flight(spec, seed) throws one body through the air with exactly one
// unmodelled effect of random magnitude (or none), records it the way a body-mounted
// gyro or a motion-capture system would, and returns the data, the nominal body that
// the diagnosis is told about, and the truth that it is not.
//
// What a flight looks like (the same kind of data as ../shared/data/practice/):
//   - duration drawn in [0.8, 1.2] s unless the spec fixes it;
//   - initial body rate |w0| in [5, 15] rad/s about a generic axis: at least 20° from
//     every principal axis, so the body tumbles and every effect has a lever;
//   - IMU: gyro at 1 kHz in sensor axes, white noise 0.02 rad/s per axis (accelerometer
//     optional, 0.05 m/s²); samples on the sensor's clock, t = k / rate;
//   - markers: six markers on the body's surface at 250 Hz, mm in the TRC, 0.2 mm
//     white noise per coordinate, up to three occlusions of one marker for 2-6 frames
//     (never two markers at once); the centre of mass flies a ballistic arc (world y up).
//
// Effect magnitudes, and why (each one is several times what noise alone can mimic over
// a ~1 s flight of ~1000 gyro samples, yet small enough to be a realistic modelling gap):
//   inertia_moments      each principal moment off by 5-20 % (random sign), then all
//                        rescaled to the nominal sum (torque-free motion fixes only the
//                        ratios); at least one moment off by >= 5 % after rescaling.
//   inertia_axes         principal axes rotated 3-15° about a random axis (about an axis
//                        normal to the symmetry axis for a body of revolution, since a
//                        turn about that axis changes nothing).
//   aero_torque          tau = -k |w| w with k chosen so |L| falls by 4-12 % over the
//                        flight (k = f / (T |w0| 2E0 / |L0|²), the initial decay rate).
//   internal_damping     spherical rotor of J = 8-15 % of the smallest principal moment
//                        in a viscous cavity, rotor co-rotating at release; |L| is
//                        constant, energy falls. The relaxation time J/c (10-500 ms) is
//                        solved for so that 1.5-6 % of the kinetic energy is lost over
//                        the flight; a throw that cannot lose that much (its body
//                        rate turns too slowly within the body) is thrown again, up to
//                        20 times. The near-symmetric cylinder, whose body rate turns
//                        at only 0.15 w_z, never gets above ~0.5 %: hardly detectable.
//   impulse              |dL| = 5-20 % of |L0|, random direction in body axes, a 3 ms
//                        half-sine torque pulse starting at 30-70 % of the flight.
//   gyro_bias            |b| = 0.05-0.3 rad/s, random direction (sensor axes).
//   gyro_scale           s_i = ±(2-8 %) per axis, with max-min >= 3 % so it is not a
//                        uniform scale (which a clock drift would mimic exactly).
//   sensor_misalignment  sensor axes rotated 3-15° about a random axis (normal to the
//                        symmetry axis for a body of revolution).
//   clock_drift          recorded time = true time × (1 + eps), |eps| = 1-5 %.
//   internal_momentum    (issue 31; not in the withheld lists, whose seeds stay as they
//                        were: rotor_cases.hpp) a rotor's h fixed in body axes, any
//                        direction, |h| = 0.5-10 % of the |L| the body carries at
//                        10 rad/s (sized from the body, not the throw, so that every
//                        flight of a session shares it; at 5-15 rad/s that is 0.3-20 %
//                        of the throw's |L|).
// Sensor effects (gyro_*, sensor_misalignment, clock_drift) exist for IMU data only.
// Measured on the withheld list (test "every withheld flight's effect is visible above
// the noise"): after the nominal model's initial rate is refitted, the clean signal
// keeps an unexplained RMS of at least 0.008 rad/s (clock drift on the cylinder; 0.05
// or more for every other effect), against the ~0.0007 rad/s that 1000 samples of
// 0.02 rad/s noise average down to.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/body_file.hpp"
#include "common/trial.hpp"
#include "gyro_filter.hpp"
#include "rotor_spin_up.hpp"

namespace aloft::generator {

// The effect names of SPEC §4 that the withheld lists cycle through, in the table's order
// (internal_momentum, added later, is not among them, so those lists keep their seeds).
const std::vector<std::string>& effect_names();
// Every effect generate_flight makes: effect_names() and internal_momentum.
bool known_effect(const std::string& effect);
// True for the effects that live in the sensor model (IMU data only).
bool is_sensor_effect(const std::string& effect);

enum class DataKind { imu, markers };
const char* to_string(DataKind kind);  // "imu" or "mocap" (as in practice/truth.json)

struct FlightSpec {
  std::string body = "box";     // a name from body_names() (body_catalogue.hpp)
  std::string effect = "none";  // a name from effect_names()
  DataKind data = DataKind::imu;
  double duration_s = 0.0;  // 0: drawn in [0.8, 1.2] s

  double imu_rate_hz = 1000.0;
  double gyro_noise_rad_s = 0.02;  // white, per axis
  // > 0: the gyro's digital low-pass (causal 2nd-order Butterworth, low_pass.hpp) acts on
  // its readings, signal and noise alike, settled on the first one (issue 31: fast,
  // filtered gyros, whose noise is correlated). 0: none (every earlier flight).
  double gyro_cutoff_hz = 0.0;
  // The low-pass's order: 2, the Butterworth above; 1, a flight controller's first-order
  // PT1 (first_order_low_pass.hpp), whose noise stays correlated over fs / (pi fc) readings.
  int gyro_filter_order = 2;
  // With order 1: how many PT1 stages in series (gyro_filter.hpp: Betaflight's PT2 is 2), the
  // first at the cutoff, each later one at gyro_later_stage_ratio times it (Betaflight's
  // default pair of gyro low-passes: 2, a second PT1 at twice the first's cutoff).
  int gyro_pt1_stages = 1;
  double gyro_later_stage_ratio = 1.0;
  // > 0: each reading rounded to a multiple of this after the noise (a flight controller
  // logs 1/16.4 deg/s, the ICM-42688's and MPU-6000's step at +-2000 deg/s). 0: none.
  double gyro_quantum_rad_s = 0.0;
  bool accelerometer = false;
  double accel_noise_m_s2 = 0.05;

  double marker_rate_hz = 250.0;
  double marker_noise_m = 0.2e-3;  // white, per coordinate
  bool occlusions = true;

  double impulse_duration_s = 0.003;  // 0: an instantaneous jump of angular momentum
  // internal_momentum: |h| drawn in this range of a typical |L| (10 rad/s about the mean
  // moment), in any direction.
  double rotor_fraction_low = 0.005, rotor_fraction_high = 0.10;
  // internal_momentum spun up by a motor after release (rotor_spin_up.hpp) instead of
  // spinning steadily: its axis and |h| (the range above) drawn once from the seed, as for a
  // steady rotor; each throw starts the motor spin_up_start_s after release, with time
  // constant spin_up_time_constant_s and a final speed spin_up_speed_spread either side of
  // the drawn one (each drawn from the throw's seed: a slightly different profile each throw).
  bool rotor_spin_up = false;
  double spin_up_start_low_s = 0.02, spin_up_start_high_s = 0.08;
  double spin_up_time_constant_low_s = 0.04, spin_up_time_constant_high_s = 0.08;
  double spin_up_speed_spread = 0.15;
  // The speed's shape (rotor_spin_up.hpp); a ramp or a smooth step rises over 3 time
  // constants (where a first-order step reaches 95 %).
  SpinUpShape spin_up_shape = SpinUpShape::first_order;

  // A compound flight: a second effect at the same time (empty or "none": one effect).
  // Its magnitude is drawn as for a flight of its own; truth.params then holds each
  // effect's params under its name.
  std::string second_effect;

  // Nonzero: the throw and the noise come from this seed, the effect from generate_flight's
  // seed; flights of one session share their effect (one body, one sensor) but not their
  // throws. An effect sized from the throw (aero_torque, internal_damping, impulse) is
  // sized from each flight's own throw.
  std::uint64_t throw_seed = 0;
};

// What the diagnosis should find. `params` uses the keys of SPEC §4 (plus a few more,
// named below); `equivalent` is the sorted list of effects counted right.
struct FlightTruth {
  std::string effect;
  std::vector<std::string> equivalent;
  // Every injected effect (one, or two for a compound flight) and each one's class.
  std::vector<std::string> effects;
  std::vector<std::vector<std::string>> equivalents;
  nlohmann::json params = nlohmann::json::object();
  std::optional<double> onset_s;                          // impulses only: when the pulse starts
  Eigen::Vector3d omega0_body = Eigen::Vector3d::Zero();  // true w at t = 0, body axes
  std::string body;
  DataKind kind = DataKind::imu;
  double duration_s = 0.0;
};
// params, beyond SPEC §4:
//   inertia_moments: principal_kg_m2 (SPEC, along the nominal principal axes in the
//     ascending order of the nominal moments, sum = nominal sum), principal_nominal_kg_m2,
//     tensor_kg_m2 (the true tensor, body axes).
//   inertia_axes: angle_deg, rotation (SPEC: true principal axes = rotation applied to
//     the nominal ones, i.e. I_true = R I_nom Rᵀ), tensor_kg_m2.
//   sensor_misalignment: angle_deg, rotation (the true sensor -> body rotation, the
//     meaning of body.json's imu.rotation; the nominal one is identity).
//     From a gyro alone, inertia_axes with R is sensor_misalignment with Rᵀ, same angle.
//   internal_damping: model "spherical_rotor_viscous_cavity", rotor_J (kg·m²),
//     c (N·m·s), relaxation_time_s = J / c, energy_loss_fraction (kinetic energy lost
//     over the flight, from the truth).
//   impulse: time_s (pulse start), angular_impulse_N_m_s (body axes), duration_s.
//   aero_torque: k_N_m_s2, L_drop_fraction (|L| lost over the flight, from the truth).
//   gyro_bias: bias_rad_s; gyro_scale: scale_error; clock_drift: rate_error.
//   internal_momentum: h_N_m_s (body axes), h_fraction_of_L (|h| over the throw's |L0|);
//     spun up (FlightSpec::rotor_spin_up): h_N_m_s is h at the flight's end, and
//     final_h_N_m_s, start_s and time_constant_s describe the profile (rise_s too,
//     other than a first-order step's: FlightSpec::spin_up_shape).

// The noise-free truth at each data sample (true time, not the sensor's clock).
struct TrueSample {
  double t_s = 0.0;
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // body -> world
  Eigen::Vector3d omega_body = Eigen::Vector3d::Zero();
  Eigen::Vector3d com_position_m = Eigen::Vector3d::Zero();  // world, markers only
  double kinetic_energy_J = 0.0;
  Eigen::Vector3d angular_momentum_world = Eigen::Vector3d::Zero();  // about the COM
};

struct GeneratedFlight {
  FlightSpec spec;
  std::uint64_t seed = 0;
  host::Body body;            // the nominal body handed to the diagnosis
  std::string body_json;      // the same as SPEC §2 JSON text (body.json)
  host::ImuLog imu;           // filled for DataKind::imu
  host::MarkerTrial markers;  // filled for DataKind::markers
  FlightTruth truth;
  std::vector<TrueSample> true_samples;  // one per data sample
  Eigen::Matrix3d true_inertia_kg_m2 = Eigen::Matrix3d::Identity();
  Eigen::Quaterniond true_imu_to_body = Eigen::Quaterniond::Identity();
  // IMU: the noise as it is in the readings (after the low-pass, if any), per axis: the
  // standard deviation of the added noise sequence itself, the truth a noise floor is
  // measured against.
  Eigen::Vector3d gyro_noise_in_readings_rad_s = Eigen::Vector3d::Zero();
  // IMU: readings per independent sample of that noise, from the filter itself:
  // (sum h)^2 / sum h^2 of its impulse response h (1 without a low-pass), the factor by
  // which a fit that counts readings overstates its evidence.
  double gyro_noise_correlation = 1.0;
};

// Deterministic in (spec, seed) on every platform. The draws come from three
// independent streams of the seed: the throw (duration, w0, orientation, launch,
// markers), the effect's magnitude and the noise; so two specs that differ only in
// their effect share the same throw and the same noise, which the tests use (except
// internal_damping, which may throw again, see above).
// Throws std::invalid_argument for an unknown body or effect, or a sensor effect
// asked of marker data.
GeneratedFlight generate_flight(const FlightSpec& spec, std::uint64_t seed);

nlohmann::json truth_to_json(const FlightTruth& truth);

// How the spec's gyro logs a reading, for logs made beside generate_flight's (a rest before a
// flight): its low-pass at the spec's rate, and the rounding to its quantum (none at 0).
GyroFilter gyro_filter_of(const FlightSpec& spec);
Eigen::Vector3d quantised_reading(const FlightSpec& spec, const Eigen::Vector3d& reading);

}  // namespace aloft::generator
