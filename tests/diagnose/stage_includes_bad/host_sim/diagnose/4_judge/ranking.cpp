// A fixture for check_stage_includes.sh: ranking and significance include each other.
#include "diagnose/4_judge/ranking.hpp"
#include "diagnose/4_judge/significance.hpp"
