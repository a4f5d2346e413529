// The firmware side of the flight records under QEMU: five flights stored through the
// record ring on the RAM fake flash, then the whole record area written to a host file by
// semihosting (port/cortex_m/record_area_dump.hpp). The ctest case after this one
// (check_record_area_dump.cmake) reads that file back.
#include "aloft/onboard/onboard_pipeline.hpp"
#include "fake_flash.hpp"
#include "record_area_dump.hpp"
#include "test_api.hpp"

ALOFT_TEST_CASE("records: five flights stored and the record area written out by semihosting", "[records]") {
  static aloft::testing::FakeFlash<512, 3> flash;
  aloft::RecordRing ring(flash.device());
  ALOFT_REQUIRE(ring.mount() == aloft::Status::ok);
  for (std::uint32_t i = 0; i < 5; ++i) {
    aloft::FlightResult<float> result;
    result.flight_number = i;
    result.release_us = 1000000u * (i + 1);
    result.landing_us = result.release_us + 800000u;
    result.landed = result.turned = true;
    result.samples = 800;
    result.overall.add_values(0.01f, 0.02f);
    ALOFT_CHECK(aloft::port::store_flight(ring, result, 0x1234u, 0x5678u) == aloft::Status::ok);
  }
  ALOFT_CHECK(aloft::port::write_record_area(flash.device(), "record_area_dump.bin") == aloft::Status::ok);
}
