// The made-up box of a new user's first hour (issue 26 item 5): a 1 kg box of 0.3 x 0.2 x
// 0.1 m, its body file with Iy 3 % high, thrown and logged at 500 Hz by a gyro with white
// noise; for a session, between throws it lies still on a table, where the accelerometer
// reads gravity. The flights come from `aloft simulate` on the true box, so the fixture
// needs no other simulator; the log is written in whatever units the test asks for, as a
// user's logger would write it.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "run_aloft.hpp"

namespace aloft::test {

struct Sample {
  double t = 0.0;
  double gyro[3] = {0.0, 0.0, 0.0};
  double accel[3] = {0.0, 0.0, 0.0};
};

struct Units {
  double time = 1.0;   // written value per second
  double gyro = 1.0;   // per rad/s
  double accel = 1.0;  // per m/s^2
};

constexpr double kRate_hz = 500.0;
constexpr double kDegreesPerRadian = 57.29577951308232;
constexpr double kGravity = 9.80665;

inline const std::string kTrueBox = R"({"name": "made-up box", "mass": 1.0,
  "inertia": {"shape": {"box": {"x": 0.3, "y": 0.2, "z": 0.1}}}})";

// The same box with Iy 3 % high: principal moments of the box above, y times 1.03.
inline std::string nominal_box_json() {
  const double ix = (0.2 * 0.2 + 0.1 * 0.1) / 12.0, iy = (0.3 * 0.3 + 0.1 * 0.1) / 12.0,
               iz = (0.3 * 0.3 + 0.2 * 0.2) / 12.0;
  char text[200];
  std::snprintf(text, sizeof text,
                R"({"name": "made-up box", "mass": 1.0, "inertia": {"principal": [%.9g, %.9g, %.9g]}})", ix,
                1.03 * iy, iz);
  return text;
}

// Deterministic noise, about normal (sum of 4 uniforms), unit variance.
class Noise {
 public:
  double next() {
    double sum = 0.0;
    for (int i = 0; i < 4; ++i) {
      state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
      sum += static_cast<double>(state_ >> 11) / 9007199254740992.0 - 0.5;
    }
    return sum * std::sqrt(3.0);
  }

 private:
  std::uint64_t state_ = 26;
};

// One throw of the true box from body rate w0 (rad/s), 0.8 s long, starting at t0: the
// rates of `aloft simulate`, with 0.01 rad/s of noise, a free-fall accelerometer.
inline std::vector<Sample> throw_of(const ScratchDir& dir, const std::string& w0, double t0, Noise& noise) {
  const std::string body = dir.write("true_box.json", kTrueBox), out = dir.path("throw.csv");
  const RunResult r =
      run_aloft(dir, "simulate --body " + body + " --w0 " + w0 + " --duration 0.8 --rate 500 --out " + out);
  if (r.exit_code != 0) throw std::runtime_error("simulate failed: " + r.err);
  std::istringstream rows(read_file(out));
  std::string row;
  std::getline(rows, row);  // t,qw,qx,qy,qz,wx,wy,wz
  std::vector<Sample> samples;
  while (std::getline(rows, row)) {
    double v[8];
    if (std::sscanf(row.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5],
                    &v[6], &v[7]) != 8)
      continue;
    Sample s;
    s.t = t0 + v[0];
    for (int k = 0; k < 3; ++k) {
      s.gyro[k] = v[5 + k] + 0.01 * noise.next();
      s.accel[k] = 0.05 * noise.next();
    }
    samples.push_back(s);
  }
  return samples;
}

// The box still on a table for `seconds` from t0: gyro noise, gravity along z.
inline std::vector<Sample> rest_of(double t0, double seconds, Noise& noise) {
  std::vector<Sample> samples;
  const int n = static_cast<int>(std::lround(seconds * kRate_hz));
  for (int i = 0; i < n; ++i) {
    Sample s;
    s.t = t0 + i / kRate_hz;
    for (int k = 0; k < 3; ++k) {
      s.gyro[k] = 0.01 * noise.next();
      s.accel[k] = 0.05 * noise.next() + (k == 2 ? kGravity : 0.0);
    }
    samples.push_back(s);
  }
  return samples;
}

struct Session {
  std::vector<Sample> samples;
  std::vector<std::pair<double, double>> flights;  // start, end (s)
};

// 1 s of rest, then three throws each followed by 1 s of rest.
inline Session made_up_session(const ScratchDir& dir) {
  Noise noise;
  Session session;
  double t = 0.0;
  auto append = [&](const std::vector<Sample>& part) {
    session.samples.insert(session.samples.end(), part.begin(), part.end());
    t = session.samples.back().t + 1.0 / kRate_hz;
  };
  append(rest_of(t, 1.0, noise));
  for (const char* w0 : {"4,8,3", "6,3,5", "2,9,1.5"}) {
    const double start = t;
    append(throw_of(dir, w0, t, noise));
    session.flights.push_back({start, session.samples.back().t});
    append(rest_of(t, 1.0, noise));
  }
  return session;
}

// A single throw, the whole log one flight.
inline std::vector<Sample> made_up_throw(const ScratchDir& dir) {
  Noise noise;
  return throw_of(dir, "4,8,3", 0.0, noise);
}

// The log as CSV in `units`: t,gx,gy,gz[,ax,ay,az].
inline std::string imu_csv(const std::vector<Sample>& samples, const Units& units, bool accel) {
  std::string text = accel ? "t,gx,gy,gz,ax,ay,az\n" : "t,gx,gy,gz\n";
  char row[200];
  for (const Sample& s : samples) {
    std::snprintf(row, sizeof row, "%.6f,%.6f,%.6f,%.6f", s.t * units.time, s.gyro[0] * units.gyro,
                  s.gyro[1] * units.gyro, s.gyro[2] * units.gyro);
    text += row;
    if (accel) {
      std::snprintf(row, sizeof row, ",%.5f,%.5f,%.5f", s.accel[0] * units.accel, s.accel[1] * units.accel,
                    s.accel[2] * units.accel);
      text += row;
    }
    text += '\n';
  }
  return text;
}

// segment,start,end for each flight, times multiplied by `time`.
inline std::string segments_csv(const Session& session, double time = 1.0) {
  std::string text = "segment,start,end\n";
  char row[120];
  for (std::size_t i = 0; i < session.flights.size(); ++i) {
    std::snprintf(row, sizeof row, "throw%zu,%.6f,%.6f\n", i + 1, session.flights[i].first * time,
                  session.flights[i].second * time);
    text += row;
  }
  return text;
}

}  // namespace aloft::test
