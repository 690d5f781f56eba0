#pragma once
// Wing of the study layer: the whole-body check: one orientation of a body
// solved in 3D against its sections and ends (whole_body_check.h: its
// settings, results, JSON and report), and the load rule that spreads the
// body's force over the sections (section_share.h). The check's stages
// (check_context.h, share_rules.h, check_stages.h) are internal to it.
#include "study/whole_body/section_share.h"
#include "study/whole_body/whole_body_check.h"
