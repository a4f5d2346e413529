// A NOR flash in a file, for the host (aloft/records/block_device.hpp): the file holds the
// record area's bytes, as a dump read from a board would. The NOR rules are kept as in
// port/fakes/fake_flash.hpp (erase to 0xFF, programming only clears bits; a 1 over a 0 is
// refused), without power cuts: this device is for making and reading dumps.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "aloft/records/block_device.hpp"

namespace aloft::test {

class FileBlockDevice {
 public:
  // Creates (or overwrites) `path` as `block_count` erased blocks.
  FileBlockDevice(const std::string& path, std::uint32_t block_size, std::uint32_t block_count,
                  std::uint32_t program_size = 4)
      : path_(path) {
    device_.context = this;
    device_.block_size = block_size;
    device_.block_count = block_count;
    device_.program_size = program_size;
    device_.read = &read_thunk;
    device_.program = &program_thunk;
    device_.erase = &erase_thunk;
    const std::vector<char> erased(std::size_t(block_size) * block_count, static_cast<char>(0xFF));
    std::ofstream(path_, std::ios::binary | std::ios::trunc)
        .write(erased.data(), std::streamsize(erased.size()));
  }

  const BlockDevice& device() const { return device_; }
  std::uint32_t violations() const { return violations_; }

 private:
  static FileBlockDevice& self(void* c) { return *static_cast<FileBlockDevice*>(c); }

  bool in_range(std::uint32_t block, std::uint32_t offset, std::uint32_t size) const {
    return block < device_.block_count && offset <= device_.block_size && size <= device_.block_size - offset;
  }

  std::streamoff at(std::uint32_t block, std::uint32_t offset) const {
    return std::streamoff(block) * device_.block_size + offset;
  }

  bool read_bytes(std::uint32_t block, std::uint32_t offset, std::uint8_t* data, std::uint32_t size) const {
    std::ifstream in(path_, std::ios::binary);
    in.seekg(at(block, offset));
    return bool(in.read(reinterpret_cast<char*>(data), size));
  }

  bool write_bytes(std::uint32_t block, std::uint32_t offset, const std::uint8_t* data,
                   std::uint32_t size) const {
    std::fstream out(path_, std::ios::binary | std::ios::in | std::ios::out);
    out.seekp(at(block, offset));
    return bool(out.write(reinterpret_cast<const char*>(data), size));
  }

  static Status read_thunk(void* c, std::uint32_t block, std::uint32_t offset, std::uint8_t* data,
                           std::uint32_t size) {
    FileBlockDevice& f = self(c);
    if (!f.in_range(block, offset, size)) return ++f.violations_, Status::invalid_dimension;
    return f.read_bytes(block, offset, data, size) ? Status::ok : Status::bus_error;
  }

  static Status program_thunk(void* c, std::uint32_t block, std::uint32_t offset, const std::uint8_t* data,
                              std::uint32_t size) {
    FileBlockDevice& f = self(c);
    if (!f.in_range(block, offset, size) || offset % f.device_.program_size || size % f.device_.program_size)
      return ++f.violations_, Status::invalid_dimension;
    std::vector<std::uint8_t> old(size);
    if (!f.read_bytes(block, offset, old.data(), size)) return Status::bus_error;
    for (std::uint32_t i = 0; i < size; ++i) {
      if ((old[i] & data[i]) != data[i]) return ++f.violations_, Status::corrupt_data;
      old[i] = static_cast<std::uint8_t>(old[i] & data[i]);
    }
    return f.write_bytes(block, offset, old.data(), size) ? Status::ok : Status::bus_error;
  }

  static Status erase_thunk(void* c, std::uint32_t block) {
    FileBlockDevice& f = self(c);
    if (block >= f.device_.block_count) return ++f.violations_, Status::invalid_dimension;
    const std::vector<std::uint8_t> erased(f.device_.block_size, 0xFF);
    return f.write_bytes(block, 0, erased.data(), f.device_.block_size) ? Status::ok : Status::bus_error;
  }

  std::string path_;
  BlockDevice device_;
  std::uint32_t violations_ = 0;
};

}  // namespace aloft::test
