// The diagnosis of the sim-to-real gap (SPEC §4): where the measured motion leaves the
// nominal torque-free model, which candidate effect explains the gap on data the fit did
// not see, and how far the gap shrinks with it.
// The judged analysis each holds is 4_judge/analysis.hpp; both are made by one candidate
// loop (judge_candidates.hpp), a flight's held out within it, a session's by leaving one
// flight out.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "common/parallel_for.hpp"
#include "diagnose/1_input/flight.hpp"
#include "diagnose/1_input/time_gaps.hpp"
#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/4_judge/analysis.hpp"
#include "diagnose/4_judge/confidence.hpp"
#include "diagnose/4_judge/flip_period.hpp"
#include "diagnose/4_judge/flip_period_summary.hpp"
#include "diagnose/4_judge/noise_floor.hpp"

namespace aloft::host::diagnose {

struct FlightDiagnosis {
  std::string name;
  std::string comment;
  double start_s = 0.0, end_s = 0.0;
  std::size_t samples = 0;
  double rate_hz = 0.0;
  NoiseFloor noise;
  std::vector<TimeGap> gaps;
  std::size_t unusable_samples = 0;
  Analysis analysis;
  const Flight* flight = nullptr;  // the data it was made from (plots)
  // Session only: the flip period measured and predicted (flip_period.hpp), nominal and
  // with the pooled final model fitted without this flight.
  std::optional<FlipPeriod> flip_period;
};

struct SessionDiagnosis {
  Analysis pooled;
  bool single_flight = false;  // one judged flight: `pooled` is that flight's own analysis
  std::vector<FlightDiagnosis> flights;
  std::optional<FlipPeriodSummary> flip_period;
};

// One flight. Never throws for data it cannot judge: the verdict says so instead. Sets the
// flight's gyro_filter_bend_s2 from its noise floor, so that every later prediction of it (a
// session's pooled fits, the plots) reads the motion through the same filter; the result
// points at the flight (plots), which must outlive it.
FlightDiagnosis diagnose_flight(Flight& flight, const NominalInertia& nominal);

// A session: every flight on its own, and the pooled analysis with effects shared by all
// flights, judged by leaving one flight out. `threads` >= 1. `flights_done`, when set, is
// told about every 100 ms how many flights have been diagnosed on their own. Each flight's
// gyro_filter_bend_s2 is set as diagnose_flight sets it.
SessionDiagnosis diagnose_session(std::vector<Flight>& flights, const NominalInertia& nominal,
                                  int threads = 2, const ParallelProgress& flights_done = {});

}  // namespace aloft::host::diagnose
