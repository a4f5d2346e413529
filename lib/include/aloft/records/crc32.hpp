// CRC-32 as zlib, PNG and Ethernet compute it (IEEE 802.3: polynomial 0x04C11DB7 used
// reflected as 0xEDB88320, initial value and final XOR 0xFFFFFFFF; "123456789" gives
// 0xCBF43926). Bit by bit, without a table: a firmware checks a few hundred bytes per
// flight, and the 1 KiB table would cost more flash than all of the flight-record code.
// Chained like zlib's crc32(): crc32(b, nb, crc32(a, na)) equals the CRC of a then b.
#pragma once

#include <cstddef>
#include <cstdint>

namespace aloft {

inline std::uint32_t crc32(const std::uint8_t* data, std::size_t size, std::uint32_t previous = 0) {
  std::uint32_t crc = ~previous;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

}  // namespace aloft
