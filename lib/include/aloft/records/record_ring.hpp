// Flight records (aloft/records/flight_record.hpp) appended to a ring over the erase blocks of a
// block device (aloft/records/block_device.hpp): 128-byte slots, written in order, block after
// block, wrapping to block 0 after the last. No heap, no file system, a few words of RAM.
//
// What it promises: a power cut at any moment leaves every record committed before it
// readable, except the oldest ones the ring had already chosen to overwrite; a record is
// either all there or recognised as torn and skipped, and mounting after a cut reads at
// most (block_count + 1) * block_size bytes to find where the next record goes.
//
// Why it holds:
//   - Commit order. A record's body (bytes 0..119, CRC included) is programmed first;
//     the 4-byte commit marker is programmed only after that call has returned. A slot
//     counts when the marker is complete and the CRC matches, so a cut inside the body
//     leaves no marker, and a cut inside the marker leaves it incomplete. Marker first
//     would make a torn body look committed, with only the CRC left to catch it. A slot
//     that is not all 0xFF is never programmed again: a torn slot is skipped, not reused.
//   - One erased block ahead. When a block receives its first committed record, the
//     block after it (holding the oldest records) is erased; only then do later
//     records fill the current block, so writing never has to wait for an erase and the
//     record that caused an erase is committed before the erase begins. A cut inside the
//     erase leaves that block partly erased; it held only records already given up, and
//     mount erases it again before it is used.
//   - Sequence numbers. Each record carries the sequence number after the highest one
//     found, so they rise across wraps; mount takes the block holding the highest as
//     the head.
//   - Mount: every slot is read once (block_count * block_size bytes) to find the head
//     and the end of its used slots, plus at most one block to see whether the block
//     after the head is erased. Then:
//       head has a free slot after its last used one -> write there;
//       head full                       -> write at the start of the next block,
//                                          erasing it first unless it is all 0xFF
//                                          (it can only hold torn writes or the
//                                          remains of a cut erase);
//       no valid record anywhere        -> block 0, erased first unless all 0xFF.
// Capacity: between (block_count - 2) * slots_per_block + 1 and (block_count - 1) *
// slots_per_block records, the newest. Needs block_count >= 2, block_size a multiple of
// 128 with at least 2 slots, program_size 1, 2, 4 or 8.
#pragma once

#include <cstdint>

#include "aloft/records/block_device.hpp"
#include "aloft/records/flight_record.hpp"

namespace aloft {

class RecordRing {
 public:
  explicit RecordRing(const BlockDevice& device) : device_(&device) {}

  // Finds the head and the next free slot (see above). Reads only; any erase it finds
  // necessary is done by the next append. invalid_dimension: a geometry the ring cannot
  // use (see the top of this file); otherwise ok or the device's own failure.
  Status mount() {
    mounted_ = false;
    if (!geometry_usable()) return Status::invalid_dimension;
    Head head;
    const Status s = find_head(head);
    if (s != Status::ok) return s;
    place_after(head);
    if (head.found && head.used_end < slots_per_block()) {
      bool erased = false;
      const Status e = block_erased(next_block(write_block_), erased);
      if (e != Status::ok) return e;
      spare_erased_ = erased;
    }
    if (needs_erase_) {
      bool erased = false;
      const Status e = block_erased(write_block_, erased);
      if (e != Status::ok) return e;
      needs_erase_ = !erased;
    }
    mounted_ = true;
    return Status::ok;
  }

  // Appends one record; sets record.sequence to the number it was stored under.
  // storage_full before a successful mount: no slot is known to be free.
  Status append(FlightRecord& record) {
    if (!mounted_) return Status::storage_full;
    if (write_slot_ == slots_per_block()) {
      write_block_ = next_block(write_block_);
      write_slot_ = 0;
      needs_erase_ = !spare_erased_;  // only after an earlier erase failed
      spare_erased_ = false;
    }
    if (needs_erase_) {
      const Status s = device_->erase(device_->context, write_block_);
      if (s != Status::ok) return s;
      needs_erase_ = false;
    }
    record.sequence = next_sequence_;
    const Status s = program_record(record);
    if (s != Status::ok) return s;
    ++next_sequence_;
    if (!spare_erased_) {
      const Status e = device_->erase(device_->context, next_block(write_block_));
      if (e != Status::ok) return e;
      spare_erased_ = true;
    }
    return Status::ok;
  }

  // Calls visit(record, block, slot) for every valid record, in the device's order.
  template <typename Visit>
  Status for_each_record(Visit&& visit) const {
    std::uint8_t bytes[flight_record_size];
    for (std::uint32_t b = 0; b < device_->block_count; ++b) {
      for (std::uint32_t i = 0; i < slots_per_block(); ++i) {
        const Status s =
            device_->read(device_->context, b, i * flight_record_size, bytes, flight_record_size);
        if (s != Status::ok) return s;
        FlightRecord record;
        if (decode_flight_record(bytes, record) == SlotState::valid) visit(record, b, i);
      }
    }
    return Status::ok;
  }

  std::uint32_t next_sequence() const { return next_sequence_; }
  std::uint32_t write_block() const { return write_block_; }
  std::uint32_t write_slot() const { return write_slot_; }
  std::uint32_t slots_per_block() const { return device_->block_size / flight_record_size; }

 private:
  struct Head {
    bool found = false;
    std::uint32_t block = 0;
    std::uint32_t used_end = 0;  // slots up to the last one that is not all 0xFF
    std::uint32_t sequence = 0;
  };

  bool geometry_usable() const {
    const std::uint32_t p = device_->program_size;
    return device_->block_count >= 2 && device_->block_size % flight_record_size == 0 &&
           slots_per_block() >= 2 && (p == 1 || p == 2 || p == 4 || p == 8);
  }

  std::uint32_t next_block(std::uint32_t b) const { return b + 1 == device_->block_count ? 0 : b + 1; }

  Status find_head(Head& head) const {
    std::uint8_t bytes[flight_record_size];
    for (std::uint32_t b = 0; b < device_->block_count; ++b) {
      std::uint32_t used_end = 0;
      bool holds_head = false;
      for (std::uint32_t i = 0; i < slots_per_block(); ++i) {
        const Status s =
            device_->read(device_->context, b, i * flight_record_size, bytes, flight_record_size);
        if (s != Status::ok) return s;
        const SlotState state = classify_slot(bytes);
        if (state != SlotState::erased) used_end = i + 1;
        const std::uint32_t sequence = flight_record_sequence(bytes);
        if (state == SlotState::valid && (!head.found || sequence > head.sequence)) {
          head.found = true;
          head.sequence = sequence;
          holds_head = true;
        }
      }
      if (holds_head) {
        head.block = b;
        head.used_end = used_end;
      }
    }
    return Status::ok;
  }

  void place_after(const Head& head) {
    next_sequence_ = head.found ? head.sequence + 1 : 1;
    spare_erased_ = false;
    needs_erase_ = false;
    if (!head.found) {
      write_block_ = 0;
      write_slot_ = 0;
      needs_erase_ = true;
    } else if (head.used_end < slots_per_block()) {
      write_block_ = head.block;
      write_slot_ = head.used_end;
    } else {
      write_block_ = next_block(head.block);
      write_slot_ = 0;
      needs_erase_ = true;
    }
  }

  Status block_erased(std::uint32_t block, bool& erased) const {
    std::uint8_t bytes[flight_record_size];
    erased = false;
    for (std::uint32_t offset = 0; offset < device_->block_size; offset += flight_record_size) {
      const Status s = device_->read(device_->context, block, offset, bytes, flight_record_size);
      if (s != Status::ok) return s;
      for (const std::uint8_t byte : bytes)
        if (byte != 0xFF) return Status::ok;
    }
    erased = true;
    return Status::ok;
  }

  // Body first, commit marker last (see the top of this file). The slot is used up
  // whatever happens: a failed program leaves bytes that cannot be written again.
  Status program_record(const FlightRecord& record) {
    std::uint8_t bytes[flight_record_size];
    encode_flight_record(record, bytes);
    const std::uint32_t at = write_slot_ * flight_record_size;
    ++write_slot_;
    const Status s = device_->program(device_->context, write_block_, at, bytes, flight_record_body_size);
    if (s != Status::ok) return s;
    const std::uint32_t commit_size = device_->program_size > 4 ? device_->program_size : 4;
    return device_->program(device_->context, write_block_, at + flight_record_commit_offset,
                            bytes + flight_record_commit_offset, commit_size);
  }

  const BlockDevice* device_;
  std::uint32_t write_block_ = 0;
  std::uint32_t write_slot_ = 0;
  std::uint32_t next_sequence_ = 1;
  bool mounted_ = false;
  bool needs_erase_ = false;   // the write block must be erased before its next program
  bool spare_erased_ = false;  // the block after the write block is all 0xFF
};

}  // namespace aloft
