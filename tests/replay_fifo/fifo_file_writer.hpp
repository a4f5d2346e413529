// Example ICM-42688-P FIFO files for the tests and the fuzz seeds: packets encoded from
// the datasheet's layout (tests/core/icm42688p_packet_encoder.hpp, not lib/'s decoder),
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

  bool missing(std::uint32_t k) const {
    for (const Hole& h : holes) {
      if (k >= h.first && k < h.first + h.count) return true;
    }
    return false;
  }

  std::string bytes() const {
    std::string out;
    for (std::uint32_t k = 0; k < packets; ++k) {
      if (missing(k)) continue;
      const ChipSample s = k < without_data ? no_data_sample() : mixed_sample(k);
      std::uint8_t packet[kEncoderPacket3Bytes];
      encode_packet3(s, static_cast<std::uint16_t>((stamp_start + k * period_us) & 0xFFFFu), true, packet);
      out.append(reinterpret_cast<const char*>(packet), sizeof packet);
    }
    return out;
  }
};

}  // namespace aloft_test
