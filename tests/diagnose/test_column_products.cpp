// diagnose/column_products: J^T J bit for bit as Eigen's dot product of each pair of
// columns, over every row count up to past two packets and a flight's, and any width.
#include <catch2/catch.hpp>

#include <cstring>
#include <random>

#include "diagnose/3_fit/column_products.hpp"

using namespace aloft::host::diagnose;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("column_products sums each entry as Eigen's dot of the two columns", "[column_products]") {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> scale(-12.0, 12.0);
  int compared = 0;
  for (Eigen::Index rows : {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 17, 3000, 3001, 3002, 3003}) {
    for (Eigen::Index cols = 1; cols <= 13; ++cols) {
      Eigen::MatrixXd jac(rows, cols);
      // Magnitudes over many decades, so that a different order of the sums shows.
      for (Eigen::Index c = 0; c < cols; ++c) {
        for (Eigen::Index r = 0; r < rows; ++r) jac(r, c) = normal(rng) * std::exp2(scale(rng));
      }
      const Eigen::MatrixXd products = column_products(jac);
      REQUIRE(products.rows() == cols);
      REQUIRE(products.cols() == cols);
      for (Eigen::Index i = 0; i < cols; ++i) {
        for (Eigen::Index j = 0; j < cols; ++j) {
          const double expected = jac.col(std::max(i, j)).dot(jac.col(std::min(i, j)));
          INFO("rows " << rows << " cols " << cols << " entry " << i << "," << j);
          REQUIRE(same_bits(products(i, j), expected));
          ++compared;
        }
      }
    }
  }
  CHECK(compared > 10000);
}

TEST_CASE("column_products differs from a plain row-by-row sum on such data", "[column_products]") {
  // The test above could not fail if any order gave the same bits: show one that does not.
  std::mt19937 rng(11);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::MatrixXd jac(3001, 2);
  for (Eigen::Index r = 0; r < jac.rows(); ++r) jac.row(r) << normal(rng) * 1e6, normal(rng) * 1e-6;
  const Eigen::MatrixXd products = column_products(jac);
  double sequential = 0.0;
  for (Eigen::Index r = 0; r < jac.rows(); ++r) sequential += jac(r, 0) * jac(r, 1);
  CHECK_FALSE(same_bits(products(1, 0), sequential));
}
