// A fixture for check_stage_includes.sh: the other half of the cycle.
#pragma once

#include "diagnose/4_judge/ranking.hpp"
