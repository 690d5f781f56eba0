// A crease inside the contact (fem/scenes/crease_contact.h) against half-space
// theory for the blunt wedge (K. L. Johnson, "Contact Mechanics", 1985,
// sec. 5.8): p(x) = (E* tan beta / pi) arccosh(a / |x|), a = P / (E* tan beta).
// The FEM pressure inside the contact converges to p(x); the apex pressure
// grows with every level, on average by (E* tan beta / pi) ln sqrt 2, as a
// logarithmic singularity sampled by elements sqrt 2 smaller must.
#include "fem/scenes/crease_contact.h"
#include "core/error.h"
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

using namespace rollcheck;

TEST(CreaseContact, ApexPeakGrowsAsTheLogarithmWhileTheContactConverges)
{
  const fem::CreaseStudy study = fem::solve_crease(MPI_COMM_WORLD, {});
  ASSERT_EQ(study.levels.size(), 3u);
  for (std::size_t k = 0; k < study.levels.size(); ++k)
  {
    const fem::CreaseLevel& level = study.levels[k];
    std::printf("level %d: h %.3g m, %lld dofs, apex %.5g Pa, p(a/2) %.5g Pa (theory %.5g), edge %.4g m (a %.4g)\n",
                level.refine, level.contact_element_m, static_cast<long long>(level.dofs), level.apex_pressure_pa,
                level.half_contact_pressure_pa, study.half_contact_pressure_pa, level.contact_edge_m, study.half_width_m);
    EXPECT_NEAR(level.half_contact_pressure_pa / study.half_contact_pressure_pa, 1.0, 0.02);
    EXPECT_NEAR(level.contact_edge_m / study.half_width_m, 1.0, 0.05);
    if (k > 0)
    {
      const double growth = level.apex_pressure_pa - study.levels[k - 1].apex_pressure_pa;
      std::printf("  apex growth %.4g Pa, theory %.4g Pa\n", growth, study.apex_growth_per_level_pa);
      EXPECT_GT(growth, 0.5 * study.apex_growth_per_level_pa);
    }
  }
  // The apex node's share of the singularity depends on the triangles at the
  // apex, so single steps scatter; over the levels the growth is the log law's.
  const double mean_growth = (study.levels.back().apex_pressure_pa - study.levels.front().apex_pressure_pa)
                             / static_cast<double>(study.levels.size() - 1);
  EXPECT_NEAR(mean_growth / study.apex_growth_per_level_pa, 1.0, 0.1);
}

TEST(CreaseContact, BadSetupIsRejected)
{
  fem::CreaseSettings setup;
  setup.face_angle_rad = 1.0;
  EXPECT_THROW(fem::solve_crease(MPI_COMM_WORLD, setup), InputError);
  setup = {};
  setup.load_n_per_m = NAN;
  EXPECT_THROW(fem::solve_crease(MPI_COMM_WORLD, setup), InputError);
  setup = {};
  setup.load_n_per_m = 1e9; // a contact as wide as the body
  EXPECT_THROW(fem::solve_crease(MPI_COMM_WORLD, setup), InputError);
}
