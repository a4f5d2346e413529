// The covariance and standard errors of a pooled fit's shared parameters, the flights'
// initial rates marginalised, from the normal matrix J^T J at the solution.
#pragma once

#include <Eigen/Core>

namespace aloft::host::diagnose {

struct ParameterErrors {
  Eigen::VectorXd standard_error;  // infinite where a parameter reaches an uninformed direction
  Eigen::MatrixXd covariance;      // over the directions the data inform, times `variance`
  bool through_schur = false;      // the arrow path (below) served, not the full decomposition
};

// `normal`: [shared | local_0 | local_1 ...], `count` shared parameters then blocks of
// `local_count`, no entry between two different blocks (an arrow). The answer is that
// of the pseudo-inverse of the whole matrix (eigenvalues below 1e-12 of the largest
// left out), but found, whenever the matrix provably has no such eigenvalue, as the
// inverse of the count x count Schur complement A - sum_i B_i D_i^-1 B_i^T: O(blocks)
// instead of one O(blocks^3) eigen-decomposition (606 x 606 at 200 flights).
ParameterErrors parameter_errors(const Eigen::MatrixXd& normal, int count, int local_count, double variance);

// The same from one eigen-decomposition of the whole matrix, always (the reference the
// arrow path is tested against, and its fallback).
ParameterErrors parameter_errors_full(const Eigen::MatrixXd& normal, int count, double variance);

}  // namespace aloft::host::diagnose
