// The board the cortex_m port targets: QEMU's model of the Arm MPS2 FPGA board with the
// AN386 image (a Cortex-M4 with FPU). Memory map: mps2_an386.ld.
#pragma once

#include <cstdint>

namespace aloft {
namespace port {
namespace board {

// The FPGA's system clock, which drives the core and SysTick's processor-clock source.
constexpr std::uint32_t processor_clock_hz = 25000000u;

}  // namespace board
}  // namespace port
}  // namespace aloft
