#include "study/study_outputs.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "study/paper_cylinder.hpp"
#include "study/percentiles.hpp"

namespace aloft::host {

using nlohmann::json;

std::vector<double> pooled_rms_da(const StudyResult& result, const std::string& name, DaFrame frame) {
  std::vector<double> out;
  for (const FlightStudy& f : result.flights) {
    for (const Analysis& a : f.analyses) {
      if (a.name == name) out.insert(out.end(), a.values(frame).begin(), a.values(frame).end());
    }
  }
  return out;
}

std::string analysis_key(const Analysis& a) {
  if (!a.monte_carlo) return a.name;
  char key[64];
  std::snprintf(key, sizeof key, "%s_%g", family_name(a.perturbation.family), a.perturbation.bound);
  return key;
}

Eigen::Vector3d principal_moments_by_body_axis(const InertiaTensor<double>& inertia) {
  const Eigen::Matrix3d axes = inertia.principal_axes().toRotationMatrix();
  Eigen::Vector3d out = Eigen::Vector3d::Constant(-1.0);
  for (int i = 0; i < 3; ++i) {
    Eigen::Index body_axis = 0;
    axes.col(i).cwiseAbs().maxCoeff(&body_axis);
    if (out(body_axis) >= 0.0 || std::abs(axes(body_axis, i)) < std::cos(M_PI / 4.0)) {
      return inertia.principal_moments();  // not a one-to-one match: ascending
    }
    out(body_axis) = inertia.principal_moments()(i);
  }
  return out;
}

namespace {

json summary_json(const std::vector<double>& values) {
  const DistributionSummary s = summarise(values);
  return {{"p10", s.p10}, {"median", s.median}, {"p90", s.p90}, {"p25", s.p25},
          {"p75", s.p75}, {"min", s.min},       {"max", s.max}, {"mean", s.mean}};
}

json published_json(const paper::PublishedRow& row) {
  return {{"p10", row.p10}, {"median", row.median}, {"p90", row.p90}};
}

}  // namespace

const paper::PublishedRow* published_row(const Analysis& a) {
  if (!a.monte_carlo) {
    if (a.name == "GF") return &paper::kGeometricFormulae;
    if (a.name == "CP") return &paper::kCompoundPendulum;
    return nullptr;
  }
  if (a.perturbation.bound != 10.0) return nullptr;
  switch (a.perturbation.family) {
    case PerturbationFamily::moments: return &paper::kMoments10;
    case PerturbationFamily::axes: return &paper::kAxes10;
    case PerturbationFamily::both: return &paper::kBoth10;
  }
  return nullptr;
}

namespace {

// "models" and "monte_carlo" for a list of analyses whose rms_da_deg are `values_of(a)`.
template <typename ValuesOf>
void analyses_json(const std::vector<Analysis>& analyses, bool with_paper, ValuesOf values_of, json& out) {
  json models = json::object();
  json monte_carlo = json::array();
  for (const Analysis& a : analyses) {
    const std::vector<double> values = values_of(a);
    json entry;
    if (!a.monte_carlo) {
      const Eigen::Vector3d p = principal_moments_by_body_axis(a.inertia);
      const Eigen::Quaterniond q = a.inertia.principal_axes();
      entry["principal_kg_m2"] = {p.x(), p.y(), p.z()};
      entry["principal_axes_wxyz"] = {q.w(), q.x(), q.y(), q.z()};
    } else {
      entry["family"] = family_name(a.perturbation.family);
      entry["bound"] = a.perturbation.bound;
      entry["unit"] = family_unit(a.perturbation.family);
    }
    entry["simulations"] = values.size();
    entry["rms_da_deg"] = summary_json(values);
    if (with_paper) {
      if (const paper::PublishedRow* row = published_row(a)) {
        entry["paper_rms_da_deg"] = published_json(*row);
      }
    }
    if (a.monte_carlo) {
      monte_carlo.push_back(entry);
    } else {
      models[a.name] = entry;
    }
  }
  out["models"] = models;
  out["monte_carlo"] = monte_carlo;
}

}  // namespace

namespace {

// SPEC §5's "models" and "monte_carlo" in the first frame reported, and "frames" with
// both keys in every frame reported, for analyses whose values in a frame are
// values_of(a, frame).
template <typename ValuesOf>
void frames_json(const StudyResult& result, const std::vector<Analysis>& analyses, bool with_paper,
                 ValuesOf values_of, json& out) {
  json frames = json::object();
  for (DaFrame frame : result.frames) {
    json block;
    analyses_json(
        analyses, with_paper, [&](const Analysis& a) { return values_of(a, frame); }, block);
    frames[frame_name(frame)] = block;
  }
  out["frame"] = frame_name(result.frames.front());
  out["models"] = frames[frame_name(result.frames.front())]["models"];
  out["monte_carlo"] = frames[frame_name(result.frames.front())]["monte_carlo"];
  out["frames"] = frames;
}

json frame_definitions() {
  return {{"body", "omega in the body's own axes: the vector part of q_j^-1 q_{j+1}"},
          {"world", "omega in the fixed lab axes: the vector part of q_{j+1} q_j^-1"},
          {"top_level_keys",
           "\"models\" and \"monte_carlo\" hold the frame named by "
           "\"frame\"; \"frames\" holds every frame reported"}};
}

}  // namespace

json results_json(const StudyResult& result) {
  json out;
  out["input"] = result.input;
  out["trial"] = result.trial;
  out["seed"] = result.seed;
  out["threads"] = result.threads;
  out["mc_samples"] = result.mc_samples;
  out["axes_sampler"] = axes_sampler_name(result.axes_sampler);
  out["percentile_definition"] =
      "linear interpolation between order statistics at rank p(n-1) (Hyndman-Fan type 7)";
  out["frame_definitions"] = frame_definitions();
  const std::vector<Analysis>& first = result.flights.front().analyses;
  frames_json(
      result, first, result.built_in,
      [&](const Analysis& a, DaFrame f) { return pooled_rms_da(result, a.name, f); }, out);
  if (!result.built_in) {
    json flights = json::array();
    for (const FlightStudy& f : result.flights) {
      json entry;
      entry["flight"] = f.flight.name;
      entry["start_s"] = f.flight.start_s;
      entry["end_s"] = f.flight.end_s;
      entry["samples"] = f.flight.samples();
      frames_json(
          result, f.analyses, false, [](const Analysis& a, DaFrame frame) { return a.values(frame); }, entry);
      flights.push_back(entry);
    }
    out["flights"] = flights;
  }
  json phases = json::object();
  for (const auto& [name, seconds] : result.phase_time_s) phases[name] = seconds;
  out["phase_time_s"] = phases;
  out["wall_time_s"] = result.wall_time_s;
  return out;
}

std::string rms_da_csv(const StudyResult& result) {
  std::ostringstream out;
  out.precision(9);
  out << "analysis,index,rms_da_deg,frame\n";
  const bool several = result.flights.size() > 1;
  for (DaFrame frame : result.frames) {
    for (const FlightStudy& f : result.flights) {
      for (const Analysis& a : f.analyses) {
        const std::string key = several ? f.flight.name + "/" + analysis_key(a) : analysis_key(a);
        const std::vector<double>& values = a.values(frame);
        for (std::size_t i = 0; i < values.size(); ++i) {
          out << key << ',' << i << ',' << values[i] << ',' << frame_name(frame) << '\n';
        }
      }
    }
  }
  return out.str();
}

std::string experiment_csv(const StudyResult& result) {
  std::ostringstream out;
  out.precision(12);
  const bool poses = result.flights.front().flight.has_orientation();
  if (poses && result.flights.size() == 1) {
    const StudyFlight& f = result.flights.front().flight;
    out << "t,qw,qx,qy,qz,wx,wy,wz\n";
    for (std::size_t i = 0; i < f.samples(); ++i) {
      const Eigen::Quaterniond& q = f.orientation[i];
      const Eigen::Vector3d& w = f.state_omega_body[i];
      out << f.time_s[i] << ',' << q.w() << ',' << q.x() << ',' << q.y() << ',' << q.z() << ',' << w.x()
          << ',' << w.y() << ',' << w.z() << '\n';
    }
    return out.str();
  }
  out << "flight,t,wx,wy,wz\n";
  for (const FlightStudy& fs : result.flights) {
    const StudyFlight& f = fs.flight;
    for (std::size_t i = 0; i < f.samples(); ++i) {
      const Eigen::Vector3d& w = f.state_omega_body[i];
      out << f.name << ',' << f.time_s[i] << ',' << w.x() << ',' << w.y() << ',' << w.z() << '\n';
    }
  }
  return out.str();
}

std::string comparison_table(const StudyResult& result) {
  std::ostringstream out;
  char line[200];
  const bool paper_side = result.built_in;
  std::snprintf(line, sizeof line, "%-22s", "RMS DA (deg)");
  out << line;
  for (DaFrame frame : result.frames) {
    std::snprintf(line, sizeof line, " | %-5s axes p10 median   p90", frame_name(frame));
    out << line;
  }
  out << " |  sims";
  if (paper_side) out << " | paper p10 median   p90";
  out << '\n';
  for (const Analysis& a : result.flights.front().analyses) {
    std::snprintf(line, sizeof line, "%-22s", a.name.c_str());
    out << line;
    std::size_t sims = 0;
    for (DaFrame frame : result.frames) {
      const std::vector<double> values = pooled_rms_da(result, a.name, frame);
      const DistributionSummary s = summarise(values);
      sims = values.size();
      std::snprintf(line, sizeof line, " |       %6.2f %6.2f %5.2f", s.p10, s.median, s.p90);
      out << line;
    }
    std::snprintf(line, sizeof line, " | %5zu", sims);
    out << line;
    if (paper_side) {
      if (const paper::PublishedRow* row = published_row(a)) {
        std::snprintf(line, sizeof line, " |     %5.1f  %5.1f %5.1f", row->p10, row->median, row->p90);
        out << line;
      } else {
        out << " |         -      -     -";
      }
    }
    out << '\n';
  }
  return out.str();
}

}  // namespace aloft::host
