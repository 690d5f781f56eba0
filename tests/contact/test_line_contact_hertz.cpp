// Slice-by-slice line contact against plane-strain Hertz, and the exact
// curvature of the developable rollers against closed forms and the discrete
// estimates on their meshes.
#include "contact/exact_curvature.h"
#include "contact/hertz.h"
#include "contact/line_contact.h"
#include "geometry/convex_hull.h"
#include "core/error.h"
#include "geometry/face_areas.h"
#include "geometry/gaussian_curvature.h"
#include "geometry/internal_angles.h"
#include "geometry/mass_properties.h"
#include "geometry/two_circle_roller.h"
#include "oracle/rolling_dynamics.h"
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;
using namespace rollcheck::contact;
constexpr double pi = std::numbers::pi;

namespace
{
/// The preprint's material and SDS load: E = 200 GPa, nu = 0.3, E* = E / (2 (1 - nu^2)), F = 100 N.
constexpr double youngs = 200e9, poisson = 0.3, force = 100;
const double e_star = effective_modulus_identical_bodies(youngs, poisson);

oracle::TwoCircleBody oloid_body()
{
  return oracle::two_circle_body(oracle::roller_circles({90, 1, 1, 2}, geometry::RollerFamily::centre_line, 1.0));
}
} // namespace

TEST(SlicedLineContact, UniformRulingIsOnePlaneStrainHertzContact)
{
  const double length = 2, radius = 0.5;
  const SlicedLineContact c = sliced_line_contact(force, 0.5, length, radius, radius, e_star, poisson, 40);
  const LineHertz reference = line_contact(force / length, radius, e_star, poisson);
  EXPECT_NEAR(c.force_n, force, 1e-12 * force);
  EXPECT_NEAR(c.loaded_length_m, length, 1e-12);
  for (const auto& s : c.slices)
  {
    EXPECT_NEAR(s.load_n_per_m, force / length, 1e-12 * force);
    EXPECT_NEAR(s.hertz.peak_pressure_pa, reference.peak_pressure_pa, 1e-9 * reference.peak_pressure_pa);
    EXPECT_NEAR(s.hertz.half_width_m, reference.half_width_m, 1e-9 * reference.half_width_m);
  }
  EXPECT_NEAR(c.max_peak_pressure_pa, reference.peak_pressure_pa, 1e-9 * reference.peak_pressure_pa);
}

TEST(SlicedLineContact, TaperedEccentricRulingFollowsTheSliceFormula)
{
  // p0 = sqrt(p E* / (pi R)) in every slice; the load keeps its resultant and
  // centre; beyond the middle third only 3c of the ruling is loaded.
  const double length = 1.7, r0 = 0.05, r1 = 1.9;
  for (double c : {0.45, 0.2})
  {
    const int n = 200;
    const SlicedLineContact sliced = sliced_line_contact(force, c, length, r0, r1, e_star, poisson, n);
    EXPECT_NEAR(sliced.force_n, force, 1e-12 * force) << c;
    double moment = 0;
    for (const auto& s : sliced.slices)
    {
      moment += s.load_n_per_m * length / n * s.position_m;
      if (s.load_n_per_m > 0)
        EXPECT_NEAR(s.hertz.peak_pressure_pa, std::sqrt(s.load_n_per_m * e_star / (pi * s.radius_m)),
                    1e-9 * s.hertz.peak_pressure_pa);
    }
    EXPECT_NEAR(moment / force / length, c, 1e-5) << c;
    EXPECT_NEAR(sliced.loaded_length_m, std::min(1.0, 3 * c) * length, length / n + 1e-12) << c;
  }
  EXPECT_THROW(sliced_line_contact(force, 1.2, length, r0, r1, e_star, poisson), InputError);
  EXPECT_THROW(sliced_line_contact(force, 0.5, length, 0, r1, e_star, poisson), InputError);
  EXPECT_THROW(sliced_line_contact(-1, 0.5, length, r0, r1, e_star, poisson), InputError);
}

TEST(PointContactRadius, IsInfiniteOnDevelopableSurfaces)
{
  EXPECT_DOUBLE_EQ(point_contact_radius(2.0, 0.5), 1.0);
  EXPECT_TRUE(std::isinf(point_contact_radius(1.3, 0.0)));
  EXPECT_TRUE(std::isinf(point_contact_radius(1.3, -0.2)));
}

TEST(ExactCurvature, OloidRuledSurfaceHasTheOloidsArea)
{
  // integral L R dsigma ds over one loop of rulings = 4 pi r^2, and every
  // ruling is sqrt(3) r long (Dirnboeck and Stachel 1997): the ruling radii
  // R(s) and lengths are exact.
  const oracle::TwoCircleBody body = oloid_body();
  const int n = 20000;
  const oracle::ContactLoop loop =
      oracle::trace_contact_loop(body, oracle::contact_curve_point(body, -Eigen::Vector3d::UnitZ()), n);
  double area = 0;
  for (const auto& u : loop.directions)
  {
    const oracle::Ruling r = oracle::ruling_at(body, u);
    area += loop.turning_angle_rad / n * r.length_m * (r.start_radius_m + r.end_radius_m) / 2;
    EXPECT_GE(std::min(r.start_radius_m, r.end_radius_m), -1e-12) << "convex";
    EXPECT_NEAR(r.length_m, std::sqrt(3.0), 1e-12) << "every ruling of the oloid is sqrt(3) r long";
  }
  EXPECT_NEAR(area, 4 * pi, 1e-9);
}

TEST(ExactCurvature, CylinderSideHasHalfTheReciprocalRadius)
{
  const double radius = 0.8, height = 1.5;
  const auto rims = oracle::cylinder_rims(radius, height);
  geometry::Vertices points(2 * 64, 3);
  for (int k = 0; k < 128; ++k)
  {
    const double t = 2 * pi * (k % 64) / 64;
    points.row(k) << radius * std::cos(t), radius * std::sin(t), (k < 64 ? -1 : 1) * height / 2;
  }
  const geometry::SurfaceMesh mesh = geometry::convex_hull(points, "cylinder rims");
  const FaceCurvatureComparison c = compare_face_curvatures(mesh, oracle::two_circle_body(rims));
  int ruled = 0;
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
  {
    if (c.ruled[static_cast<std::size_t>(f)])
    {
      ++ruled;
      EXPECT_NEAR(c.exact_mean_per_m[f], 1 / (2 * radius), 1e-9);
    }
    else
      EXPECT_EQ(c.exact_mean_per_m[f], 0.0) << "caps are flat";
    EXPECT_EQ(c.exact_gaussian_per_m2[f], 0.0);
  }
  EXPECT_EQ(ruled, 128) << "two triangles per side panel";
}

TEST(ExactCurvature, DiscreteGaussianCurvatureOfTheOloidMeasuresItsRimsNotItsSurface)
{
  // Exact: K = 0 on every face. Discrete: the angle defects sit on the rim
  // vertices, total 4 pi at every resolution, so the area-weighted mean of the
  // face values stays near 4 pi / A = 1 for r = 1 instead of tending to 0.
  const oracle::TwoCircleBody body = oloid_body();
  for (int n : {100, 400})
  {
    const geometry::SurfaceMesh mesh = geometry::two_circle_roller({90, 1, 1, 2}, geometry::RollerFamily::centre_line, 1.0, n);
    const FaceCurvatureComparison c = compare_face_curvatures(mesh, body);
    const Eigen::VectorXd areas = geometry::face_areas(mesh);
    const double mean_discrete = c.discrete_gaussian_per_m2.dot(areas) / areas.sum();
    const double total_defect = geometry::angle_defects(mesh, geometry::internal_angles(mesh)).sum();
    EXPECT_NEAR(total_defect, 4 * pi, 1e-9);
    EXPECT_GT(mean_discrete, 0.5) << n;
    EXPECT_EQ(c.exact_gaussian_per_m2.cwiseAbs().maxCoeff(), 0.0);
    // The exact mean curvature lies between the ruling's end values: 1/(2 R) >= 1/(2 max R) = 1/4.
    for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
      if (c.ruled[static_cast<std::size_t>(f)])
        EXPECT_GE(c.exact_mean_per_m[f], 0.25 - 1e-9);
    std::printf("oloid N=%d: discrete K mean %.4f (exact 0), discrete H mean %.4f, exact H mean %.4f\n", n,
                mean_discrete, c.discrete_mean_per_m.dot(areas) / areas.sum(), c.exact_mean_per_m.dot(areas) / areas.sum());
  }
}

TEST(ExactCurvature, LineContactBesideThePreprintsPointContactOnTheRestingOloid)
{
  // The resting oloid (its ruling through the lowest centre of mass) under the
  // preprint's SDS load: slices with the exact radii, against point contact
  // with R = 1/sqrt(K) from the mean discrete K of the preprint's 400-point mesh.
  const oracle::TwoCircleBody body = oloid_body();
  const oracle::MassModel mass = oracle::mass_model_of_mesh(
      geometry::two_circle_roller({90, 1, 1, 2}, geometry::RollerFamily::centre_line, 1.0, 2048), 1.0);
  const oracle::Ruling r =
      oracle::ruling_at(body, oracle::resting_direction(body, mass, oracle::contact_curve_point(body, -Eigen::Vector3d::UnitZ())));
  // At rest the centre of mass is above the ruling: centre of pressure at its projection.
  const double cop = (mass.centre_of_mass_m - r.start_m).dot(r.axis) / r.length_m;
  EXPECT_NEAR(cop, 0.5, 1e-6) << "symmetric";
  const SlicedLineContact line = sliced_line_contact(force, cop, r.length_m, r.start_radius_m, r.end_radius_m, e_star, poisson);
  EXPECT_NEAR(line.force_n, force, 1e-9);
  const geometry::SurfaceMesh mesh = geometry::two_circle_roller({90, 1, 1, 2}, geometry::RollerFamily::centre_line, 1.0, 400);
  const FaceCurvatureComparison c = compare_face_curvatures(mesh, body);
  const Eigen::VectorXd areas = geometry::face_areas(mesh);
  const double discrete_k = c.discrete_gaussian_per_m2.dot(areas) / areas.sum();
  const PointHertz point = point_contact(force, 1 / std::sqrt(discrete_k), e_star, poisson);
  EXPECT_TRUE(std::isinf(point_contact_radius(0.0, 1 / r.start_radius_m))) << "exact: no point contact";
  std::printf("resting oloid, F = %.0f N: ruling %.4f m, R %.4f..%.4f m; line contact max p0 %.2f MPa, max von Mises "
              "%.2f MPa, loaded %.3f m; point contact with discrete R = %.4f m: p0 %.2f MPa\n",
              force, r.length_m, r.start_radius_m, r.end_radius_m, line.max_peak_pressure_pa / 1e6,
              line.max_von_mises_pa / 1e6, line.loaded_length_m, 1 / std::sqrt(discrete_k), point.peak_pressure_pa / 1e6);
  EXPECT_LT(line.max_peak_pressure_pa, point.peak_pressure_pa) << "a line spreads the load";
}
