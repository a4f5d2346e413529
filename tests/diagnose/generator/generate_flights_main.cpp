// aloft_generate_flights: writes generated flights to a folder, one sub-folder per
// flight (body.json, imu.csv or markers.trc, truth.json) and a truth.json over all of
// them, so `aloft diagnose` can be run on them end to end during development.
//
//   aloft_generate_flights --out DIR                 the withheld-effect cases
//   aloft_generate_flights --out DIR --random 20 --seed 7   20 random flights
//   aloft_generate_flights --out DIR --compound      the compound (two-effect) cases
//   aloft_generate_flights --out DIR --phone         the phone-like flights and sessions
//                                                    (imu.csv is the whole log; the
//                                                    flights are in segments.csv)
//   aloft_generate_flights --out DIR --flight-controller   flight-controller sessions, one
//                                                    of each kind (a spin-up rotor and its
//                                                    look-alikes), laid out as --phone's;
//                                                    --sessions N of each, --spin-up-shape
//                                                    ramp or smooth_step for the wheels,
//                                                    --seed the first of a new set (as the
//                                                    spin-up test's ALOFT_SPIN_UP_SEEDS),
//                                                    --log-rotor: the spin-up sessions' body
//                                                    files name the wheel (SPEC §2 `rotor`) and
//                                                    their logs its speed (`rotor_rad_s`)
#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "body_catalogue.hpp"
#include "compound_effect_cases.hpp"
#include "flight_controller_cases.hpp"
#include "common/atomic_file.hpp"
#include "common/commands.hpp"
#include "common/usage_error.hpp"
#include "flight_files.hpp"
#include "phone_like_cases.hpp"
#include "phone_like_flights.hpp"
#include "seeded_random.hpp"
#include "withheld_effect_cases.hpp"

namespace {

using namespace aloft::generator;

std::vector<FlightCase> random_cases(int count, std::uint64_t seed) {
  SeededRandom rng(seed);
  std::vector<FlightCase> cases;
  for (int i = 0; i < count; ++i) {
    FlightCase c;
    c.spec.effect = effect_names()[std::size_t(rng.index(int(effect_names().size())))];
    c.spec.body = body_names()[std::size_t(rng.index(int(body_names().size())))];
    const bool markers = !is_sensor_effect(c.spec.effect) && rng.uniform() < 0.35;
    c.spec.data = markers ? DataKind::markers : DataKind::imu;
    c.seed = seed * 1000003ull + std::uint64_t(i);
    char name[32];
    std::snprintf(name, sizeof name, "case%02d", i);
    c.name = name;
    cases.push_back(c);
  }
  return cases;
}

// Writes `flight` (its imu is the whole log) and its segments file into out/name.
void write_logged(const GeneratedFlight& flight, const std::string& segments_csv, const std::string& out,
                  const std::string& name, std::uint64_t seed, nlohmann::json& all) {
  const std::filesystem::path dir = std::filesystem::path(out) / name;
  write_flight(flight, dir.string());
  aloft::host::write_file_atomically((dir / "segments.csv").string(),
                                     [&](std::ostream& o) { o << segments_csv; });
  nlohmann::json truth = truth_to_json(flight.truth);
  truth["seed"] = seed;
  all[name] = truth;
  std::cout << name << "/imu.csv + segments.csv  " << flight.truth.effect << " on " << flight.truth.body
            << "\n";
}

void write_phone_like(const std::string& out, nlohmann::json& all) {
  for (const FlightCase& c : phone_like_flight_cases()) {
    const PhoneLikeFlight p = generate_phone_like_flight(c.spec, c.seed);
    write_logged(p.flight, p.segments_csv, out, c.name, c.seed, all);
  }
  for (const PhoneSessionCase& c : phone_like_session_cases()) {
    const PhoneLikeSession s = generate_phone_like_session(c.flight.spec, c.flights, c.flight.seed);
    write_logged(s.first, s.segments_csv, out, c.flight.name, c.flight.seed, all);
  }
}

// A wheel of kLoggedWheel_kg_m2 about its spin axis (a reaction wheel of some 50 g): at
// the generated |h| of 0.01-0.1 N m s it turns at 50-500 rad/s.
constexpr double kLoggedWheel_kg_m2 = 2e-4;

// With --log-rotor: the wheel of a spin-up session in its body file (`rotor`, about the h
// the session shares) and its speed in each sample of flight `g` (exact, unquantised).
void log_rotor(GeneratedFlight& g, nlohmann::json& body) {
  const nlohmann::json& p = g.truth.params;
  Eigen::Vector3d final_h;
  for (int i = 0; i < 3; ++i) final_h(i) = p["final_h_N_m_s"][i].get<double>();
  const Eigen::Vector3d axis = final_h.normalized();
  body["rotor"] = {{"inertia_kg_m2", kLoggedWheel_kg_m2}, {"axis", {axis(0), axis(1), axis(2)}}};
  const SpinUpShape shape = spin_up_shape_named(p["shape"].get<std::string>());
  const RotorSpinUp wheel{final_h, p["start_s"].get<double>(), p["time_constant_s"].get<double>(), shape,
                          p.value("rise_s", 0.0)};
  g.imu.rotor_rad_s.clear();
  for (double t : g.imu.time_s)
    g.imu.rotor_rad_s.push_back(wheel.momentum(t - g.imu.time_s.front()).dot(axis) / kLoggedWheel_kg_m2);
}

// The flights of a session one after another in one log, each on its own clock moved on to
// kBetweenFlights_s after the last one's end (the log has no samples there, as a flight
// controller's log between two armings), with a segments file naming each.
constexpr double kBetweenFlights_s = 1.0;
// `first_seed`: none for the fresh set.
void write_flight_controller(const std::string& out, int per_kind, SpinUpShape shape,
                             std::optional<std::uint64_t> first_seed, bool with_rotor, nlohmann::json& all) {
  const std::vector<SessionCase> cases =
      first_seed ? flight_controller_session_cases(*first_seed, per_kind, 4, shape)
                 : flight_controller_session_cases(RotorSeeds::fresh, per_kind, 4, shape);
  for (const SessionCase& c : cases) {
    GeneratedFlight joined;
    std::string segments = kSegmentsHeader;
    double offset = 0.0;
    for (std::size_t j = 0; j < c.flights.size(); ++j) {
      GeneratedFlight g = generate_flight(c.flights[j], c.seed);
      if (with_rotor && g.truth.params.contains("final_h_N_m_s")) {
        nlohmann::json body = nlohmann::json::parse(g.body_json);
        log_rotor(g, body);
        g.body_json = body.dump(2) + "\n";
      }
      if (j == 0) joined = g;
      aloft::host::ImuLog& log = joined.imu;
      if (j > 0) {
        for (double t : g.imu.time_s) log.time_s.push_back(offset + t);
        log.gyro_rad_s.insert(log.gyro_rad_s.end(), g.imu.gyro_rad_s.begin(), g.imu.gyro_rad_s.end());
        log.accel_m_s2.insert(log.accel_m_s2.end(), g.imu.accel_m_s2.begin(), g.imu.accel_m_s2.end());
        log.rotor_rad_s.insert(log.rotor_rad_s.end(), g.imu.rotor_rad_s.begin(), g.imu.rotor_rad_s.end());
      }
      segments += segment_row({"flight" + std::to_string(j + 1), offset + g.imu.time_s.front(),
                               offset + g.imu.time_s.back(), ""});
      offset = log.time_s.back() + kBetweenFlights_s;
    }
    write_logged(joined, segments, out, c.name, c.seed, all);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Write generated flights with one withheld effect each (SPEC §3 files)."};
  std::string out_dir;
  int random_count = 0;
  std::uint64_t seed = 1;
  int limit = -1;
  bool phone = false;
  bool compound = false;
  bool flight_controller = false;
  std::string spin_up_shape = "first_order";
  int sessions_per_kind = 1;
  bool log_rotor_speed = false;
  app.add_option("--out", out_dir, "folder to write into")->required();
  app.add_flag("--compound", compound, "write the compound flights, two effects each (issue 8)");
  app.add_flag("--phone", phone, "write the phone-like flights and sessions (issue 8)");
  app.add_flag(
      "--flight-controller", flight_controller,
      "write flight-controller sessions: a rotor spun up after release and its look-alikes (issue 44)");
  app.add_option("--spin-up-shape", spin_up_shape,
                 "with --flight-controller: how the wheels spin up (first_order, ramp: a motor at its "
                 "current limit, smooth_step)")
      ->check(CLI::IsMember(
          std::vector<std::string>(std::begin(kSpinUpShapeNames), std::end(kSpinUpShapeNames))));
  app.add_flag("--log-rotor", log_rotor_speed,
               "with --flight-controller: the spin-up sessions' body files name the wheel and their logs "
               "its speed (rotor_rad_s)");
  app.add_option("--sessions", sessions_per_kind,
                 "with --flight-controller: sessions of each kind (the fresh seeds of the spin-up test)")
      ->check(CLI::Range(1, 100));
  app.add_option("--random", random_count,
                 "write this many random flights instead of the "
                 "withheld-effect cases")
      ->check(CLI::PositiveNumber);
  app.add_option(
      "--seed", seed,
      "seed of the random flights; with --flight-controller, the first seed of a new set (default: "
      "the fresh set)");
  app.add_option("--limit", limit, "write only the first N flights")->check(CLI::NonNegativeNumber);
  if (const auto code = aloft::host::parse_command_line(app, argc, argv)) return *code;

  try {
    if (phone || flight_controller) {
      nlohmann::json all = nlohmann::json::object();
      if (phone) write_phone_like(out_dir, all);
      if (flight_controller)
        write_flight_controller(out_dir, sessions_per_kind, spin_up_shape_named(spin_up_shape),
                                app.count("--seed") > 0 ? std::optional<std::uint64_t>(seed) : std::nullopt,
                                log_rotor_speed, all);
      aloft::host::write_file_atomically((std::filesystem::path(out_dir) / "truth.json").string(),
                                         [&](std::ostream& o) { o << all.dump(1) << '\n'; });
      return 0;
    }
    std::vector<FlightCase> cases = random_count > 0 ? random_cases(random_count, seed)
                                    : compound       ? compound_effect_cases()
                                                     : withheld_effect_cases();
    if (limit >= 0 && std::size_t(limit) < cases.size()) cases.resize(std::size_t(limit));
    nlohmann::json all = nlohmann::json::object();
    for (const FlightCase& c : cases) {
      const GeneratedFlight flight = generate_flight(c.spec, c.seed);
      const std::string data_file = write_flight(flight, (std::filesystem::path(out_dir) / c.name).string());
      nlohmann::json truth = truth_to_json(flight.truth);
      truth["seed"] = c.seed;
      all[c.name] = truth;
      std::cout << c.name << "/" << data_file << "  " << flight.truth.effect << " on " << flight.truth.body
                << "\n";
    }
    aloft::host::write_file_atomically((std::filesystem::path(out_dir) / "truth.json").string(),
                                       [&](std::ostream& o) { o << all.dump(1) << '\n'; });
    std::cout << cases.size() << " flights written to " << out_dir << "\n";
  } catch (const std::exception& e) {
    std::cerr << "aloft_generate_flights: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
