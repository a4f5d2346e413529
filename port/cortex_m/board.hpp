// What the shared Cortex-M port (startup.cpp, port_cortex_m.cpp) needs from the board it
// runs on. Each board defines these in a .cpp of its own, picked by port/CMakeLists.txt:
//   mps2-an386 (QEMU's Arm MPS2 + AN386, the `cortex-m4f` preset)  board_mps2_an386.cpp
//   STM32F405 (flight controllers; QEMU netduinoplus2, `stm32f405`)  ../stm32f405/board_stm32f405.cpp
#pragma once

#include <cstdint>

namespace aloft {
namespace port {
namespace board {

// Brings up the board's clocks, called by port::init() before SysTick starts. Never
// hangs: every wait on the hardware is bounded, and a board that falls back to a slower
// clock says so through write_text in one line.
void init_clocks();

// The processor clock after init_clocks(): SysTick's processor-clock source.
std::uint32_t processor_clock_hz();

}  // namespace board
}  // namespace port
}  // namespace aloft
