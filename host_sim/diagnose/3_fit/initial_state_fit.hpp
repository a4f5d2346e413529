// One flight's initial state (its body rate at the reference sample) with the effect
// parameters held, fitted so that it survives the separatrix. Near an intermediate-axis
// flip the readings depend on the start rate so steeply that a local fit over the whole
// flight, started from a reading, can settle in the basin of a motion that flips at the
// wrong time. Continuation avoids it: fit a short span around the reference first (where
// the cost is nearly quadratic in the rate), then refit over spans that double each time,
// each started from the last, until the span is the flight. The result is kept only if it
// beats a plain local fit from the caller's start, so the fit is never worse than before.
#pragma once

#include <Eigen/Core>

#include <cstddef>

#include "diagnose/2_model/flight_model.hpp"
#include "diagnose/3_fit/flight_data.hpp"

namespace aloft::host::diagnose {

struct InitialState {
  Eigen::Vector3d omega_ref = Eigen::Vector3d::Zero();
  double cost = 0.0;  // weighted squared residuals on the masked samples
};

// The rate at sample `ref` of `data` under `model` with parameters `theta`, from `start`
// (nullptr: the reading at ref) and by continuation from the reading at ref.
InitialState fit_initial_state(const EffectModel& model, const FlightData& data, std::size_t ref,
                               const Eigen::VectorXd& theta, const Eigen::Vector3d* start);

}  // namespace aloft::host::diagnose
