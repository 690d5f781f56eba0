#pragma once
// Wing of the study layer: every score of one body under one oracle (score_body.h:
// the preprint's template scores, real rolling, paper-compatible columns) and
// the paper-compatible oracles' quirk table and spin-nudge band
// (paper_quirks.h), the ranked table of the preprint's parametric search
// (search_table.h). Light: no FEM library.
#include "study/body_scores/paper_quirks.h"
#include "study/body_scores/score_body.h"
#include "study/body_scores/search_table.h"
