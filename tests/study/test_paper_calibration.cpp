// The calibration search (`aloft study --calibrate-to-paper`) on a two-point grid: what
// it reports is what its throw gives, and it moves towards the paper's GF and CP rows.
#include <catch2/catch.hpp>

#include <cmath>

#include "study/built_in_study.hpp"
#include "study/paper_calibration.hpp"
#include "study/paper_cylinder.hpp"
#include "study/study_analyses.hpp"

using namespace aloft::host;

namespace {

// RMS of the six differences from the paper's GF and CP rows, every sample as seed,
// computed here from the study's public pieces.
double gf_cp_rms_difference(const SyntheticThrowSettings& settings, DaFrame frame) {
  const BuiltInTrial trial = make_built_in_trial(settings);
  std::vector<Analysis> analyses = {model_analysis("GF", trial.body.inertia),
                                    model_analysis("CP", compound_pendulum_inertia())};
  RunSettings run;
  run.threads = 2;
  run_analyses(trial.flight, trial.body.inertia, analyses, run);
  double sum = 0.0;
  const paper::PublishedRow* rows[] = {&paper::kGeometricFormulae, &paper::kCompoundPendulum};
  for (int m = 0; m < 2; ++m) {
    const DistributionSummary s = summarise(analyses[static_cast<std::size_t>(m)].values(frame));
    sum += std::pow(s.p10 - rows[m]->p10, 2) + std::pow(s.median - rows[m]->median, 2) +
           std::pow(s.p90 - rows[m]->p90, 2);
  }
  return std::sqrt(sum / 6.0);
}

}  // namespace

TEST_CASE("the calibration reports what its throw gives, and GF/CP come closer to the paper") {
  CalibrationSettings settings;
  settings.mc_samples = 20;
  settings.threads = 2;
  settings.grid = {{1.5, 50.0, 30.0, 0.1}, {1.0, 85.0, 30.0, 0.06}};
  settings.refine_starts = 1;
  settings.refine_budget = 4;
  std::size_t reports = 0;
  settings.progress = [&](const std::string&, std::size_t, std::size_t) { ++reports; };
  const CalibrationResult result = calibrate_to_paper(settings, {DaFrame::body});

  CHECK(reports > 0);
  REQUIRE(result.frames.size() == 1);
  const FrameCalibration& f = result.frames[0];
  CHECK(f.frame == DaFrame::body);
  REQUIRE(f.rows.size() == 5);
  CHECK(f.rows[0].name == "GF");
  CHECK(f.rows[1].name == "CP");
  CHECK(f.rows[0].used_in_search);
  CHECK(f.rows[1].used_in_search);
  for (std::size_t i = 2; i < 5; ++i) CHECK_FALSE(f.rows[i].used_in_search);  // predictions

  const SyntheticThrowSettings found = with_parameters(settings.base, f.throw_found);
  CHECK(f.search_rms_diff_deg == Approx(gf_cp_rms_difference(found, DaFrame::body)).epsilon(1e-12));
  // The built-in throw (the first grid point) is far from the paper's CP row; the
  // search must have done better.
  CHECK(f.search_rms_diff_deg < gf_cp_rms_difference(SyntheticThrowSettings{}, DaFrame::body) - 0.5);
}
