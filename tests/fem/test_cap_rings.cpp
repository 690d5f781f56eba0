// The rings of the structured contact cap (fem/mesh/cap_rings.h): they run
// from the pole to the cap's radius exactly, equally spaced inside the
// contact with its edge midway between two rings (no ring within half a
// spacing of it), growing beyond it; the segments are powers of two within
// a factor sqrt(2) of the spacing (near-equilateral triangles) up to the
// edge rings' count M, which every ring from the edge outwards keeps; every
// second ring of a run alike is staggered by half a segment.
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

fem::CapRingDesign design(double spacing)
{
  return {.edge_radius_m = c,
          .spacing_m = spacing,
          .far_spacing_m = h_c,
          .edge_segment_m = h_c,
          .cap_radius_m = 2 * c,
          .growth = 0.25};
}
} // namespace cap_rings_test
using namespace cap_rings_test;

TEST(CapRings, EqualRingsWithTheEdgeMidwayFromPoleToCap)
{
  for (double spacing : {h_c, h_c / std::sqrt(2.0), h_c / 2, h_c / 4})
  {
    const fem::CapRingDesign d = design(spacing);
    const fem::CapRings rings = fem::cap_rings(d);
    const std::vector<double>& s = rings.radius_m;
    ASSERT_EQ(rings.segments.size(), s.size());
    EXPECT_EQ(s.front(), 0.0);
    EXPECT_EQ(s.back(), d.cap_radius_m);
    EXPECT_EQ(rings.segments.front(), 0);
    EXPECT_TRUE(std::is_sorted(s.begin(), s.end()));
    // Inside: s_k = k h, h <= h_0, the edge at (K + 1/2) h.
    const std::size_t K = std::upper_bound(s.begin(), s.end(), c) - s.begin() - 1;
    const double h = s[1];
    EXPECT_LE(h, spacing * (1 + 1e-12));
    EXPECT_GT(h, spacing * K / (K + 1.0));
    EXPECT_NEAR(c, (K + 0.5) * h, 1e-12 * c);
    for (std::size_t k = 0; k <= K + 1; ++k)
      EXPECT_NEAR(s[k], k * h, 1e-12 * c) << "ring " << k;
    // Beyond: gaps from h growing by at most g per unit of distance, at most h_far.
    for (std::size_t j = K + 2; j < s.size(); ++j)
    {
      const double gap = s[j] - s[j - 1];
      EXPECT_GT(gap, 0.75 * h);
      EXPECT_LT(gap, 1.34 * std::min(d.far_spacing_m, h + d.growth * (s[j - 1] - s[K + 1])));
    }
    // Segments: powers of two, near-equilateral below M, M from the edge out.
    const int M = 1 << static_cast<int>(std::lround(std::log2(std::numbers::pi / 2 * c / h_c)));
    for (std::size_t j = 1; j < s.size(); ++j)
    {
      const int m = rings.segments[j];
      EXPECT_EQ(m & (m - 1), 0) << "ring " << j;
      EXPECT_LE(m, M);
      EXPECT_GE(m, rings.segments[j - 1]);
      if (j > K)
        EXPECT_EQ(m, M) << "ring " << j;
      else if (m < M)
      {
        const double tangential = std::numbers::pi / 2 * s[j] / m;
        EXPECT_GT(tangential / h, 1 / std::sqrt(2.0) - 1e-12) << "ring " << j;
        EXPECT_LT(tangential / h, std::sqrt(2.0) + 1e-12) << "ring " << j;
      }
      // Angles: k pi / (2 m), or staggered by half a segment with both
      // planes' ends, every second ring of a run alike.
      const std::vector<double>& t = rings.angles_rad[j];
      const bool staggered = t.size() == static_cast<std::size_t>(m) + 2;
      ASSERT_TRUE(staggered || t.size() == static_cast<std::size_t>(m) + 1) << "ring " << j;
      EXPECT_EQ(t.front(), 0.0);
      EXPECT_EQ(t.back(), std::numbers::pi / 2);
      for (std::size_t k = 1; k + 1 < t.size(); ++k)
        EXPECT_NEAR(t[k], (k - (staggered ? 0.5 : 0.0)) * std::numbers::pi / 2 / m, 1e-14) << "ring " << j;
      const bool previous_staggered = rings.angles_rad[j - 1].size() == rings.segments[j - 1] + 2u;
      EXPECT_EQ(staggered, m == rings.segments[j - 1] && !previous_staggered) << "ring " << j;
    }
  }
}

TEST(CapRings, RefusesAnEdgeOutsideTheCapOrBadSizes)
{
  fem::CapRingDesign d = design(h_c);
  d.cap_radius_m = c;
  EXPECT_THROW(fem::cap_rings(d), InputError);
  d = design(2 * h_c);
  EXPECT_THROW(fem::cap_rings(d), InputError); // h_0 above the largest spacing
  d = design(h_c);
  d.growth = 0;
  EXPECT_THROW(fem::cap_rings(d), InputError);
  d = design(std::nan(""));
  EXPECT_THROW(fem::cap_rings(d), InputError);
}
