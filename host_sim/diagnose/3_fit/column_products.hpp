// J^T J of a tall, narrow Jacobian (thousands of rows by at most a dozen columns), each
// entry Eigen's dot product of the two columns.
#pragma once

#include <Eigen/Core>

namespace aloft::host::diagnose {

// jac^T jac; entry (i, j) is bit for bit jac.col(i).dot(jac.col(j)).
Eigen::MatrixXd column_products(const Eigen::MatrixXd& jac);

}  // namespace aloft::host::diagnose
