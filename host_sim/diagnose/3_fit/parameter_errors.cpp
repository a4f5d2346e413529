#include "diagnose/3_fit/parameter_errors.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace aloft::host::diagnose {
namespace {

// Eigenvalues at or below this fraction of the largest are directions the data do not
// inform (left out of the pseudo-inverse): the full decomposition's rule.
constexpr double kUninformedFraction = 1e-12;
// The arrow path is taken only when its lower bound on the smallest eigenvalue clears
// the full path's cutoff by this factor: a margin far above the eigen-solvers' rounding
// (~1e-16 of the largest eigenvalue), so that the two paths cannot disagree about
// which directions are informed.
constexpr double kSchurMargin = 10.0;

// True when every entry outside the shared rows/columns and the diagonal blocks is zero.
bool is_arrow(const Eigen::MatrixXd& normal, int count, int local_count) {
  const Eigen::Index size = normal.rows();
  for (Eigen::Index j = count; j < size; ++j) {
    const Eigen::Index block_start = count + (j - count) / local_count * local_count;
    for (Eigen::Index i = count; i < size; ++i) {
      if ((i < block_start || i >= block_start + local_count) && normal(i, j) != 0.0) return false;
    }
  }
  return true;
}

// An upper bound on the largest eigenvalue of a symmetric positive semi-definite matrix:
// the smaller of its trace and its largest absolute row sum (Gershgorin).
double largest_eigenvalue_bound(const Eigen::MatrixXd& normal) {
  return std::min(normal.trace(), normal.cwiseAbs().rowwise().sum().maxCoeff());
}

// The shared parameters' block of the inverse, S^-1, when the whole matrix is provably
// well away from singular; nothing when it may not be (or is not an arrow).
//   N^-1 = [0 0; 0 D^-1] + [I; -D^-1 B^T] S^-1 [I, -B D^-1], so
//   ||N^-1|| <= max_i ||D_i^-1|| + ||S^-1|| (1 + ||B D^-1||_F^2)
// bounds the smallest eigenvalue of N from below.
std::optional<Eigen::MatrixXd> schur_inverse(const Eigen::MatrixXd& normal, int count, int local_count) {
  const Eigen::Index size = normal.rows();
  if (local_count <= 0 || (size - count) % local_count != 0 || !is_arrow(normal, count, local_count)) {
    return std::nullopt;
  }
  Eigen::MatrixXd schur = normal.topLeftCorner(count, count);
  double largest_block_inverse = 0.0, coupling = 0.0;  // max ||D_i^-1||, ||B D^-1||_F^2
  for (Eigen::Index start = count; start < size; start += local_count) {
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> block(
        normal.block(start, start, local_count, local_count));
    const double smallest = block.eigenvalues().minCoeff();
    if (!(smallest > 0.0)) return std::nullopt;
    largest_block_inverse = std::max(largest_block_inverse, 1.0 / smallest);
    const Eigen::MatrixXd block_inverse = block.eigenvectors() *
                                          block.eigenvalues().cwiseInverse().asDiagonal() *
                                          block.eigenvectors().transpose();
    const Eigen::MatrixXd coupled = normal.block(0, start, count, local_count) * block_inverse;
    coupling += coupled.squaredNorm();
    schur.noalias() -= coupled * normal.block(0, start, count, local_count).transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(schur);
  const double smallest = solver.eigenvalues().minCoeff();
  if (!(smallest > 0.0)) return std::nullopt;
  const double inverse_norm_bound = largest_block_inverse + (1.0 + coupling) / smallest;
  const double cutoff = kUninformedFraction * std::max(largest_eigenvalue_bound(normal), 1e-300);
  if (!(1.0 / inverse_norm_bound > kSchurMargin * cutoff)) return std::nullopt;
  return Eigen::MatrixXd(solver.eigenvectors() * solver.eigenvalues().cwiseInverse().asDiagonal() *
                         solver.eigenvectors().transpose());
}

}  // namespace

ParameterErrors parameter_errors_full(const Eigen::MatrixXd& normal, int count, double variance) {
  ParameterErrors out{Eigen::VectorXd::Constant(count, std::numeric_limits<double>::infinity()),
                      Eigen::MatrixXd::Zero(count, count)};
  if (count == 0 || normal.rows() == 0) return out;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(normal);
  const Eigen::VectorXd& values = solver.eigenvalues();
  const double cutoff = kUninformedFraction * std::max(values.maxCoeff(), 1e-300);
  std::vector<bool> informed(static_cast<std::size_t>(count), true);
  for (int k = 0; k < values.size(); ++k) {
    const Eigen::VectorXd v = solver.eigenvectors().col(k).head(count);
    if (values(k) <= cutoff) {
      for (int i = 0; i < count; ++i) {
        if (std::abs(v(i)) > 1e-6) informed[static_cast<std::size_t>(i)] = false;
      }
      continue;
    }
    out.covariance += v * v.transpose() / values(k);
  }
  for (int i = 0; i < count; ++i) {
    if (informed[static_cast<std::size_t>(i)])
      out.standard_error(i) = std::sqrt(out.covariance(i, i) * variance);
  }
  out.covariance *= variance;
  return out;
}

ParameterErrors parameter_errors(const Eigen::MatrixXd& normal, int count, int local_count, double variance) {
  if (count == 0 || normal.rows() == 0) return parameter_errors_full(normal, count, variance);
  const std::optional<Eigen::MatrixXd> inverse = schur_inverse(normal, count, local_count);
  if (!inverse) return parameter_errors_full(normal, count, variance);
  ParameterErrors out;
  out.covariance = *inverse * variance;
  out.standard_error = out.covariance.diagonal().cwiseSqrt();
  out.through_schur = true;
  return out;
}

}  // namespace aloft::host::diagnose
