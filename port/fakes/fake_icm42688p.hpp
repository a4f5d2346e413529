// A fake ICM-42688-P behind aloft::ImuBus, for the driver's tests on the host and on the
// bare-metal targets under QEMU (no heap: fixed arrays only). It is a register file of
// banks 0-2 and a 2 KiB byte FIFO that turns a sample stream into the bytes the chip
// would give (icm42688p_packet_encoder.hpp), on a simulated MCU clock:
//   - the MCU clock (bus.now_us) moves by 1 µs per now_us call, so bounded waits end,
//     and by advance_us(), which the test calls between polls;
//   - once the FIFO is in a non-bypass mode with accel and gyro enabled and both sensors
//     in low-noise mode, sample k (k = 0, 1, ...) is made at the ODR of GYRO_CONFIG0 and
//     appended to the FIFO as packet 3 with the time stamp counter's value: 1 µs ticks,
//     or 30/32 of that when INTF_CONFIG1 selects the internal RC oscillator (CLKSEL 00),
//     starting from `stamp_start` so that the 16-bit stamp wraps early in a test;
//   - stream mode: when a packet does not fit, the oldest is dropped and INT_STATUS
//     FIFO_FULL is set (cleared when read);
//   - registers: SOFT_RESET_CONFIG restores the reset values and empties the FIFO;
//     FIFO_FLUSH empties the FIFO; INT_STATUS, FIFO_COUNTH/L (bytes or records, endian
//     per INTF_CONFIG0) and FIFO_DATA (no address increment) are read as the chip does.
// Faults, scheduled by the test: power-up packets without data (-32768), a wrong
// WHO_AM_I, a register that ignores writes, a register that changes on its own
// (corrupt_register), a garbled header, empty reads, a truncated burst (the port
// sees the short transfer and returns bus_error), and reads of FIFO_DATA that find the
// FIFO empty (HEADER_MSG, 0x80, DS-000347 §6.2): whole bursts that read 0x80 while
// FIFO_COUNT said there were packets (empty_bursts), or one 0x80 byte before the
// packets of a burst, which then ends 15 bytes into its last packet: a cut tail
// (empty_byte_before_next_burst). A tap (tap_fifo_data) sees every byte read from
// FIFO_DATA, as a logic analyser would: the recording that `aloft replay --fifo` reads.
#pragma once

#include <cstdint>

#include "aloft/sensor/icm42688p_registers.hpp"
#include "aloft/sensor/imu_bus.hpp"
#include "icm42688p_packet_encoder.hpp"

namespace aloft_test {

using SampleSource = ChipSample (*)(std::uint32_t index);

struct FakeChipFaults {
  std::uint8_t who_am_i = 0x47;
  std::uint32_t packets_without_data = 0;   // the first packets after power-up hold -32768
  std::int64_t garbled_header_packet = -1;  // index of the packet whose header is garbled
  std::uint8_t stuck_bank = 0xFF;           // this register ignores writes
  std::uint8_t stuck_reg = 0;
};

class FakeIcm42688p {
 public:
  static constexpr std::uint16_t kFifoBytes = 2048;

  explicit FakeIcm42688p(SampleSource source, const FakeChipFaults& faults = FakeChipFaults(),
                         std::uint16_t stamp_start = 0xF000)
      : source_(source), faults_(faults), stamp_start_(stamp_start) {
    reset_registers();
  }

  aloft::ImuBus bus() {
    aloft::ImuBus b;
    b.context = this;
    b.read = &read_callback;
    b.write = &write_callback;
    b.now_us = &now_callback;
    return b;
  }

  void advance_us(std::uint64_t us) {
    now_us_ += us;
    make_due_packets();
  }
  void force_empty_reads(std::uint32_t n) { empty_reads_left_ = n; }
  void truncate_next_burst(std::uint16_t bytes) {
    truncate_armed_ = true;
    truncate_at_ = bytes;
  }
  // The next n FIFO_DATA bursts read as from an empty FIFO: every byte 0x80 (what
  // pop_byte gives), nothing taken from the FIFO; one empty read per 16-byte slot.
  void empty_bursts(std::uint32_t n) { empty_bursts_left_ = n; }
  // The next burst begins with one 0x80 byte, then the FIFO's bytes: its last packet is
  // cut 15 bytes in, and the FIFO's read point is left inside that packet.
  void empty_byte_before_next_burst() { empty_byte_armed_ = true; }
  // Every byte read from FIFO_DATA, in order, to `tap` (no heap: the test stores them).
  using FifoTap = void (*)(void* context, const std::uint8_t* bytes, std::uint16_t length);
  void tap_fifo_data(FifoTap tap, void* context) {
    tap_ = tap;
    tap_context_ = context;
  }
  std::uint32_t empty_reads_sent() const { return empty_reads_sent_; }
  void corrupt_register(std::uint8_t bank, std::uint8_t reg, std::uint8_t value) { regs_[bank][reg] = value; }

  std::uint8_t reg(std::uint8_t bank, std::uint8_t reg) const { return regs_[bank][reg]; }
  std::uint32_t packets_made() const { return next_index_; }
  std::uint32_t packets_dropped() const { return dropped_; }
  std::uint32_t flushes() const { return flushes_; }
  std::uint16_t fifo_bytes() const { return size_; }
  std::uint32_t period_us() const {
    const std::uint8_t odr = regs_[0][aloft::icm42688p::bank0::gyro_config0] & 0x0F;
    return odr == 0x04 ? 250u : (odr == 0x05 ? 500u : 1000u);
  }

 private:
  static aloft::Status read_callback(void* c, std::uint8_t reg, std::uint8_t* data, std::uint16_t length) {
    return static_cast<FakeIcm42688p*>(c)->read(reg, data, length);
  }
  static aloft::Status write_callback(void* c, std::uint8_t reg, std::uint8_t value) {
    return static_cast<FakeIcm42688p*>(c)->write(reg, value);
  }
  static std::uint64_t now_callback(void* c) {
    auto* chip = static_cast<FakeIcm42688p*>(c);
    chip->advance_us(1);
    return chip->now_us_;
  }

  void reset_registers() {
    namespace b0 = aloft::icm42688p::bank0;
    for (auto& bank : regs_) {
      for (std::uint8_t& r : bank) r = 0;
    }
    // Reset values of the datasheet's register map, for the registers the driver touches.
    regs_[0][b0::drive_config] = 0x05;
    regs_[0][b0::int_status] = 0x10;
    regs_[0][b0::intf_config0] = 0x30;
    regs_[0][b0::intf_config1] = 0x91;
    regs_[0][b0::gyro_config0] = 0x06;
    regs_[0][b0::accel_config0] = 0x06;
    regs_[0][b0::gyro_config1] = 0x16;
    regs_[0][b0::gyro_accel_config0] = 0x11;
    regs_[0][b0::accel_config1] = 0x0D;
    regs_[0][b0::tmst_config] = 0x23;
    regs_[0][b0::who_am_i] = faults_.who_am_i;
    regs_[1][0x0B] = 0xA0;
    regs_[1][0x0C] = 0x0D;
    regs_[1][0x0D] = 0xAA;
    regs_[1][0x0E] = 0x80;
    regs_[2][0x03] = 0x30;
    regs_[2][0x04] = 0x40;
    regs_[2][0x05] = 0x62;
    bank_ = 0;
    size_ = 0;
    head_ = 0;
    sampling_ = false;
  }

  bool sampling_enabled() const {
    namespace b0 = aloft::icm42688p::bank0;
    const std::uint8_t fifo_mode = regs_[0][b0::fifo_config] & 0xC0;
    const std::uint8_t fifo_cfg1 = regs_[0][b0::fifo_config1];
    const std::uint8_t pwr = regs_[0][b0::pwr_mgmt0];
    return fifo_mode != 0 && (fifo_cfg1 & 0x03) == 0x03 && (pwr & 0x0F) == 0x0F;
  }

  // Ticks of the time stamp counter at `us` after power-on of the sensors.
  std::uint16_t stamp_at(std::uint64_t us) const {
    const bool rc_only = (regs_[0][aloft::icm42688p::bank0::intf_config1] & 0x03) == 0x00;
    const std::uint64_t ticks = rc_only ? us * 30u / 32u : us;
    return static_cast<std::uint16_t>((stamp_start_ + ticks) & 0xFFFFu);
  }

  void make_due_packets() {
    const bool enabled = sampling_enabled();
    if (enabled && !sampling_) {
      epoch_us_ = now_us_;
      next_sample_us_ = now_us_ + period_us();
    }
    sampling_ = enabled;
    while (sampling_ && next_sample_us_ <= now_us_) {
      const std::uint32_t k = next_index_++;
      ChipSample s =
          k - first_index_after_reset_ < faults_.packets_without_data ? no_data_sample() : source_(k);
      std::uint8_t packet[kEncoderPacket3Bytes];
      const bool big_endian = (regs_[0][aloft::icm42688p::bank0::intf_config0] & 0x10) != 0;
      encode_packet3(s, stamp_at(next_sample_us_ - epoch_us_), big_endian, packet);
      if (static_cast<std::int64_t>(k) == faults_.garbled_header_packet) packet[0] = 0x3C;
      push_packet(packet);
      next_sample_us_ += period_us();
    }
  }

  void push_packet(const std::uint8_t (&packet)[kEncoderPacket3Bytes]) {
    if (size_ + kEncoderPacket3Bytes > kFifoBytes) {
      regs_[0][aloft::icm42688p::bank0::int_status] |= 0x02;  // FIFO_FULL_INT
      head_ = static_cast<std::uint16_t>((head_ + kEncoderPacket3Bytes) % kFifoBytes);
      size_ = static_cast<std::uint16_t>(size_ - kEncoderPacket3Bytes);
      ++dropped_;
    }
    for (std::uint8_t byte : packet) {
      fifo_[(head_ + size_) % kFifoBytes] = byte;
      ++size_;
    }
  }

  std::uint8_t pop_byte() {
    if (size_ == 0) return 0x80;  // HEADER_MSG: the FIFO is empty
    const std::uint8_t byte = fifo_[head_];
    head_ = static_cast<std::uint16_t>((head_ + 1) % kFifoBytes);
    --size_;
    return byte;
  }

  std::uint8_t read_register(std::uint8_t reg) {
    namespace b0 = aloft::icm42688p::bank0;
    if (reg >= 128) return 0;
    if (bank_ == 0 && (reg == b0::fifo_counth || reg == b0::fifo_countl)) {
      const std::uint8_t intf0 = regs_[0][b0::intf_config0];
      std::uint16_t count =
          (intf0 & 0x40) != 0 ? static_cast<std::uint16_t>(size_ / kEncoderPacket3Bytes) : size_;
      if (empty_reads_left_ > 0) count = 0;
      const bool big = (intf0 & 0x20) != 0;
      const bool high = (reg == b0::fifo_counth) == big;
      return static_cast<std::uint8_t>(high ? count >> 8 : count & 0xFF);
    }
    const std::uint8_t value = regs_[bank_][reg];
    if (bank_ == 0 && reg == b0::int_status) regs_[0][reg] = 0;
    return value;
  }

  aloft::Status read(std::uint8_t reg, std::uint8_t* data, std::uint16_t length) {
    make_due_packets();
    if (bank_ == 0 && reg == aloft::icm42688p::bank0::fifo_data) return read_fifo(data, length);
    for (std::uint16_t i = 0; i < length; ++i) data[i] = read_register(static_cast<std::uint8_t>(reg + i));
    if (bank_ == 0 && reg <= aloft::icm42688p::bank0::fifo_countl && empty_reads_left_ > 0)
      --empty_reads_left_;
    return aloft::Status::ok;
  }

  aloft::Status read_fifo(std::uint8_t* data, std::uint16_t length) {
    const bool truncated = truncate_armed_ && truncate_at_ < length;
    const std::uint16_t n = truncated ? truncate_at_ : length;
    truncate_armed_ = false;
    if (empty_bursts_left_ > 0) {
      --empty_bursts_left_;
      for (std::uint16_t i = 0; i < length; ++i) data[i] = 0x80;
      empty_reads_sent_ +=
          static_cast<std::uint32_t>((length + kEncoderPacket3Bytes - 1) / kEncoderPacket3Bytes);
    } else {
      std::uint16_t i = 0;
      if (empty_byte_armed_ && length > 0) {
        data[i++] = 0x80;
        ++empty_reads_sent_;
      }
      empty_byte_armed_ = false;
      for (; i < length; ++i) data[i] = i < n ? pop_byte() : 0xFF;
    }
    if (tap_ != nullptr) tap_(tap_context_, data, n);
    return truncated ? aloft::Status::bus_error : aloft::Status::ok;
  }

  aloft::Status write(std::uint8_t reg, std::uint8_t value) {
    namespace b0 = aloft::icm42688p::bank0;
    make_due_packets();
    if (reg == b0::reg_bank_sel) {
      bank_ = static_cast<std::uint8_t>(value & 0x07);
      return bank_ <= 2 ? aloft::Status::ok : aloft::Status::bus_error;
    }
    if (reg >= 128 || (bank_ == faults_.stuck_bank && reg == faults_.stuck_reg)) return aloft::Status::ok;
    if (bank_ == 0 && reg == b0::device_config && (value & 0x01) != 0) {
      reset_registers();
      first_index_after_reset_ = next_index_;
      return aloft::Status::ok;
    }
    if (bank_ == 0 && reg == b0::signal_path_reset && (value & 0x02) != 0) {
      size_ = 0;
      head_ = 0;
      ++flushes_;
      return aloft::Status::ok;
    }
    if (bank_ == 0 && (reg == b0::who_am_i || reg == b0::int_status)) return aloft::Status::ok;  // read-only
    regs_[bank_][reg] = value;
    make_due_packets();
    return aloft::Status::ok;
  }

  SampleSource source_;
  FakeChipFaults faults_;
  std::uint16_t stamp_start_;
  std::uint8_t regs_[3][128] = {};
  std::uint8_t bank_ = 0;
  std::uint8_t fifo_[kFifoBytes] = {};
  std::uint16_t head_ = 0;
  std::uint16_t size_ = 0;
  std::uint64_t now_us_ = 0;
  std::uint64_t epoch_us_ = 0;
  std::uint64_t next_sample_us_ = 0;
  std::uint32_t next_index_ = 0;
  std::uint32_t first_index_after_reset_ = 0;
  std::uint32_t dropped_ = 0;
  std::uint32_t flushes_ = 0;
  std::uint32_t empty_reads_left_ = 0;
  bool sampling_ = false;
  bool truncate_armed_ = false;
  std::uint16_t truncate_at_ = 0;
  std::uint32_t empty_bursts_left_ = 0;
  bool empty_byte_armed_ = false;
  std::uint32_t empty_reads_sent_ = 0;
  FifoTap tap_ = nullptr;
  void* tap_context_ = nullptr;
};

}  // namespace aloft_test
