#pragma once
// Wing of the study layer: the whole-body check: one orientation of a body
// solved in 3D against its sections and ends (whole_body_check.h), and the
// load rule that spreads the body's force over the sections
// (section_load_rule.h).
#include "study/whole_body/section_load_rule.h"
#include "study/whole_body/whole_body_check.h"
