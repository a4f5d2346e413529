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

// The parameter section's records: one group record, then parameters of that group.
class C3dParameterRecords {
 public:
  explicit C3dParameterRecords(const C3dBytesWriter& w) : w_(w) {}
  void group(int group_id, const std::string& name) { record(group_id, name, std::vector<std::uint8_t>{0}); }
  void parameter(const std::string& name, int type, const std::vector<int>& dims,
                 const std::vector<std::uint8_t>& data, int group_id = 1) {
    std::vector<std::uint8_t> body;
    w_.u8(body, type);
    w_.u8(body, static_cast<int>(dims.size()));
    for (int d : dims) w_.u8(body, d);
    body.insert(body.end(), data.begin(), data.end());
    w_.u8(body, 0);  // no description
    record(group_id, name, body);
  }
  std::vector<std::uint8_t> int_data(int v) const {
    std::vector<std::uint8_t> d;
    w_.i16(d, v);
    return d;
  }
  std::vector<std::uint8_t> float_data(float v) const {
    std::vector<std::uint8_t> d;
    w_.f32(d, v);
    return d;
  }
  // Two 16-bit words, low word first (TRIAL:ACTUAL_*_FIELD).
  std::vector<std::uint8_t> two_words(std::size_t v) const {
    std::vector<std::uint8_t> d;
    w_.i16(d, static_cast<int>(v & 0xFFFF));
    w_.i16(d, static_cast<int>(v >> 16));
    return d;
  }
  // The records, closed by the end of the chain.
  std::vector<std::uint8_t> finished() const {
    std::vector<std::uint8_t> out = records_;
    out.push_back(0);
    out.push_back(0);
    return out;
  }

 private:
  void record(int group_id, const std::string& name, const std::vector<std::uint8_t>& body) {
    w_.u8(records_, static_cast<int>(name.size()));
    w_.u8(records_, group_id);
    records_.insert(records_.end(), name.begin(), name.end());
    w_.i16(records_, static_cast<int>(body.size() + 2));
    records_.insert(records_.end(), body.begin(), body.end());
  }

  const C3dBytesWriter& w_;
  std::vector<std::uint8_t> records_;
};

// Where the parameters end and the point data starts, and the POINT:SCALE as stored
// (negative for float data).
struct C3dLayout {
  std::size_t parameter_blocks = 0;
  int data_start = 0;  // 512-byte blocks counted from 1
  float stored_scale = 0.0f;
};

inline C3dLayout c3d_layout(const C3dContent& c) {
  C3dLayout layout;
  layout.parameter_blocks = 2;  // ample for the tests' small label lists
  layout.data_start = static_cast<int>(2 + layout.parameter_blocks);  // after the header block
  layout.stored_scale = static_cast<float>(c.float_data ? -c.scale : c.scale);
  return layout;
}

inline std::size_t longest_label(const std::vector<std::string>& labels) {
  std::size_t length = 1;
  for (const auto& l : labels) length = std::max(length, l.size());
  return length;
}

// The labels, each padded with spaces to `length`.
inline std::vector<std::uint8_t> padded_labels(const std::vector<std::string>& labels, std::size_t length) {
  std::vector<std::uint8_t> out;
  for (const auto& l : labels) {
    std::string padded = l;
    padded.resize(length, ' ');
    out.insert(out.end(), padded.begin(), padded.end());
  }
  return out;
}

// The parameter section (its 4-byte header, then the records), whole blocks.
inline std::vector<std::uint8_t> c3d_parameter_section(const C3dContent& c, const C3dBytesWriter& w,
                                                       const C3dLayout& layout) {
  const std::size_t points = c.labels.size();
  const std::size_t frames = c.coordinates.size();
  const std::size_t label_length = longest_label(c.labels);
  const std::vector<std::uint8_t> labels = padded_labels(c.labels, label_length);
  C3dParameterRecords r(w);
  r.group(-1, "POINT");
  r.parameter("USED", 2, {}, r.int_data(static_cast<int>(points)));
  r.parameter("SCALE", 4, {}, r.float_data(layout.stored_scale));
  r.parameter("RATE", 4, {}, r.float_data(c.rate_hz));
  r.parameter("DATA_START", 2, {}, r.int_data(layout.data_start));
  r.parameter("FRAMES", 2, {}, r.int_data(static_cast<int>(frames)));
  r.parameter("LABELS", -1, {static_cast<int>(label_length), static_cast<int>(points)}, labels);
  r.parameter("UNITS", -1, {static_cast<int>(c.units.size())},
              std::vector<std::uint8_t>(c.units.begin(), c.units.end()));
  if (c.trial_fields) {
    r.group(-2, "TRIAL");
    r.parameter("ACTUAL_START_FIELD", 2, {2}, r.two_words(1), 2);
    r.parameter("ACTUAL_END_FIELD", 2, {2}, r.two_words(frames), 2);
  }
  const std::vector<std::uint8_t> records = r.finished();
  // Whole blocks; records past the last one would be cut (the tests' short lists never get there).
  std::vector<std::uint8_t> section(layout.parameter_blocks * 512, 0);
  section[0] = 1;
  section[1] = 0x50;
  section[2] = static_cast<std::uint8_t>(layout.parameter_blocks);
  section[3] = static_cast<std::uint8_t>(c.processor);
  std::copy_n(records.begin(), std::min(records.size(), section.size() - 4), section.begin() + 4);
  return section;
}

// The 512-byte header block.
inline std::vector<std::uint8_t> c3d_header(const C3dContent& c, const C3dBytesWriter& w,
                                            const C3dLayout& layout) {
  std::vector<std::uint8_t> file(512, 0);
  file[0] = 2;
  file[1] = 0x50;
  std::vector<std::uint8_t> h;
  w.i16(h, static_cast<int>(c.labels.size()));
  w.i16(h, 0);  // analog samples per frame
  w.i16(h, 1);
  w.i16(h, static_cast<int>(std::min<std::size_t>(c.coordinates.size(), 65535)));
  w.i16(h, 0);
  w.f32(h, layout.stored_scale);
  w.i16(h, layout.data_start);
  w.i16(h, 0);
  w.f32(h, c.rate_hz);
  std::copy(h.begin(), h.end(), file.begin() + 2);
  return file;
}

// Each point of each frame: x, y, z and a residual word (-1: invalid).
inline void append_c3d_points(const C3dContent& c, const C3dBytesWriter& w, std::vector<std::uint8_t>& file) {
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
}

inline std::vector<std::uint8_t> write_c3d_bytes(const C3dContent& c) {
  const C3dBytesWriter w(c.processor);
  const C3dLayout layout = c3d_layout(c);
  std::vector<std::uint8_t> file = c3d_header(c, w, layout);
  const std::vector<std::uint8_t> section = c3d_parameter_section(c, w, layout);
  file.insert(file.end(), section.begin(), section.end());
  append_c3d_points(c, w, file);
  file.resize((file.size() + 511) / 512 * 512, 0);
  return file;
}

}  // namespace aloft::test
