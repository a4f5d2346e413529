// A fixture for check_stage_includes.sh, which must reject it: an input header that
// includes a judging header (against the flow).
#pragma once

#include "diagnose/4_judge/ranking.hpp"
