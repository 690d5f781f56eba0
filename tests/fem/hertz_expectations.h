#pragma once
// What every Hertz FEM test expects of a converged run: the relative error
// against a reference, the reaction carrying the load, and the subsurface
// maxima (largest shear and von Mises stress and their depths) within 3 % of
// Hertz theory, with no flag raised.
#include "fem/scenes/hertz_solve.h"
#include <cmath>
#include <gtest/gtest.h>

namespace rollcheck::test
{
inline double error(double fem_value, double reference) { return std::abs(fem::relative_error(fem_value, reference)); }

/// The load balance and the subsurface maxima against Hertz's (shear, its
/// depth, von Mises, its depth), and no flags.
inline void expect_balanced_with_hertz_subsurface(const fem::HertzResult& r, double max_shear_pa,
                                                  double max_shear_depth_m, double max_von_mises_pa,
                                                  double max_von_mises_depth_m)
{
  EXPECT_LT(error(r.load_reaction, r.hertz.load), 1e-4);
  EXPECT_LT(error(r.load_contact, r.load_reaction), 1e-6);
  EXPECT_LT(error(r.max_shear.value, max_shear_pa), 0.03);
  EXPECT_LT(error(r.max_shear.depth_m, max_shear_depth_m), 0.03);
  EXPECT_LT(error(r.max_von_mises.value, max_von_mises_pa), 0.03);
  EXPECT_LT(error(r.max_von_mises.depth_m, max_von_mises_depth_m), 0.03);
  EXPECT_TRUE(r.flags.empty());
}
} // namespace rollcheck::test
