#include "diagnose/3_fit/levenberg_marquardt.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/parallel_for.hpp"

namespace aloft::host::diagnose {

double forward_difference_step(double value) { return 1e-7 * std::max(1.0, std::abs(value)); }

namespace {

struct Point {
  Eigen::VectorXd shared;
  std::vector<Eigen::VectorXd> local;
};

// Runs body(b) for every block, on problem.threads threads.
void for_each_block(const ArrowProblem& problem, const std::function<void(std::size_t)>& body) {
  const std::size_t count = static_cast<std::size_t>(problem.block_count);
  if (problem.threads <= 1 || count <= 1) {
    for (std::size_t b = 0; b < count; ++b) body(b);
    return;
  }
  parallel_for(count, problem.threads, body);
}

// The residuals of every block at a point, kept so that linearising there (when the
// point is accepted) does not compute them again.
struct Evaluation {
  std::vector<Eigen::VectorXd> residuals;  // per block
  double cost = 0.0;
};

Evaluation evaluate(const ArrowProblem& problem, const Point& x) {
  Evaluation e;
  e.residuals.resize(static_cast<std::size_t>(problem.block_count));
  for_each_block(problem, [&](std::size_t b) {
    problem.residuals(static_cast<int>(b), x.shared, x.local[b], e.residuals[b]);
  });
  for (const Eigen::VectorXd& r : e.residuals) e.cost += r.squaredNorm();
  if (!std::isfinite(e.cost)) e.cost = std::numeric_limits<double>::infinity();
  return e;
}

// One block's part of the normal equations: J^T J and J^T r over [shared | its locals],
// with J by forward differences, and its squared residuals.
struct BlockNormal {
  Eigen::MatrixXd jtj;
  Eigen::VectorXd jtr;
  double cost = 0.0;
};

// J^T J of a tall, narrow Jacobian, one column dot product per entry of the lower half,
// mirrored: half the work of the general product (and none of its packing), which for
// p + m <= 12 columns by thousands of rows spent more copying the blocks than multiplying.
Eigen::MatrixXd gram(const Eigen::MatrixXd& jac) {
  const Eigen::Index k = jac.cols();
  Eigen::MatrixXd out(k, k);
  for (Eigen::Index i = 0; i < k; ++i) {
    for (Eigen::Index j = 0; j <= i; ++j) out(i, j) = out(j, i) = jac.col(i).dot(jac.col(j));
  }
  return out;
}

BlockNormal normal_of(const Eigen::MatrixXd& jac, const Eigen::VectorXd& r) {
  BlockNormal out;
  out.jtj = gram(jac);
  out.jtr = jac.transpose() * r;
  out.cost = r.squaredNorm();
  return out;
}

// `known`: the block's residuals at (shared, local) when already computed (nullptr: not).
BlockNormal block_normal(const ArrowProblem& problem, int block, const Eigen::VectorXd& shared,
                         const Eigen::VectorXd& local, const Eigen::VectorXd* known) {
  const int p = problem.shared_count;
  const int m = problem.local_count;
  Eigen::VectorXd r0, r1;
  Eigen::MatrixXd jac;
  if (problem.jacobian && problem.jacobian(block, shared, local, r0, jac)) return normal_of(jac, r0);
  if (known != nullptr) {
    r0 = *known;
  } else {
    problem.residuals(block, shared, local, r0);
  }
  jac.resize(r0.size(), p + m);
  for (int i = 0; i < p; ++i) {
    Eigen::VectorXd s = shared;
    const double h = forward_difference_step(s(i));
    s(i) += h;
    problem.residuals(block, s, local, r1);
    jac.col(i) = (r1 - r0) / h;
  }
  for (int i = 0; i < m; ++i) {
    Eigen::VectorXd l = local;
    const double h = forward_difference_step(l(i));
    l(i) += h;
    problem.residuals(block, shared, l, r1);
    jac.col(p + i) = (r1 - r0) / h;
  }
  return normal_of(jac, r0);
}

std::vector<BlockNormal> block_normals(const ArrowProblem& problem, const Eigen::VectorXd& shared,
                                       const std::vector<Eigen::VectorXd>& local,
                                       const Evaluation* known = nullptr) {
  std::vector<BlockNormal> blocks(static_cast<std::size_t>(problem.block_count));
  for_each_block(problem, [&](std::size_t b) {
    blocks[b] = block_normal(problem, static_cast<int>(b), shared, local[b],
                             known != nullptr ? &known->residuals[b] : nullptr);
  });
  return blocks;
}

// J^T J and J^T r of the whole problem at x, assembled block by block. `known`: the
// residuals at x, when evaluated already.
double linearise(const ArrowProblem& problem, const Point& x, Eigen::MatrixXd& normal,
                 Eigen::VectorXd& gradient, const Evaluation* known = nullptr) {
  const int p = problem.shared_count;
  const int m = problem.local_count;
  const int size = p + m * problem.block_count;
  normal.setZero(size, size);
  gradient.setZero(size);
  double cost = 0.0;
  const std::vector<BlockNormal> blocks = block_normals(problem, x.shared, x.local, known);
  for (int b = 0; b < problem.block_count; ++b) {
    const BlockNormal& block = blocks[static_cast<std::size_t>(b)];
    cost += block.cost;
    const Eigen::MatrixXd& jtj = block.jtj;
    const Eigen::VectorXd& jtr = block.jtr;
    const int offset = p + m * b;
    normal.topLeftCorner(p, p) += jtj.topLeftCorner(p, p);
    normal.block(0, offset, p, m) += jtj.topRightCorner(p, m);
    normal.block(offset, 0, m, p) += jtj.bottomLeftCorner(m, p);
    normal.block(offset, offset, m, m) += jtj.bottomRightCorner(m, m);
    gradient.head(p) += jtr.head(p);
    gradient.segment(offset, m) += jtr.tail(m);
  }
  return cost;
}

Point moved(const ArrowProblem& problem, const Point& x, const Eigen::VectorXd& delta) {
  Point y = x;
  const int p = problem.shared_count;
  const int m = problem.local_count;
  y.shared += delta.head(p);
  for (int b = 0; b < problem.block_count; ++b) {
    y.local[static_cast<std::size_t>(b)] += delta.segment(p + m * b, m);
  }
  return y;
}

}  // namespace

LeastSquaresResult minimise(const ArrowProblem& problem, const Eigen::VectorXd& shared_start,
                            const std::vector<Eigen::VectorXd>& local_start,
                            const LeastSquaresOptions& options) {
  Point x{shared_start, local_start};
  Eigen::MatrixXd normal;
  Eigen::VectorXd gradient;
  double cost = linearise(problem, x, normal, gradient);
  // Damping relative to each parameter's own curvature (Marquardt), so lambda is unitless.
  double lambda = 1e-3;
  double growth = 2.0;
  int small_gains = 0;
  int iteration = 0;
  for (; iteration < options.max_iterations && std::isfinite(cost); ++iteration) {
    // Marquardt's scaling by diag(J^T J), with a floor so that a parameter the data does
    // not inform (zero column) stays put instead of making the system singular.
    const double floor = 1e-9 * std::max(normal.diagonal().maxCoeff(), 1e-12);
    Eigen::MatrixXd damped = normal;
    damped.diagonal() += lambda * (normal.diagonal().array() + floor).matrix();
    const Eigen::VectorXd delta = damped.ldlt().solve(-gradient);
    if (!delta.allFinite()) break;
    const Point candidate = moved(problem, x, delta);
    const Evaluation evaluation = evaluate(problem, candidate);
    const double new_cost = evaluation.cost;
    // Gain predicted by the linear model: -(2 g.d + d.H.d) for cost = |r|^2.
    const double predicted = -(2.0 * gradient.dot(delta) + delta.dot(normal * delta));
    const double rho = predicted > 0.0 ? (cost - new_cost) / predicted : -1.0;
    if (std::isfinite(new_cost) && new_cost < cost) {
      const double gain = (cost - new_cost) / std::max(cost, 1e-300);
      x = candidate;
      lambda *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * std::min(rho, 1.0) - 1.0, 3));
      growth = 2.0;
      // Converged when accepted steps stop paying, with the damping low enough that the
      // step was close to Gauss-Newton's (a heavily damped step may gain little only
      // because it is short).
      small_gains = gain < options.relative_tolerance ? small_gains + 1 : 0;
      const bool converged = small_gains >= 2 && lambda < 1e-2;
      if ((converged || iteration + 1 >= options.max_iterations) && !options.normal_at_solution) {
        cost = evaluation.cost;  // the last step: nothing needs the Jacobian here
      } else {
        cost = linearise(problem, x, normal, gradient, &evaluation);
      }
      if (converged) {
        ++iteration;
        break;
      }
    } else {
      lambda *= growth;
      growth *= 2.0;
      if (lambda > 1e16) break;
    }
  }
  LeastSquaresResult result;
  result.shared = x.shared;
  result.local = x.local;
  result.cost = cost;
  result.iterations = iteration;
  result.normal_matrix = normal;
  return result;
}

double cost_at(const ArrowProblem& problem, const Eigen::VectorXd& shared,
               const std::vector<Eigen::VectorXd>& local) {
  return evaluate(problem, Point{shared, local}).cost;
}

std::vector<Eigen::VectorXd> leave_one_block_out(const ArrowProblem& problem, const Eigen::VectorXd& shared,
                                                 const std::vector<Eigen::VectorXd>& local) {
  const int p = problem.shared_count;
  const int m = problem.local_count;
  const std::size_t blocks = static_cast<std::size_t>(problem.block_count);
  std::vector<Eigen::MatrixXd> schur(blocks);
  std::vector<Eigen::VectorXd> rhs(blocks);
  Eigen::MatrixXd schur_total = Eigen::MatrixXd::Zero(p, p);
  Eigen::VectorXd rhs_total = Eigen::VectorXd::Zero(p);
  const std::vector<BlockNormal> normals = block_normals(problem, shared, local);
  for (std::size_t b = 0; b < blocks; ++b) {
    const Eigen::MatrixXd& jtj = normals[b].jtj;
    const Eigen::VectorXd& jtr = normals[b].jtr;
    Eigen::MatrixXd hll = jtj.bottomRightCorner(m, m);
    hll.diagonal().array() += 1e-9 * std::max(hll.diagonal().maxCoeff(), 1e-12);
    const Eigen::LDLT<Eigen::MatrixXd> local_solve(hll);
    const Eigen::MatrixXd hls = jtj.bottomLeftCorner(m, p);
    schur[b] = jtj.topLeftCorner(p, p) - hls.transpose() * local_solve.solve(hls);
    rhs[b] = jtr.head(p) - hls.transpose() * local_solve.solve(jtr.tail(m));
    schur_total += schur[b];
    rhs_total += rhs[b];
  }
  std::vector<Eigen::VectorXd> out(blocks);
  for (std::size_t j = 0; j < blocks; ++j) {
    Eigen::MatrixXd s = schur_total - schur[j];
    s.diagonal().array() += 1e-9 * std::max(s.diagonal().maxCoeff(), 1e-12);
    const Eigen::VectorXd step = s.ldlt().solve(-(rhs_total - rhs[j]));
    out[j] = step.allFinite() ? Eigen::VectorXd(shared + step) : shared;
  }
  return out;
}

}  // namespace aloft::host::diagnose
