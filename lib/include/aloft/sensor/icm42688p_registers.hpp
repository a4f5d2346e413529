// The TDK InvenSense ICM-42688-P register map: the addresses and named bits the driver
// (aloft/sensor/icm42688p_driver.hpp) and the FIFO decoder (aloft/sensor/icm42688p_fifo.hpp) use, from
// the datasheet DS-000347 (rev 1.6). Each block names its register: the source is that
// register's entry in the register map and in the datasheet's bank 0/1/2 register
// descriptions; other sections are named where they are the source (§3 sensitivities,
// §5.3 anti-alias filter, §6 FIFO packets, §12.7 time stamps).
//
// Conventions: addresses are the chip's 7-bit register addresses (the SPI read bit 0x80
// is the port's business, aloft/sensor/imu_bus.hpp); a bank-1 or bank-2 register is reached by
// first writing its bank number to REG_BANK_SEL (0x76, present in every bank). Multi-bit
// fields are given as a mask and a shift; single bits as masks.
//
// Where other open drivers differ from the datasheet, the comment says so: check each
// fact here against the datasheet, not against another driver.
#pragma once

#include <cstdint>

namespace aloft::icm42688p {

// --- Identity
constexpr std::uint8_t kWhoAmIValue = 0x47;  // ICM-42688-P; the ICM-42686-P answers 0x44

// --- Register banks
enum class Bank : std::uint8_t { bank0 = 0, bank1 = 1, bank2 = 2 };

// --- Bank 0 addresses
namespace bank0 {
constexpr std::uint8_t device_config = 0x11;
constexpr std::uint8_t drive_config = 0x13;
constexpr std::uint8_t int_config = 0x14;
constexpr std::uint8_t fifo_config = 0x16;
constexpr std::uint8_t temp_data1 = 0x1D;  // temperature, high byte; data registers follow
constexpr std::uint8_t accel_data_x1 = 0x1F;
constexpr std::uint8_t gyro_data_x1 = 0x25;
constexpr std::uint8_t tmst_fsynch = 0x2B;
constexpr std::uint8_t int_status = 0x2D;
constexpr std::uint8_t fifo_counth = 0x2E;  // INT_STATUS, FIFO_COUNTH, FIFO_COUNTL are adjacent:
constexpr std::uint8_t fifo_countl = 0x2F;  // one 3-byte burst from 0x2D reads all three
constexpr std::uint8_t fifo_data = 0x30;    // a burst here does not advance the address
constexpr std::uint8_t signal_path_reset = 0x4B;
constexpr std::uint8_t intf_config0 = 0x4C;
constexpr std::uint8_t intf_config1 = 0x4D;
constexpr std::uint8_t pwr_mgmt0 = 0x4E;
constexpr std::uint8_t gyro_config0 = 0x4F;
constexpr std::uint8_t accel_config0 = 0x50;
constexpr std::uint8_t gyro_config1 = 0x51;
constexpr std::uint8_t gyro_accel_config0 = 0x52;
constexpr std::uint8_t accel_config1 = 0x53;
constexpr std::uint8_t tmst_config = 0x54;
constexpr std::uint8_t fifo_config1 = 0x5F;
constexpr std::uint8_t fifo_config2 = 0x60;  // watermark [7:0]
constexpr std::uint8_t fifo_config3 = 0x61;  // watermark [11:8]
constexpr std::uint8_t int_source0 = 0x65;
constexpr std::uint8_t who_am_i = 0x75;
constexpr std::uint8_t reg_bank_sel = 0x76;  // in every bank
}  // namespace bank0

// --- Bank 1 addresses: gyro anti-alias filter
namespace bank1 {
constexpr std::uint8_t gyro_config_static2 = 0x0B;
constexpr std::uint8_t gyro_config_static3 = 0x0C;
constexpr std::uint8_t gyro_config_static4 = 0x0D;
constexpr std::uint8_t gyro_config_static5 = 0x0E;
}  // namespace bank1

// --- Bank 2 addresses: accelerometer anti-alias filter
namespace bank2 {
constexpr std::uint8_t accel_config_static2 = 0x03;
constexpr std::uint8_t accel_config_static3 = 0x04;
constexpr std::uint8_t accel_config_static4 = 0x05;
}  // namespace bank2

// --- DEVICE_CONFIG
constexpr std::uint8_t kSoftResetConfig = 1u << 0;  // self-clearing; wait 1 ms after it
constexpr std::uint32_t kSoftResetWaitUs = 1000;

// --- FIFO_CONFIG: FIFO_MODE [7:6]
// 00 bypass, 01 stream-to-FIFO, 10 and 11 STOP-on-FULL. PX4 writes 11 (stop on full);
// aloft streams, as the issue asks, and detects the overflow instead.
constexpr std::uint8_t kFifoModeMask = 0xC0;
constexpr std::uint8_t kFifoModeStream = 0x40;

// --- INT_STATUS, cleared when read
constexpr std::uint8_t kIntStatusResetDone = 1u << 4;
constexpr std::uint8_t kIntStatusDataReady = 1u << 3;
constexpr std::uint8_t kIntStatusFifoThreshold = 1u << 2;
constexpr std::uint8_t kIntStatusFifoFull = 1u << 1;

// --- SIGNAL_PATH_RESET
constexpr std::uint8_t kAbortAndReset = 1u << 3;
constexpr std::uint8_t kFifoFlush = 1u << 1;  // self-clearing

// --- INTF_CONFIG0; reset value 0x30: both endian bits set = big-endian
constexpr std::uint8_t kFifoHoldLastDataEn = 1u << 7;
constexpr std::uint8_t kFifoCountRec = 1u << 6;      // 1: FIFO_COUNT in records, 0: in bytes
constexpr std::uint8_t kFifoCountEndian = 1u << 5;   // 1: FIFO_COUNT big-endian
constexpr std::uint8_t kSensorDataEndian = 1u << 4;  // 1: data registers and FIFO big-endian

// --- INTF_CONFIG1: CLKSEL [1:0], RTC_MODE bit 2
// CLKSEL 00: always the internal RC oscillator; 01: the PLL when available, else RC (the
// reset value). RTC_MODE 1 takes an external clock on pin 9 (needs INTF_CONFIG5 in bank 1).
constexpr std::uint8_t kClkSelMask = 0x03;
constexpr std::uint8_t kClkSelRcOnly = 0x00;
constexpr std::uint8_t kClkSelPll = 0x01;
constexpr std::uint8_t kRtcMode = 1u << 2;

// --- PWR_MGMT0
constexpr std::uint8_t kTempDis = 1u << 5;
constexpr std::uint8_t kIdle = 1u << 4;
constexpr std::uint8_t kGyroModeMask = 0x0C;
constexpr std::uint8_t kGyroModeLowNoise = 0x0C;
constexpr std::uint8_t kAccelModeMask = 0x03;
constexpr std::uint8_t kAccelModeLowNoise = 0x03;
// PWR_MGMT0 description: after PWR_MGMT0 turns a sensor on, no register write for 200 µs.
constexpr std::uint32_t kPowerOnWriteWaitUs = 200;

// --- GYRO_CONFIG0 and ACCEL_CONFIG0
// FS_SEL [7:5]: 000 is the widest range, ±2000 °/s and ±16 g (reset value).
// ODR [3:0]: 0100 4 kHz, 0101 2 kHz, 0110 1 kHz (reset value), same codes for both.
constexpr std::uint8_t kFsSelMask = 0xE0;
constexpr std::uint8_t kFsSelWidest = 0x00;
constexpr std::uint8_t kOdrMask = 0x0F;
constexpr std::uint8_t kOdr4kHz = 0x04;
constexpr std::uint8_t kOdr2kHz = 0x05;
constexpr std::uint8_t kOdr1kHz = 0x06;

// --- GYRO_CONFIG1, GYRO_ACCEL_CONFIG0, ACCEL_CONFIG1
// UI filter order: GYRO_UI_FILT_ORD [3:2], ACCEL_UI_FILT_ORD [4:3]; 00 = 1st order.
// UI filter bandwidths: ACCEL_UI_FILT_BW [7:4], GYRO_UI_FILT_BW [3:0]; 1 = ODR/4 in
// low-noise mode (the reset value 0x11).
constexpr std::uint8_t kGyroUiFiltOrdMask = 0x0C;
constexpr std::uint8_t kAccelUiFiltOrdMask = 0x18;
constexpr std::uint8_t kUiFiltBwOdrDiv4 = 0x11;

// --- TMST_CONFIG; reset value 0x23
constexpr std::uint8_t kTmstToRegsEn = 1u << 4;
constexpr std::uint8_t kTmstRes = 1u << 3;      // 0: 1 µs, 1: 16 µs (or one RTC period)
constexpr std::uint8_t kTmstDeltaEn = 1u << 2;  // 1: stamps are deltas; aloft wants absolute
constexpr std::uint8_t kTmstFsyncEn = 1u << 1;
constexpr std::uint8_t kTmstEn = 1u << 0;

// --- FIFO_CONFIG1
// FIFO_RESUME_PARTIAL_RD must be 1 here: the driver reads at most one burst buffer per
// poll and leaves the rest for the next one (with 0 the datasheet requires the whole FIFO
// be read). FIFO_HIRES_EN selects packet 4 (20-bit); aloft uses packet 3.
// (One open ChibiOS-based driver writes FIFO_TMST_FSYNC_EN, a FIFO_CONFIG1 bit, into
// FIFO_CONFIG, where bit 3 is reserved.)
constexpr std::uint8_t kFifoResumePartialRd = 1u << 6;
constexpr std::uint8_t kFifoWmGtTh = 1u << 5;
constexpr std::uint8_t kFifoHiresEn = 1u << 4;
constexpr std::uint8_t kFifoTmstFsyncEn = 1u << 3;
constexpr std::uint8_t kFifoTempEn = 1u << 2;
constexpr std::uint8_t kFifoGyroEn = 1u << 1;
constexpr std::uint8_t kFifoAccelEn = 1u << 0;

// --- REG_BANK_SEL: BANK_SEL [2:0]
constexpr std::uint8_t kBankSelMask = 0x07;

// --- Anti-alias filter (§5.3 table; GYRO_CONFIG_STATIC2-5, ACCEL_CONFIG_STATIC2-4)
// GYRO_CONFIG_STATIC2 (B1 0x0B): GYRO_AAF_DIS bit 1 (0 = filter on), GYRO_NF_DIS bit 0.
// GYRO_CONFIG_STATIC3: GYRO_AAF_DELT [5:0]. GYRO_CONFIG_STATIC4: GYRO_AAF_DELTSQR [7:0].
// GYRO_CONFIG_STATIC5: GYRO_AAF_BITSHIFT [7:4], GYRO_AAF_DELTSQR [11:8] in [3:0].
// ACCEL_CONFIG_STATIC2 (B2 0x03): ACCEL_AAF_DELT [6:1], ACCEL_AAF_DIS bit 0.
// ACCEL_CONFIG_STATIC3: ACCEL_AAF_DELTSQR [7:0].
// ACCEL_CONFIG_STATIC4: ACCEL_AAF_BITSHIFT [7:4], ACCEL_AAF_DELTSQR [11:8] in [3:0].
constexpr std::uint8_t kGyroAafDis = 1u << 1;
constexpr std::uint8_t kGyroAafDeltMask = 0x3F;
constexpr std::uint8_t kAccelAafDeltMask = 0x7E;
constexpr std::uint8_t kAccelAafDis = 1u << 0;

// One row of the datasheet's AAF table. DELTSQR is the table's value, not DELT²: the
// table rounds it for the filter's fixed-point arithmetic (e.g. DELT 13 → 170, not 169).
struct AafRow {
  std::uint16_t bandwidth_hz;  // 3 dB bandwidth
  std::uint8_t delt;
  std::uint16_t deltsqr;
  std::uint8_t bitshift;
};
// The rows aloft uses, about a quarter of each ODR (as the UI filter's default ODR/4),
// well below Nyquist so that the ODR does not alias vibration into the throw.
constexpr AafRow kAaf258Hz{258, 6, 36, 10};   // for 1 kHz
constexpr AafRow kAaf536Hz{536, 12, 144, 8};  // for 2 kHz
constexpr AafRow kAaf997Hz{997, 21, 440, 6};  // for 4 kHz

// --- FIFO packet (§6 FIFO: packet structure and header)
// Header bits. HEADER_TIMESTAMP_FSYNC [3:2]: 10 = the packet holds an ODR time stamp,
// 11 = an FSYNC time stamp. HEADER_ODR_* flag a packet whose ODR differs from the one
// before (after a configuration change), and are ignored by the check of the header.
constexpr std::uint8_t kHeaderMsg = 1u << 7;  // 1: FIFO is empty
constexpr std::uint8_t kHeaderAccel = 1u << 6;
constexpr std::uint8_t kHeaderGyro = 1u << 5;
constexpr std::uint8_t kHeader20 = 1u << 4;  // packet 4 (20-bit data)
constexpr std::uint8_t kHeaderTimestampFsyncMask = 0x0C;
constexpr std::uint8_t kHeaderTimestampOdr = 0x08;
constexpr std::uint8_t kHeaderOdrAccel = 1u << 1;
constexpr std::uint8_t kHeaderOdrGyro = 1u << 0;
// Packet 3: header 0b0110'10xx.
constexpr std::uint8_t kPacket3HeaderMask = 0xFC;
constexpr std::uint8_t kPacket3Header = kHeaderAccel | kHeaderGyro | kHeaderTimestampOdr;
// Packet 3 layout: header, accel X Y Z (16-bit each), gyro X Y Z, temperature (8-bit),
// time stamp (16-bit): 16 bytes.
constexpr std::uint16_t kPacket3Bytes = 16;
constexpr std::uint16_t kPacket3AccelOffset = 1;
constexpr std::uint16_t kPacket3GyroOffset = 7;
constexpr std::uint16_t kPacket3TemperatureOffset = 13;
constexpr std::uint16_t kPacket3TimestampOffset = 14;
// §6: a sensor's value -32768 (0x8000) in the FIFO marks invalid data (the sensor is
// off or has no sample yet, as after power-up).
constexpr std::int16_t kInvalidSample = -32768;
// §6: the FIFO holds 2 KiB.
constexpr std::uint16_t kFifoCapacityBytes = 2048;

// --- Full scale (§3 gyro and accelerometer specifications)
// ±2000 °/s: 16.4 LSB/(°/s); ±16 g: 2048 LSB/g.
constexpr double kGyroLsbPerDps = 16.4;
constexpr double kAccelLsbPerG = 2048.0;
constexpr double kStandardGravity = 9.80665;  // m/s² per g (CGPM 1901)

// --- Time stamps (§12.7 and TMST_CONFIG)
// At TMST_RES = 0 a stamp tick is 1 µs when the chip runs on the PLL or an external clock;
// counted on the internal RC oscillator a tick is 32/30 µs (§12.7), so stamps need ×32/30.
constexpr std::uint32_t kRcTickNumerator = 32;
constexpr std::uint32_t kRcTickDenominator = 30;

}  // namespace aloft::icm42688p
