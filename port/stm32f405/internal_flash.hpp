// The STM32F405's internal flash as a block device (aloft/records/block_device.hpp), through
// its flash interface (RM0090 §3): blocks are the 128 KiB sectors 5 to 11 (the
// smaller sectors 0 to 4 hold the vector table and code, and a block device needs one
// block size). Programming is by 32-bit word (PSIZE = x32, for a supply of 2.7 to
// 3.6 V), so program_size is 4. Reads are plain loads from the memory-mapped flash.
//
// Every wait on the busy flag is bounded (sector erase: 4 s, twice the datasheet's
// 2 s maximum at x32, DS8626 Table 43; word program: 1 ms, ten times its 100 µs) by the
// port's clock (aloft_port/port.hpp ticks) and by a cap on the number of polls, so a
// stuck controller returns bus_error instead of hanging the firmware. The controller is
// locked again after every operation.
//
// QEMU's netduinoplus2 does not model the flash interface: under QEMU the firmware uses
// the RAM fake (port/fakes/fake_flash.hpp); this driver has been compiled for the
// cortex-m4f toolchain, not run.
#pragma once

#include <cstdint>

#include "aloft/records/block_device.hpp"

namespace aloft::port::stm32f405 {

// Three sectors by default: the ring keeps (3 - 2) * 1024 + 1 to (3 - 1) * 1024 flights
// (aloft/records/record_ring.hpp); with two it would keep as few as one right after a wrap.
struct InternalFlashConfig {
  std::uint32_t first_sector = 9;  // 5..11: 128 KiB sectors (9, 10, 11: the last 384 KiB)
  std::uint32_t sector_count = 3;  // the record ring needs at least 2
};

class InternalFlash {
 public:
  static constexpr std::uint32_t sector_size = 128u * 1024u;

  // constexpr: a flash in static memory is filled in when the image is built (its .data),
  // not by start-up code (STM32F405: 88 B of flash less).
  constexpr explicit InternalFlash(const InternalFlashConfig& config = {})
      : config_(config),
        usable_(config.first_sector >= 5 && config.sector_count >= 2 &&
                config.first_sector + config.sector_count <= 12) {
    device_.context = this;
    device_.block_size = sector_size;
    device_.block_count = usable_ ? config.sector_count : 0;
    device_.program_size = 4;
    device_.read = &InternalFlash::read;
    device_.program = &InternalFlash::program;
    device_.erase = &InternalFlash::erase;
  }

  // False when the configuration names sectors outside 5..11 or fewer than 2.
  bool usable() const { return usable_; }
  const BlockDevice& device() const { return device_; }

 private:
  static Status read(void* context, std::uint32_t block, std::uint32_t offset, std::uint8_t* data,
                     std::uint32_t size);
  static Status program(void* context, std::uint32_t block, std::uint32_t offset, const std::uint8_t* data,
                        std::uint32_t size);
  static Status erase(void* context, std::uint32_t block);

  InternalFlashConfig config_;
  BlockDevice device_;
  bool usable_ = false;
};

}  // namespace aloft::port::stm32f405
