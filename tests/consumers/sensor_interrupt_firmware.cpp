// A firmware as a user of aloft writes it: the gyro's data-ready interrupt puts each
// sample in a ring buffer, the main loop feeds them to aloft::OnboardCheck. Built by the
// two consumer projects (find_package on an install prefix, add_subdirectory) for the
// host and for the Cortex-M4F, which only works if the package carries what it must:
// headers, Eigen, C++17 (the projects ask for C++14) and the port.
//
// The "sensor" here is a torque-free flight of a known box integrated finely; the check
// must find the true tensor within 0.01 degrees and a tensor 25 % off beyond 0.3 degrees
// (0.71 measured: each simulation lives 80 samples, 0.16 s).
#include <cstdint>

#include "aloft/dynamics/euler_equations.hpp"
#include "aloft/onboard/onboard_check.hpp"
#include "aloft_port/report_writer.hpp"

static_assert(__cplusplus >= 201703L, "aloft::core carries cxx_std_17 to its consumers");

namespace {

constexpr float kSampleRateHz = 500.0f;
constexpr int kFlightSamples = 400;  // 0.8 s of flight

// The simulated gyro: the body rate of a torque-free box, 8 RK4 substeps per sample.
struct SimulatedGyro {
  aloft::InertiaTensor<float> truth;
  aloft::Vec3<float> rate{4.0f, 0.5f, 9.0f};
  aloft::Vec3<float> next_sample() {
    const aloft::Vec3<float> sample = rate;
    for (int i = 0; i < 8; ++i) rate = aloft::body_rate_rk4_step(truth, rate, 1.0f / (8 * kSampleRateHz));
    return sample;
  }
};
SimulatedGyro gyro;

// Single producer (the interrupt), single consumer (the main loop): no locks needed.
constexpr unsigned kRingSize = 16;
aloft::Vec3<float> ring[kRingSize];
volatile unsigned ring_head = 0, ring_tail = 0;

extern "C" void GYRO_DATA_READY_IRQHandler() {
  ring[ring_head % kRingSize] = gyro.next_sample();
  ring_head = ring_head + 1;
}

using Check = aloft::OnboardCheck<float, 8>;

// Drains the ring into the check; returns false on an error status.
bool drain(Check& check) {
  while (ring_tail != ring_head) {
    const aloft::Status s = check.update(ring[ring_tail % kRingSize], 1.0f / kSampleRateHz);
    ring_tail = ring_tail + 1;
    if (s != aloft::Status::ok) return false;
  }
  return true;
}

// RMS DA in degrees of the check run with `model` over the flight; negative on failure.
float rms_da_deg(const aloft::InertiaTensor<float>& model) {
  gyro.rate = aloft::Vec3<float>(4.0f, 0.5f, 9.0f);
  ring_head = ring_tail = 0;
  Check check(model, aloft::OnboardCheckSettings<float>{});
  for (int i = 0; i < kFlightSamples; ++i) {
    GYRO_DATA_READY_IRQHandler();  // on a board, the sensor raises it
    if (i % 4 == 3 && !drain(check)) return -1.0f;
  }
  if (!drain(check)) return -1.0f;
  return check.overall().rms_da() * 57.29578f;
}

}  // namespace

int main() {
  aloft::port::init();
  aloft::port::ReportWriter out;
  aloft::InertiaTensor<float> wrong;
  if (aloft::InertiaTensor<float>::make_box(1.0f, 0.30f, 0.20f, 0.05f, gyro.truth) != aloft::Status::ok ||
      aloft::InertiaTensor<float>::make_box(1.0f, 0.30f, 0.25f, 0.05f, wrong) != aloft::Status::ok) {
    out.text("consumer: tensor rejected").line();
    aloft::port::exit_with_status(1);
  }
  const float right_deg = rms_da_deg(gyro.truth);
  const float wrong_deg = rms_da_deg(wrong);
  out.text("consumer: RMS DA true tensor ")
      .fixed(right_deg, 4)
      .text(" deg, wrong tensor ")
      .fixed(wrong_deg, 4)
      .text(" deg")
      .line();
  const bool pass = right_deg >= 0.0f && right_deg < 0.01f && wrong_deg > 0.3f;
  aloft::port::exit_with_status(pass ? 0 : 1);
}
