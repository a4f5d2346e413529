// The seed corpus of each fuzz harness, generated here rather than copied from
// ../shared: small valid files of every layout the readers know, written by the same
// means as the reader tests (c3d_test_writer.hpp for C3D). test_fuzz_seeds.cpp checks
// that each seed is read, so the fuzzers start from inputs that reach deep code.
#pragma once

#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "aloft/records/flight_record.hpp"
#include "c3d_test_writer.hpp"
#include "fifo_file_writer.hpp"

namespace aloft::fuzz {

struct Seed {
  std::string name;
  std::string bytes;
};

inline std::string c3d_seed(aloft::test::Processor p, bool float_data, bool trial_fields) {
  aloft::test::C3dContent c;
  c.processor = p;
  c.float_data = float_data;
  c.trial_fields = trial_fields;
  c.labels = {"M1", "M2", "M3"};
  for (int f = 0; f < 4; ++f) {
    const double d = f;
    c.coordinates.push_back({{{10 + d, 20, 30}}, {{-5, 6 + d, 7}}, {{1, 2, 3 + d}}});
  }
  const auto bytes = aloft::test::write_c3d_bytes(c);
  return std::string(bytes.begin(), bytes.end());
}

const std::string kTrcSeed =
    "PathFileType\t4\t(X/Y/Z)\tt.trc\n"
    "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n"
    "100\t100\t3\t2\tmm\t100\t1\t3\n"
    "Frame#\tTime\tA\t\t\tB\t\t\n"
    "\t\tX1\tY1\tZ1\tX2\tY2\tZ2\n\n"
    "1\t0.00\t1.0\t2.0\t3.0\t4.0\t5.0\t6.0\n"
    "2\t0.01\t1.5\t2.5\t3.5\t\t\t\n"
    "3\t0.02\t1.6\t2.6\t3.6\t4.2\t5.2\t6.2\n";

const std::string kMotSeed =
    "throw\nversion=1\nnRows=3\nnColumns=7\ninDegrees=yes\nendheader\n"
    "time\tbox_rotX\tbox_rotY\tbox_rotZ\tbox_tx\tbox_ty\tbox_tz\n"
    "0.000\t90\t0\t0\t1\t2\t3\n0.004\t10\t20\t30\t0.1\t0.2\t0.3\n0.008\t11\t21\t31\t0.1\t0.2\t0.3\n";

const std::string kStoSeed =
    "states\nversion=1\ninDegrees=no\nendheader\n"
    "time /jointset/free/free_coord_0/value /jointset/free/free_coord_1/value "
    "/jointset/free/free_coord_2/value "
    "/jointset/free/free_coord_3/value /jointset/free/free_coord_4/value /jointset/free/free_coord_5/value\n"
    "0 0.1 0.2 0.3 1 2 3\n0.01 0.11 0.21 0.31 1 2 3\n";

const std::string kOsimSeed =
    "<?xml version=\"1.0\" encoding=\"UTF-8\" ?>\n<OpenSimDocument Version=\"40000\"><Model name=\"m\">"
    "<JointSet name=\"jointset\"><objects>"
    "<CustomJoint name=\"j\"><socket_parent_frame>ground_offset</socket_parent_frame>"
    "<socket_child_frame>body</socket_child_frame><frames><PhysicalOffsetFrame name=\"ground_offset\">"
    "<socket_parent>/ground</socket_parent><translation>0 1 0</translation><orientation>0 0 0.5</orientation>"
    "</PhysicalOffsetFrame></frames><SpatialTransform>"
    "<TransformAxis name=\"rotation1\"><coordinates>a</coordinates><axis>0 0 1</axis>"
    "<LinearFunction name=\"function\"><coefficients>1 0</coefficients></LinearFunction></TransformAxis>"
    "<TransformAxis name=\"rotation2\"><coordinates>b</coordinates><axis>1 0 0</axis></TransformAxis>"
    "<TransformAxis name=\"rotation3\"><coordinates>c</coordinates><axis>0 1 0</axis></TransformAxis>"
    "<TransformAxis name=\"translation1\"><coordinates>x</coordinates><axis>1 0 0</axis></TransformAxis>"
    "<TransformAxis name=\"translation2\"><coordinates></coordinates><axis>0 1 0</axis>"
    "<Constant name=\"function\"><value>0.5</value></Constant></TransformAxis>"
    "<TransformAxis name=\"translation3\"><coordinates>z</coordinates><axis>0 0 1</axis></TransformAxis>"
    "</SpatialTransform></CustomJoint></objects></JointSet></Model></OpenSimDocument>\n";

// harness name -> seeds
// A dump of the record area: `records` flight records, the slot `torn` (if < records)
// without its commit marker, then one erased slot.
inline std::string record_dump_seed(std::uint32_t records, std::uint32_t torn) {
  std::string dump;
  for (std::uint32_t i = 0; i <= records; ++i) {
    aloft::FlightRecord r;
    r.sequence = i + 1;
    r.flight_number = i;
    r.release_us = 1000000u * (i + 1);
    r.landing_us = r.release_us + 800000;
    r.samples = 800;
    r.landed = r.turned = true;
    r.rms_da_rad = 0.01f;
    r.seeds_stored = 2;
    std::uint8_t slot[aloft::flight_record_size];
    aloft::encode_flight_record(r, slot);
    if (i == torn)
      std::fill(slot + aloft::flight_record_commit_offset, slot + aloft::flight_record_size, 0xFF);
    if (i == records) std::fill(slot, slot + aloft::flight_record_size, 0xFF);
    dump.append(reinterpret_cast<const char*>(slot), sizeof(slot));
  }
  return dump;
}

inline std::map<std::string, std::vector<Seed>> seed_corpus() {
  using aloft::test::Processor;
  std::map<std::string, std::vector<Seed>> corpus;
  corpus["imu_csv"] = {
      {"plain.csv", "t,gx,gy,gz\n0,1,2,3\n0.001,4,5,6\n0.002,4.1,5.1,6.1\n"},
      {"accel.csv",
       "gz, gy, gx, t, az, ay, ax\r\n3, 2, 1, 0.5, 9.8, 0, 0.1\r\n3, 2, 1, 0.6, 9.8, 0, 0.1\r\n"},
      {"phyphox.csv",
       "\"Time (s)\",\"Gyroscope x (rad/s)\",\"Gyroscope y (rad/s)\",\"Gyroscope z (rad/s)\",\"Absolute "
       "(rad/s)\"\n"
       "1.0E-2,1.5E-1,-2.0E-2,3.0E0,3.01E0\n2.0E-2,1.6E-1,-2.1E-2,3.1E0,3.11E0\n"}};
  corpus["segments"] = {
      {"segments.csv",
       "segment, start, end, keep, comment\n0,,,false,warm-up\n1, 12.0, 13.0, , Intermediate axis\n"
       "2,18.65,19.84,true,\"fast, then slow\"\n3,25.2,26.25\n"}};
  corpus["trc"] = {{"markers.trc", kTrcSeed}};
  corpus["mot"] = {{"pose.mot", kMotSeed}, {"states.sto", kStoSeed}};
  corpus["pose_csv"] = {{"pose.csv",
                         "t,qw,qx,qy,qz,x,y,z,wx,wy,wz\n0,1,0,0,0,0.5,0.25,2,1,2,3\n"
                         "0.001,0.866025,0.5,0,0,0.5,0.25,2,1,2,3\n"}};
  corpus["body_json"] = {
      {"tensor.json",
       R"({"name": "box", "mass": 1.2, "inertia": {"tensor": [[0.01, 0, 0], [0, 0.02, 0], [0, 0, 0.025]]},
 "markers": {"M1": [0.1, 0, 0], "M2": [0, 0.1, 0], "M3": [0, 0, 0.1]}, "imu": {"rotation": [1, 0, 0, 0]}})"},
      {"principal.json", R"({"inertia": {"principal": [1, 2, 2.5], "axes": [0.7071068, 0.7071068, 0, 0]}})"},
      {"shape.json",
       R"({"mass": 10, "inertia": {"shape": {"cylinder": {"radius": 0.065, "height": 0.097}}}})"}};
  corpus["osim"] = {{"model.osim", kOsimSeed}};
  corpus["records"] = {{"three.bin", record_dump_seed(3, 3)},
                       {"torn.bin", record_dump_seed(3, 1)},
                       {"truncated.bin", record_dump_seed(2, 2).substr(0, 300)}};
  std::vector<Seed> c3d;
  for (Processor p : {Processor::intel, Processor::dec, Processor::mips}) {
    for (bool float_data : {false, true}) {
      c3d.push_back(
          {std::string(aloft::host::c3d::processor_name(p)) + (float_data ? "_float" : "_int") + ".c3d",
           c3d_seed(p, float_data, p == Processor::intel)});
    }
  }
  corpus["c3d"] = c3d;
  // ICM-42688-P FIFO bytes (`replay --fifo`): plain, with power-up packets without data,
  // with a hole (an overflow) across a wrap of the 16-bit stamp, and with faults.
  aloft_test::FifoFile fifo;
  fifo.packets = 8;
  aloft_test::FifoFile powerup = fifo;
  powerup.without_data = 3;
  aloft_test::FifoFile hole = fifo;
  hole.packets = 80;
  hole.holes = {{20, 30}};
  // The faults a recording of FIFO_DATA reads holds (DS-000347 §6.2): 0x80 empty reads,
  // alone and as whole slots, a foreign header mid-stream, and a cut last packet.
  aloft_test::FifoFile faults = fifo;
  faults.packets = 40;
  faults.empty_reads = {{0, false, 0x80}, {10, true, 0x00}, {20, true, 0x80}, {30, false, 0x80}};
  faults.foreign_header_packet = 25;
  faults.cut_tail = 9;
  corpus["icm42688p_fifo"] = {{"plain.bin", fifo.bytes()},
                              {"powerup.bin", powerup.bytes()},
                              {"hole.bin", hole.bytes()},
                              {"faults.bin", faults.bytes()}};
  // The dispatch sees every trial format (FIFO bytes and record dumps are not trials).
  std::vector<Seed> all;
  for (const auto& [harness, seeds] : corpus) {
    if (harness == "body_json" || harness == "osim" || harness == "icm42688p_fifo" || harness == "records")
      continue;
    for (const Seed& s : seeds) all.push_back({harness + "_" + s.name, s.bytes});
  }
  corpus["trial_dispatch"] = all;
  return corpus;
}

}  // namespace aloft::fuzz
