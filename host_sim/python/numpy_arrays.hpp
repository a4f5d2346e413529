// Vectors handed to NumPy without a copy: the array views the vector's memory, which a
// capsule owns and frees with the array. Every array is float64 and C-contiguous.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace aloft::host::python {

// Rows of Eigen::Vector3d lie in memory as an N x 3 array of doubles, with no padding.
static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double), "Vector3d rows are not packed");

template <typename Element>
pybind11::array_t<double> numpy_owning(std::vector<Element>&& values, std::vector<pybind11::ssize_t> shape) {
  if (values.empty()) return pybind11::array_t<double>(shape);
  auto* owner = new std::vector<Element>(std::move(values));
  const pybind11::capsule free_when_done(owner,
                                         [](void* p) { delete static_cast<std::vector<Element>*>(p); });
  return pybind11::array_t<double>(shape, reinterpret_cast<const double*>(owner->data()), free_when_done);
}

// N doubles as an array of shape (N).
inline pybind11::array_t<double> numpy_vector(std::vector<double>&& values) {
  const auto n = static_cast<pybind11::ssize_t>(values.size());
  return numpy_owning(std::move(values), {n});
}

// N rows as an array of shape (N, 3).
inline pybind11::array_t<double> numpy_rows(std::vector<Eigen::Vector3d>&& rows) {
  const auto n = static_cast<pybind11::ssize_t>(rows.size());
  return numpy_owning(std::move(rows), {n, 3});
}

// An argument as a float64 C-contiguous array: the caller's own memory where it is one
// already (no copy), else converted once.
using InputArray = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

}  // namespace aloft::host::python
