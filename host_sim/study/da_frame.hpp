// The two frames in which the study compares a simulated angular velocity with the
// measured one. The seed paper says only that "each pair of consecutive rotation
// matrices defined an instantaneous axis of rotation"; it does not say in which axes
// that axis was expressed, and the choice changes the numbers (docs/study.md):
//  - body: in the body's own axes, the vector part of q_j^-1 q_{j+1}. A wrong tensor
//    makes ω drift through the body, so the deviation grows with time from the seed;
//  - world: in the fixed lab axes, the vector part of q_{j+1} q_j^-1 (the body axis
//    rotated by q_j). Torque-free, ω stays near the fixed angular momentum whatever the
//    tensor, so the deviation stays bounded.
// Rate flights (IMU) have no orientation, so only the body frame exists for them.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace aloft::host {

enum class DaFrame { body, world };
constexpr std::size_t kDaFrames = 2;
constexpr std::array<DaFrame, kDaFrames> kAllDaFrames = {DaFrame::body, DaFrame::world};

inline std::size_t frame_index(DaFrame frame) { return static_cast<std::size_t>(frame); }
inline const char* frame_name(DaFrame frame) { return frame == DaFrame::body ? "body" : "world"; }

// One RMS deviation angle per frame, degrees (world is NaN for a rate flight).
using RmsDaByFrame = std::array<double, kDaFrames>;

}  // namespace aloft::host
