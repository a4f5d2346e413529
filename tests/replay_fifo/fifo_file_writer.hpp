// Example ICM-42688-P FIFO files for the tests and the fuzz seeds: packets encoded from
// the datasheet's layout (port/fakes/icm42688p_packet_encoder.hpp, not lib/'s decoder),
// sample k from aloft_test::mixed_sample(k) at k periods after the first, time stamps at
// 1 µs from `stamp_start` (so that they wrap), as the driver's configuration gives them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "icm42688p_packet_encoder.hpp"

namespace aloft_test {

struct FifoFile {
  std::uint32_t packets = 100;     // samples k = 0 .. packets-1, holes included
  std::uint32_t without_data = 0;  // the first packets hold -32768 (power-up)
  std::uint32_t period_us = 1000;
  std::uint16_t stamp_start = 0xFF00;
  struct Hole {
    std::uint32_t first = 0;  // first sample missing
    std::uint32_t count = 0;
  };
  std::vector<Hole> holes;  // samples left out, as after an overflow
  // Empty reads (a header with HEADER_MSG, 0x80, DS-000347 §6.2) before sample `before`:
  // the byte alone (a reader that stops at it), or a whole 16-byte slot, 0x80 and 15 fill
  // bytes (a fixed-size burst while the FIFO was empty; the datasheet does not say what the
  // rest reads, so the fill is the test's choice).
  struct EmptyRead {
    std::uint32_t before = 0;
    bool whole_slot = false;
    std::uint8_t fill = 0x80;
  };
  std::vector<EmptyRead> empty_reads;
  std::int64_t foreign_header_packet = -1;  // this sample's header reads 0x3C
  std::uint32_t cut_tail = 0;               // the first bytes of sample `packets`, cut (0-15)

  bool missing(std::uint32_t k) const {
    for (const Hole& h : holes) {
      if (k >= h.first && k < h.first + h.count) return true;
    }
    return false;
  }

  std::string bytes() const {
    std::string out;
    for (std::uint32_t k = 0; k <= packets; ++k) {
      for (const EmptyRead& e : empty_reads) {
        if (e.before != k) continue;
        out += '\x80';
        if (e.whole_slot) out.append(kEncoderPacket3Bytes - 1, static_cast<char>(e.fill));
      }
      if (k == packets) {
        out += packet(k).substr(0, cut_tail);
        break;
      }
      if (!missing(k)) out += packet(k);
    }
    return out;
  }

  std::string packet(std::uint32_t k) const {
    const ChipSample s = k < without_data ? no_data_sample() : mixed_sample(k);
    std::uint8_t p[kEncoderPacket3Bytes];
    encode_packet3(s, static_cast<std::uint16_t>((stamp_start + k * period_us) & 0xFFFFu), true, p);
    if (static_cast<std::int64_t>(k) == foreign_header_packet) p[0] = 0x3C;
    return std::string(reinterpret_cast<const char*>(p), sizeof p);
  }
};

}  // namespace aloft_test
