// The float onboard pipeline run over a generated recording (generated_throws.hpp): every
// sample pushed as the firmware would, every finished flight taken as it comes. One loop for
// the release tests and the tensor estimate's rotor throws.
#pragma once

#include <catch2/catch.hpp>

#include <vector>

#include "aloft/onboard/onboard_pipeline.hpp"
#include "generated_throws.hpp"

namespace aloft_test {

inline std::vector<aloft::FlightResult<float>> pipeline_flights(aloft::OnboardPipeline<float, 8>& pipeline,
                                                                const Recording& rec) {
  std::vector<aloft::FlightResult<float>> flights;
  aloft::FlightResult<float> flight;
  for (const auto& s : rec.samples) {
    aloft::ImuSample<float> f;
    f.t_us = s.t_us;
    f.gyro_rad_s = s.gyro_rad_s.cast<float>();
    f.accel_m_s2 = s.accel_m_s2.cast<float>();
    f.flags = s.flags;
    f.rotor_rad_s = static_cast<float>(s.rotor_rad_s);
    if (pipeline.push(f) != aloft::Status::ok) FAIL("sample refused at t_us " << f.t_us);
    while (pipeline.take_finished_flight(flight)) flights.push_back(flight);
  }
  pipeline.finish();
  while (pipeline.take_finished_flight(flight)) flights.push_back(flight);
  return flights;
}

}  // namespace aloft_test
