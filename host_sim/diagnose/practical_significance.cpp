#include "diagnose/practical_significance.hpp"

#include <cmath>
#include <cstdio>

namespace aloft::host::diagnose {
namespace {

std::string text(const char* format, double value) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

}  // namespace

bool matters(const Candidate& c, const RankingContext& context, std::string* why) {
  std::string reason;
  const EffectParameters& p = c.params;
  const double speed = std::max(context.mean_speed, 1e-9);
  const double gap_rad_s = c.reference_rms_rel_err * speed;
  if (context.resolution > 0.0 && gap_rad_s < kResolutionMultiple * context.resolution) {
    reason = text("the held-out gap (%.2g rad/s) is below what the data resolve", gap_rad_s);
  } else {
    switch (c.effect) {
      case Effect::inertia_moments:
        if (context.nominal != nullptr) {
          const double change = (p.principal_kg_m2.cwiseQuotient(context.nominal->principal_moments).array() - 1.0)
                                    .abs()
                                    .maxCoeff();
          if (change < 0.005) reason = text("its moments differ from nominal by at most %.2g %%", 100.0 * change);
        }
        break;
      case Effect::inertia_axes:
      case Effect::sensor_misalignment:
        if (p.angle_deg < 0.25) reason = text("it turns the axes by only %.2g deg", p.angle_deg);
        break;
      case Effect::aero_torque:
        if (context.nominal != nullptr) {
          const double fall = std::abs(p.k_N_m_s2) / (context.nominal->tensor.trace() / 3.0) * speed * context.duration_s;
          if (fall < 0.005) reason = text("|w| would fall by only %.2g %%", 100.0 * fall);
        }
        break;
      case Effect::impulse:
        if (context.nominal != nullptr) {
          const double jump = (context.nominal->tensor.inverse() * p.vector).norm() / speed;
          if (jump < 0.005) reason = text("its jump is %.2g %% of |w|", 100.0 * jump);
        }
        break;
      case Effect::gyro_bias:
        if (p.vector.norm() < 0.001 * speed) reason = text("its bias is %.2g rad/s", p.vector.norm());
        break;
      case Effect::gyro_scale:
        if (p.vector.cwiseAbs().maxCoeff() < 0.001) reason = text("its scale errors are below %.2g %%", 0.1);
        break;
      case Effect::clock_drift:
        if (std::abs(p.rate_error) < 0.001) reason = text("its rate error is %.2g %%", 100.0 * p.rate_error);
        break;
      case Effect::internal_damping:
      case Effect::none:
        break;
    }
  }
  if (why != nullptr) *why = reason;
  return reason.empty();
}

}  // namespace aloft::host::diagnose
