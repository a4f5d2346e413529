// A recording as `aloft replay` reads it, whatever the file: the samples in the one type
// the firmware's pipeline takes (aloft/sensor/imu_sample.hpp, float), and what the reader found
// wrong with the source on the way. The CSV reader (--imu) and the ICM-42688-P FIFO reader
// (--fifo) each fill one; the replay itself (the firmware's pipeline, sample by sample)
// does not know which file it came from.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "aloft/sensor/imu_sample.hpp"

namespace aloft::host {

struct Recording {
  std::string path;
  std::string format;  // "imu_csv" or "icm42688p_fifo"
  std::vector<ImuSample<float>> samples;
  // Source-level accounting (SPEC §5 replay report, `stream`): what the reader dropped
  // or skipped before any sample reached the pipeline. A CSV has none of these.
  std::uint32_t invalid_samples = 0;  // e.g. FIFO packets holding -32768 (no data yet)
  std::uint64_t bytes_skipped = 0;    // bytes not decoded: skipped to resynchronise, or a cut last packet
  std::uint32_t empty_reads = 0;      // FIFO reads that found it empty (HEADER_MSG, 0x80)
  std::uint32_t resyncs = 0;          // foreign headers skipped past to the next packet boundary
  // Recording time of the first sample, so that reports can give times in the
  // recording's own base (the CSV's `t`; 0 for the first valid FIFO packet).
  std::uint64_t t0_us = 0;
  // The same in seconds, which is what reports add: a CSV's `t` may start below zero,
  // where t0_us (unsigned) stays 0.
  double t0_s = 0.0;
  // The body's rotor speed (a CSV's rotor_rad_s; a FIFO recording has none): whether the
  // recording carries it, and its largest magnitude (rad/s).
  bool has_rotor_speed = false;
  double max_abs_rotor_rad_s = 0.0;
};

}  // namespace aloft::host
