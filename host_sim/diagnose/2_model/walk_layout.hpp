// Where the two walks of predict_readings (flight_model.hpp) step and what they
// interpolate. From the reference sample one walk goes forwards and one backwards, a
// segment at a time: several samples no further apart than the longest shared segment
// (one integration, the readings between by cubic Hermite), or one longer interval
// (integrated in steps of at most kMaxStep), or the one interval the impulse falls in.
//
// All of it follows from the flight's time stamps, the reference sample, the longest
// segment, whether the model has a rotor (one sample a segment), and the model's clock
// factor and impulse time: never from the rates or the other parameters. A fit predicts
// one flight hundreds of times under one layout, so a layout is made once and kept (the
// few latest, per thread): the segments' ends, true times and steps, and the Hermite
// weights of every sample between, each computed by the same expression as before, so
// the readings are the same bit for bit. Case00 (callgrind, one thread): 516.5 -> 458.3 M
// instructions; the 65 reports of make_reports.sh byte-identical.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace aloft::host::diagnose {

// Longest integration step: RK4 at 5 ms keeps the relative error of a 15 rad/s motion
// near 1e-6 over a second, far below any gyro's noise.
constexpr double kMaxStep = 0.005;

// The steps of at most kMaxStep that cover a span (either sign), and their length.
int steps_over(double span);
double step_of(double span, int steps);

// One segment of a walk, from sample `from` to `to` (either direction).
struct WalkSegment {
  std::size_t from = 0, to = 0;
  double a = 0.0, b = 0.0;  // true (simulation) times of from and to
  bool crosses = false;     // the impulse falls in it (then it is one interval)
  int steps = 1;            // rk4 steps over [a, b] when it does not cross
  double h = 0.0;           // their length
  std::size_t weights = 0;  // where its interpolated samples' weights start in WalkLayout::weights
};

// Cubic Hermite weights of an interpolated sample, of (reading at from, reading at to,
// slope at from times the segment's length, slope at to times it).
using HermiteWeights = std::array<double, 4>;

struct WalkLayout {
  std::vector<WalkSegment> up, down;    // forwards and backwards from the reference
  std::vector<HermiteWeights> weights;  // per segment, its samples between from and to, in index order
};

// What a layout depends on besides the time stamps.
struct WalkLayoutKey {
  std::size_t ref = 0;
  double max_segment = 0.0;     // samples this close share one integration (0: none do)
  bool single_samples = false;  // one sample a segment whatever the spacing (a rotor)
  bool has_jump = false;
  double jump_time = 0.0;    // true time of the impulse (has_jump only)
  double time_factor = 1.0;  // true time = t_ref + (stamp - t_ref) * time_factor

  bool operator==(const WalkLayoutKey& o) const {
    return ref == o.ref && max_segment == o.max_segment && single_samples == o.single_samples &&
           has_jump == o.has_jump && jump_time == o.jump_time && time_factor == o.time_factor;
  }
};

// The layout of a flight with time stamps `time_s` under `key`, from this thread's cache
// when it was made lately. The reference stays valid until this thread's next call.
const WalkLayout& walk_layout(const std::vector<double>& time_s, const WalkLayoutKey& key);

}  // namespace aloft::host::diagnose
