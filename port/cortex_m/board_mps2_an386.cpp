// The board behind the `cortex-m4f` preset: QEMU's model of the Arm MPS2 FPGA board with
// the AN386 image (a Cortex-M4 with FPU). Memory map: mps2_an386.ld.
#include "board.hpp"

namespace aloft {
namespace port {
namespace board {

// The FPGA's clock is fixed: nothing to bring up.
void init_clocks() {}

// The FPGA's system clock, which drives the core and SysTick's processor-clock source.
std::uint32_t processor_clock_hz() { return 25000000u; }

}  // namespace board
}  // namespace port
}  // namespace aloft
