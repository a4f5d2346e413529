// The tensor estimate as a flight record keeps it (FlightRecordTensor), printed as "key value"
// lines, each float as its bit pattern: records_lines.cpp prints it from the record the
// STM32F405 replay image stored, replay_lines.hpp from the record the host's replay of the
// same bytes would store. tests/stm32f405 compares the two to the bit.
#pragma once

#include "aloft/records/flight_record.hpp"
#include "aloft_port/report_writer.hpp"
#include "flight_lines.hpp"

namespace aloft_tensor_record_lines {

inline void write_bits(aloft::port::ReportWriter& out, const char* key, const float* values, int n) {
  out.text(key);
  for (int i = 0; i < n; ++i) out.text(" ").integer(aloft_flight_lines::bits_of(values[i]));
  out.line();
}

inline void write_tensor_lines(aloft::port::ReportWriter& out, const aloft::FlightRecordTensor& t) {
  out.text("tensor_determined ").integer(t.determined ? 1 : 0).line();
  out.text("tensor_absolute ").integer(t.absolute ? 1 : 0).line();
  out.text("tensor_note ").integer(t.note).line();
  write_bits(out, "tensor_principal_bits", t.principal, 3);
  write_bits(out, "tensor_axes_xyz_bits", t.axes_xyz, 3);
  write_bits(out, "tensor_ratios_95_bits", t.ratios_95, 2);
  write_bits(out, "tensor_principal_95_bits", t.principal_95, 3);
  write_bits(out, "tensor_axes_95_rad_bits", t.axes_95_rad, 3);
}

}  // namespace aloft_tensor_record_lines
