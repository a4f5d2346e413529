// How the report words an effect's fitted parameters: a line of text for the summary and
// SPEC §4's JSON `params` object. One pair per effect of
// 2_model/effects/effect_list.def, in effect_words.cpp, where a missing pair is a compile
// error. The words live here, not in the effect's descriptor, so that the model and the
// judging stages carry no report (docs/architecture.md, "diagnose: the stages").
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "diagnose/2_model/effect.hpp"
#include "diagnose/2_model/effect_parameters.hpp"
#include "diagnose/4_judge/analysis.hpp"

namespace aloft::host::diagnose {

// The summary's words for `params` of `effect` (empty for none).
std::string params_text(Effect effect, const EffectParameters& params);

// SPEC §4 `params` of `effect`.
nlohmann::json params_json(Effect effect, const EffectParameters& params);

// A note's whole text: its own words, then the parameters it carries in the summary's.
std::string note_text(const Note& note);

}  // namespace aloft::host::diagnose
