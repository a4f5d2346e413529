#include "diagnose/4_judge/practical_significance.hpp"

#include <algorithm>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "common/printf_text.hpp"

namespace aloft::host::diagnose {

bool matters(const Candidate& c, const RankingContext& context, std::string* why) {
  std::string reason;
  const double speed = std::max(context.mean_speed, 1e-9);
  const double gap_rad_s = c.reference_rms_rel_err * speed;
  if (context.resolution > 0.0 && gap_rad_s < kResolutionMultiple * context.resolution) {
    reason = printf_text("the held-out gap (%.2g rad/s) is below what the data resolve", gap_rad_s);
  } else if (c.shrink < kSmallestShrink) {
    reason = printf_text("it closes only %.1f %% of the held-out gap", 100.0 * c.shrink);
  } else {
    reason = describe(c.effect).hooks.too_small(
        c.params, SignificanceScale{context.nominal, speed, context.duration_s});
  }
  if (why != nullptr) *why = reason;
  return reason.empty();
}

}  // namespace aloft::host::diagnose
