// diagnose/held_out: how a flight's samples are split between fitting and judging.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstddef>

#include "diagnose/3_fit/held_out.hpp"

using namespace aloft::host::diagnose;

namespace {

std::size_t count(const SampleMask& m) { return static_cast<std::size_t>(std::count(m.begin(), m.end(), 1)); }

// Lengths of the runs of equal values in a mask.
std::vector<std::size_t> run_lengths(const SampleMask& m) {
  std::vector<std::size_t> runs;
  for (std::size_t k = 0; k < m.size(); ++k) {
    if (k == 0 || m[k] != m[k - 1]) runs.push_back(0);
    ++runs.back();
  }
  return runs;
}

}  // namespace

TEST_CASE("interleaved_folds: every sample judged exactly once, never by a fold that saw it", "[held_out]") {
  for (std::size_t n : {20u, 99u, 1000u, 1234u}) {
    CAPTURE(n);
    const Folds folds = interleaved_folds(n);
    for (int f = 0; f < 2; ++f) {
      REQUIRE(folds.train[f].size() == n);
      REQUIRE(folds.judge[f].size() == n);
    }
    for (std::size_t k = 0; k < n; ++k) {
      CHECK(folds.train[0][k] != folds.judge[0][k]);  // a fold judges what it did not fit
      CHECK(folds.train[1][k] != folds.judge[1][k]);
      CHECK(folds.judge[0][k] + folds.judge[1][k] == 1);  // judged once over both folds
    }
    // Interleaved chunks of at least 5 samples and about 1/20 of the flight, both folds
    // fitting on about half of it.
    const std::vector<std::size_t> runs = run_lengths(folds.train[0]);
    CHECK(runs.size() >= 2);
    for (std::size_t i = 0; i + 1 < runs.size(); ++i) {
      CHECK(runs[i] >= 5);
      CHECK(runs[i] == std::max<std::size_t>(5, n / 20));
    }
    CHECK(count(folds.train[0]) == Approx(n / 2.0).epsilon(0.15));
  }
}

TEST_CASE("all_samples and leading_samples", "[held_out]") {
  CHECK(count(all_samples(37)) == 37);
  const SampleMask lead = leading_samples(200, 0.25, 10);
  CHECK(count(lead) == 50);
  CHECK(std::all_of(lead.begin(), lead.begin() + 50, [](char c) { return c == 1; }));
  CHECK(count(leading_samples(200, 0.01, 30)) == 30);  // the minimum wins
  CHECK(count(leading_samples(20, 0.5, 30)) == 20);    // never more than the flight
}
