#pragma once
// The JSON of the FEM end model's study (fem/scenes/rim_end_contact.h) as the
// rim command writes it: one end alone (`rim`), or each end of the rim loop
// in brief (`rim --body`, study/rims/rim_loop.h). Both carry the end's q, R,
// b, p0 and the model's verdict under the same keys.
#include "fem/scenes/rim_end_contact.h"
#include <nlohmann/json.hpp>
#include <string>

namespace rollcheck::study::rims
{
/// The counter-face as the JSON names it: "rigid" or "steel".
std::string counter_face_name(fem::CounterFace face);

/// One end alone: its setting, its verdict (study/rims/rim_report.h
/// rim_end_verdict) and every level with its centre line from 3 b beyond
/// where the sheet ends to the edge.
nlohmann::json to_json(const fem::RimEndStudy& study);

/// One end of the rim loop: its q, R, H / b and verdict, and its levels'
/// count, load steps, Newton iterations and wall time together.
nlohmann::json end_model_json(const fem::RimEndStudy& study);
} // namespace rollcheck::study::rims
