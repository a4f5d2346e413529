// The shape of the built-in study's result (issues 4 and 9), in body axes: CP far above
// GF, medians growing with the bound, axes-only near GF, as in the paper. Unlike the
// paper, whose "both ±10" median sits 2.0 deg above its "moments ±10 %" one, aloft's
// "both" is only a few hundredths above "moments" (docs/study.md): asserted as such.
#include <catch2/catch.hpp>

#include "study/built_in_study.hpp"
#include "study/paper_cylinder.hpp"
#include "study/percentiles.hpp"
#include "study/study_analyses.hpp"

using namespace aloft::host;

namespace {

double median_of(const Analysis& a) { return summarise(a.values(DaFrame::body)).median; }

const Analysis& find(const std::vector<Analysis>& analyses, PerturbationFamily family, double bound) {
  for (const Analysis& a : analyses) {
    if (a.monte_carlo && a.perturbation.family == family && a.perturbation.bound == bound) return a;
  }
  throw std::logic_error("no such analysis");
}

}  // namespace

TEST_CASE("the built-in study: CP far above GF, medians grow with the bound, both just above moments") {
  // Exactly the default study (seed 1, 5,000 simulations per analysis): about 6 s of
  // CPU. Fewer simulations do not resolve "both" against "moments" (see below).
  const std::uint64_t seed = 1;
  const BuiltInTrial trial = make_built_in_trial();
  aloft::InertiaTensor<double> cp;
  REQUIRE(aloft::InertiaTensor<double>::make_from_principal(
              Eigen::Vector3d(paper::kCompoundPendulumKgM2[0], paper::kCompoundPendulumKgM2[1],
                              paper::kCompoundPendulumKgM2[2]),
              Eigen::Quaterniond::Identity(), cp) == aloft::Status::ok);
  std::vector<Analysis> analyses = {model_analysis("GF", trial.body.inertia), model_analysis("CP", cp)};
  for (Analysis& a : paper_monte_carlo_analyses(paper::kMonteCarloSimulations)) analyses.push_back(a);
  RunSettings settings;
  settings.seed = seed;
  settings.threads = 2;
  run_analyses(trial.flight, trial.body.inertia, analyses, settings);

  const double gf = median_of(analyses[0]);
  const double cp_median = median_of(analyses[1]);
  INFO("GF median " << gf << ", CP median " << cp_median);
  CHECK(cp_median >= 3.0 * gf);

  for (PerturbationFamily family :
       {PerturbationFamily::moments, PerturbationFamily::axes, PerturbationFamily::both}) {
    double previous = 0.0;
    for (double bound : paper::kBounds) {
      const double m = median_of(find(analyses, family, bound));
      INFO(family_name(family) << " " << bound << ": median " << m);
      CHECK(m >= previous);
      previous = m;
    }
  }
  // "both" against "moments": on this throw adding axes errors to moment errors raises
  // RMS DA only a little (paired median +0.01 to +0.04 deg at 5,000 simulations), less than
  // the sampling error of two medians of 5,000. The paired draws (common random numbers)
  // resolve it: the median of the per-simulation differences is positive at every
  // bound, and the two medians agree within their sampling error (0.05 deg).
  for (double bound : paper::kBounds) {
    const Analysis& m = find(analyses, PerturbationFamily::moments, bound);
    const Analysis& b = find(analyses, PerturbationFamily::both, bound);
    std::vector<double> paired;
    for (std::size_t i = 0; i < m.values(DaFrame::body).size(); ++i) {
      paired.push_back(b.values(DaFrame::body)[i] - m.values(DaFrame::body)[i]);
    }
    const double moments = median_of(m);
    const double both = median_of(b);
    const double axes = median_of(find(analyses, PerturbationFamily::axes, bound));
    INFO("bound " << bound << ": moments " << moments << ", both " << both << ", axes " << axes);
    CHECK(summarise(paired).median > 0.0);
    CHECK(both >= moments - 0.05);
    CHECK(both <= moments + 0.5);  // not the paper's +2 deg
    CHECK(std::abs(axes - gf) <= 1.0);
  }
}
