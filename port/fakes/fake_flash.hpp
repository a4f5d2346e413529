// A NOR flash in RAM for the record ring's tests (aloft/records/block_device.hpp), on the host
// and on bare metal alike (fixed storage, no heap). It enforces the rules a real part
// only punishes later: programming a 1 over a 0, a range off the program unit or across
// a block, is counted as a violation and refused. And it cuts the power where told, the
// way littlefs's emulated block device does:
//   - after operation k (programs and erases counted together from 0) has finished;
//   - inside program k after its first j bytes (the rest of the range untouched);
//   - inside erase k after its first j bytes are 0xFF (the rest holds the old bytes), or
//     with the whole block left as garbage.
// Once cut, every call fails with bus_error and changes nothing until power_on().
#pragma once

#include <cstdint>

#include "aloft/records/block_device.hpp"

namespace aloft::testing {

enum class EraseCut : std::uint8_t { prefix_erased, garbage };

template <std::uint32_t BlockSize, std::uint32_t BlockCount>
class FakeFlash {
 public:
  static constexpr std::uint32_t never = 0xFFFFFFFFu;
  struct Program {
    std::uint32_t block = 0, offset = 0, size = 0;
  };

  explicit FakeFlash(std::uint32_t program_size = 4) {
    device_.context = this;
    device_.block_size = BlockSize;
    device_.block_count = BlockCount;
    device_.program_size = program_size;
    device_.read = &read_thunk;
    device_.program = &program_thunk;
    device_.erase = &erase_thunk;
    reset();
  }

  // Every byte erased, counters at zero, power on, no cut scheduled.
  void reset() {
    for (std::uint8_t& b : bytes_) b = 0xFF;
    for (std::uint32_t& c : erase_counts_) c = 0;
    operations_ = completed_programs_ = violations_ = 0;
    bytes_read_ = 0;
    last_program_ = Program();
    power_on();
  }

  // Cut the power inside operation `op` after `bytes_done` bytes (`never`: after the
  // whole operation). For an erase, `how` says what the block holds afterwards.
  void schedule_cut(std::uint32_t op, std::uint32_t bytes_done, EraseCut how = EraseCut::prefix_erased) {
    cut_op_ = op;
    cut_bytes_ = bytes_done;
    cut_how_ = how;
  }

  void power_on() {
    powered_ = true;
    cut_op_ = never;
  }

  const BlockDevice& device() const { return device_; }
  bool powered() const { return powered_; }
  std::uint32_t operations() const { return operations_; }
  std::uint32_t completed_programs() const { return completed_programs_; }
  const Program& last_program() const { return last_program_; }
  std::uint32_t violations() const { return violations_; }
  std::uint64_t bytes_read() const { return bytes_read_; }
  std::uint32_t erase_count(std::uint32_t block) const { return erase_counts_[block]; }
  const std::uint8_t* bytes() const { return bytes_; }
  std::uint8_t* bytes() { return bytes_; }
  // What the operation the power was cut in was: an erase (of the whole block), or a
  // program of this range.
  bool cut_was_erase() const { return cut_was_erase_; }
  const Program& cut_operation() const { return cut_range_; }
  static constexpr std::uint32_t size() { return BlockSize * BlockCount; }

 private:
  static FakeFlash& self(void* context) { return *static_cast<FakeFlash*>(context); }

  bool in_range(std::uint32_t block, std::uint32_t offset, std::uint32_t size) const {
    return block < BlockCount && offset <= BlockSize && size <= BlockSize - offset;
  }

  // Counts the operation; true when the power goes off inside it.
  bool cut_now(bool erase, std::uint32_t block, std::uint32_t offset, std::uint32_t size) {
    const bool cut = operations_ == cut_op_;
    ++operations_;
    if (cut) {
      cut_was_erase_ = erase;
      cut_range_ = Program{block, offset, size};
    }
    return cut;
  }

  static Status read_thunk(void* c, std::uint32_t block, std::uint32_t offset, std::uint8_t* data,
                           std::uint32_t size) {
    FakeFlash& f = self(c);
    if (!f.powered_) return Status::bus_error;
    if (!f.in_range(block, offset, size)) return ++f.violations_, Status::invalid_dimension;
    for (std::uint32_t i = 0; i < size; ++i) data[i] = f.bytes_[block * BlockSize + offset + i];
    f.bytes_read_ += size;
    return Status::ok;
  }

  static Status program_thunk(void* c, std::uint32_t block, std::uint32_t offset, const std::uint8_t* data,
                              std::uint32_t size) {
    FakeFlash& f = self(c);
    if (!f.powered_) return Status::bus_error;
    const std::uint32_t unit = f.device_.program_size;
    if (!f.in_range(block, offset, size) || offset % unit != 0 || size % unit != 0)
      return ++f.violations_, Status::invalid_dimension;
    std::uint8_t* to = f.bytes_ + block * BlockSize + offset;
    for (std::uint32_t i = 0; i < size; ++i)
      if ((to[i] & data[i]) != data[i]) return ++f.violations_, Status::corrupt_data;  // a 0 bit back to 1
    const bool cut = f.cut_now(false, block, offset, size);
    const std::uint32_t written = cut && f.cut_bytes_ < size ? f.cut_bytes_ : size;
    for (std::uint32_t i = 0; i < written; ++i) to[i] = static_cast<std::uint8_t>(to[i] & data[i]);
    if (cut) f.powered_ = false;
    if (written < size) return Status::bus_error;
    ++f.completed_programs_;
    f.last_program_ = Program{block, offset, size};
    return cut ? Status::bus_error : Status::ok;
  }

  static Status erase_thunk(void* c, std::uint32_t block) {
    FakeFlash& f = self(c);
    if (!f.powered_) return Status::bus_error;
    if (block >= BlockCount) return ++f.violations_, Status::invalid_dimension;
    ++f.erase_counts_[block];  // counted from its start: what the block held is given up
    const bool cut = f.cut_now(true, block, 0, BlockSize);
    std::uint8_t* to = f.bytes_ + block * BlockSize;
    if (cut && f.cut_bytes_ < BlockSize && f.cut_how_ == EraseCut::garbage) {
      std::uint32_t x = 0x9E3779B9u ^ (f.operations_ * 0x85EBCA6Bu);
      for (std::uint32_t i = 0; i < BlockSize; ++i) {
        x ^= x << 13, x ^= x >> 17, x ^= x << 5;  // xorshift32: repeatable garbage
        to[i] = static_cast<std::uint8_t>(x);
      }
    } else {
      const std::uint32_t erased = cut && f.cut_bytes_ < BlockSize ? f.cut_bytes_ : BlockSize;
      for (std::uint32_t i = 0; i < erased; ++i) to[i] = 0xFF;
    }
    if (cut) f.powered_ = false;
    return cut ? Status::bus_error : Status::ok;
  }

  BlockDevice device_;
  std::uint8_t bytes_[BlockSize * BlockCount];
  std::uint32_t erase_counts_[BlockCount];
  std::uint32_t operations_ = 0, completed_programs_ = 0, violations_ = 0;
  std::uint64_t bytes_read_ = 0;
  Program last_program_;
  bool powered_ = true;
  std::uint32_t cut_op_ = never, cut_bytes_ = never;
  EraseCut cut_how_ = EraseCut::prefix_erased;
  bool cut_was_erase_ = false;
  Program cut_range_;
};

}  // namespace aloft::testing
