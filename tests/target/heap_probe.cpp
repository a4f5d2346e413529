// A function written the way lib/ code is (a template in namespace aloft, compiled with
// the strict firmware flags), into which heap use is deliberately added, one way per
// ALOFT_HEAP_PROBE value. The tests build each variant and expect the link to fail with
// the cortex_m port's trap symbol (port/cortex_m/no_heap.cpp); variant 0 allocates nothing
// and must link, so a failure is the heap's doing and not a broken probe.
//   0 none   1 malloc   2 operator new   3 a dynamic-size Eigen matrix   4 std::vector
#include <cstdlib>
#include <new>
#include <vector>

#include "aloft/aloft.hpp"

#ifndef ALOFT_HEAP_PROBE
#error "define ALOFT_HEAP_PROBE"
#endif

namespace aloft {

// Sums the rates of n samples through a scratch buffer.
template <typename Scalar>
Scalar sum_of_rates(const Vec3<Scalar>* samples, int n) {
  Scalar total = Scalar(0);
#if ALOFT_HEAP_PROBE == 0
  for (int i = 0; i < n; ++i) total += samples[i].norm();
#elif ALOFT_HEAP_PROBE == 1
  Scalar* scratch = static_cast<Scalar*>(std::malloc(sizeof(Scalar) * static_cast<unsigned>(n)));
  for (int i = 0; i < n; ++i) scratch[i] = samples[i].norm();
  for (int i = 0; i < n; ++i) total += scratch[i];
  std::free(scratch);
#elif ALOFT_HEAP_PROBE == 2
  Scalar* scratch = new Scalar[static_cast<unsigned>(n)];
  for (int i = 0; i < n; ++i) scratch[i] = samples[i].norm();
  for (int i = 0; i < n; ++i) total += scratch[i];
  delete[] scratch;
#elif ALOFT_HEAP_PROBE == 3
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> scratch(n);
  for (int i = 0; i < n; ++i) scratch(i) = samples[i].norm();
  total = scratch.sum();
#elif ALOFT_HEAP_PROBE == 4
  std::vector<Scalar> scratch;
  for (int i = 0; i < n; ++i) scratch.push_back(samples[i].norm());
  for (Scalar s : scratch) total += s;
#endif
  return total;
}

}  // namespace aloft

// The count comes from a volatile, so the compiler cannot prove the allocation away.
volatile int sample_count = 2;
volatile float result;

int main() {
  const aloft::Vec3<float> samples[2] = {aloft::Vec3<float>(1.0f, 0.0f, 0.0f),
                                         aloft::Vec3<float>(0.0f, 2.0f, 0.0f)};
  result = aloft::sum_of_rates(samples, sample_count);
  return 0;
}
