#include "diagnose/2_model/walk_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace aloft::host::diagnose {
namespace {

// Layouts kept per thread. A time search alternates between a few impulse times and the
// nominal model, and a fold's fit shares its flight's layout. Case00 (callgrind): one kept
// 460.1 M instructions, four 458.3 M, eight 458.0 M; each about 40 kB for 1.2 s at 1 kHz.
constexpr std::size_t kKeptLayouts = 4;

class LayoutBuilder {
 public:
  LayoutBuilder(const std::vector<double>& time_s, const WalkLayoutKey& key)
      : time_s_(time_s), key_(key), t_ref_(time_s[key.ref]) {}

  WalkLayout build() const {
    WalkLayout layout;
    // At most a segment and a sample's weights a sample: grown once, not doubling (a time
    // search makes a layout for every impulse time it tries: case00 367.9 -> 366.2 M).
    const std::size_t n = time_s_.size();
    layout.weights.reserve(n);
    layout.up.reserve(n - key_.ref);
    layout.down.reserve(key_.ref);
    walk(layout, layout.up, true);
    walk(layout, layout.down, false);
    return layout;
  }

 private:
  double true_time(std::size_t k) const { return t_ref_ + (time_s_[k] - t_ref_) * key_.time_factor; }

  // Whether the impulse falls between samples a and b (strictly after the earlier, on or
  // before the later one).
  bool crosses(std::size_t a, std::size_t b) const {
    const double early = true_time(std::min(a, b)), late = true_time(std::max(a, b));
    return key_.has_jump && key_.jump_time > early && key_.jump_time <= late;
  }

  // The last sample of the segment that starts at `at`. Decided on the time stamps, not
  // the true times, so that a clock-drift parameter never moves a segment's end (the
  // readings stay smooth in it).
  std::size_t segment_end(std::size_t at, bool forwards) const {
    const std::size_t n = time_s_.size();
    const auto next = [&](std::size_t k) { return forwards ? k + 1 : k - 1; };
    std::size_t end = next(at);
    if (crosses(at, end) || key_.single_samples) return end;
    while (forwards ? end + 1 < n : end > 0) {
      const std::size_t further = next(end);
      const double span = std::abs(time_s_[further] - time_s_[at]);
      if (span > key_.max_segment * (1.0 + 1e-9) || crosses(end, further)) break;
      end = further;
    }
    return end;
  }

  void walk(WalkLayout& layout, std::vector<WalkSegment>& segments, bool forwards) const {
    const std::size_t n = time_s_.size();
    std::size_t at = key_.ref;
    while (forwards ? at + 1 < n : at > 0) {
      WalkSegment s;
      s.from = at;
      s.to = segment_end(at, forwards);
      s.a = true_time(s.from);
      s.b = true_time(s.to);
      s.crosses = crosses(s.from, s.to);
      s.steps = steps_over(s.b - s.a);
      s.h = step_of(s.b - s.a, s.steps);
      s.weights = layout.weights.size();
      if (!s.crosses) add_weights(layout, s);
      segments.push_back(s);
      at = s.to;
    }
  }

  // The Hermite weights of the samples strictly between the segment's ends.
  void add_weights(WalkLayout& layout, const WalkSegment& seg) const {
    const double t0 = seg.a, h = seg.b - t0;
    const std::size_t lo = std::min(seg.from, seg.to), hi = std::max(seg.from, seg.to);
    for (std::size_t k = lo + 1; k < hi; ++k) {
      const double s = (true_time(k) - t0) / h, s2 = s * s, s3 = s2 * s;
      layout.weights.push_back({2.0 * s3 - 3.0 * s2 + 1.0, 3.0 * s2 - 2.0 * s3, s3 - 2.0 * s2 + s, s3 - s2});
    }
  }

  const std::vector<double>& time_s_;
  WalkLayoutKey key_;
  double t_ref_;
};

struct KeptLayout {
  std::vector<double> time_s;
  WalkLayoutKey key;
  WalkLayout layout;
};

// The same time stamps bit for bit (a byte comparison: a tenth of comparing them as numbers).
bool same_stamps(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

}  // namespace

int steps_over(double span) {
  // One step a sample at kHz rates: no divisions (the same count either way).
  if (std::abs(span) < kMaxStep) return 1;
  return std::max(1, static_cast<int>(std::ceil(std::abs(span) / kMaxStep - 1e-9)));
}

double step_of(double span, int steps) { return steps == 1 ? span : span / steps; }

const WalkLayout& walk_layout(const std::vector<double>& time_s, const WalkLayoutKey& key) {
  thread_local std::vector<KeptLayout> kept;  // the latest used last
  for (std::size_t i = kept.size(); i-- > 0;) {
    if (kept[i].key == key && same_stamps(kept[i].time_s, time_s)) {
      std::rotate(kept.begin() + static_cast<long>(i), kept.begin() + static_cast<long>(i) + 1, kept.end());
      return kept.back().layout;
    }
  }
  if (kept.size() == kKeptLayouts) kept.erase(kept.begin());
  kept.push_back({time_s, key, LayoutBuilder(time_s, key).build()});
  return kept.back().layout;
}

}  // namespace aloft::host::diagnose
