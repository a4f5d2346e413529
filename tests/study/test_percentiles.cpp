#include <catch2/catch.hpp>

#include "study/percentiles.hpp"

using namespace aloft::host;

TEST_CASE("percentiles interpolate linearly between order statistics (type 7)") {
  // 1..11: rank p*(n-1) lands on whole numbers for p = 0.1, 0.5, 0.9.
  std::vector<double> v;
  for (int i = 11; i >= 1; --i) v.push_back(i);
  const DistributionSummary s = summarise(v);
  CHECK(s.p10 == Approx(2.0));
  CHECK(s.median == Approx(6.0));
  CHECK(s.p90 == Approx(10.0));
  CHECK(s.p25 == Approx(3.5));
  CHECK(s.min == 1.0);
  CHECK(s.max == 11.0);
  CHECK(s.mean == Approx(6.0));
  // Between order statistics: {0, 10}: p10 = 1, median = 5.
  const DistributionSummary two = summarise({10.0, 0.0});
  CHECK(two.p10 == Approx(1.0));
  CHECK(two.median == Approx(5.0));
  CHECK_THROWS(summarise({}));
}
