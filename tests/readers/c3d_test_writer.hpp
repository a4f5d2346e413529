// A minimal C3D writer for tests: header, a POINT group (USED, SCALE, RATE, DATA_START,
// FRAMES, LABELS, UNITS) and the point data, in any of the three processor formats,
// integer or float. It lets the tests check the reader against known coordinates and
// build damaged files on purpose. Encodings are the inverse of c3d_numbers.hpp's.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "readers/c3d_numbers.hpp"

namespace aloft::test {

using aloft::host::c3d::Processor;

struct C3dContent {
  Processor processor = Processor::intel;
  bool float_data = false;
  double scale = 0.1;  // file units per integer step (integer data)
  float rate_hz = 100.0f;
  std::string units = "mm";
  // Long trials (over 65,535 frames): the frame range also goes into
  // TRIAL:ACTUAL_START_FIELD/ACTUAL_END_FIELD as two 16-bit words, low word first, and the
  // header's 16-bit last frame is capped at 65535, as Vicon writes them.
  bool trial_fields = false;
  std::vector<std::string> labels;
  // coordinates[frame][point] in file units; a NaN x marks the point invalid.
  std::vector<std::vector<std::array<double, 3>>> coordinates;
};

class C3dBytesWriter {
 public:
  explicit C3dBytesWriter(Processor p) : p_(p) {}
  void u8(std::vector<std::uint8_t>& out, int v) const { out.push_back(static_cast<std::uint8_t>(v)); }
  void i16(std::vector<std::uint8_t>& out, int v) const {
    const auto u = static_cast<std::uint16_t>(v);
    if (p_ == Processor::mips) {
      out.push_back(static_cast<std::uint8_t>(u >> 8));
      out.push_back(static_cast<std::uint8_t>(u & 0xFF));
    } else {
      out.push_back(static_cast<std::uint8_t>(u & 0xFF));
      out.push_back(static_cast<std::uint8_t>(u >> 8));
    }
  }
  void f32(std::vector<std::uint8_t>& out, float v) const {
    std::uint32_t bits;
    if (p_ == Processor::dec) {
      const float four = v * 4.0f;
      std::memcpy(&bits, &four, 4);
      if (v == 0.0f) bits = 0;
      out.push_back(static_cast<std::uint8_t>(bits >> 16));
      out.push_back(static_cast<std::uint8_t>(bits >> 24));
      out.push_back(static_cast<std::uint8_t>(bits));
      out.push_back(static_cast<std::uint8_t>(bits >> 8));
      return;
    }
    std::memcpy(&bits, &v, 4);
    for (int k = 0; k < 4; ++k) {
      const int shift = p_ == Processor::mips ? 24 - 8 * k : 8 * k;
      out.push_back(static_cast<std::uint8_t>(bits >> shift));
    }
  }

 private:
  Processor p_;
};

inline std::vector<std::uint8_t> write_c3d_bytes(const C3dContent& c) {
  const C3dBytesWriter w(c.processor);
  const std::size_t points = c.labels.size();
  const std::size_t frames = c.coordinates.size();
  const float stored_scale = static_cast<float>(c.float_data ? -c.scale : c.scale);

  // Parameter records (after the 4-byte section header).
  std::vector<std::uint8_t> records;
  auto record = [&](int group_id, const std::string& name, const std::vector<std::uint8_t>& body) {
    w.u8(records, static_cast<int>(name.size()));
    w.u8(records, group_id);
    records.insert(records.end(), name.begin(), name.end());
    w.i16(records, static_cast<int>(body.size() + 2));
    records.insert(records.end(), body.begin(), body.end());
  };
  auto parameter = [&](const std::string& name, int type, const std::vector<int>& dims,
                       const std::vector<std::uint8_t>& data, int group_id = 1) {
    std::vector<std::uint8_t> body;
    w.u8(body, type);
    w.u8(body, static_cast<int>(dims.size()));
    for (int d : dims) w.u8(body, d);
    body.insert(body.end(), data.begin(), data.end());
    w.u8(body, 0);  // no description
    record(group_id, name, body);
  };
  auto int_data = [&](int v) {
    std::vector<std::uint8_t> d;
    w.i16(d, v);
    return d;
  };
  auto float_data = [&](float v) {
    std::vector<std::uint8_t> d;
    w.f32(d, v);
    return d;
  };

  std::size_t label_length = 1;
  for (const auto& l : c.labels) label_length = std::max(label_length, l.size());
  std::vector<std::uint8_t> labels;
  for (const auto& l : c.labels) {
    std::string padded = l;
    padded.resize(label_length, ' ');
    labels.insert(labels.end(), padded.begin(), padded.end());
  }
  const std::size_t parameter_blocks = 2;  // ample for the tests' small label lists
  const int data_start = static_cast<int>(2 + parameter_blocks);

  record(-1, "POINT", std::vector<std::uint8_t>{0});
  parameter("USED", 2, {}, int_data(static_cast<int>(points)));
  parameter("SCALE", 4, {}, float_data(stored_scale));
  parameter("RATE", 4, {}, float_data(c.rate_hz));
  parameter("DATA_START", 2, {}, int_data(data_start));
  parameter("FRAMES", 2, {}, int_data(static_cast<int>(frames)));
  parameter("LABELS", -1, {static_cast<int>(label_length), static_cast<int>(points)}, labels);
  parameter("UNITS", -1, {static_cast<int>(c.units.size())},
            std::vector<std::uint8_t>(c.units.begin(), c.units.end()));
  if (c.trial_fields) {
    auto two_words = [&](std::size_t v) {
      std::vector<std::uint8_t> d;
      w.i16(d, static_cast<int>(v & 0xFFFF));
      w.i16(d, static_cast<int>(v >> 16));
      return d;
    };
    record(-2, "TRIAL", std::vector<std::uint8_t>{0});
    parameter("ACTUAL_START_FIELD", 2, {2}, two_words(1), 2);
    parameter("ACTUAL_END_FIELD", 2, {2}, two_words(frames), 2);
  }
  records.push_back(0);  // end of the chain
  records.push_back(0);

  std::vector<std::uint8_t> file(512, 0);
  file[0] = 2;
  file[1] = 0x50;
  {
    std::vector<std::uint8_t> h;
    w.i16(h, static_cast<int>(points));
    w.i16(h, 0);  // analog samples per frame
    w.i16(h, 1);
    w.i16(h, static_cast<int>(std::min<std::size_t>(frames, 65535)));
    w.i16(h, 0);
    w.f32(h, stored_scale);
    w.i16(h, data_start);
    w.i16(h, 0);
    w.f32(h, c.rate_hz);
    std::copy(h.begin(), h.end(), file.begin() + 2);
  }
  std::vector<std::uint8_t> section{1, 0x50, static_cast<std::uint8_t>(parameter_blocks),
                                    static_cast<std::uint8_t>(c.processor)};
  section.insert(section.end(), records.begin(), records.end());
  section.resize(parameter_blocks * 512, 0);
  file.insert(file.end(), section.begin(), section.end());

  for (const auto& frame : c.coordinates) {
    for (const auto& xyz : frame) {
      const bool invalid = std::isnan(xyz[0]);
      for (int a = 0; a < 3; ++a) {
        const double v = invalid ? 0.0 : xyz[a];
        if (c.float_data) {
          w.f32(file, static_cast<float>(v));
        } else {
          w.i16(file, static_cast<int>(std::lround(v / c.scale)));
        }
      }
      if (c.float_data) {
        w.f32(file, invalid ? -1.0f : 0.0f);
      } else {
        w.i16(file, invalid ? -1 : 0);
      }
    }
  }
  file.resize((file.size() + 511) / 512 * 512, 0);
  return file;
}

}  // namespace aloft::test
