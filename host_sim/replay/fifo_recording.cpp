#include "replay/fifo_recording.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <vector>

#include "common/commands.hpp"
#include "common/file_error.hpp"
#include "common/warning.hpp"

namespace aloft::host {
namespace {

using icm42688p::is_empty_read_header;

std::string at_offset(const std::string& path, std::size_t offset, const std::string& problem) {
  return path + ": byte offset " + std::to_string(offset) + ": " + problem;
}

std::string hex_byte(std::uint8_t value) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%02X", static_cast<unsigned>(value));
  return text;
}

std::vector<std::uint8_t> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path + ": cannot be opened");
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw FileError(path + ": read failed");
  return bytes;
}

std::uint32_t checked_odr(double odr_hz) {
  // The chip's rates run from 1.5625 Hz to 32 kHz.
  if (!std::isfinite(odr_hz) || odr_hz < 1.0 || odr_hz > 32000.0) {
    throw Error("--odr-hz " + std::to_string(odr_hz) + ": the output data rate must be 1 to 32000 Hz");
  }
  return static_cast<std::uint32_t>(std::lround(odr_hz));
}

}  // namespace

// Warnings name each fault with its byte offset; a file with many says so once more.
constexpr std::uint32_t kResyncWarnings = 8;

Recording read_fifo_recording(const std::string& path, double odr_hz, icm42688p::TimestampClock clock) {
  const std::uint32_t odr = checked_odr(odr_hz);
  return with_file_context(path, [&] {
    const std::vector<std::uint8_t> bytes = read_bytes(path);
    if (bytes.empty()) throw Error(at_offset(path, 0, "empty file: no FIFO packet"));
    Recording recording;
    recording.path = path;
    recording.format = "icm42688p_fifo";
    recording.t0_us = 0;
    recording.samples.reserve(bytes.size() / icm42688p::kPacket3Bytes);
    icm42688p::FifoDecoder<float> decoder(odr, clock);
    std::uint32_t packets = 0;
    std::vector<std::string> warnings;  // given only if the file is read: a refusal is one line
    for (std::size_t offset = 0; offset < bytes.size();) {
      const std::size_t left = bytes.size() - offset;
      ImuSample<float> sample;
      const icm42688p::FifoStep step = decoder.next(bytes.data() + offset, left, sample);
      switch (step.outcome) {
        case icm42688p::PacketOutcome::sample:
          recording.samples.push_back(sample);
          ++packets;
          break;
        case icm42688p::PacketOutcome::invalid:
          ++recording.invalid_samples;
          ++packets;
          break;
        case icm42688p::PacketOutcome::empty_read: ++recording.empty_reads; break;
        case icm42688p::PacketOutcome::cut:
          recording.bytes_skipped += step.bytes;
          warnings.push_back(at_offset(
              path, offset,
              "the last " + std::string(is_empty_read_header(bytes[offset]) ? "empty read" : "packet") +
                  " is cut (" + std::to_string(left) + " of 16 bytes at the end of the file): skipped"));
          break;
        case icm42688p::PacketOutcome::foreign_header: {
          const std::size_t skip = decoder.resync_bytes(bytes.data() + offset, left);
          if (++recording.resyncs <= kResyncWarnings) {
            warnings.push_back(
                at_offset(path, offset,
                          "header " + hex_byte(bytes[offset]) +
                              " is not an ICM-42688-P packet 3 (0x68-0x6B: accel, gyro, time stamp): " +
                              std::to_string(skip) + " bytes skipped to the next packet boundary"));
          }
          recording.bytes_skipped += skip;
          offset += skip;
          continue;
        }
      }
      offset += step.bytes;  // a cut takes the rest
    }
    if (recording.resyncs > kResyncWarnings) {
      warnings.push_back(path + ": " + std::to_string(recording.resyncs) + " foreign headers in all, " +
                         std::to_string(recording.bytes_skipped) + " bytes skipped");
    }
    // Nothing decoded is the one refusal: every fault above is survivable.
    if (packets == 0) {
      throw Error(at_offset(path, 0,
                            "no ICM-42688-P packet 3 in " + std::to_string(bytes.size()) + " bytes (" +
                                std::to_string(recording.empty_reads) + " empty reads, " +
                                std::to_string(recording.bytes_skipped) + " bytes skipped)"));
    }
    if (recording.samples.empty()) {
      throw Error(at_offset(
          path, 0,
          "no packet holds data (all " + std::to_string(recording.invalid_samples) + " hold -32768)"));
    }
    for (const std::string& w : warnings) warn(w);
    return recording;
  });
}

}  // namespace aloft::host
