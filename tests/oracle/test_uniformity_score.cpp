// The normalised score on hand-made densities, and the contact measure's
// conservation and mesh independence.
#include "core/error.h"
#include "geometry/face_areas.h"
#include "geometry/primitives.h"
#include "geometry/two_circle_roller.h"
#include "oracle/contact_density.h"
#include "oracle/rolling_dynamics.h"
#include "oracle/uniformity_score.h"
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;
using namespace rollcheck::oracle;

TEST(UniformityScore, UniformContactScoresZero)
{
  const Eigen::VectorXd areas = geometry::face_areas(geometry::icosphere(1, 2));
  const UniformityScore s = uniformity_score(3.7 * areas, areas);
  EXPECT_NEAR(s.normalised_variance, 0, 1e-15);
  EXPECT_NEAR(s.coverage, 1, 1e-14);
  EXPECT_NEAR(s.max_over_mean, 1, 1e-15);
}

TEST(UniformityScore, ContactOnOneFaceGivesTheClosedForm)
{
  // rho / rho_bar = A / a_k on face k, 0 elsewhere: U = A / a_k - 1.
  const Eigen::VectorXd areas = geometry::face_areas(geometry::uv_sphere(1, 6, 9));
  for (Eigen::Index k : {Eigen::Index(0), Eigen::Index(17)})
  {
    Eigen::VectorXd measure = Eigen::VectorXd::Zero(areas.size());
    measure[k] = 2.5;
    const UniformityScore s = uniformity_score(measure, areas);
    EXPECT_NEAR(s.normalised_variance, areas.sum() / areas[k] - 1, 1e-12 * areas.sum() / areas[k]);
    EXPECT_NEAR(s.coverage, areas[k] / areas.sum(), 1e-15);
  }
}

TEST(UniformityScore, UniformContactOnAFractionPhiGivesOneOverPhiMinusOne)
{
  const Eigen::VectorXd areas = geometry::face_areas(geometry::cylinder(1, 2, 30));
  Eigen::VectorXd measure = areas;
  double touched = 0;
  for (Eigen::Index f = 0; f < areas.size(); ++f)
    if (f % 4 < 2) // the cylinder's side triangles
      touched += areas[f];
    else
      measure[f] = 0;
  const double phi = touched / areas.sum();
  EXPECT_NEAR(uniformity_score(measure, areas).normalised_variance, 1 / phi - 1, 1e-12);
}

TEST(UniformityScore, RejectsBadInput)
{
  const Eigen::VectorXd areas = Eigen::VectorXd::Ones(3);
  EXPECT_THROW(uniformity_score(Eigen::VectorXd::Zero(3), areas), InputError) << "no contact";
  EXPECT_THROW(uniformity_score(Eigen::VectorXd::Ones(2), areas), InputError);
  EXPECT_THROW(uniformity_score(-Eigen::VectorXd::Ones(3), areas), InputError);
  EXPECT_THROW(uniformity_score(Eigen::VectorXd::Ones(3), Eigen::VectorXd::Zero(3)), InputError);
}

TEST(LineLoad, NoTensionRuleKeepsTheResultantAndItsMoment)
{
  const double force = 7.0, length = 1.3;
  for (double c : {0.5, 0.4, 1.0 / 3, 0.2, 0.05, 0.8, 0.97})
  {
    double total = 0, moment = 0, lowest = 1e9;
    const int n = 200000;
    for (int k = 0; k < n; ++k)
    {
      const double s = (k + 0.5) / n, p = line_load(force, c, length, s);
      total += p * length / n;
      moment += p * length / n * s;
      lowest = std::min(lowest, p);
    }
    EXPECT_NEAR(total, force, 1e-6 * force) << c;
    EXPECT_NEAR(moment / total, c, 1e-6) << c;
    EXPECT_GE(lowest, 0) << c;
  }
}

namespace
{
RollingTrajectory rolling_oloid()
{
  const geometry::RollerGenome genome{90, 1, 1, 2};
  const TwoCircleBody body = two_circle_body(roller_circles(genome, geometry::RollerFamily::centre_line, 1.0));
  const MassModel mass =
      mass_model_of_mesh(geometry::two_circle_roller(genome, geometry::RollerFamily::centre_line, 1.0, 1024), 1.0);
  RollingParameters p;
  p.duration_s = 3;
  return roll_on_ruling(body, mass, {resting_direction(body, mass, contact_curve_point(body, -Eigen::Vector3d::UnitZ())), 1.2, 0}, p);
}
} // namespace

TEST(ContactDensity, ConservesTheContactMeasureOnAnyMesh)
{
  const RollingTrajectory tr = rolling_oloid();
  for (const auto model : {ContactWidthModel::hertz, ContactWidthModel::rigid})
  {
    ContactWidth width;
    width.model = model;
    // The measure by the trapezoid rule on the samples, without any mesh.
    double expected = 0;
    for (std::size_t k = 0; k + 1 < tr.samples.size(); ++k)
      expected += 0.5 * (contact_measure_rate(tr.samples[k], tr.mode, width) + contact_measure_rate(tr.samples[k + 1], tr.mode, width)) *
                  (tr.samples[k + 1].time_s - tr.samples[k].time_s);
    for (int points : {40, 300})
      for (int parts : {1, 3})
      {
        const geometry::SurfaceMesh mesh = subdivide_faces(
            geometry::two_circle_roller({90, 1, 1, 2}, geometry::RollerFamily::centre_line, 1.0, points), parts);
        const ContactDensity d = contact_density(mesh, tr, width);
        EXPECT_NEAR(d.measure.sum(), expected, 1e-9 * expected) << points << " " << parts;
        EXPECT_NEAR(d.total_measure, expected, 1e-9 * expected);
        EXPECT_EQ(d.fallback_scans, 0);
      }
  }
}

TEST(ContactDensity, SubdividedFacesSumToTheirParentFace)
{
  // A face's cone is the union of its parts' cones: the parts' measures add up
  // to the parent's.
  const RollingTrajectory tr = rolling_oloid();
  const geometry::SurfaceMesh mesh = geometry::two_circle_roller({90, 1, 1, 2}, geometry::RollerFamily::centre_line, 1.0, 50);
  const int parts = 3;
  const ContactDensity coarse = contact_density(mesh, tr);
  const ContactDensity fine = contact_density(subdivide_faces(mesh, parts), tr);
  ASSERT_EQ(fine.measure.size(), coarse.measure.size() * parts * parts);
  for (Eigen::Index f = 0; f < coarse.measure.size(); ++f)
    EXPECT_NEAR(fine.measure.segment(f * parts * parts, parts * parts).sum(), coarse.measure[f],
                1e-9 * coarse.measure.maxCoeff());
  EXPECT_NEAR(fine.face_areas_m2.sum(), coarse.face_areas_m2.sum(), 1e-12);
}

TEST(ContactDensity, SphereTrackHoldsTheContactTime)
{
  const Ellipsoid sphere{Eigen::Vector3d::Ones()};
  RollingParameters p;
  p.duration_s = 1.5;
  const RollingTrajectory tr =
      roll_on_point(sphere, mass_model_of_ellipsoid(sphere, 1), {Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 2, 0)}, p);
  ContactWidth rigid;
  rigid.model = ContactWidthModel::rigid;
  const ContactDensity d = contact_density(geometry::icosphere(1, 3), tr, rigid, 1.25);
  EXPECT_NEAR(d.measure.sum(), 1.25, 1e-12) << "seconds of contact up to the end time";
  // The track is the great circle y = 0 of the body: every touched face meets it.
  const geometry::SurfaceMesh mesh = geometry::icosphere(1, 3);
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    if (d.measure[f] > 0)
    {
      double lo = 1, hi = -1;
      for (int k = 0; k < 3; ++k)
        lo = std::min(lo, mesh.vertices(mesh.faces(f, k), 1)), hi = std::max(hi, mesh.vertices(mesh.faces(f, k), 1));
      EXPECT_LE(lo, 1e-12);
      EXPECT_GE(hi, -1e-12);
    }
}
