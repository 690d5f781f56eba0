#pragma once
// Wing of the study layer: rolling-contact fatigue life over the loop.
//   stress_volume.h   the life models' constants and the depth integrals of one pass
//   loop_life.h       the stress-volume integrals of a body over one loop
//   fem_subsurface.h  the FEM slice's subsurface stress against the closed form
//   life_study.h      the bodies' life ratios over the modelling choices, with verdicts
#include "study/life/fem_subsurface.h"
#include "study/life/life_study.h"
#include "study/life/loop_life.h"
#include "study/life/stress_volume.h"
