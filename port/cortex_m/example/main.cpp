// Example firmware: the onboard check (aloft::OnboardCheck<float, 8>) run over a flight
// recorded in flash (recorded_flight.hpp), as it would run on a thrown sensor. Prints the
// RMS deviation angle for the comparison with the host's double-precision answer
// (host/reference_rms_da.cpp), and the SysTick counts the footprint measurement reads.
//
// Built twice: as is, and with ALOFT_EXAMPLE_WITHOUT_ALOFT, where the check is replaced by
// a trivial use of each sample. Everything else is identical, so the difference of the two
// images is aloft's share of flash and RAM, and the difference of their loop timings is
// the cost of an update.
#include <cstdint>
#include <optional>

#include "aloft_port/report_writer.hpp"
#include "../icount_calibration.hpp"
#include "check_settings.hpp"
#include "recorded_flight.hpp"

#if !defined(ALOFT_EXAMPLE_WITHOUT_ALOFT)
#include "aloft/onboard/onboard_check.hpp"
#endif

namespace {

using aloft_example::live_simulations;
using aloft_example::recorded_flight;
using aloft_example::recorded_flight_samples;

// The updates timed: from the first one that finds all K simulations live to the last.
// Seeds start at samples 0, N, 2N, ..., so the K-th starts at sample (K - 1) N.
constexpr unsigned first_steady_sample = (live_simulations - 1) * aloft_example::seed_every_samples + 1;

#if !defined(ALOFT_EXAMPLE_WITHOUT_ALOFT)
using Check = aloft::OnboardCheck<float, live_simulations>;
// Static storage, so the check's whole memory shows in .bss; emplaced once the tensor is
// validated (std::optional holds it in place: no heap).
std::optional<Check> check;
#else
volatile float sample_sink;
#endif

}  // namespace

int main() {
  aloft::port::init();
  aloft::port::ReportWriter out;
  out.text("aloft example firmware: onboard check, K = ")
      .integer(live_simulations)
      .text(", N = ")
      .integer(aloft_example::seed_every_samples)
      .text(", flight ")
      .text(aloft_example::recorded_flight_source)
      .line();
  aloft::port::report_calibration(out);

#if !defined(ALOFT_EXAMPLE_WITHOUT_ALOFT)
  aloft::InertiaTensor<float> inertia;
  const aloft::Status made = aloft::InertiaTensor<float>::make_from_tensor(
      Eigen::Map<const aloft::Mat3<float>>(&aloft_example::recorded_inertia_kg_m2[0][0]), inertia);
  if (made != aloft::Status::ok) {
    out.text("inertia tensor rejected: ").text(aloft::describe(made)).line();
    return 1;
  }
  check.emplace(inertia, aloft_example::check_settings<float>());
#endif

  std::uint64_t steady_start = 0;
  for (unsigned i = 0; i < recorded_flight_samples; ++i) {
    if (i == first_steady_sample) steady_start = aloft::port::ticks();
    const aloft_example::GyroSample& sample = recorded_flight[i];
    const float dt = i == 0 ? 0.0f : static_cast<float>(sample.t_us - recorded_flight[i - 1].t_us) * 1e-6f;
#if !defined(ALOFT_EXAMPLE_WITHOUT_ALOFT)
    const aloft::Status s = check->update(Eigen::Map<const aloft::Vec3<float>>(sample.omega_rad_s), dt);
    if (s != aloft::Status::ok) {
      out.text("sample ").integer(i + 1).text(": ").text(aloft::describe(s)).line();
      return 1;
    }
#else
    sample_sink = sample.omega_rad_s[0] + sample.omega_rad_s[1] + sample.omega_rad_s[2] + dt;
#endif
  }
  const std::uint64_t steady_ticks = aloft::port::ticks() - steady_start;

#if !defined(ALOFT_EXAMPLE_WITHOUT_ALOFT)
  const float rad_to_deg = 57.2957795f;
  const aloft::DeviationStats<float>& stats = check->overall();
  out.text("samples ").integer(check->airborne_samples()).line();
  out.text("seeds ").integer(check->seeds_started()).line();
  out.text("comparisons ").integer(stats.count()).line();
  out.text("rms_da_deg ").fixed(stats.rms_da() * rad_to_deg, 6).line();
  out.text("max_da_deg ").fixed(stats.max_da() * rad_to_deg, 6).line();
  out.text("rms_rel_err ").fixed(stats.rms_relative_error(), 6).line();
#endif
  out.text("steady_updates ").integer(recorded_flight_samples - first_steady_sample).line();
  out.text("steady_ticks ").integer(static_cast<std::int64_t>(steady_ticks)).line();
  out.text("ticks_per_second ").integer(aloft::port::ticks_per_second()).line();
  return 0;
}
