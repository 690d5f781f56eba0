#pragma once
// Wing of the study layer: scores over one rolling loop: the loop's samples
// mapped to the contact loci and their line-Hertz and FEM pressures
// (loop_sds.h), FEM-SDS/FDS over the loop with its convergence (fem_sds.h) and
// over the family (fem_sds_family.h). Links the fem layer.
#include "study/loop_scores/fem_sds.h"
#include "study/loop_scores/fem_sds_family.h"
#include "study/loop_scores/loop_sds.h"
