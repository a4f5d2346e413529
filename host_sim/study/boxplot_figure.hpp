// The figure of `aloft study`, in the style of the seed paper's Fig. 3: boxplots of RMS
// DA with whiskers at the 10th and 90th percentiles (box: quartiles; line: median).
// Panel A: the models (GF vs CP; for a recording, the nominal tensor per flight);
// B1, B2, B3: the Monte Carlo families (moments, axes, both) against their bound, the
// unperturbed model drawn at bound 0 as in the paper. Where the paper gives numbers,
// its median and p10-p90 range are drawn in red beside aloft's box.
// Drawn with cairo, which writes the same drawing as SVG and as PNG.
#pragma once

#include <string>

#include "common/figure_render.hpp"
#include "study/study_result.hpp"

namespace aloft::host {

// Renders both files in memory. Throws aloft::host::Error if cairo fails.
FigureFiles render_study_figure(const StudyResult& result);

}  // namespace aloft::host
