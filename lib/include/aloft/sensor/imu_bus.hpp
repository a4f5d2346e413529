// The bus a sensor driver talks through, in the shape of ST's platform-independent MEMS
// drivers (stmdev_ctx_t): the driver knows nothing of the board; a port fills in three
// functions (SPI or I²C, a fake chip in the tests) and a context pointer of its own.
// Register addresses are the chip's, without any read/write bit: setting the SPI read bit
// (0x80 on InvenSense parts) is the port's business.
#pragma once

#include <cstdint>

#include "aloft/status.hpp"

namespace aloft {

struct ImuBus {
  void* context = nullptr;  // passed back to every call; the port's own state
  // Reads `length` bytes starting at `reg` in one transaction (a burst: the chip advances
  // the address, or not, as its datasheet says; FIFO_DATA does not advance).
  Status (*read)(void* context, std::uint8_t reg, std::uint8_t* data, std::uint16_t length) = nullptr;
  // Writes one register.
  Status (*write)(void* context, std::uint8_t reg, std::uint8_t value) = nullptr;
  // Microseconds on the MCU's own clock, monotonic: measures gaps the chip cannot (a FIFO
  // overflow loses time stamps with the data).
  std::uint64_t (*now_us)(void* context) = nullptr;
};

}  // namespace aloft
