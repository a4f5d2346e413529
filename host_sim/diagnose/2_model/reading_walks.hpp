// The walks of a prediction (flight_model.cpp) from the reference sample outwards through
// the segments of their layout (walk_layout.hpp): each segment integrated by the flight's
// dynamics (flight_dynamics.hpp), the readings at its ends read and those between
// interpolated; and two independent walks stepped side by side. Header-only: inlined into
// the prediction's loops.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <vector>

#include "diagnose/2_model/flight_dynamics.hpp"
#include "diagnose/2_model/read_samples.hpp"
#include "diagnose/2_model/walk_layout.hpp"

namespace aloft::host::diagnose {

// The walks of predict_readings from the reference sample outwards, one segment of
// their layout (walk_layout.hpp) at a time.
class ReadingWalks {
 public:
  using Vec3 = Eigen::Vector3d;

  ReadingWalks(const FlightDynamics& dynamics, double jump_time, std::vector<Vec3>& readings,
               const std::vector<HermiteWeights>& weights, Vec3* rate_at_impulse, ReadSamples read)
      : d_(dynamics),
        readings_(readings),
        weights_(weights),
        rate_at_impulse_(rate_at_impulse),
        t_jump_(jump_time),
        read_(read) {}

  // A walk at its latest sample: the state there and, when the segment that ended there
  // interpolated, the readings' rate of change there (the next segment starts with it).
  struct Walk {
    Motion m;
    std::size_t at = 0;
    bool slope_known = false;
    Vec3 slope = Vec3::Zero();  // d reading / dt, without the segment's length
  };

  // One segment of a walk, on its own.
  void step(Walk& walk, const WalkSegment& seg) const {
    Motion& x = walk.m;
    const double a = seg.a, b = seg.b;
    if (seg.crosses) {
      const bool forwards = seg.to > seg.from;
      // Forwards: to the impulse, add it, on if it is before b. Backwards: to the impulse
      // if it is before a, take it away, on.
      if (forwards) {
        d_.advance(x, a, t_jump_);
        if (rate_at_impulse_ != nullptr) *rate_at_impulse_ = x.x.head<3>();
        d_.apply_jump(x, 1.0);
        if (b > t_jump_) d_.advance(x, t_jump_, b);
      } else {
        if (a > t_jump_) d_.advance(x, a, t_jump_);
        if (rate_at_impulse_ != nullptr) *rate_at_impulse_ = x.x.head<3>();
        d_.apply_jump(x, -1.0);
        d_.advance(x, t_jump_, b);
      }
      readings_[seg.to] = d_.reading(x.x);
      walk.at = seg.to;
      walk.slope_known = false;
      return;
    }
    const Motion start = x;
    d_.advance(x, seg.steps, seg.h);
    read_segment(start, walk, seg);
  }

  // The readings of a segment integrated from `x_from` at sample `from` to `x_to` at
  // `to`: the end's own, and those between by cubic Hermite interpolation of the rate
  // (its error, h^4 |d4w/dt4| / 384, is 1e-6 rad/s for a 15 rad/s tumble over 5 ms),
  // made on the readings: they are affine in the rate, and the basis weights of the two
  // ends sum to one, so interpolating the readings with the rate's derivatives mapped
  // as the rate is (sensor_map) is interpolating the rate.
  // `walk` has been integrated to `to` from `x_from`, its state at walk.at.
  void read_segment(const Motion& x_from, Walk& walk, const WalkSegment& seg) const {
    const std::size_t from = seg.from, to = seg.to;
    walk.at = to;
    readings_[to] = d_.reading(walk.m.x);
    if (to == from + 1 || from == to + 1) {
      walk.slope_known = false;
      return;
    }
    const Vec3 slope_from = walk.slope_known ? walk.slope : d_.sensor_map(d_.body_rate_derivative(x_from));
    walk.slope = d_.sensor_map(d_.body_rate_derivative(walk.m));
    walk.slope_known = true;
    const double h = seg.b - seg.a;
    const Vec3 r0 = readings_[from], r1 = readings_[to];
    const Vec3 g0 = slope_from * h, g1 = walk.slope * h;
    const std::size_t lo = std::min(from, to), hi = std::max(from, to);
    if (!wanted_between(lo, hi)) {
      for (std::size_t k = lo + 1; k < hi; ++k) readings_[k].setZero();
      return;
    }
    const HermiteWeights* w = &weights_[seg.weights];
    for (std::size_t k = lo + 1; k < hi; ++k, ++w) {
      readings_[k] = (*w)[0] * r0 + (*w)[1] * r1 + (*w)[2] * g0 + (*w)[3] * g1;
    }
  }

  // Some sample strictly between lo and hi is wanted (read_): a segment lies nearly always
  // wholly inside a fold's chunk or outside it, so it is interpolated whole or not at all.
  bool wanted_between(std::size_t lo, std::size_t hi) const {
    for (std::size_t k = lo + 1; k < hi; ++k) {
      if (read_.wanted(k)) return true;
    }
    return false;
  }

 private:
  const FlightDynamics& d_;
  std::vector<Vec3>& readings_;
  const std::vector<HermiteWeights>& weights_;
  Vec3* rate_at_impulse_ = nullptr;  // where the walk that meets the impulse reaches it
  double t_jump_ = 0.0;
  ReadSamples read_;  // the samples between steps worth interpolating
};

// Two independent walks, each through its own segments into its own readings: while both
// have segments to go, they step together (advance_pair(a, a_steps, a_h, b, b_steps, b_h):
// FlightDynamics::advance_pair or advance_two) where neither crosses the impulse.
template <class AdvancePair>
void walk_together(const AdvancePair& advance_pair, const ReadingWalks& walks_a, ReadingWalks::Walk& a,
                   const std::vector<WalkSegment>& segments_a, const ReadingWalks& walks_b,
                   ReadingWalks::Walk& b, const std::vector<WalkSegment>& segments_b) {
  const std::size_t both = std::min(segments_a.size(), segments_b.size());
  for (std::size_t i = 0; i < both; ++i) {
    const WalkSegment &u = segments_a[i], &d = segments_b[i];
    if (!u.crosses && !d.crosses) {
      const Motion a_from = a.m, b_from = b.m;
      advance_pair(a.m, u.steps, u.h, b.m, d.steps, d.h);
      walks_a.read_segment(a_from, a, u);
      walks_b.read_segment(b_from, b, d);
    } else {
      walks_a.step(a, u);
      walks_b.step(b, d);
    }
  }
  for (std::size_t i = both; i < segments_a.size(); ++i) walks_a.step(a, segments_a[i]);
  for (std::size_t i = both; i < segments_b.size(); ++i) walks_b.step(b, segments_b[i]);
}

}  // namespace aloft::host::diagnose
