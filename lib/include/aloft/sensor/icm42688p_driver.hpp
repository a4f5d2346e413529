// A board-independent ICM-42688-P driver that streams the chip's FIFO into ImuSamples,
// over the bus a port provides (aloft/sensor/imu_bus.hpp): SPI1 on a flight controller, a fake
// chip in the tests. Shaped after PX4's InvenSense drivers, with every fact checked
// against the datasheet (aloft/sensor/icm42688p_registers.hpp says where each comes from).
//
//   begin()  soft reset; WHO_AM_I must read 0x47 (else Status::sensor_not_found); the
//            configuration table below is written and read back (Status::register_not_kept
//            when a register does not keep its bits); the FIFO is flushed.
//   poll()   one bounded step: now and then one table register is read back (a register
//            that lost its bits is rewritten, counted, and the call returns
//            register_not_kept); INT_STATUS and FIFO_COUNT in one 3-byte read; then the
//            whole packets present, in bursts of at most kBurstPackets, decoded by
//            aloft/sensor/icm42688p_fifo.hpp and handed to the sink in order. A part of a packet
//            stays in the FIFO for the next poll (FIFO_RESUME_PARTIAL_RD).
//
// Faults and what poll() does (each is counted in DriverCounters):
//   - overflow (INT_STATUS FIFO_FULL, or FIFO_COUNT at the 2 KiB capacity): the FIFO is
//     flushed; the samples lost make a gap, whose length the next sample's time stamp
//     gives: measured from the stamps, with the wrap count (65.536 ms at 1 µs) taken from
//     the MCU clock (bus.now_us), so gaps longer than one wrap are measured too.
//   - a header that is not packet 3, or a packet cut by the burst's end (after a lone
//     0x80 byte): the rest of the burst is skipped (bytes_skipped), the FIFO
//     flushed and the stream resynchronised on the next packet boundary.
//   - the header 0x80 (HEADER_MSG, §6.2 "FIFO is empty") inside a burst: an empty
//     read, counted, the walk goes on (the byte alone or its 16-byte slot, by the rule
//     of aloft/sensor/icm42688p_fifo.hpp).
//   - a bus error during the burst (a truncated transfer the port detected): the same.
//   - packets holding -32768 (no data yet, as after power-up): dropped.
//   - FIFO_COUNT below one packet: an empty read (no burst).
//
// RAM: the object itself, burst buffer included, at most 512 bytes (static_assert below).
// No heap, no exceptions, no blocking wait longer than the datasheet's 1 ms after reset.
#pragma once

#include <cstdint>

#include "aloft/cold_path.hpp"
#include "aloft/sensor/icm42688p_fifo.hpp"
#include "aloft/sensor/icm42688p_registers.hpp"
#include "aloft/sensor/imu_bus.hpp"
#include "aloft/sensor/imu_sample.hpp"
#include "aloft/status.hpp"

namespace aloft::icm42688p {

enum class OutputDataRate : std::uint8_t { hz1000, hz2000, hz4000 };

struct DriverSettings {
  OutputDataRate odr = OutputDataRate::hz1000;
  TimestampClock clock = TimestampClock::pll_or_external;
  // Polls between two read-backs of one configuration register (the table is walked one
  // register at a time); 0 never checks after begin().
  std::uint16_t register_check_every = 64;
};

inline std::uint32_t odr_hz(OutputDataRate odr) {
  return odr == OutputDataRate::hz4000 ? 4000u : (odr == OutputDataRate::hz2000 ? 2000u : 1000u);
}

// One configuration step: in `reg` of `bank`, these bits set and these cleared; the
// other bits are left as they are.
struct ConfigEntry {
  Bank bank;
  std::uint8_t reg;
  std::uint8_t set_bits;
  std::uint8_t clear_bits;
};

constexpr int kConfigEntries = 18;

// The configuration table (entry i of kConfigEntries), in the order it is written:
// interface, FIFO and time stamps, ranges and rates, filters, and the sensors switched
// on last (the AAF registers are static: written while the sensors are off).
ALOFT_COLD inline ConfigEntry config_entry(const DriverSettings& s, int i) {
  const std::uint8_t odr =
      s.odr == OutputDataRate::hz4000 ? kOdr4kHz : (s.odr == OutputDataRate::hz2000 ? kOdr2kHz : kOdr1kHz);
  const AafRow aaf =
      s.odr == OutputDataRate::hz4000 ? kAaf997Hz : (s.odr == OutputDataRate::hz2000 ? kAaf536Hz : kAaf258Hz);
  const std::uint8_t clk = s.clock == TimestampClock::internal_rc ? kClkSelRcOnly : kClkSelPll;
  const auto low = [](std::uint16_t v) { return static_cast<std::uint8_t>(v & 0xFF); };
  const auto not8 = [](unsigned v) { return static_cast<std::uint8_t>(~v & 0xFFu); };
  const auto u8 = [](unsigned v) { return static_cast<std::uint8_t>(v & 0xFFu); };
  const std::uint8_t aaf_hi = static_cast<std::uint8_t>((aaf.bitshift << 4) | (aaf.deltsqr >> 8));
  const std::uint8_t accel_delt = static_cast<std::uint8_t>(aaf.delt << 1);
  switch (i) {
    case 0:
      return {Bank::bank0, bank0::intf_config0, kFifoCountEndian | kSensorDataEndian,
              kFifoCountRec | kFifoHoldLastDataEn};
    case 1:
      return {Bank::bank0, bank0::intf_config1, clk,
              static_cast<std::uint8_t>((kClkSelMask & ~clk) | kRtcMode)};
    case 2: return {Bank::bank0, bank0::fifo_config, kFifoModeStream, kFifoModeMask & not8(kFifoModeStream)};
    case 3:
      return {Bank::bank0, bank0::fifo_config1,
              kFifoResumePartialRd | kFifoTempEn | kFifoGyroEn | kFifoAccelEn,
              kFifoHiresEn | kFifoTmstFsyncEn | kFifoWmGtTh};
    case 4: return {Bank::bank0, bank0::tmst_config, kTmstEn, kTmstRes | kTmstDeltaEn | kTmstFsyncEn};
    case 5: return {Bank::bank0, bank0::gyro_config0, odr, u8(kFsSelMask | (kOdrMask & not8(odr)))};
    case 6: return {Bank::bank0, bank0::accel_config0, odr, u8(kFsSelMask | (kOdrMask & not8(odr)))};
    case 7: return {Bank::bank0, bank0::gyro_config1, 0, kGyroUiFiltOrdMask};
    case 8: return {Bank::bank0, bank0::accel_config1, 0, kAccelUiFiltOrdMask};
    case 9: return {Bank::bank0, bank0::gyro_accel_config0, kUiFiltBwOdrDiv4, not8(kUiFiltBwOdrDiv4)};
    case 10: return {Bank::bank1, bank1::gyro_config_static2, 0, kGyroAafDis};
    case 11:
      return {Bank::bank1, bank1::gyro_config_static3, aaf.delt, u8(kGyroAafDeltMask & not8(aaf.delt))};
    case 12: return {Bank::bank1, bank1::gyro_config_static4, low(aaf.deltsqr), not8(low(aaf.deltsqr))};
    case 13: return {Bank::bank1, bank1::gyro_config_static5, aaf_hi, not8(aaf_hi)};
    case 14:
      return {Bank::bank2, bank2::accel_config_static2, accel_delt,
              static_cast<std::uint8_t>((kAccelAafDeltMask & not8(accel_delt)) | kAccelAafDis)};
    case 15: return {Bank::bank2, bank2::accel_config_static3, low(aaf.deltsqr), not8(low(aaf.deltsqr))};
    case 16: return {Bank::bank2, bank2::accel_config_static4, aaf_hi, not8(aaf_hi)};
    default: return {Bank::bank0, bank0::pwr_mgmt0, kGyroModeLowNoise | kAccelModeLowNoise, kTempDis | kIdle};
  }
}

// What the driver met, counted since begin(). None is hidden: a port logs them.
struct DriverCounters {
  std::uint32_t packets = 0;          // packet-3 packets read (valid and invalid)
  std::uint32_t samples = 0;          // samples handed to the sink
  std::uint32_t invalid = 0;          // packets holding -32768, dropped
  std::uint32_t resyncs = 0;          // foreign header or broken burst: flushed, resynchronised
  std::uint32_t overflows = 0;        // FIFO full: flushed
  std::uint32_t bytes_skipped = 0;    // bytes read but not decoded (foreign header, cut packet)
  std::uint32_t empty_reads = 0;      // polls that found no whole packet, and 0x80 (HEADER_MSG) reads
  std::uint32_t register_faults = 0;  // configuration registers found without their bits
  std::uint32_t bus_errors = 0;       // bus calls that failed
  std::uint32_t gaps = 0;             // samples with gap_before
  std::uint64_t last_gap_us = 0;      // time from the sample before the last gap to the one after
};

template <typename Scalar>
struct SampleSink {
  void* context = nullptr;
  void (*push)(void* context, const ImuSample<Scalar>& sample) = nullptr;
};

template <typename Scalar>
class Icm42688pDriver {
 public:
  // 3 packets (48 B of RAM): a poll takes every whole packet present, in as many bursts as
  // that needs (the FIFO holds 128), and on a flight controller RAM is the scarcer
  // resource (issue 29: the STM32F405 image's RAM bar; 16 packets were 256 B, 8 were 128 B;
  // with the 32-sample history that keeps the ring index a mask, 4 left that image 8 B over
  // its 4 KiB bar and 3 bring it 8 B under, with its instructions per sample and its replay
  // lines unchanged). A poll every millisecond at 4 kHz reads two bursts.
  static constexpr std::uint16_t kBurstPackets = 3;
  static constexpr std::uint16_t kBurstBytes = kBurstPackets * kPacket3Bytes;

  Icm42688pDriver(const ImuBus& bus, const DriverSettings& settings)
      : bus_(bus), settings_(settings), decoder_(odr_hz(settings.odr), settings.clock) {}

  ALOFT_COLD Status begin();
  Status poll(const SampleSink<Scalar>& sink);
  const DriverCounters& counters() const { return counters_; }
  const DriverSettings& settings() const { return settings_; }
  const ImuBus& bus() const { return bus_; }

 private:
  Status select_bank(Bank bank);
  Status read(Bank bank, std::uint8_t reg, std::uint8_t* data, std::uint16_t length);
  Status write(Bank bank, std::uint8_t reg, std::uint8_t value);
  ALOFT_COLD void wait_us(std::uint32_t us);
  ALOFT_COLD Status apply(const ConfigEntry& e);
  ALOFT_COLD Status entry_kept(const ConfigEntry& e);
  ALOFT_COLD Status check_next_register();
  ALOFT_COLD void flush_and_mark_lost();
  Status read_burst(std::uint16_t packets_in_fifo, const SampleSink<Scalar>& sink);
  void emit(const ImuSample<Scalar>& sample, std::uint64_t mcu_us, const SampleSink<Scalar>& sink);
  std::uint64_t us_to_ticks(std::uint64_t us) const {
    return settings_.clock == TimestampClock::internal_rc ? us * kRcTickDenominator / kRcTickNumerator : us;
  }
  std::uint32_t period_us() const { return 1000000u / odr_hz(settings_.odr); }

  ImuBus bus_;
  DriverSettings settings_;
  FifoDecoder<Scalar> decoder_;
  DriverCounters counters_;
  std::uint8_t bank_ = 0xFF;  // unknown until selected
  std::uint8_t check_index_ = 0;
  std::uint16_t polls_since_check_ = 0;
  bool data_lost_ = false;                // the FIFO was flushed since the last sample
  bool have_sample_ = false;              // a sample has been emitted since begin()
  std::uint64_t last_sample_mcu_us_ = 0;  // MCU time the last emitted sample was taken, estimated
  std::uint64_t last_sample_t_us_ = 0;
  std::uint8_t burst_[kBurstBytes] = {};
};

template <typename Scalar>
Status Icm42688pDriver<Scalar>::select_bank(Bank bank) {
  const auto b = static_cast<std::uint8_t>(bank);
  if (bank_ == b) return Status::ok;
  const Status s = bus_.write(bus_.context, bank0::reg_bank_sel, b);
  if (s != Status::ok) {
    ++counters_.bus_errors;
    bank_ = 0xFF;
    return s;
  }
  bank_ = b;
  return Status::ok;
}

template <typename Scalar>
Status Icm42688pDriver<Scalar>::read(Bank bank, std::uint8_t reg, std::uint8_t* data, std::uint16_t length) {
  Status s = select_bank(bank);
  if (s != Status::ok) return s;
  s = bus_.read(bus_.context, reg, data, length);
  if (s != Status::ok) ++counters_.bus_errors;
  return s;
}

template <typename Scalar>
Status Icm42688pDriver<Scalar>::write(Bank bank, std::uint8_t reg, std::uint8_t value) {
  Status s = select_bank(bank);
  if (s != Status::ok) return s;
  s = bus_.write(bus_.context, reg, value);
  if (s != Status::ok) ++counters_.bus_errors;
  return s;
}

// Waits on the MCU clock, bounded in iterations too: a clock that does not advance
// (a port fault) must not hang the bring-up.
template <typename Scalar>
void Icm42688pDriver<Scalar>::wait_us(std::uint32_t us) {
  const std::uint64_t start = bus_.now_us(bus_.context);
  for (std::uint32_t i = 0; i < 1000000u; ++i) {
    if (bus_.now_us(bus_.context) - start >= us) return;
  }
}

// Writes one table entry (read, modify, write when it differs) and reads it back.
template <typename Scalar>
Status Icm42688pDriver<Scalar>::apply(const ConfigEntry& e) {
  std::uint8_t value = 0;
  Status s = read(e.bank, e.reg, &value, 1);
  if (s != Status::ok) return s;
  const auto wanted = static_cast<std::uint8_t>((value & ~e.clear_bits & 0xFF) | e.set_bits);
  if (wanted != value) {
    s = write(e.bank, e.reg, wanted);
    if (s != Status::ok) return s;
    if (e.bank == Bank::bank0 && e.reg == bank0::pwr_mgmt0) wait_us(kPowerOnWriteWaitUs);
  }
  return entry_kept(e);
}

template <typename Scalar>
Status Icm42688pDriver<Scalar>::entry_kept(const ConfigEntry& e) {
  std::uint8_t value = 0;
  const Status s = read(e.bank, e.reg, &value, 1);
  if (s != Status::ok) return s;
  if ((value & (e.set_bits | e.clear_bits)) != e.set_bits) {
    ++counters_.register_faults;
    return Status::register_not_kept;
  }
  return Status::ok;
}

template <typename Scalar>
Status Icm42688pDriver<Scalar>::begin() {
  counters_ = DriverCounters{};
  decoder_ = FifoDecoder<Scalar>(odr_hz(settings_.odr), settings_.clock);
  data_lost_ = false;
  have_sample_ = false;
  bank_ = 0xFF;
  Status s = write(Bank::bank0, bank0::device_config, kSoftResetConfig);
  if (s != Status::ok) return s;
  bank_ = 0;  // the reset selects bank 0
  wait_us(kSoftResetWaitUs);
  std::uint8_t who = 0;
  s = read(Bank::bank0, bank0::who_am_i, &who, 1);
  if (s != Status::ok) return s;
  if (who != kWhoAmIValue) return Status::sensor_not_found;
  for (int i = 0; i < kConfigEntries; ++i) {
    s = apply(config_entry(settings_, i));
    if (s != Status::ok) return s;
  }
  s = write(Bank::bank0, bank0::signal_path_reset, kFifoFlush);
  if (s != Status::ok) return s;
  decoder_ = FifoDecoder<Scalar>(odr_hz(settings_.odr), settings_.clock);
  return Status::ok;
}

// Reads back the next table register; a register that lost its bits is rewritten and
// the FIFO flushed (the data since the change are of unknown configuration).
template <typename Scalar>
Status Icm42688pDriver<Scalar>::check_next_register() {
  const ConfigEntry e = config_entry(settings_, check_index_);
  check_index_ = static_cast<std::uint8_t>((check_index_ + 1) % kConfigEntries);
  Status s = entry_kept(e);
  if (s != Status::register_not_kept) return s;
  const Status repaired = apply(e);
  if (repaired == Status::register_not_kept) --counters_.register_faults;  // one fault, counted once
  flush_and_mark_lost();
  return Status::register_not_kept;
}

template <typename Scalar>
void Icm42688pDriver<Scalar>::flush_and_mark_lost() {
  static_cast<void>(write(Bank::bank0, bank0::signal_path_reset, kFifoFlush));
  data_lost_ = true;
  decoder_.expect_gap(0);
}

template <typename Scalar>
Status Icm42688pDriver<Scalar>::poll(const SampleSink<Scalar>& sink) {
  Status status = Status::ok;
  if (settings_.register_check_every > 0 && ++polls_since_check_ >= settings_.register_check_every) {
    polls_since_check_ = 0;
    status = check_next_register();
  }
  std::uint8_t head[3] = {0, 0, 0};  // INT_STATUS, FIFO_COUNTH, FIFO_COUNTL
  const Status s = read(Bank::bank0, bank0::int_status, head, 3);
  if (s != Status::ok) return s;
  const auto count = static_cast<std::uint16_t>((head[1] << 8) | head[2]);
  if ((head[0] & kIntStatusFifoFull) != 0 || count >= kFifoCapacityBytes) {
    ++counters_.overflows;
    flush_and_mark_lost();
    return status;
  }
  const auto packets_in_fifo = static_cast<std::uint16_t>(count / kPacket3Bytes);
  if (packets_in_fifo == 0) {
    ++counters_.empty_reads;
    return status;
  }
  std::uint16_t left = packets_in_fifo;
  Status burst = read_burst(left, sink);
  // More than a burst holds (a poll loop slower than the rate): the rest in further bursts,
  // unless one was resynchronised (the FIFO flushed, data_lost_ set).
  while (burst == Status::ok && left > kBurstPackets && !data_lost_) {
    left = static_cast<std::uint16_t>(left - kBurstPackets);
    burst = read_burst(left, sink);
  }
  return burst != Status::ok ? burst : status;
}

// One burst of whole packets, the oldest of packets_in_fifo, decoded in order.
template <typename Scalar>
Status Icm42688pDriver<Scalar>::read_burst(std::uint16_t packets_in_fifo, const SampleSink<Scalar>& sink) {
  const std::uint16_t n = packets_in_fifo < kBurstPackets ? packets_in_fifo : kBurstPackets;
  const std::uint32_t bytes = static_cast<std::uint32_t>(n) * kPacket3Bytes;
  std::uint32_t at = 0;  // bytes walked
  const std::uint64_t now = bus_.now_us(bus_.context);
  const Status s = read(Bank::bank0, bank0::fifo_data, burst_, static_cast<std::uint16_t>(bytes));
  if (s == Status::ok) {
    // The newest packet in the FIFO was taken about now; the older ones a period apart.
    const std::uint32_t period = period_us();  // once: the sink may touch memory
    const std::uint32_t age_us = static_cast<std::uint32_t>(packets_in_fifo - 1) * period;  // <= 127 ms
    const std::uint64_t first_mcu_us = now > age_us ? now - age_us : 0;
    if (data_lost_ && have_sample_ && first_mcu_us > last_sample_mcu_us_) {
      decoder_.expect_gap(us_to_ticks(first_mcu_us - last_sample_mcu_us_));
    }
    data_lost_ = false;
    while (at < bytes) {
      ImuSample<Scalar> sample;
      const FifoStep step = decoder_.next(burst_ + at, bytes - at, sample);
      if (step.outcome >= PacketOutcome::foreign_header) break;  // or cut
      // The slot's place in the burst dates it (an empty slot before it counts a period:
      // an estimate for the wrap count only, which tolerates half a wrap).
      const std::uint32_t slot = at / kPacket3Bytes;
      at += step.bytes;
      if (step.outcome == PacketOutcome::empty_read) {
        ++counters_.empty_reads;
        continue;
      }
      ++counters_.packets;
      if (step.outcome == PacketOutcome::invalid) {
        ++counters_.invalid;
        continue;
      }
      emit(sample, first_mcu_us + slot * period, sink);
    }
    if (at == bytes) return Status::ok;
  }
  // A broken transfer, a foreign header, or a packet cut by the end of the burst (a lone
  // 0x80 byte moved the packets): the FIFO's read point is not on a packet boundary. The
  // rest of the burst is counted, the FIFO flushed, and the chip restarts on a boundary.
  ++counters_.resyncs;
  counters_.bytes_skipped += bytes - at;
  flush_and_mark_lost();
  return s;
}

template <typename Scalar>
void Icm42688pDriver<Scalar>::emit(const ImuSample<Scalar>& sample, std::uint64_t mcu_us,
                                   const SampleSink<Scalar>& sink) {
  if (sample.gap_before() && have_sample_) {
    ++counters_.gaps;
    counters_.last_gap_us = sample.t_us - last_sample_t_us_;
  }
  ++counters_.samples;
  have_sample_ = true;
  last_sample_t_us_ = sample.t_us;
  last_sample_mcu_us_ = mcu_us;
  if (sink.push != nullptr) sink.push(sink.context, sample);
}

static_assert(sizeof(Icm42688pDriver<double>) <= 512,
              "the driver's RAM, burst buffer included, is 512 B at most");
static_assert(sizeof(Icm42688pDriver<float>) <= 512,
              "the driver's RAM, burst buffer included, is 512 B at most");

}  // namespace aloft::icm42688p

namespace aloft {
template <typename Scalar>
using Icm42688pDriver = icm42688p::Icm42688pDriver<Scalar>;
}  // namespace aloft
