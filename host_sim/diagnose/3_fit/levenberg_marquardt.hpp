// Levenberg-Marquardt least squares for problems of "arrow" shape: parameters shared by
// every block (an effect common to all flights of a session) plus parameters local to
// each block (each flight's initial rate). One flight is the case of a single block.
//
// Written here rather than taken from Eigen's unsupported LevenbergMarquardt module
// because that solver wants one dense (or sparse-QR) Jacobian of the whole problem: a
// 60-flight session has ~180,000 residuals by ~190 parameters, while the normal
// equations assembled block by block below are only 190 x 190. No Debian-packaged
// solver other than Ceres exploits that structure, and Ceres, weighed on the same fits,
// reached the same minima in more time (docs/validation/diagnose-speed.md; tests/diagnose/ceres/).
#pragma once

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace aloft::host::diagnose {

struct ArrowProblem {
  int shared_count = 0;  // parameters common to every block
  int local_count = 0;   // parameters of each block
  int block_count = 1;
  // Blocks are evaluated on up to this many threads (parallel_for); `residuals` must then
  // be safe to call concurrently for different blocks. The result does not depend on it:
  // the blocks' sums are added in block order whatever thread made them.
  unsigned threads = 1;
  // Writes the residuals of `block` for the given parameters. The length must be the
  // same at every call for the same block.
  std::function<void(int block, const Eigen::VectorXd& shared, const Eigen::VectorXd& local,
                     Eigen::VectorXd& residuals)>
      residuals;
  // Optional: the residuals of `block` and their Jacobian, columns [shared | local], in
  // one call, for a problem that knows some columns without simulating (the sensor's
  // parameters). Returns false when it has nothing better for this point; the fitter then
  // differentiates `residuals` by forward differences, as it does when this is empty. The
  // residuals must be `residuals`' (same length, same values), the columns it does not
  // know forward differences with forward_difference_step, and it must be as safe to
  // call concurrently. On entry `residuals` holds the residuals at this point when the
  // fitter has them already (else it is empty), so that they need not be made again.
  std::function<bool(int block, const Eigen::VectorXd& shared, const Eigen::VectorXd& local,
                     Eigen::VectorXd& residuals, Eigen::MatrixXd& jacobian)>
      jacobian;
};

// The forward-difference step the fitter takes for a parameter of this value.
double forward_difference_step(double value);

// One block's residuals and Jacobian, columns [shared | local], as the fitter linearises
// it: the problem's `jacobian` where it gives one, else forward differences of `residuals`
// (p + m simulations, one more unless `known`, the residuals at this point, is given).
void block_jacobian(const ArrowProblem& problem, int block, const Eigen::VectorXd& shared,
                    const Eigen::VectorXd& local, const Eigen::VectorXd* known, Eigen::VectorXd& residuals,
                    Eigen::MatrixXd& jacobian);

struct LeastSquaresOptions {
  int max_iterations = 40;
  // Stop when two accepted steps in a row gain less than this share of the cost, or when
  // no step is predicted to gain more than the smaller of this and 1e-9 (the last bits).
  double relative_tolerance = 1e-7;
  // false: the caller wants only the solution and its cost, not normal_matrix, so the
  // last accepted point is not linearised (one Jacobian fewer; the solution is the same).
  bool normal_at_solution = true;
  // With normal_at_solution: each block's residuals and Jacobian at the solution too, in
  // the result (a single flight's folds step from them: refit_from_solution.hpp).
  bool keep_jacobian = false;
};

struct LeastSquaresResult {
  Eigen::VectorXd shared;
  std::vector<Eigen::VectorXd> local;
  double cost = 0.0;  // sum of squared residuals at the solution
  int iterations = 0;
  Eigen::MatrixXd normal_matrix;  // J^T J at the solution, [shared | local_0 | local_1 ...]
  // Each block's residuals and Jacobian [shared | its locals] at the solution, when
  // options.keep_jacobian (else empty).
  std::vector<Eigen::VectorXd> block_residuals;
  std::vector<Eigen::MatrixXd> block_jacobians;
};

// Minimises the sum of squared residuals from the given start. Derivatives are the
// problem's `jacobian` where it gives them, else forward differences. Never throws on a bad start: a
// non-finite cost is treated as a rejected step.
LeastSquaresResult minimise(const ArrowProblem& problem, const Eigen::VectorXd& shared_start,
                            const std::vector<Eigen::VectorXd>& local_start,
                            const LeastSquaresOptions& options = {});

// One Gauss-Newton step from (shared, local) in the directions the normal equations
// inform (those nearly flat left out: their step rides on the differences' last bits), the
// point reached and its cost (no normal_matrix). The first iteration of a refit started
// there: from the solution of a problem that had more residuals than this one, it reaches
// this one's solution to first order in those directions (exactly when the residuals are
// linear in the parameters), so the residuals left out do not steer it to that order.
// Where the step does not lower the cost by more than the last bits could (a parameter
// the data hardly inform, moved where the model is far from linear), Marquardt-damped
// steps are tried, more damped each time, and where none pays the point stays: the cost
// is then at its minimum within what the linearisation resolves.
LeastSquaresResult gauss_newton_step(const ArrowProblem& problem, const Eigen::VectorXd& shared,
                                     const std::vector<Eigen::VectorXd>& local);

// The sum of squared residuals at one point, without a Jacobian: one simulation of each
// block. What a search that looks over a whole range before refining pays per point.
double cost_at(const ArrowProblem& problem, const Eigen::VectorXd& shared,
               const std::vector<Eigen::VectorXd>& local);

// Leave-one-block-out: for each block j, the shared parameters after one Gauss-Newton
// step, from `shared`/`local` (normally the all-blocks solution), on the problem without
// block j. The normal equations are linearised once; each block's locals are eliminated
// (Schur complement), so every left-out step costs one small solve. This is the first
// iteration of refitting without block j, started from the all-blocks solution, which is
// where a refit without one flight of many ends up to first order.
std::vector<Eigen::VectorXd> leave_one_block_out(const ArrowProblem& problem, const Eigen::VectorXd& shared,
                                                 const std::vector<Eigen::VectorXd>& local);

}  // namespace aloft::host::diagnose
