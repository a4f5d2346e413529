#include "diagnose/3_fit/column_products.hpp"

#include <algorithm>

namespace aloft::host::diagnose {

namespace {

using Packet = Eigen::internal::packet_traits<double>::type;
constexpr Eigen::Index kLanes = Eigen::internal::packet_traits<double>::size;

Packet product(const double* x, const double* y, Eigen::Index row) {
  return Eigen::internal::pmul(Eigen::internal::ploadu<Packet>(x + row),
                               Eigen::internal::ploadu<Packet>(y + row));
}

// The four dot products x[a] . y[b] (a, b in {0, 1}) of columns of n rows, each summed
// as Eigen 3.4's dot sums it (Redux.h, a linear vectorised traversal with no unrolling,
// which a column of a MatrixXd takes): two packet sums over blocks of two packets, the
// first packets their start, merged; one packet more when left; the packet's lanes
// added; then the rows that fill no packet, in order. Done four at a time, each column's
// packet is loaded once for two products instead of once for each (Eigen's dot, one pair
// at a time, loaded both columns for every entry of J^T J).
void dot_tile(const double* const x[2], const double* const y[2], Eigen::Index n, double out[2][2]) {
  using Eigen::internal::padd;
  if (n < kLanes) {
    for (int a = 0; a < 2; ++a) {
      for (int b = 0; b < 2; ++b) {
        double sum = n > 0 ? x[a][0] * y[b][0] : 0.0;
        for (Eigen::Index row = 1; row < n; ++row) sum += x[a][row] * y[b][row];
        out[a][b] = sum;
      }
    }
    return;
  }
  const Eigen::Index end_pairs = n / (2 * kLanes) * (2 * kLanes), end = n / kLanes * kLanes;
  Packet first[2][2], second[2][2];
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) first[a][b] = product(x[a], y[b], 0);
  }
  if (end > kLanes) {
    for (int a = 0; a < 2; ++a) {
      for (int b = 0; b < 2; ++b) second[a][b] = product(x[a], y[b], kLanes);
    }
    for (Eigen::Index row = 2 * kLanes; row < end_pairs; row += 2 * kLanes) {
      for (int a = 0; a < 2; ++a) {
        for (int b = 0; b < 2; ++b) {
          first[a][b] = padd(first[a][b], product(x[a], y[b], row));
          second[a][b] = padd(second[a][b], product(x[a], y[b], row + kLanes));
        }
      }
    }
    for (int a = 0; a < 2; ++a) {
      for (int b = 0; b < 2; ++b) {
        first[a][b] = padd(first[a][b], second[a][b]);
        if (end > end_pairs) first[a][b] = padd(first[a][b], product(x[a], y[b], end_pairs));
      }
    }
  }
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) {
      double sum = Eigen::internal::predux(first[a][b]);
      for (Eigen::Index row = end; row < n; ++row) sum += x[a][row] * y[b][row];
      out[a][b] = sum;
    }
  }
}

}  // namespace

// Columns in pairs: tile (I, J) gives the entries of columns 2I, 2I + 1 against 2J,
// 2J + 1 for J <= I; an odd last column pairs with itself (its products made twice).
Eigen::MatrixXd column_products(const Eigen::MatrixXd& jac) {
  const Eigen::Index k = jac.cols(), n = jac.rows();
  Eigen::MatrixXd out(k, k);
  const auto column = [&](Eigen::Index c) { return jac.data() + std::min(c, k - 1) * n; };
  for (Eigen::Index i = 0; i < k; i += 2) {
    for (Eigen::Index j = 0; j <= i; j += 2) {
      const double* const x[2] = {column(i), column(i + 1)};
      const double* const y[2] = {column(j), column(j + 1)};
      double tile[2][2];
      dot_tile(x, y, n, tile);
      for (Eigen::Index a = 0; a < 2 && i + a < k; ++a) {
        for (Eigen::Index b = 0; b < 2 && j + b < k; ++b) out(i + a, j + b) = out(j + b, i + a) = tile[a][b];
      }
    }
  }
  return out;
}

}  // namespace aloft::host::diagnose
