// The fitter's problems (diagnose/3_fit/levenberg_marquardt.hpp, ArrowProblem) solved by
// Ceres instead, for weighing the two on the same fits (fitter_comparison_benchmark.cpp,
// docs/validation/diagnose-speed.md). Not part of `aloft`: built only where Ceres is installed.
//
// Each block is one ceres residual block over two parameter blocks, [shared] and its own
// [local] (only [local] when nothing is shared), so Ceres sees the same arrow. Its
// Jacobian is the one the hand-written fitter uses: the problem's own `jacobian` where it
// gives one, else forward differences of `residuals` with forward_difference_step. The
// two fitters then differ only in how they step (trust region, damping, stopping) and
// solve (Ceres' linear solver against the fitter's normal equations).
#pragma once

#include <ceres/types.h>

#include <Eigen/Core>

#include <vector>

#include "diagnose/3_fit/levenberg_marquardt.hpp"

namespace aloft::host::diagnose {

struct CeresArrowOptions {
  ceres::LinearSolverType linear_solver = ceres::DENSE_QR;
  // The hand-written fitter's defaults (LeastSquaresOptions): at most 40 iterations, and
  // done when the cost falls by less than this share (Ceres' function_tolerance).
  int max_iterations = 40;
  double function_tolerance = 1e-7;
};

struct CeresArrowResult {
  Eigen::VectorXd shared;
  std::vector<Eigen::VectorXd> local;
  double cost = 0.0;             // sum of squared residuals (twice Ceres' own cost), as minimise's
  int iterations = 0;            // Ceres' steps, successful and not (minimise counts both too)
  int residual_evaluations = 0;  // Ceres' count: each evaluates every block once
  int jacobian_evaluations = 0;
  bool converged = false;  // stopped by a tolerance, not by the iteration limit
};

// Minimises the same sum of squares as minimise(problem, ...) from the same start, with
// Ceres' Levenberg-Marquardt trust region on one thread.
CeresArrowResult minimise_with_ceres(const ArrowProblem& problem, const Eigen::VectorXd& shared_start,
                                     const std::vector<Eigen::VectorXd>& local_start,
                                     const CeresArrowOptions& options = {});

}  // namespace aloft::host::diagnose
