#pragma once
// The JSON summary of a Hertz verification run: every measured value next to
// its Hertz value and their relative error, under named keys with units
// (docs/methods/hertz-fem.md; the audit's pointers and the plots read these keys).
#include "fem/scenes/hertz_solve.h"
#include <nlohmann/json.hpp>

namespace rollcheck::fem
{
/// Keys: the setup (model, degree, refine, ...), the mesh grading, the force,
/// for each compared quantity `name`, `name`_hertz and `name`_error (a_m or
/// b_m, p0_pa, max_shear_pa, ...), the pressure profile, the flags and the cost.
nlohmann::json to_json(const HertzResult& result);
} // namespace rollcheck::fem
