// How far a held-out score could move with other data of the same kind: the spread that
// the tie rule (confidence.hpp) weighs a ranking margin against.
//
// A candidate's held-out chi-square is a sum over the chunks of the interleaved folds
// (3_fit/held_out.hpp: each chunk judged by the fold that did not see it; in a session,
// every flight's chunks, each judged by the fit without that flight). Chunks are the
// units: residuals inside one are correlated (a misfit lasts longer than a sample), those
// of different chunks much less. So the standard error of a sum of N chunk values is
// sqrt(N) times their standard deviation. For two candidates the chunks are paired (the
// same samples), and the spread of their score difference comes from the chunk-by-chunk
// differences: what the two share (most of the gap, and the noise) cancels.
//
// Scores are divided by the step's dispersion (candidate_ranking.hpp), so spreads are too.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "diagnose/1_input/flight.hpp"

namespace aloft::host::diagnose {

struct Candidate;

// The held-out chi-square of `c` chunk by chunk, over every flight (empty when the
// candidate holds no held-out predictions).
std::vector<double> chunk_chi_squares(const Candidate& c, const std::vector<const Flight*>& flights,
                                      const std::vector<Eigen::Vector3d>& inverse_sigma);

// The standard error of the sum of `parts` (sqrt(N) times their standard deviation; 0
// for fewer than two parts).
double spread_of_sum(const std::vector<double>& parts);

// The standard error of the sum of a - b, chunk by chunk (same length, else 0).
double spread_of_difference(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace aloft::host::diagnose
