// A fixture for check_stage_includes.sh: half of a cycle with ranking.cpp's partner.
#pragma once
