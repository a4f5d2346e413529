// diagnose_compare_verdicts: the verdicts of two folders of `aloft diagnose --json`
// reports (same file names), for same_verdict_every_cpu.sh; and a probe of libm's last
// bits, to show that a GLIBC_TUNABLES setting reached the functions diagnose calls.
//
//   diagnose_compare_verdicts REF_DIR NEW_DIR [SCORE_TOLERANCE [RELATIVE_TOLERANCE]]
//     Identical: each verdict's (and each session flight's) effect, equivalent,
//     indistinguishable_from, confident and the effects of its final model. Within the
//     tolerances: every identifiable candidate's score (absolute, score units; default 1.0,
//     the ranking's kScoreRoundingTolerance) and the verdict's held-out errors (relative;
//     default 1e-4: a spun-up wheel's rise and start are nearly one direction where it spins
//     up as a step, and where the fit stops along it moved a session's held-out errors by
//     2.75e-5 between SSE2 and FMA libm; every other verdict's agreed within 1e-11). Prints
//     each difference, then the largest differences measured. A candidate is its effect and,
//     where it has one, its profile (a steady rotor and a spun-up one are both
//     `internal_momentum`). A candidate the report marks not
//     identifiable is left out of the scores: the data leave a direction of its parameters
//     unpinned, so where each fold's fit stops along it, and so its held-out score, rests
//     on the last bits. What such a score changes of the outcome is still compared: the
//     verdict's effect, ties and confidence, and its held-out errors, whichever candidate
//     it took.
//     Exit 0: all agree; 1: a difference; 2: bad use or a missing report.
//   diagnose_compare_verdicts --libm-probe
//     Prints a hash of sin, cos, exp, log, pow and atan2 over 200000 arguments.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

using nlohmann::json;

int libm_probe() {
  std::uint64_t hash = 1469598103934665603ull;
  volatile double x = 0.1;  // volatile: no constant folding, every call reaches libm
  for (int i = 0; i < 200000; ++i) {
    const double v = x;
    const double r[] = {std::sin(v), std::cos(v),       std::exp(0.1 * v),
                        std::log(v), std::pow(v, 1.37), std::atan2(v, 1.3)};
    for (double d : r) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &d, sizeof bits);
      hash = (hash ^ bits) * 1099511628211ull;
    }
    x = v * 1.0000013 + 1e-7 > 50.0 ? v * 1.0000013 + 1e-7 - 49.7 : v * 1.0000013 + 1e-7;
  }
  std::printf("%016llx\n", static_cast<unsigned long long>(hash));
  return 0;
}

struct Tolerances {
  double score = 1.0;
  double relative = 1e-4;
};

struct Measured {
  double score = 0.0;
  double relative = 0.0;
  int differences = 0;
  int unidentifiable = 0;  // candidates whose scores were not compared
};

// A candidate's name in the report: its effect, and its profile where it has one.
std::string candidate_key(const json& c) {
  const json params = c.value("params", json::object());
  return c.value("effect", "") +
         (params.contains("profile") ? "/" + params["profile"].get<std::string>() : "");
}

json verdict_names(const json& v) {
  json effects = json::array();
  for (const json& e : v.value("effects", json::array())) effects.push_back(e.value("effect", ""));
  return {{"effect", v.value("effect", "")},
          {"equivalent", v.value("equivalent", json::array())},
          {"indistinguishable_from", v.value("indistinguishable_from", json::array())},
          {"confident", v.value("confident", false)},
          {"effects", effects}};
}

double relative_difference(double a, double b) {
  const double scale = std::max(std::abs(a), std::abs(b));
  return scale > 0.0 ? std::abs(a - b) / scale : 0.0;
}

// A candidate's score in both reports. A score is null where the report had no finite
// number to write (a candidate not evaluated): two nulls agree, a null and a number differ.
void compare_scores(const std::string& what, const json& a, const json& b, const Tolerances& tol,
                    Measured& m) {
  if (!a.is_number() || !b.is_number()) {
    if (a.is_number() == b.is_number()) return;
    std::printf("%s scores %s here, %s there\n", what.c_str(), a.dump().c_str(), b.dump().c_str());
    ++m.differences;
    return;
  }
  const double d = std::abs(a.get<double>() - b.get<double>());
  m.score = std::max(m.score, d);
  if (d > tol.score) {
    std::printf("%s scores %.6f here, %.6f there\n", what.c_str(), a.get<double>(), b.get<double>());
    ++m.differences;
  }
}

// One analysis (a flight, or a session's pooled one): its verdict and candidates.
void compare_analysis(const std::string& where, const json& a, const json& b, const Tolerances& tol,
                      Measured& m) {
  const json va = verdict_names(a.value("verdict", json::object()));
  const json vb = verdict_names(b.value("verdict", json::object()));
  if (va != vb) {
    std::printf("%s: verdict %s here, %s there\n", where.c_str(), va.dump().c_str(), vb.dump().c_str());
    ++m.differences;
  }
  for (const char* key : {"heldout_rms_rel_err_before", "heldout_rms_rel_err_after",
                          "heldout_rms_da_before_deg", "heldout_rms_da_after_deg"}) {
    const double x = a.value("verdict", json::object()).value(key, 0.0);
    const double y = b.value("verdict", json::object()).value(key, 0.0);
    const double d = relative_difference(x, y);
    m.relative = std::max(m.relative, d);
    if (d > tol.relative) {
      std::printf("%s: verdict.%s %.9g here, %.9g there\n", where.c_str(), key, x, y);
      ++m.differences;
    }
  }
  for (const json& ca : a.value("candidates", json::array())) {
    if (!ca.contains("score")) continue;
    for (const json& cb : b.value("candidates", json::array())) {
      if (candidate_key(cb) != candidate_key(ca) || !cb.contains("score")) continue;
      if (!ca.value("identifiable", true) || !cb.value("identifiable", true)) {
        ++m.unidentifiable;
        continue;
      }
      compare_scores(where + ": " + candidate_key(ca), ca["score"], cb["score"], tol, m);
    }
  }
}

bool read_json(const std::filesystem::path& path, json& out) {
  std::ifstream in(path);
  if (!in) return false;
  try {
    in >> out;
  } catch (const json::exception&) {
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--libm-probe") return libm_probe();
  if (argc < 3 || argc > 5) {
    std::fprintf(stderr,
                 "usage: diagnose_compare_verdicts REF_DIR NEW_DIR [SCORE_TOL [REL_TOL]] | --libm-probe\n");
    return 2;
  }
  Tolerances tol;
  if (argc > 3) tol.score = std::stod(argv[3]);
  if (argc > 4) tol.relative = std::stod(argv[4]);
  Measured m;
  int reports = 0;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(argv[1])) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& path : files) {
    json a, b;
    const std::filesystem::path other = std::filesystem::path(argv[2]) / path.filename();
    if (!read_json(path, a) || !read_json(other, b)) {
      std::fprintf(stderr, "compare_verdicts: %s: unreadable or missing in one folder\n",
                   path.filename().c_str());
      return 2;
    }
    ++reports;
    const std::string name = path.stem().string();
    compare_analysis(name, a, b, tol, m);
    const json fa = a.value("flights", json::array()), fb = b.value("flights", json::array());
    for (std::size_t i = 0; i < fa.size() && i < fb.size(); ++i) {
      compare_analysis(name + " flight " + std::to_string(i), fa[i], fb[i], tol, m);
    }
  }
  std::printf(
      "compare_verdicts: %d reports, %d differences; largest score difference %.3g (tolerance %.3g), largest "
      "relative difference of held-out errors %.3g (tolerance %.3g); %d scores of candidates not "
      "identifiable "
      "left out\n",
      reports, m.differences, m.score, tol.score, m.relative, tol.relative, m.unidentifiable);
  return reports > 0 && m.differences == 0 ? 0 : 1;
}
