// The measurements the Hertz FEM post-processing makes from nodal data,
// checked on data with known answers: exact Hertz profiles, a known gap, a
// parabola with a known vertex.
#include "contact/hertz.h"
#include "fem/contact_measures.h"
#include <cmath>
#include <gtest/gtest.h>
#include <random>

using namespace rollcheck;

namespace
{
/// Hertz profile p0 sqrt(1 - (s/c)^2) sampled at n nodes spaced h from s = 0.
std::vector<fem::SurfaceNode> hertz_nodes(double p0, double c, double h, int n)
{
  std::vector<fem::SurfaceNode> nodes;
  for (int i = 0; i < n; ++i)
  {
    const double s = i * h;
    nodes.push_back({s, contact::pressure_profile(p0, c, s), s * s / 0.02 - c * c / 0.02});
  }
  return nodes;
}
} // namespace

TEST(HertzMeasures, FitRecoversAnExactProfile)
{
  const double p0 = 2.1e9, a = 1.5e-4;
  const auto nodes = hertz_nodes(p0, a, a / 13.7, 40);
  const fem::ProfileFit fit = fem::fit_hertz_profile(nodes, p0);
  EXPECT_NEAR(fit.peak_pressure_pa / p0, 1.0, 1e-12);
  EXPECT_NEAR(fit.contact_size_m / a, 1.0, 1e-12);
  // Only the nodes with p >= p0 / 2, i.e. s <= sqrt(3)/2 a, enter the fit.
  EXPECT_EQ(fit.nodes_used, static_cast<int>(std::floor(std::sqrt(3.0) / 2 * 13.7)) + 1);
}

TEST(HertzMeasures, FitAveragesNoise)
{
  // 3D-like scatter: nodes at random radii with 2 % multiplicative noise.
  const double p0 = 1.0, a = 1.0;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> radius(0.0, 1.2);
  std::normal_distribution<double> noise(0.0, 0.02);
  std::vector<fem::SurfaceNode> nodes;
  for (int i = 0; i < 2000; ++i)
  {
    const double s = radius(rng);
    nodes.push_back({s, contact::pressure_profile(p0, a, s) * (1 + noise(rng)), 0.0});
  }
  const fem::ProfileFit fit = fem::fit_hertz_profile(nodes, 1.0);
  EXPECT_NEAR(fit.peak_pressure_pa, p0, 0.005);
  EXPECT_NEAR(fit.contact_size_m, a, 0.005);
}

TEST(HertzMeasures, FitNeedsTwoRadii)
{
  const std::vector<fem::SurfaceNode> one = {{0.0, 1.0, -1.0}, {1.0, 0.0, 1.0}};
  EXPECT_LT(fem::fit_hertz_profile(one, 1.0).nodes_used, 2);
}

TEST(HertzMeasures, ContactEdgeInterpolatesTheGap)
{
  // gap = s - 0.35 crosses zero at 0.35, between the nodes 0.3 and 0.4.
  std::vector<fem::SurfaceNode> nodes;
  for (int i = 5; i >= 0; --i)
    nodes.push_back({0.1 * i, 0.0, 0.1 * i - 0.35});
  EXPECT_NEAR(fem::contact_edge(nodes), 0.35, 1e-12);
  for (auto& node : nodes)
    node.gap = 1.0;
  EXPECT_EQ(fem::contact_edge(nodes), 0.0);
}

TEST(HertzMeasures, AxisMaximumOfAParabola)
{
  // f = 3 - 2 (z - 0.4812)^2 on an uneven grid: the vertex is found exactly.
  std::vector<fem::AxisNode> nodes;
  for (double z : {0.0, 0.1, 0.25, 0.33, 0.47, 0.52, 0.8, 1.3, 2.0})
    nodes.push_back({z, 0.0, 3 - 2 * (z - 0.4812) * (z - 0.4812)});
  const fem::DepthMaximum m = fem::maximum_along_axis(nodes, 1e-12);
  EXPECT_NEAR(m.value, 3.0, 1e-12);
  EXPECT_NEAR(m.depth_m, 0.4812, 1e-12);
}

TEST(HertzMeasures, AxisMaximumOfTheHertzShearProfile)
{
  // Johnson eq. 3.45 on the axis of a point contact (nu = 0.3, a = p0 = 1):
  // skewed, with its maximum 0.3100 at z = 0.4809. Sampled every 0.05 (the
  // default 3D mesh) on the axis and on nodes at s = 0.05 and 0.1 off it,
  // where it is lower by 0.05 s^2. Exact data: the fit's own bias, within
  // 0.1 %. With a 1e-3 scatter off the axis (the recovered 3D stress): the
  // issue's 3 %.
  auto shear = [](double z) {
    const double nu = 0.3, sz = -1 / (1 + z * z);
    const double sr = -(1 + nu) * (1 - z * std::atan(1 / z)) + 0.5 / (1 + z * z);
    return 0.5 * std::abs(sz - sr);
  };
  for (double scatter : {0.0, 1e-3})
  {
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 1.0);
    std::vector<fem::AxisNode> nodes;
    for (int i = 1; i <= 60; ++i)
    {
      const double z = 0.05 * i;
      nodes.push_back({z, 0.0, shear(z)});
      for (double s : {0.05, 0.1})
        nodes.push_back({z + 0.02, s, shear(z + 0.02) - 0.05 * s * s + scatter * noise(rng)});
    }
    const fem::DepthMaximum m = fem::maximum_along_axis(nodes, 1e-12);
    const double tolerance = scatter == 0 ? 0.001 : 0.03;
    SCOPED_TRACE(testing::Message() << "scatter " << scatter);
    EXPECT_NEAR(m.value, 0.3100, tolerance * 0.3100);
    EXPECT_NEAR(m.depth_m, 0.4809, tolerance * 0.4809);
  }
}
