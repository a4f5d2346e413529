#include "diagnose/3_fit/column_products.hpp"

namespace aloft::host::diagnose {

// One dot product of two columns per entry of the lower half, mirrored: half the work of
// the general product (and none of its packing, which for a dozen columns by thousands of
// rows cost more than the multiplying). Only Eigen's public API: a tiling that loaded
// each column's packet once for two products had to write Eigen's packet sums out itself
// through Eigen::internal (its packet type, loads and reductions, and the order Redux.h
// sums them in), for 3.3 M of case00's 424.6 M instructions then.
Eigen::MatrixXd column_products(const Eigen::MatrixXd& jac) {
  const Eigen::Index k = jac.cols();
  Eigen::MatrixXd out(k, k);
  for (Eigen::Index i = 0; i < k; ++i) {
    for (Eigen::Index j = 0; j <= i; ++j) out(i, j) = out(j, i) = jac.col(i).dot(jac.col(j));
  }
  return out;
}

}  // namespace aloft::host::diagnose
