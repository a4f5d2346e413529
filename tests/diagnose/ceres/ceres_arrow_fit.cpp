#include "ceres/ceres_arrow_fit.hpp"

#include <ceres/ceres.h>

#include <memory>

namespace aloft::host::diagnose {
namespace {

// One block of an ArrowProblem as a Ceres cost: parameter blocks [shared] (when there is
// any) and [local] (when there is any), residuals as the problem writes them.
class ArrowBlockCost final : public ceres::CostFunction {
 public:
  ArrowBlockCost(const ArrowProblem& problem, int block, int residual_count)
      : problem_(problem), block_(block) {
    set_num_residuals(residual_count);
    if (problem.shared_count > 0) mutable_parameter_block_sizes()->push_back(problem.shared_count);
    if (problem.local_count > 0) mutable_parameter_block_sizes()->push_back(problem.local_count);
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const int p = problem_.shared_count, m = problem_.local_count;
    const Eigen::VectorXd shared =
        p > 0 ? Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(parameters[0], p)) : Eigen::VectorXd();
    const Eigen::VectorXd local =
        m > 0 ? Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(parameters[p > 0 ? 1 : 0], m))
              : Eigen::VectorXd();
    Eigen::VectorXd r;
    Eigen::MatrixXd jacobian;
    if (jacobians == nullptr) {
      problem_.residuals(block_, shared, local, r);
    } else {
      block_jacobian(problem_, block_, shared, local, nullptr, r, jacobian);
    }
    // A failed evaluation makes Ceres reject the step, as minimise rejects a non-finite cost.
    if (r.size() != num_residuals() || !r.allFinite()) return false;
    Eigen::Map<Eigen::VectorXd>(residuals, r.size()) = r;
    if (jacobians == nullptr) return true;
    using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    if (p > 0 && jacobians[0] != nullptr) {
      Eigen::Map<RowMajor>(jacobians[0], r.size(), p) = jacobian.leftCols(p);
    }
    double* local_jacobian = m > 0 ? jacobians[p > 0 ? 1 : 0] : nullptr;
    if (local_jacobian != nullptr) Eigen::Map<RowMajor>(local_jacobian, r.size(), m) = jacobian.rightCols(m);
    return jacobian.allFinite();
  }

 private:
  const ArrowProblem& problem_;
  int block_;
};

}  // namespace

CeresArrowResult minimise_with_ceres(const ArrowProblem& problem, const Eigen::VectorXd& shared_start,
                                     const std::vector<Eigen::VectorXd>& local_start,
                                     const CeresArrowOptions& options) {
  CeresArrowResult result;
  result.shared = shared_start;
  result.local = local_start;
  ceres::Problem::Options problem_options;
  ceres::Problem ceres_problem(problem_options);
  auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
  const int p = problem.shared_count, m = problem.local_count;
  if (p > 0) {
    ceres_problem.AddParameterBlock(result.shared.data(), p);
    ordering->AddElementToGroup(result.shared.data(), 1);
  }
  for (int b = 0; b < problem.block_count; ++b) {
    Eigen::VectorXd& local = result.local[static_cast<std::size_t>(b)];
    // The residual count is fixed per block (ArrowProblem): read it off the start.
    Eigen::VectorXd start_residuals;
    problem.residuals(b, result.shared, local, start_residuals);
    std::vector<double*> blocks;
    if (p > 0) blocks.push_back(result.shared.data());
    if (m > 0) {
      blocks.push_back(local.data());
      // The locals are eliminated first (a Schur solver's points, the fitter's blocks).
      ordering->AddElementToGroup(local.data(), 0);
    }
    ceres_problem.AddResidualBlock(new ArrowBlockCost(problem, b, static_cast<int>(start_residuals.size())),
                                   nullptr, blocks);
  }
  ceres::Solver::Options solver;
  solver.minimizer_type = ceres::TRUST_REGION;
  solver.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  solver.linear_solver_type = options.linear_solver;
  if (p > 0 && m > 0) solver.linear_solver_ordering = ordering;
  solver.max_num_iterations = options.max_iterations;
  solver.function_tolerance = options.function_tolerance;
  solver.num_threads = 1;
  solver.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &ceres_problem, &summary);
  result.cost = 2.0 * summary.final_cost;
  result.iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
  result.residual_evaluations = summary.num_residual_evaluations;
  result.jacobian_evaluations = summary.num_jacobian_evaluations;
  result.converged = summary.termination_type == ceres::CONVERGENCE;
  return result;
}

}  // namespace aloft::host::diagnose
