// The STM32F405's 82 interrupt vectors (RM0090 Table 61), placed right after the core's 16
// (../cortex_m/startup.cpp) by the linker (section .isr_vector.device). aloft enables no
// device interrupt, so each one goes to the fault handler, which names the exception and
// ends the program: an interrupt enabled by mistake fails a test instead of hanging it.
#include <array>
#include <cstddef>

#include "stm32f405_registers.hpp"

extern "C" void Fault_Handler();

namespace {

using Handler = void (*)();
constexpr std::size_t count = aloft::port::stm32f405::device_interrupt_count;

constexpr std::array<Handler, count> all_to_fault_handler() {
  std::array<Handler, count> table{};
  for (Handler& entry : table) entry = Fault_Handler;
  return table;
}

}  // namespace

extern "C" __attribute__((section(".isr_vector.device"), used)) constexpr std::array<Handler, count>
    device_vector_table = all_to_fault_handler();
