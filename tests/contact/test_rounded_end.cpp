// The pieces of the rounded end's half-space solve (contact/rounded_end.h):
// the ruling's line load against the contact locus's rule (oracle/line_load.h),
// the line Hertz pressure prescribed beyond the window against Boussinesq's
// point load, the ball's rounding on a grid against the crease's closed form
// (geometry/rolling_ball_opening.h) and the straight rim's surface. The
// whole solve is study/rims/test_flat_rim_contact.cpp's.
#include "contact/ball_rounded_surface.h"
#include "contact/hertz.h"
#include "contact/line_hertz_beyond.h"
#include "contact/ruling_line_load.h"
#include "contact/straight_rim_end.h"
#include "core/error.h"
#include "oracle/line_load.h"
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <numbers>
#include <optional>

using namespace rollcheck;

TEST(RoundedEnd, RulingLineLoadCarryingIsTheLocusRule)
{
  const double force = 800, length = 0.0173;
  for (const double c : {0.2, 0.25, 0.4, 0.6})
  {
    const std::optional<contact::RulingLineLoad> load = contact::RulingLineLoad::carrying(force, c * length, 0, length);
    ASSERT_TRUE(load) << c;
    for (const double s : {0.0, 0.1, 0.3, 0.5, 0.9})
      EXPECT_NEAR(load->at(s * length), oracle::line_load(force, c, length, s), 1e-9 * force / length)
          << "c = " << c << ", s = " << s;
    EXPECT_NEAR(load->load_to(length) / force, 1.0, 1e-12);
    EXPECT_NEAR(load->moment_to(length) / load->load_to(length) / (c * length), 1.0, 1e-12);
    EXPECT_EQ(load->at(-1e-9), 0.0);
  }
  // The far third loads the ruling from its far end: not this rule.
  EXPECT_FALSE(contact::RulingLineLoad::carrying(force, 0.7 * length, 0, length));
  // From a station on: the same rule over [from, L], centred there.
  const double from = 0.2 * length;
  const std::optional<contact::RulingLineLoad> beyond
      = contact::RulingLineLoad::carrying(force, from + 0.3 * (length - from), from, length);
  ASSERT_TRUE(beyond);
  const double carried = beyond->load_to(length) - beyond->load_to(from);
  EXPECT_NEAR(carried / force, 1.0, 1e-12);
  EXPECT_NEAR((beyond->moment_to(length) - beyond->moment_to(from)) / carried, from + 0.3 * (length - from),
              1e-12 * length);
}

TEST(RoundedEnd, NoTensionRuleEndsWhereTheLoadFallsToNone)
{
  const contact::RulingLineLoad falling = contact::RulingLineLoad::no_tension(1e5, -1e7, 0.1);
  EXPECT_DOUBLE_EQ(falling.length_m, 0.01);
  EXPECT_EQ(falling.at(0.011), 0.0);
  EXPECT_DOUBLE_EQ(falling.load_to(1.0), 1e5 * 0.01 / 2);
  EXPECT_DOUBLE_EQ(contact::RulingLineLoad::no_tension(1e5, 1e6, 0.1).length_m, 0.1);
}

// Each column carries its q exactly, so that far from the loaded columns
// the deflection is the columns' point forces q dx by Boussinesq, u = P /
// (pi E* r).
TEST(RoundedEnd, LineHertzBeyondCarriesTheLineLoad)
{
  const double cell = 2e-5, modulus = 1.1e11, q = 1.2e5;
  const contact::HalfSpaceGrid grid{400, 21, cell, cell, 0, -10 * cell};
  const std::size_t first = 390;
  const contact::LineHertzBeyond beyond{grid, first, contact::HalfSpaceDeflection(grid, modulus),
                                        [](double) { return 1e-3; }, modulus, 0.3};
  const std::vector<double> u = beyond.deflection({q, 0.0, 1.0});
  double expected = 0;
  for (std::size_t i = first; i < grid.nx; ++i)
    expected += q * cell / (std::numbers::pi * modulus * (grid.x(i) - grid.x(0)));
  EXPECT_NEAR(u[0 * grid.ny + 10] / expected, 1.0, 1e-3);
  // Where the line load is none, nothing is prescribed.
  const std::vector<double> none = beyond.deflection({q, 0.0, grid.x(first) - cell});
  EXPECT_EQ(*std::max_element(none.begin(), none.end()), 0.0);
}

// A crease z = k |y| rounded by a ball of r: k^2 r / 2 + y^2 / (2 r) for
// |y| <= k r, the crease beyond; read on the grid's own cells, the margin
// holding the ball's reach.
TEST(RoundedEnd, BallRoundsACreaseOnTheGridsCells)
{
  const double k = 0.1, r = 4e-4, cell = 1e-5;
  const contact::HalfSpaceGrid grid{5, 41, cell, cell, 0, -20 * cell};
  const contact::BallRoundedSurface surface
      = contact::ball_rounded_surface([k](double, double y) { return k * std::abs(y); }, grid, r);
  EXPECT_EQ(surface.margin, contact::rounding_margin(r, cell));
  EXPECT_EQ(surface.margin, 24u);
  for (std::size_t j = 0; j < grid.ny; ++j)
  {
    const double y = grid.y(j);
    const double rounded = std::abs(y) <= k * r ? k * k * r / 2 + y * y / (2 * r) : k * std::abs(y);
    EXPECT_NEAR(surface(2, j), rounded, 1e-12) << "y = " << y;
  }
  // The slope under a load across the whole grid: the crease's, k, at most.
  const std::vector<double> loaded(grid.size(), 1.0);
  EXPECT_NEAR(contact::largest_loaded_slope(surface, grid, loaded), k, 1e-9);
  EXPECT_EQ(contact::largest_loaded_slope(surface, grid, std::vector<double>(grid.size(), 0.0)), 0.0);
  EXPECT_THROW(contact::ball_rounded_surface(
                   [](double x, double) { return x > 0 ? std::numeric_limits<double>::infinity() : 0.0; }, grid, r),
               ComputationError);
}

TEST(RoundedEnd, StraightRimEndIsTheSheetAndTheLeaningFace)
{
  contact::RoundedEndSettings s;
  const double angle = 170 * std::numbers::pi / 180, radius = 1e-3, q = 1.2e5;
  const contact::RoundedEndProblem end = contact::straight_rim_end(s, angle, radius, q);
  const double lean = std::tan(10 * std::numbers::pi / 180);
  EXPECT_DOUBLE_EQ(end.hull_height(1e-4, 2e-5), 2e-5 * 2e-5 / (2 * radius));
  EXPECT_NEAR(end.hull_height(-1e-4, 2e-5), 2e-5 * 2e-5 / (2 * radius) + 1e-4 * lean, 1e-15);
  EXPECT_EQ(end.sheet_radius(0.5), radius);
  const double b = contact::line_contact(q, radius, contact::effective_modulus(s), s.poisson_ratio).half_width_m;
  EXPECT_DOUBLE_EQ(end.load.length_m, 400 * b);
  EXPECT_EQ(end.ruling_length_m, end.load.length_m);
  EXPECT_EQ(end.load.at(0.5 * end.load.length_m), q);
  EXPECT_FALSE(end.balance_body);
  // The finish has no radius below r_e.
  EXPECT_EQ(contact::reference_radius(s, contact::straight_rim_end(s, angle, 1e-4, q)), s.edge_radius_m);
}
