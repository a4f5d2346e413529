// The storage a port lends to aloft: NOR flash seen as `block_count` erase blocks of
// `block_size` bytes, in the shape of littlefs's lfs_config and of aloft/sensor/imu_bus.hpp (a
// few function pointers and a context of the port's own). The rules are NOR flash's:
//   - erase(block) sets every byte of the block to 0xFF;
//   - program(...) can only clear bits (a byte becomes old & new); writing a 1 over a 0
//     needs an erase of the whole block first. Offsets and lengths of program() are
//     multiples of `program_size`, and a range never crosses a block;
//   - read(...) returns the stored bytes, any offset and length within a block;
//   - each call returns when the operation has finished (or failed: then a status other
//     than ok). A power cut inside program() may leave any of its bits programmed or
//     not; inside erase(), any byte of the block erased or not.
// Ports: the STM32F405's internal flash (port/stm32f405/internal_flash.hpp); the tests
// use a RAM-backed fake that enforces these rules and cuts the power where told
// (port/fakes/fake_flash.hpp), and a file-backed one on the host.
#pragma once

#include <cstdint>

#include "aloft/status.hpp"

namespace aloft {

struct BlockDevice {
  void* context = nullptr;         // passed back to every call; the port's own state
  std::uint32_t block_size = 0;    // bytes in one erase block
  std::uint32_t block_count = 0;   // erase blocks lent to aloft
  std::uint32_t program_size = 0;  // bytes in one program unit (1, 2, 4 or 8 for the record ring)
  Status (*read)(void* context, std::uint32_t block, std::uint32_t offset, std::uint8_t* data,
                 std::uint32_t size) = nullptr;
  Status (*program)(void* context, std::uint32_t block, std::uint32_t offset, const std::uint8_t* data,
                    std::uint32_t size) = nullptr;
  Status (*erase)(void* context, std::uint32_t block) = nullptr;
};

}  // namespace aloft
