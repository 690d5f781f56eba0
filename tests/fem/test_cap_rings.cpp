// The rings of the structured contact cap (fem/mesh/cap_rings.h): they run
// from the pole to the cap's radius exactly, the contact's edge lies midway
// between two rings the edge spacing apart (no ring within half of it), the
// gaps follow the spacing h(s) and the segments make near-equilateral
// triangles.
#include "core/error.h"
#include "fem/mesh/cap_rings.h"
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;

// A named namespace: a unity batch of this folder's tests shares one
// anonymous namespace.
namespace cap_rings_test
{
constexpr double c = 1.5e-4, h_c = c / 10;

fem::CapRingDesign design(double edge_spacing, double pole_spacing)
{
  return {.edge_radius_m = c,
          .edge_spacing_m = edge_spacing,
          .pole_spacing_m = pole_spacing,
          .pole_radius_m = 0.25 * c,
          .far_spacing_m = h_c,
          .edge_segment_m = h_c,
          .cap_radius_m = 2 * c,
          .growth = 0.25};
}

/// h(s) of cap_rings.h.
double spacing(const fem::CapRingDesign& d, double s)
{
  return std::min({d.far_spacing_m, d.edge_spacing_m + d.growth * std::abs(s - d.edge_radius_m),
                   d.pole_spacing_m + d.growth * std::max(0.0, s - d.pole_radius_m)});
}
} // namespace cap_rings_test
using namespace cap_rings_test;

TEST(CapRings, EdgeMidwayBetweenRingsFromPoleToCap)
{
  for (const auto& [edge, pole] : {std::pair{h_c, h_c}, std::pair{h_c / 2, h_c / 2}, std::pair{h_c / 4, h_c / 2}})
  {
    const fem::CapRingDesign d = design(edge, pole);
    const fem::CapRings rings = fem::cap_rings(d);
    const std::vector<double>& s = rings.radius_m;
    ASSERT_EQ(rings.segments.size(), s.size());
    EXPECT_EQ(s.front(), 0.0);
    EXPECT_EQ(s.back(), d.cap_radius_m);
    EXPECT_EQ(rings.segments.front(), 0);
    EXPECT_TRUE(std::is_sorted(s.begin(), s.end()));
    // The rings either side of the edge lie h_e / 2 from it; none nearer.
    const auto outer = std::upper_bound(s.begin(), s.end(), c);
    ASSERT_NE(outer, s.begin());
    EXPECT_NEAR(*outer - c, edge / 2, 1e-12 * c);
    EXPECT_NEAR(c - *(outer - 1), edge / 2, 1e-12 * c);
    for (std::size_t j = 1; j < s.size(); ++j)
    {
      // Each gap is h(s) at its edge-side end, scaled by less than a half
      // gap's worth over the side (the last gap dropped or kept).
      const double gap = s[j] - s[j - 1];
      const double designed = spacing(d, s[j] <= c ? s[j] : s[j - 1]);
      EXPECT_GT(gap, 0.75 * designed) << "gap " << j;
      EXPECT_LT(gap, 1.34 * designed) << "gap " << j;
      // Near-equilateral: the ring's segment within a third of its gaps'
      // mean (rounding m_j moves it by at most half a segment).
      if (rings.segments[j] >= 3)
      {
        const double radial = j + 1 < s.size() ? 0.5 * (s[j + 1] - s[j - 1]) : gap;
        const double tangential = std::numbers::pi / 2 * s[j] / rings.segments[j];
        EXPECT_GT(tangential / radial, 0.75) << "ring " << j;
        EXPECT_LT(tangential / radial, 1.34) << "ring " << j;
      }
    }
  }
}

TEST(CapRings, RefusesAnEdgeOutsideTheCapOrBadSizes)
{
  fem::CapRingDesign d = design(h_c, h_c);
  d.cap_radius_m = c;
  EXPECT_THROW(fem::cap_rings(d), InputError);
  d = design(2 * h_c, h_c);
  EXPECT_THROW(fem::cap_rings(d), InputError); // h_e above the largest spacing
  d = design(h_c, h_c);
  d.growth = 0;
  EXPECT_THROW(fem::cap_rings(d), InputError);
  d = design(h_c, std::nan(""));
  EXPECT_THROW(fem::cap_rings(d), InputError);
}
