// The text outputs of `aloft study` (SPEC §5), built in memory so that nothing is
// written until everything has been computed:
//  - results.json: "models" (GF and CP for the built-in study; "nominal" for a recording)
//    with principal_kg_m2, simulations and rms_da_deg {p10, median, p90}, "monte_carlo"
//    (family, bound, unit, simulations, rms_da_deg), "wall_time_s"; beside them the
//    trial, the seed, quartiles, the paper's numbers and, for recordings, "flights".
//    "models" and "monte_carlo" hold the frame named by "frame" (body axes unless only
//    --frame world was asked); "frames" holds both keys for every frame reported;
//  - rms_da.csv: analysis,index,rms_da_deg,frame, one row per simulation and frame;
//  - experiment.csv: the trial the study used: pose flights t,qw,qx,qy,qz,wx,wy,wz
//    (omega in body axes); rate flights flight,t,wx,wy,wz;
//  - the side-by-side table printed on stdout.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "study/paper_cylinder.hpp"
#include "study/study_result.hpp"

namespace aloft::host {

nlohmann::json results_json(const StudyResult& result);
std::string rms_da_csv(const StudyResult& result);
std::string experiment_csv(const StudyResult& result);
std::string comparison_table(const StudyResult& result);

// The analysis key used in rms_da.csv: "GF", "CP", "nominal", "moments_2.5", ...
std::string analysis_key(const Analysis& analysis);

// The paper's published row for an analysis (GF, CP, the three ±10 analyses), or null.
const paper::PublishedRow* published_row(const Analysis& analysis);

// Principal moments in the order of the body axes they lie along (the paper's IX, IY,
// IZ), or ascending when the principal axes are not near body axes.
Eigen::Vector3d principal_moments_by_body_axis(const InertiaTensor<double>& inertia);

}  // namespace aloft::host
