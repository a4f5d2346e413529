// The lines the replay firmwares (port/cortex_m/replay_example, port/stm32f405/firmware)
// print per flight, and the host programs that replay the same recording print the same
// way (port/host_tools: replay_lines.cpp, fifo_replay_lines.cpp, records_lines.cpp): one
// writer for all, so equal results print as equal text. Times are whole microseconds in
// the recording's base, written as seconds with six decimals; each float result also as
// its bit pattern, so that equality is checked exactly, not to the printed digits.
//   flight 0
//   release_s 0.202000
//   landing_s 0.500000          (or "landing_s null")
//   samples 298
//   gaps 0
//   imu_position_from body      (or "estimated")
//   comparisons 1490
//   rms_da_deg 0.000123
//   rms_da_rad_bits 951234567
//   rms_rel_err 0.000002
//   rms_rel_err_bits 901234567
#pragma once

#include <cstdint>
#include <cstring>

#include "aloft/cold_path.hpp"
#include "aloft/onboard/onboard_pipeline.hpp"
#include "aloft_port/divide_u64.hpp"
#include "aloft_port/report_writer.hpp"

namespace aloft_flight_lines {

ALOFT_COLD inline void write_seconds(aloft::port::ReportWriter& out, std::int64_t us) {
  if (us < 0) {
    out.text("-");
    us = -us;
  }
  // Seconds and µs by two divisions by 1000 (aloft_port/divide_u64.hpp).
  std::uint32_t us_digits = 0, ms_digits = 0;
  const std::uint64_t ms = aloft::port::divide_u64(static_cast<std::uint64_t>(us), 1000u, us_digits);
  const std::uint64_t s = aloft::port::divide_u64(ms, 1000u, ms_digits);
  out.integer(static_cast<std::int64_t>(s)).text(".");
  char digits[7];
  std::uint32_t fraction = ms_digits * 1000u + us_digits;
  for (int i = 5; i >= 0; --i, fraction /= 10) digits[i] = static_cast<char>('0' + fraction % 10);
  digits[6] = '\0';
  out.text(digits);
}

// A label and a whole number on a line ("samples 298"). Out of line: one copy of the
// calls for every such line (the STM32F405 flight image writes nine: 72 B of flash less).
ALOFT_COLD inline void write_integer_line(aloft::port::ReportWriter& out, const char* label,
                                          std::int64_t value) {
  out.text(label).integer(value).line();
}

inline std::int64_t bits_of(float value) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  return static_cast<std::int64_t>(bits);
}

ALOFT_COLD inline void write_flight_lines(aloft::port::ReportWriter& out, const aloft::FlightResult<float>& f,
                                          std::int64_t t0_us) {
  write_integer_line(out, "flight ", f.flight_number);
  write_seconds(out.text("release_s "), t0_us + static_cast<std::int64_t>(f.release_us));
  out.line();
  if (f.landed) {
    write_seconds(out.text("landing_s "), t0_us + static_cast<std::int64_t>(f.landing_us));
    out.line();
  } else {
    out.text("landing_s null").line();
  }
  write_integer_line(out, "samples ", f.samples);
  write_integer_line(out, "gaps ", f.gaps);
  out.text("imu_position_from ").text(f.imu_position_estimated ? "estimated" : "body").line();
  write_integer_line(out, "comparisons ", f.overall.count());
  const float rms_da_rad = f.overall.rms_da(), rms_rel_err = f.overall.rms_relative_error();
  out.text("rms_da_deg ").fixed(rms_da_rad * 57.2957795f, 6).line();
  write_integer_line(out, "rms_da_rad_bits ", bits_of(rms_da_rad));
  out.text("rms_rel_err ").fixed(rms_rel_err, 6).line();
  write_integer_line(out, "rms_rel_err_bits ", bits_of(rms_rel_err));
}

}  // namespace aloft_flight_lines
