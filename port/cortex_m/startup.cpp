// Reset and exception entry for a Cortex-M4F: the vector table, the reset handler that
// prepares memory and the FPU before any C++ runs, and fault handlers that report
// through the port instead of hanging (so a crash under QEMU fails the test at once).
// Symbols from the linker script (cortex_m_sections.ld). A board with interrupts of its
// own puts their vectors in section .isr_vector.device, which the linker places right
// after these 16 (../stm32f405/device_vectors.cpp).
#include <cstdint>

#include "aloft_port/port.hpp"
#include "core_registers.hpp"

extern "C" {
extern std::uint32_t __data_load[];
extern std::uint32_t __data_start[];
extern std::uint32_t __data_end[];
extern std::uint32_t __bss_start[];
extern std::uint32_t __bss_end[];
extern std::uint32_t __stack_top[];
using Constructor = void (*)();
extern Constructor __init_array_start[];
extern Constructor __init_array_end[];

int main();
[[noreturn]] void Reset_Handler();
void SysTick_Handler();
void Fault_Handler();
}

namespace {

using Handler = void (*)();
constexpr int vector_count = 16;  // the core's exceptions

}  // namespace

// Entry 0 is the initial stack pointer, the rest are handlers (ARMv7-M ARM, B1.5.3).
extern "C" __attribute__((section(".isr_vector"), used)) const Handler vector_table[vector_count] = {
    reinterpret_cast<Handler>(__stack_top),
    Reset_Handler,
    Fault_Handler,  // NMI
    Fault_Handler,  // HardFault
    Fault_Handler,  // MemManage
    Fault_Handler,  // BusFault
    Fault_Handler,  // UsageFault
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    Fault_Handler,  // SVCall
    Fault_Handler,  // DebugMonitor
    nullptr,
    Fault_Handler,  // PendSV
    SysTick_Handler,
};

extern "C" void Reset_Handler() {
  namespace core = aloft::port::core;
  // The FPU first: the compiler may use FP registers in any code below.
  core::scb_cpacr() = core::scb_cpacr() | core::cpacr_fpu_full_access;
  // No FP context on exception entry (core_registers.hpp, FPCCR): neither handler here
  // (SysTick_Handler, Fault_Handler) nor anything it calls holds an FPU instruction, which
  // the stack measurement checks on the linked image (port/host_tools/worst_case_stack.cpp
  // fails otherwise), so the interrupted code's FP registers need no saving. Each
  // exception then stacks 32 B (36 with the aligner), not 108: 144 B of worst-case stack
  // for the two handlers. Cleared before any FPU instruction runs, so CONTROL.FPCA is
  // never set.
  core::fpu_fpccr() = core::fpu_fpccr() & ~(core::fpccr_aspen | core::fpccr_lspen);
  asm volatile("dsb\n\tisb" ::: "memory");
  for (std::uint32_t *src = __data_load, *dst = __data_start; dst < __data_end;) *dst++ = *src++;
  for (std::uint32_t* dst = __bss_start; dst < __bss_end;) *dst++ = 0;
  for (Constructor* c = __init_array_start; c < __init_array_end; ++c) (*c)();
  aloft::port::exit_with_status(main());
}

extern "C" void Fault_Handler() {
  // IPSR holds the number of the exception being handled.
  std::uint32_t exception;
  asm volatile("mrs %0, ipsr" : "=r"(exception));
  aloft::port::write_text(exception == 3 ? "\n*** HardFault\n" : "\n*** unexpected exception\n");
  aloft::port::exit_with_status(128 + static_cast<int>(exception & 0xFFu));
}
