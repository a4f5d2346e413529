// Everything in lib/, for callers who want one include.
#pragma once

#include "aloft/angular_velocity.hpp"
#include "aloft/deviation.hpp"
#include "aloft/euler_equations.hpp"
#include "aloft/flight_detector.hpp"
#include "aloft/inertia_tensor.hpp"
#include "aloft/lane_angle.hpp"
#include "aloft/lanes.hpp"
#include "aloft/onboard_check.hpp"
#include "aloft/principal_dynamics.hpp"
#include "aloft/principal_frame.hpp"
#include "aloft/rigid_body_state.hpp"
#include "aloft/rk4_integrator.hpp"
#include "aloft/rotation.hpp"
#include "aloft/splitting_integrator.hpp"
#include "aloft/status.hpp"
