// ARM semihosting (the "Semihosting for AArch32 and AArch64" specification): on M-profile
// a BKPT 0xAB with the operation in r0 and its argument in r1 asks the debugger, or QEMU
// with -semihosting-config enable=on, to do the work; the result comes back in r0.
// Without a debugger attached the BKPT is a fault, so only builds meant for QEMU or a
// debug probe use this.
#pragma once

#include <cstdint>

namespace aloft {
namespace port {
namespace semihosting {

enum class Operation : std::uint32_t {
  open = 0x01,           // open a host file: {name, mode, name length}; a handle or -1
  close = 0x02,          // close it: {handle}; 0 on success
  write = 0x05,          // write: {handle, data, length}; the bytes NOT written (0: all)
  write0 = 0x04,         // write a NUL-terminated string to the debug console
  exit = 0x18,           // end the program; AArch32 passes only a reason code
  exit_extended = 0x20,  // end the program with a reason code and an exit status
};

// Reason codes of exit / exit_extended.
constexpr std::uint32_t application_exit = 0x20026;  // ADP_Stopped_ApplicationExit

inline std::uint32_t call(Operation op, const void* argument) {
  register std::uint32_t r0 asm("r0") = static_cast<std::uint32_t>(op);
  register const void* r1 asm("r1") = argument;
  asm volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
  return r0;
}

}  // namespace semihosting
}  // namespace port
}  // namespace aloft
