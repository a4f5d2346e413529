// The session figure of `aloft diagnose --segments ... --plot DIR`: the answer to "is my
// tensor right?" at a glance. Two panels show each flight's 95 % interval of a moment
// ratio (I2/I1, I3/I1 in the body file's axis order) beside the pooled interval and the
// body file's ratio; the third shows measured against simulated ω (the nominal model,
// held out), flight after flight.
#pragma once

#include <vector>

#include "diagnose/5_flow/diagnosis.hpp"
#include "diagnose/6_report/panel_figure.hpp"

namespace aloft::host::diagnose {

std::vector<Panel> session_panels(const SessionDiagnosis& session);

}  // namespace aloft::host::diagnose
