// The host side of the replay images: `aloft replay`'s own code path (host_sim/replay: the
// body settings, run_replay) on a body file and a recording, printing each flight as the
// images print it (port/cortex_m/flight_lines.hpp). One implementation for every reader:
// replay_lines.cpp hands it the CSV reader, fifo_replay_lines.cpp the FIFO reader. Each
// flight's tensor estimate follows as the flight record would keep it (encoded and read
// back: tensor_record_lines.hpp).
#pragma once

#include <cstdio>
#include <exception>

#include "aloft/records/flight_record_from_result.hpp"
#include "common/body_file.hpp"
#include "flight_lines.hpp"
#include "replay/recording.hpp"
#include "replay/replay_run.hpp"
#include "tensor_record_lines.hpp"

namespace aloft_replay_lines {

inline void write_stdout(const char* text) { std::fputs(text, stdout); }

// The flight's tensor estimate as its record keeps it: encoded into a slot and decoded.
inline aloft::FlightRecordTensor recorded_tensor(const aloft::FlightResult<float>& f) {
  std::uint8_t slot[aloft::flight_record_size];
  aloft::encode_flight_record(aloft::make_flight_record(f, 0, 0), slot);
  aloft::FlightRecord read_back;
  aloft::decode_flight_record_fields(slot, read_back);
  return read_back.tensor;
}

// Reads the body file, then the recording (read_recording()), replays it and prints the
// lines, the first one naming the recording as "<source> <path>". Returns the program's
// exit status: 0, or 2 with "<program>: <what went wrong>" on stderr.
template <typename ReadRecording>
int print_replay_lines(const char* program, const char* body_path, const char* source,
                       const char* recording_path, ReadRecording read_recording) {
  try {
    const aloft::host::Body body = aloft::host::read_body_file(body_path);
    const aloft::host::Recording recording = read_recording();
    const aloft::host::ReplayResult result =
        aloft::host::run_replay(aloft::host::replay_settings_from_body(body), body_path, recording);
    aloft::port::ReportWriter out(write_stdout);
    out.text("aloft replay host: OnboardPipeline<float, 8>, ")
        .text(source)
        .text(" ")
        .text(recording_path)
        .line();
    for (const aloft::FlightResult<float>& f : result.flights) {
      aloft_flight_lines::write_flight_lines(out, f, result.t0_us);
      aloft_tensor_record_lines::write_tensor_lines(out, recorded_tensor(f));
    }
    out.text("stream_samples ").integer(result.stream.samples).line();
    out.text("stream_gaps ").integer(result.stream.gaps).line();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", program, e.what());
    return 2;
  }
  return 0;
}

}  // namespace aloft_replay_lines
