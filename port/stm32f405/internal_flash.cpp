#include "internal_flash.hpp"

#include "aloft_port/port.hpp"
#include "stm32f405_registers.hpp"

namespace aloft::port::stm32f405 {
namespace {

// Registers and bits: stm32f405_registers.hpp (RM0090 §3.9). Sectors 5..11 are 128 KiB
// from 0x08020000 (§3.3, Table 5, 1 MiB devices).
using namespace flash_bits;
constexpr std::uint32_t sector5_address = 0x08020000u;
constexpr std::uint32_t sector_size = InternalFlash::sector_size;
constexpr std::uint32_t sr_errors = sr_operr | sr_wrperr | sr_pgaerr | sr_pgperr | sr_pgserr;

constexpr std::uint32_t erase_timeout_us = 4000000;  // DS8626 Table 43: tERASE128KB max 2 s (x32)
constexpr std::uint32_t program_timeout_us = 1000;   // DS8626 Table 43: tWORD max 100 µs (x32)
// A cap on polls in case the clock does not run: at 168 MHz a poll takes more than one
// cycle, so 200 polls per µs of timeout are more than the timeout itself.
constexpr std::uint32_t polls_per_us = 200;

volatile std::uint32_t& word_register(std::uint32_t address) {
  return *reinterpret_cast<volatile std::uint32_t*>(address);
}

std::uint32_t sector_address(std::uint32_t sector) { return sector5_address + (sector - 5) * sector_size; }

Status wait_while_busy(std::uint32_t timeout_us) {
  const std::uint64_t start = ticks();
  // Ticks per µs rounded up, so the wait is never shorter than asked (and no 64-bit division).
  const std::uint64_t limit = std::uint64_t(timeout_us) * (ticks_per_second() / 1000000u + 1);
  const std::uint64_t max_polls = std::uint64_t(timeout_us) * polls_per_us;
  for (std::uint64_t polls = 0; polls < max_polls; ++polls) {
    if ((flash().sr & sr_bsy) == 0) {
      const std::uint32_t errors = flash().sr & sr_errors;
      flash().sr = errors | sr_eop;  // write 1 to clear
      return errors == 0 ? Status::ok : Status::bus_error;
    }
    if (ticks() - start > limit) break;
  }
  return Status::bus_error;
}

// Unlocks the control register and clears stale flags; bus_error if it stays locked.
Status unlock() {
  if (wait_while_busy(erase_timeout_us) != Status::ok) return Status::bus_error;
  if (flash().cr & cr_lock) {
    flash().keyr = key1;
    flash().keyr = key2;
  }
  flash().sr = sr_errors | sr_eop;
  return (flash().cr & cr_lock) ? Status::bus_error : Status::ok;
}

Status lock(Status s) {
  flash().cr = (flash().cr & ~(cr_pg | cr_ser | cr_snb_mask)) | cr_lock;
  return s;
}

void flush_data_cache() {
  const std::uint32_t acr = flash().acr;
  if ((acr & acr_dcen) == 0) return;
  flash().acr = acr & ~acr_dcen;  // reset only while disabled (§3.5.2)
  flash().acr = (acr & ~acr_dcen) | acr_dcrst;
  flash().acr = acr & ~acr_dcrst;
}

std::uint32_t word_at(const std::uint8_t* p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
         std::uint32_t(p[3]) << 24;
}

}  // namespace

Status InternalFlash::read(void* context, std::uint32_t block, std::uint32_t offset, std::uint8_t* data,
                           std::uint32_t size) {
  const InternalFlash& f = *static_cast<const InternalFlash*>(context);
  if (block >= f.device_.block_count || offset > sector_size || size > sector_size - offset)
    return Status::invalid_dimension;
  const volatile std::uint8_t* from =
      reinterpret_cast<const volatile std::uint8_t*>(sector_address(f.config_.first_sector + block) + offset);
  for (std::uint32_t i = 0; i < size; ++i) data[i] = from[i];
  return Status::ok;
}

// RM0090 §3.6.2: BSY clear, PG set with PSIZE x32, one 32-bit write per word, BSY clear.
Status InternalFlash::program(void* context, std::uint32_t block, std::uint32_t offset,
                              const std::uint8_t* data, std::uint32_t size) {
  const InternalFlash& f = *static_cast<const InternalFlash*>(context);
  if (block >= f.device_.block_count || offset % 4 || size % 4 || offset > sector_size ||
      size > sector_size - offset)
    return Status::invalid_dimension;
  if (unlock() != Status::ok) return lock(Status::bus_error);
  flash().cr = (flash().cr & ~cr_psize_mask) | cr_psize_x32 | cr_pg;
  const std::uint32_t base = sector_address(f.config_.first_sector + block) + offset;
  for (std::uint32_t i = 0; i < size; i += 4) {
    volatile std::uint32_t& word = word_register(base + i);
    const std::uint32_t value = word_at(data + i);
    word = value;
    if (wait_while_busy(program_timeout_us) != Status::ok) return lock(Status::bus_error);
    if (word != value) return lock(Status::corrupt_data);  // a 1 over a 0, or a weak cell
  }
  return lock(Status::ok);
}

// RM0090 §3.6.3 sector erase: BSY clear, SER and SNB set, STRT set, BSY clear.
Status InternalFlash::erase(void* context, std::uint32_t block) {
  const InternalFlash& f = *static_cast<const InternalFlash*>(context);
  if (block >= f.device_.block_count) return Status::invalid_dimension;
  if (unlock() != Status::ok) return lock(Status::bus_error);
  const std::uint32_t sector = f.config_.first_sector + block;
  flash().cr = (flash().cr & ~(cr_psize_mask | cr_snb_mask | cr_pg)) | cr_psize_x32 | cr_ser | cr_snb(sector);
  flash().cr = flash().cr | cr_strt;
  const Status s = wait_while_busy(erase_timeout_us);
  flush_data_cache();
  return lock(s);
}

}  // namespace aloft::port::stm32f405
