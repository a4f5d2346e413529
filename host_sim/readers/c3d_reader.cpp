#include "readers/c3d_reader.hpp"

#include <cmath>
#include <optional>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>

#include "common/commands.hpp"
#include "common/file_error.hpp"
#include "readers/c3d_numbers.hpp"
#include "readers/c3d_parameters.hpp"
#include "readers/length_units.hpp"

namespace aloft::host {

namespace {

using c3d::ByteView;
using c3d::ParameterSection;
using c3d::Processor;

constexpr std::size_t kBlockBytes = 512;

// The whole file, once its first block has shown the C3D key: a large file of anything
// else is refused after 512 bytes rather than read into memory.
std::vector<std::uint8_t> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path + ": cannot open file");
  std::vector<std::uint8_t> bytes(kBlockBytes);
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  if (bytes.empty()) throw Error(path + ": file is empty");
  if (bytes.size() < kBlockBytes) throw Error(path + ": too short for a C3D header (512 bytes)");
  if (bytes[1] != 0x50) throw Error(path + ": not a C3D file (no 0x50 key in its header)");
  bytes.insert(bytes.end(), std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return bytes;
}

// A parameter that means an unsigned count or block number (frame numbers, DATA_START),
// checked before it is converted: int16 words are read as unsigned 16-bit (writers use
// the sign bit for counts over 32767); a float (float-processor files) must be a whole
// number from 0 to 65535. nullopt otherwise, so a value like 1e30 is never converted.
std::optional<std::size_t> unsigned_word(const ParameterSection& params, const char* group, const char* name,
                                         std::size_t index = 0) {
  constexpr double kMostWord = 65535.0;
  const c3d::Parameter* p = params.find(group, name);
  const auto value = params.number(group, name, index);
  if (!p || !value) return std::nullopt;
  if (p->type == 2) return static_cast<std::size_t>(static_cast<std::uint16_t>(std::int16_t(*value)));
  if (!(*value >= 0.0 && *value <= kMostWord) || *value != std::floor(*value)) return std::nullopt;
  return static_cast<std::size_t>(*value);
}

// The highest sample rate any motion-capture or force-plate system records at; a rate
// above it is a damaged field, not a measurement.
constexpr double kMostRateHz = 1e6;

bool plausible_rate(double rate) { return std::isfinite(rate) && rate > 0.0 && rate <= kMostRateHz; }

std::vector<std::string> point_labels(const ParameterSection& params, std::size_t points) {
  std::vector<std::string> labels = params.strings("POINT", "LABELS");
  // Files with more than 255 points continue the list in LABELS2, LABELS3, ...
  for (int k = 2; labels.size() < points; ++k) {
    const auto more = params.strings("POINT", "LABELS" + std::to_string(k));
    if (more.empty()) break;
    labels.insert(labels.end(), more.begin(), more.end());
  }
  labels.resize(points);
  for (std::size_t i = 0; i < points; ++i) {
    if (labels[i].empty()) labels[i] = "point" + std::to_string(i + 1);
  }
  return labels;
}

// Where and how the points are stored, from the header, which every writer fills in;
// POINT:SCALE and POINT:DATA_START repeat it and win when present (the parameters are
// authoritative). Not yet checked.
struct PointLayout {
  std::size_t points = 0;
  std::size_t analog_per_frame = 0;
  std::size_t first_frame = 0;
  std::size_t last_frame = 0;
  double scale = 0.0;  // negative: float data
  std::size_t data_start = 0;
};

PointLayout point_layout(const std::uint8_t* header, const ParameterSection& params) {
  const Processor format = params.processor;
  auto header_word = [&](int n) { return decode_u16(header + 2 * (n - 1), format); };  // 1-based
  PointLayout layout;
  layout.points = header_word(2);
  layout.analog_per_frame = header_word(3);
  layout.first_frame = header_word(4);
  layout.last_frame = header_word(5);
  layout.scale = params.number("POINT", "SCALE").value_or(0.0);
  if (!std::isfinite(layout.scale) || layout.scale == 0.0)
    layout.scale = c3d::decode_f32(header + 12, format);
  layout.data_start = unsigned_word(params, "POINT", "DATA_START").value_or(0);
  if (layout.data_start < 2) layout.data_start = header_word(9);  // some writers leave the parameter 0
  // Long trials do not fit the header's 16-bit frame numbers: TRIAL:ACTUAL_*_FIELD hold
  // them as two 16-bit words, low word first.
  const auto start_low = unsigned_word(params, "TRIAL", "ACTUAL_START_FIELD", 0);
  const auto start_high = unsigned_word(params, "TRIAL", "ACTUAL_START_FIELD", 1);
  const auto end_low = unsigned_word(params, "TRIAL", "ACTUAL_END_FIELD", 0);
  const auto end_high = unsigned_word(params, "TRIAL", "ACTUAL_END_FIELD", 1);
  if (start_low && start_high && end_low && end_high) {
    layout.first_frame = *start_low + (*start_high << 16);
    layout.last_frame = *end_low + (*end_high << 16);
  }
  return layout;
}

// The frames of the data section, once the layout is checked and the file found to hold
// them all.
struct DataSection {
  std::size_t frames = 0;
  bool float_data = false;
  std::size_t width = 0;        // bytes per value
  std::size_t frame_bytes = 0;  // points and analog samples
  std::size_t offset = 0;       // of the first frame in the file
};

DataSection locate_data(const PointLayout& layout, const ByteView& file, const std::string& path) {
  if (layout.points == 0) throw Error(path + ": holds no 3D points");
  if (!std::isfinite(layout.scale) || layout.scale == 0.0)
    throw Error(path + ": POINT:SCALE is 0 or not finite");
  if (layout.last_frame < layout.first_frame) {
    throw Error(path + ": last frame " + std::to_string(layout.last_frame) + " before first frame " +
                std::to_string(layout.first_frame));
  }
  if (layout.data_start < 2)
    throw Error(path + ": data section start block " + std::to_string(layout.data_start) + " is invalid");
  // Every term below is at most 32 bits wide (16-bit words, a 65535·65536 frame number),
  // so the sizes cannot overflow; the frame count is then held to what the file holds
  // before anything is allocated for it.
  DataSection data;
  data.frames = layout.last_frame - layout.first_frame + 1;
  data.float_data = layout.scale < 0.0;
  data.width = data.float_data ? 4 : 2;
  data.frame_bytes = (4 * layout.points + layout.analog_per_frame) * data.width;
  data.offset = (layout.data_start - 1) * kBlockBytes;
  if (data.offset >= file.size()) {
    throw Error(path + ": data section starts at block " + std::to_string(layout.data_start) +
                ", beyond the file's " + std::to_string((file.size() + kBlockBytes - 1) / kBlockBytes) +
                " blocks");
  }
  const std::size_t available = (file.size() - data.offset) / data.frame_bytes;
  if (available < data.frames) {
    throw Error(path + ": claims " + std::to_string(data.frames) + " frames, its data section holds " +
                std::to_string(available) + " (truncated file?)");
  }
  return data;
}

double point_rate(const ParameterSection& params, const std::uint8_t* header, const std::string& path) {
  double rate = params.number("POINT", "RATE").value_or(0.0);
  if (!plausible_rate(rate)) rate = c3d::decode_f32(header + 20, params.processor);
  if (!plausible_rate(rate)) throw Error(path + ": no valid POINT:RATE (a rate above 0 and up to 1 MHz)");
  return rate;
}

// Every frame's points into `trial` (sized for them), in metres; an occluded point (a
// negative residual, or not finite) is NaN.
void read_points(const ByteView& file, const PointLayout& layout, const DataSection& data, double metres,
                 Processor format, const std::string& path, MarkerTrial& trial) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double integer_scale = std::abs(layout.scale) * metres;
  const std::size_t width = data.width;
  for (std::size_t f = 0; f < data.frames; ++f) {
    // Frame numbers are 1-based; a writer that starts at 0 gets a negative first time.
    trial.time_s[f] =
        (static_cast<double>(layout.first_frame) - 1.0 + static_cast<double>(f)) / trial.rate_hz;
    const std::uint8_t* frame = file.at(data.offset + f * data.frame_bytes, data.frame_bytes);
    if (!frame)
      throw Error(path + ": frame " + std::to_string(layout.first_frame + f) + " lies beyond the file");
    for (std::size_t m = 0; m < layout.points; ++m) {
      const std::uint8_t* word = frame + 4 * m * width;
      Eigen::Vector3d xyz;
      double residual;
      if (data.float_data) {
        for (int a = 0; a < 3; ++a) xyz[a] = c3d::decode_f32(word + 4 * a, format) * metres;
        residual = c3d::decode_f32(word + 12, format);
      } else {
        for (int a = 0; a < 3; ++a) xyz[a] = c3d::decode_i16(word + 2 * a, format) * integer_scale;
        residual = c3d::decode_i16(word + 6, format);
      }
      const bool occluded = residual < 0.0 || !xyz.allFinite();
      trial.positions_m[f][m] = occluded ? Eigen::Vector3d(nan, nan, nan) : xyz;
    }
  }
}

// What the caller asked to know of the file beyond its points; without such a caller, a
// damaged parameter section is warned of.
void report_details(const ParameterSection& params, const PointLayout& layout, const DataSection& data,
                    const std::string& path, C3dDetails* details) {
  if (!params.damage.empty() && !details) {
    // The points are sound (the data section checked out), but the user should know
    // that labels or units may be missing: one line, as every message of aloft. A
    // caller that asks for C3dDetails reports the damage itself.
    std::fprintf(stderr, "aloft: warning: %s: parameter section damaged (%s); read up to there\n",
                 path.c_str(), params.damage.c_str());
  }
  if (details) {
    details->processor = c3d::processor_name(params.processor);
    details->float_data = data.float_data;
    details->point_scale = layout.scale;
    details->first_frame = static_cast<long>(layout.first_frame);
    details->analog_samples_per_frame = static_cast<int>(layout.analog_per_frame);
    details->parameter_damage = params.damage;
    details->parameter_repairs = params.repairs;
  }
}

}  // namespace

static MarkerTrial read_c3d_unguarded(const std::string& path, C3dDetails* details) {
  const std::vector<std::uint8_t> bytes = read_bytes(path);
  const ByteView file(bytes);
  const std::uint8_t* header = file.at(0, kBlockBytes);  // read_bytes checked it is there

  const ParameterSection params = parse_parameter_section(file, header[0], path);
  const PointLayout layout = point_layout(header, params);
  const DataSection data = locate_data(layout, file, path);
  const double rate = point_rate(params, header, path);

  const std::vector<std::string> units = params.strings("POINT", "UNITS");
  const std::string unit = units.empty() || units[0].empty() ? "mm" : units[0];
  const double metres = metres_per_unit(unit);
  if (metres == 0.0) throw Error(path + ": unknown POINT:UNITS '" + unit + "' (expected mm, cm or m)");

  MarkerTrial trial;
  trial.path = path;
  trial.format = "c3d";
  trial.units_in_file = unit;
  trial.rate_hz = rate;
  trial.marker_names = point_labels(params, layout.points);
  trial.time_s.resize(data.frames);
  trial.positions_m.assign(data.frames, std::vector<Eigen::Vector3d>(layout.points));
  read_points(file, layout, data, metres, params.processor, path, trial);
  report_details(params, layout, data, path, details);
  return trial;
}

MarkerTrial read_c3d(const std::string& path, C3dDetails* details) {
  return with_file_context(path, [&] { return read_c3d_unguarded(path, details); });
}

}  // namespace aloft::host
