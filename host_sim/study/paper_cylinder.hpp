// The numbers of the seed study (../shared/STUDY.md), in SI units: the steel cylinder,
// its two inertia estimates, the Monte Carlo bounds and the published results that
// aloft's figures are printed beside.
#pragma once

#include <array>

namespace aloft::host::paper {

constexpr double kMassKg = 10.010;
constexpr double kHeightM = 0.0970;
constexpr double kDiameterM = 0.1298;
constexpr double kFlightTimeS = 0.872;
constexpr double kCameraRateHz = 250.0;     // Vicon MX
constexpr double kResampleRateHz = 1000.0;  // OpenSim inverse kinematics output
constexpr double kMarkerDiameterM = 0.012;

// Compound pendulum estimate, principal moments about CCS X, Y, Z (kg·m²).
constexpr std::array<double, 3> kCompoundPendulumKgM2 = {203.3e-4, 155.0e-4, 192.5e-4};

// Monte Carlo: bounds of each family (percent for moments, degrees for axes).
constexpr std::array<double, 4> kBounds = {2.5, 5.0, 7.5, 10.0};
constexpr int kMonteCarloSimulations = 5000;

// Published RMS DA (degrees) where the paper gives them.
struct PublishedRow {
  const char* label;
  double p10, median, p90;
};
constexpr PublishedRow kGeometricFormulae = {"GF", 2.9, 3.1, 4.3};
constexpr PublishedRow kCompoundPendulum = {"CP", 11.7, 13.5, 15.2};
constexpr PublishedRow kMoments10 = {"moments ±10 %", 3.2, 4.4, 6.6};
constexpr PublishedRow kAxes10 = {"axes ±10°", 3.0, 3.3, 4.4};
constexpr PublishedRow kBoth10 = {"moments ±10 % and axes ±10°", 5.5, 6.4, 7.9};

}  // namespace aloft::host::paper
