#include "phone_like_flights.hpp"

#include <cmath>

#include "flight_files.hpp"
#include "seeded_random.hpp"

namespace aloft::generator {
namespace {

using Vec3 = Eigen::Vector3d;

constexpr double kStep_s = 0.0002;  // the fine grid the filter runs on (5 kHz)

// The flight's sensor readings without noise on the fine grid (the sensor's clock).
GeneratedFlight clean_fine_flight(FlightSpec spec, std::uint64_t seed) {
  spec.data = DataKind::imu;
  spec.imu_rate_hz = 1.0 / kStep_s;
  spec.gyro_noise_rad_s = 0.0;
  spec.accelerometer = false;
  return generate_flight(spec, seed);
}

// What the gyro reads lying still: its bias (zero rate through any gain or rotation).
Vec3 resting_reading(const FlightTruth& truth) {
  Vec3 bias = Vec3::Zero();
  auto add = [&](const nlohmann::json& params) {
    if (params.contains("bias_rad_s")) {
      for (int a = 0; a < 3; ++a) bias(a) += params["bias_rad_s"][std::size_t(a)].get<double>();
    }
  };
  if (truth.effects.size() > 1) {
    for (const auto& e : truth.effects) add(truth.params[e]);
  } else {
    add(truth.params);
  }
  return bias;
}

PhoneGyroSpec draw_phone(SeededRandom& rng) {
  PhoneGyroSpec g;
  g.rate_hz = rng.uniform(100.0, 500.0);
  g.cutoff_hz = rng.uniform(15.0, 40.0);
  g.noise_rad_s = rng.uniform(0.005, 0.02);
  g.quantum_rad_s = 0.001;
  g.jitter = 0.02;
  return g;
}

// Appends `seconds` of the phone lying still; returns nothing.
void rest(std::vector<Vec3>& fine, const Vec3& reading, double seconds) {
  const long n = std::lround(seconds / kStep_s);
  fine.insert(fine.end(), static_cast<std::size_t>(n), reading);
}

// Appends a straight ramp from the last reading to `to` over `seconds` (the hand
// spinning the body up, or stopping it); a reading is linear in the rate, so a ramp of
// the rate is a ramp of the reading whatever the sensor model.
void ramp(std::vector<Vec3>& fine, const Vec3& to, double seconds) {
  const Vec3 from = fine.back();
  const long n = std::lround(seconds / kStep_s);
  for (long k = 1; k < n; ++k)
    fine.push_back(from + (to - from) * (static_cast<double>(k) / static_cast<double>(n)));
}

// Appends one throw: the spin-up in the hand (0.1-0.2 s), the flight's clean readings
// and the catch (0.03-0.05 s) back to `still`. Returns the flight's window (release to
// catch) on the log's clock.
host::Segment append_throw(std::vector<Vec3>& fine, const GeneratedFlight& g, const Vec3& still,
                           const std::string& name, SeededRandom& rng) {
  ramp(fine, g.imu.gyro_rad_s.front(), rng.uniform(0.1, 0.2));
  const double start = static_cast<double>(fine.size()) * kStep_s;
  fine.insert(fine.end(), g.imu.gyro_rad_s.begin(), g.imu.gyro_rad_s.end());
  ramp(fine, still, rng.uniform(0.03, 0.05));
  return {name, start, start + g.imu.time_s.back(), ""};
}

void move_onset(FlightTruth& truth, double start_s) {
  if (truth.onset_s) *truth.onset_s += start_s;
  if (truth.effects.size() <= 1 && truth.params.contains("time_s")) {
    truth.params["time_s"] = truth.params["time_s"].get<double>() + start_s;
  }
}

}  // namespace

PhoneLikeFlight generate_phone_like_flight(const FlightSpec& spec, std::uint64_t seed) {
  PhoneLikeFlight out;
  GeneratedFlight g = clean_fine_flight(spec, seed);
  SeededRandom phone(seed ^ 0x50686f6e654c696bULL);
  out.gyro = draw_phone(phone);
  const Vec3 still = resting_reading(g.truth);
  std::vector<Vec3> fine;
  rest(fine, still, phone.uniform(1.0, 2.0));
  out.window = append_throw(fine, g, still, "flight", phone);
  rest(fine, still, phone.uniform(1.0, 2.0));
  out.flight = std::move(g);
  out.flight.spec = spec;
  out.flight.imu = read_phone_gyro(fine, kStep_s, out.gyro, phone);
  out.flight.imu.path = "imu.csv";
  move_onset(out.flight.truth, out.window.start_s);
  out.segments_csv = std::string(kSegmentsHeader) + segment_row(out.window);
  return out;
}

PhoneLikeSession generate_phone_like_session(const FlightSpec& spec, int flights, std::uint64_t seed) {
  PhoneLikeSession out;
  SeededRandom phone(seed ^ 0x53657373696f6e21ULL);
  out.gyro = draw_phone(phone);
  std::vector<Vec3> fine;
  out.segments_csv = kSegmentsHeader;
  for (int i = 0; i < flights; ++i) {
    FlightSpec one = spec;
    one.throw_seed = seed + 0x9E3779B1ull * static_cast<std::uint64_t>(i + 1);
    GeneratedFlight g = clean_fine_flight(one, seed);
    const Vec3 still = resting_reading(g.truth);
    if (i == 0) rest(fine, still, phone.uniform(1.0, 2.0));
    out.flights.push_back(append_throw(fine, g, still, "flight" + std::to_string(i + 1), phone));
    rest(fine, still, phone.uniform(1.0, 2.0));
    move_onset(g.truth, out.flights.back().start_s);
    out.truths.push_back(g.truth);
    out.segments_csv += segment_row(out.flights.back());
    // A throw the user marked as no flight (phone caught early), times left blank.
    if (i == 0) out.segments_csv += "dropped,,,false,caught at once\n";
    if (i == 0) out.first = std::move(g);
  }
  out.first.spec = spec;
  out.log = read_phone_gyro(fine, kStep_s, out.gyro, phone);
  out.log.path = "imu.csv";
  out.first.imu = out.log;
  return out;
}

}  // namespace aloft::generator
