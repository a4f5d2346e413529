// Host program: `aloft records`' own reader (host_sim/records/record_dump.cpp) on a
// record-area dump, printing each intact record in the lines the STM32F405 replay image
// prints for the flight it stored (flight_lines.hpp's keys, and record_sequence), and
// each bad slot as "problem OFFSET REASON", and the record's tensor estimate
// (tensor_record_lines.hpp). tests/stm32f405 compares them with the image's lines and with
// the host's replay.
//   records_lines DUMP
#include <cstdio>
#include <cstring>
#include <exception>

#include "aloft_port/report_writer.hpp"
#include "flight_lines.hpp"
#include "records/record_dump.hpp"
#include "tensor_record_lines.hpp"

namespace {

void write_stdout(const char* text) { std::fputs(text, stdout); }

void write_record(aloft::port::ReportWriter& out, const aloft::FlightRecord& r) {
  out.text("flight ").integer(r.flight_number).line();
  aloft_flight_lines::write_seconds(out.text("release_s "), static_cast<std::int64_t>(r.release_us));
  out.line();
  if (r.landed) {
    aloft_flight_lines::write_seconds(out.text("landing_s "), static_cast<std::int64_t>(r.landing_us));
    out.line();
  } else {
    out.text("landing_s null").line();
  }
  out.text("samples ").integer(r.samples).line();
  out.text("gaps ").integer(r.gaps).line();
  out.text("imu_position_from ").text(r.imu_position_estimated ? "estimated" : "body").line();
  out.text("comparisons ").integer(r.comparisons).line();
  out.text("rms_da_deg ").fixed(r.rms_da_rad * 57.2957795f, 6).line();
  out.text("rms_da_rad_bits ").integer(aloft_flight_lines::bits_of(r.rms_da_rad)).line();
  out.text("rms_rel_err ").fixed(r.rms_rel_err, 6).line();
  out.text("rms_rel_err_bits ").integer(aloft_flight_lines::bits_of(r.rms_rel_err)).line();
  out.text("record_sequence ").integer(r.sequence).line();
  aloft_tensor_record_lines::write_tensor_lines(out, r.tensor);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: records_lines DUMP\n");
    return 2;
  }
  try {
    const aloft::host::RecordDump dump = aloft::host::read_record_dump(argv[1]);
    aloft::port::ReportWriter out(write_stdout);
    for (const aloft::host::ListedRecord& listed : dump.records) write_record(out, listed.record);
    for (const aloft::host::DumpProblem& p : dump.problems)
      std::printf("problem %llu %s\n", static_cast<unsigned long long>(p.offset), p.reason.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "records_lines: %s\n", e.what());
    return 2;
  }
  return 0;
}
