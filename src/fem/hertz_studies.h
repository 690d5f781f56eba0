#pragma once
// The two studies behind the defaults (README, "Hertz FEM"):
// - convergence: each model and degree over its refine levels, for the
//   speed-against-error plot and the choice of default_refine();
// - penalty: penalty_c from 0.1 to 1000 on each model's default mesh, for
//   the choice of HertzSetup::default_penalty_c.
// A study is a list of setups derived from a base setup (its body, load and
// solver options); running them is the caller's business.
#include "fem/hertz_setup.h"
#include <vector>

namespace rollcheck::fem
{
/// Refine levels of the convergence study per model and degree: 2D P1
/// 0..6, 2D P2 0..4, 3D P1 0..2, 3D P2 0.
std::vector<HertzSetup> convergence_study(const HertzSetup& base, const std::vector<Model>& models);

/// penalty_c in {0.1, 0.3, 1, 3, 10, 30, 100, 300, 1000}, P1, default mesh.
std::vector<HertzSetup> penalty_study(const HertzSetup& base, const std::vector<Model>& models);
} // namespace rollcheck::fem
