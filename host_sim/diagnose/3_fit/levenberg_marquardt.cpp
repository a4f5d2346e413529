#include "diagnose/3_fit/levenberg_marquardt.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <utility>

#include "common/parallel_for.hpp"
#include "diagnose/3_fit/column_products.hpp"

namespace aloft::host::diagnose {

double forward_difference_step(double value) { return 1e-7 * std::max(1.0, std::abs(value)); }

void block_jacobian(const ArrowProblem& problem, int block, const Eigen::VectorXd& shared,
                    const Eigen::VectorXd& local, const Eigen::VectorXd* known, Eigen::VectorXd& residuals,
                    Eigen::MatrixXd& jacobian) {
  if (problem.jacobian) {
    if (known != nullptr) {
      residuals = *known;
    } else {
      residuals.resize(0);
    }
    if (problem.jacobian(block, shared, local, residuals, jacobian)) return;
  }
  if (known != nullptr) {
    residuals = *known;
  } else {
    problem.residuals(block, shared, local, residuals);
  }
  const int p = problem.shared_count;
  const int m = problem.local_count;
  jacobian.resize(residuals.size(), p + m);
  Eigen::VectorXd moved;
  for (int i = 0; i < p; ++i) {
    Eigen::VectorXd s = shared;
    const double h = forward_difference_step(s(i));
    s(i) += h;
    problem.residuals(block, s, local, moved);
    jacobian.col(i) = (moved - residuals) / h;
  }
  for (int i = 0; i < m; ++i) {
    Eigen::VectorXd l = local;
    const double h = forward_difference_step(l(i));
    l(i) += h;
    problem.residuals(block, shared, l, moved);
    jacobian.col(p + i) = (moved - residuals) / h;
  }
}

namespace {

// gauss_newton_step's first try leaves out the directions whose curvature (each parameter
// in its own scale) is below this share of the largest: a plain Gauss-Newton step moved
// inertia_axes of imu_aero_torque_2 along such a direction by 0.29 on one CPU and 4.1 on
// another (the Jacobian's differences differ in their last bits), a score 218 apart.
// Marquardt's damping of 1e-4 still left them 2 apart, 1e-3 0.3 (the tolerance is 1).
constexpr double kFlatDirection = 1e-3;
// Its later tries, where that step does not pay: Marquardt's damping, relative to each
// parameter's own curvature, more each time.
constexpr double kStepDamping[] = {1e-3, 1e-2, 1e-1, 1.0, 10.0, 100.0};
// A step of gauss_newton_step pays when it lowers the cost by more than this share of it.
// The last bits of libm move a flight's costs by about 1e-11 of themselves (the held-out
// errors of diagnose_same_verdict_every_cpu's CPUs); a step that gains less than that was
// taken on one CPU and refused on another (imu_aero_torque_2's inertia_axes, a score 218
// apart), so a gain must clear it by a wide margin. minimise stops where no step is
// predicted to gain this much.
constexpr double kStepGain = 1e-9;

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
  Eigen::VectorXd residuals;  // what they were made of
  Eigen::MatrixXd jacobian;
};

BlockNormal block_normal(const ArrowProblem& problem, int block, const Eigen::VectorXd& shared,
                         const Eigen::VectorXd& local, const Eigen::VectorXd* known) {
  BlockNormal out;
  block_jacobian(problem, block, shared, local, known, out.residuals, out.jacobian);
  out.jtj = column_products(out.jacobian);
  out.jtr = out.jacobian.transpose() * out.residuals;
  out.cost = out.residuals.squaredNorm();
  return out;
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

// Each block's residuals and Jacobian, as the last linearise() made them.
struct BlockJacobians {
  std::vector<Eigen::VectorXd> residuals;
  std::vector<Eigen::MatrixXd> jacobians;
};

// J^T J and J^T r of the whole problem at x, assembled block by block. `known`: the
// residuals at x, when evaluated already; `kept` (optional): where the blocks' residuals
// and Jacobians go.
double linearise(const ArrowProblem& problem, const Point& x, Eigen::MatrixXd& normal,
                 Eigen::VectorXd& gradient, const Evaluation* known = nullptr,
                 BlockJacobians* kept = nullptr) {
  const int p = problem.shared_count;
  const int m = problem.local_count;
  const int size = p + m * problem.block_count;
  normal.setZero(size, size);
  gradient.setZero(size);
  double cost = 0.0;
  std::vector<BlockNormal> blocks = block_normals(problem, x.shared, x.local, known);
  if (kept != nullptr) {
    kept->residuals.resize(blocks.size());
    kept->jacobians.resize(blocks.size());
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      kept->residuals[b] = std::move(blocks[b].residuals);
      kept->jacobians[b] = std::move(blocks[b].jacobian);
    }
  }
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

// The gain the linear model at x predicts for a step damped only as lightly as
// minimise's first (kLightDamping): about the most any step from x can gain, whatever
// damping the rejected steps before have piled up. `predicted`: the gain of the step at
// `lambda`, which is that step when lambda is that light already.
constexpr double kLightDamping = 1e-3;

// Marquardt's step at damping lambda: each parameter's curvature scaled by 1 + lambda,
// with `floor` so that a parameter the data does not inform (zero column) stays put
// instead of making the system singular.
Eigen::VectorXd damped_step(const Eigen::MatrixXd& normal, const Eigen::VectorXd& gradient, double floor,
                            double lambda) {
  Eigen::MatrixXd damped = normal;
  damped.diagonal() += lambda * (normal.diagonal().array() + floor).matrix();
  return damped.ldlt().solve(-gradient);
}

// Gain predicted by the linear model for the step `delta`: -(2 g.d + d.H.d) for cost = |r|^2.
double predicted_gain(const Eigen::MatrixXd& normal, const Eigen::VectorXd& gradient,
                      const Eigen::VectorXd& delta) {
  return -(2.0 * gradient.dot(delta) + delta.dot(normal * delta));
}

double lightly_damped_gain(const Eigen::MatrixXd& normal, const Eigen::VectorXd& gradient, double floor,
                           double lambda, double predicted) {
  if (lambda <= kLightDamping) return predicted;
  const Eigen::VectorXd light = damped_step(normal, gradient, floor, kLightDamping);
  if (!light.allFinite()) return predicted;
  return predicted_gain(normal, gradient, light);
}

}  // namespace

LeastSquaresResult minimise(const ArrowProblem& problem, const Eigen::VectorXd& shared_start,
                            const std::vector<Eigen::VectorXd>& local_start,
                            const LeastSquaresOptions& options) {
  Point x{shared_start, local_start};
  Eigen::MatrixXd normal;
  Eigen::VectorXd gradient;
  // x is linearised whenever it moves (normal_at_solution), so the last kept is x's.
  BlockJacobians at_x;
  BlockJacobians* const kept = options.keep_jacobian && options.normal_at_solution ? &at_x : nullptr;
  double cost = linearise(problem, x, normal, gradient, nullptr, kept);
  // Damping relative to each parameter's own curvature (Marquardt), so lambda is unitless.
  double lambda = kLightDamping;
  double growth = 2.0;
  int small_gains = 0;
  int iteration = 0;
  for (; iteration < options.max_iterations && std::isfinite(cost); ++iteration) {
    const double floor = 1e-9 * std::max(normal.diagonal().maxCoeff(), 1e-12);
    const Eigen::VectorXd delta = damped_step(normal, gradient, floor, lambda);
    if (!delta.allFinite()) break;
    const double predicted = predicted_gain(normal, gradient, delta);
    // Converged, too, when no step could gain more than the last bits move the cost
    // (kStepGain), or than the caller's tolerance where it asks for less: what the dance
    // of rejected and tiny steps round the minimum cost (case00 366.9 -> 274.8 M
    // instructions, docs/validation/diagnose-speed.md).
    const double least_gain = std::min(kStepGain, options.relative_tolerance) * cost;
    if (lightly_damped_gain(normal, gradient, floor, lambda, predicted) < least_gain) break;
    const Point candidate = moved(problem, x, delta);
    const Evaluation evaluation = evaluate(problem, candidate);
    const double new_cost = evaluation.cost;
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
        cost = linearise(problem, x, normal, gradient, &evaluation, kept);
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
  result.block_residuals = std::move(at_x.residuals);
  result.block_jacobians = std::move(at_x.jacobians);
  return result;
}

// The Gauss-Newton step of the normal equations in the directions they inform: solved in
// each parameter's own scale (the normal matrix divided by its diagonal's square roots)
// over the eigen-directions whose curvature is at least kFlatDirection of the largest.
Eigen::VectorXd step_in_informed_directions(const Eigen::MatrixXd& normal, const Eigen::VectorXd& gradient) {
  const Eigen::VectorXd scale = normal.diagonal().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd scaled = scale.asDiagonal() * normal * scale.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(scaled);
  const Eigen::VectorXd& values = solver.eigenvalues();
  const Eigen::VectorXd projected = solver.eigenvectors().transpose() * scale.cwiseProduct(-gradient);
  Eigen::VectorXd step = Eigen::VectorXd::Zero(normal.rows());
  for (Eigen::Index k = 0; k < values.size(); ++k) {
    if (values(k) >= kFlatDirection * values.maxCoeff()) {
      step += solver.eigenvectors().col(k) * (projected(k) / values(k));
    }
  }
  return scale.cwiseProduct(step);
}

LeastSquaresResult gauss_newton_step(const ArrowProblem& problem, const Eigen::VectorXd& shared,
                                     const std::vector<Eigen::VectorXd>& local) {
  const Point x{shared, local};
  Eigen::MatrixXd normal;
  Eigen::VectorXd gradient;
  LeastSquaresResult result;
  result.shared = shared;
  result.local = local;
  result.cost = linearise(problem, x, normal, gradient);
  const double floor = 1e-9 * std::max(normal.diagonal().maxCoeff(), 1e-12);
  // The informed directions' step first, then ever more damped ones.
  for (std::size_t attempt = 0; attempt <= std::size(kStepDamping); ++attempt) {
    Eigen::VectorXd delta;
    if (attempt == 0) {
      delta = step_in_informed_directions(normal, gradient);
    } else {
      Eigen::MatrixXd damped = normal;
      damped.diagonal() +=
          kStepDamping[attempt - 1] * normal.diagonal() + Eigen::VectorXd::Constant(normal.rows(), floor);
      delta = damped.ldlt().solve(-gradient);
    }
    if (!delta.allFinite()) continue;
    const Point y = moved(problem, x, delta);
    const double cost = evaluate(problem, y).cost;
    if (cost < (1.0 - kStepGain) * result.cost) {
      result.shared = y.shared;
      result.local = y.local;
      result.cost = cost;
      result.iterations = 1;
      return result;
    }
  }
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
