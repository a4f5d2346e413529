#include "aloft/aloft.hpp"
extern aloft::ImuBus imu_bus;  // the port's SPI read/write and µs clock (port/stm32f405/)
void report(const aloft::FlightResult<float>& flight);  // flight.overall.rms_da(), radians
int run() {
  aloft::InertiaTensor<float> inertia;  // the body's tensor, checked once at start-up
  if (aloft::InertiaTensor<float>::make_cylinder(10.01f, 0.0649f, 0.097f, inertia) != aloft::Status::ok)
    return 1;
  static aloft::OnboardPipeline<float, 8> pipeline(inertia, {});  // release, flight, landing
  aloft::Icm42688pDriver<float> imu(imu_bus, {});                 // 1 kHz FIFO, time-stamped
  if (imu.begin() != aloft::Status::ok) return 2;                 // WHO_AM_I, settings kept
  const aloft::icm42688p::SampleSink<float> sink{
      &pipeline, [](void* p, const aloft::ImuSample<float>& s) {
        (void)static_cast<aloft::OnboardPipeline<float, 8>*>(p)->push(s);  // a bad sample is skipped
      }};
  for (aloft::FlightResult<float> flight;;) {
    if (imu.poll(sink) != aloft::Status::ok) return 3;
    if (pipeline.take_finished_flight(flight)) report(flight);
  }
}
