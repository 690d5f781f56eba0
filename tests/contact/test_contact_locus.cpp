// Stratified sampling and contact loci (fem-sds): the picks against their
// definition, the loci of the cylinder and the oloid against closed forms and
// a brute-force count of the preprint's contact faces.
#include "contact/contact_locus.h"
#include "contact/rim_overhang.h"
#include <cstdio>
#include "geometry/body.h"
#include "core/error.h"
#include "oracle/contact_density.h"
#include "oracle/rolling_body.h"
#include "oracle/rolling_study.h"
#include "oracle/stratified_samples.h"
#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <limits>
#include <numbers>
#include <set>

using namespace rollcheck;

namespace
{
Eigen::Matrix3d resting_on(const Eigen::Vector3d& down)
{
  return Eigen::Quaterniond::FromTwoVectors(down.normalized(), -Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

/// Faces whose centroid is within eps of the lowest centroid, by brute force.
std::vector<int> faces_within(const geometry::SurfaceMesh& mesh, const Eigen::Matrix3d& rotation, double eps)
{
  std::vector<double> heights;
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
  {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
      centroid += mesh.vertices.row(mesh.faces(f, k)).transpose() / 3;
    heights.push_back(rotation.row(2).dot(centroid));
  }
  const double lowest = *std::min_element(heights.begin(), heights.end());
  std::vector<int> faces;
  for (std::size_t f = 0; f < heights.size(); ++f)
    if (heights[f] - lowest < eps)
      faces.push_back(static_cast<int>(f));
  return faces;
}

struct Body
{
  geometry::BodySpec spec;
  geometry::SurfaceMesh mesh;
  oracle::RollingBody rolling;
  std::vector<oracle::Circle> circles;
};

Body make(const std::string& name)
{
  geometry::BodySpec spec;
  spec.body = name;
  geometry::SurfaceMesh mesh = geometry::make_body(spec);
  oracle::RollingBody rolling = oracle::make_rolling_body(mesh, oracle::PaperCompat::reference());
  return {spec, mesh, rolling, oracle::line_contact_circles(spec)};
}
} // namespace

TEST(StratifiedSamples, OnePickPerStratumReproducibleFromTheSeed)
{
  const auto a = oracle::stratified_samples(1000, 12, 7);
  ASSERT_EQ(a.size(), 12u);
  for (std::size_t j = 0; j < a.size(); ++j)
  {
    EXPECT_GE(a[j], j * 1000 / 12);
    EXPECT_LT(a[j], (j + 1) * 1000 / 12);
  }
  EXPECT_EQ(a, oracle::stratified_samples(1000, 12, 7));
  EXPECT_NE(a, oracle::stratified_samples(1000, 12, 8));
  const auto all = oracle::stratified_samples(5, 5, 3);
  EXPECT_EQ(all, (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  EXPECT_THROW(oracle::stratified_samples(5, 6, 1), InputError);
  EXPECT_THROW(oracle::stratified_samples(5, 0, 1), InputError);
}

TEST(ContactLocus, CylinderOnItsSideTouchesAGeneratorWithCreasesAtBothRims)
{
  const Body b = make("cylinder"); // r = 1, height 2, axis z
  const Eigen::Matrix3d rotation = resting_on(Eigen::Vector3d(1, 0.3, 0));
  const contact::ContactLocus locus =
      contact::contact_locus(b.circles, b.rolling.mass.centre_of_mass, b.rolling, rotation, {});
  ASSERT_EQ(locus.support.kind, oracle::CircleSupportKind::segment);
  ASSERT_TRUE(locus.ruling);
  EXPECT_NEAR(locus.ruling->length_m, 2.0, 1e-12);
  EXPECT_NEAR(locus.ruling->start_radius_m, 1.0, 1e-9);
  EXPECT_NEAR(locus.ruling->end_radius_m, 1.0, 1e-9);
  EXPECT_NEAR(locus.centre_of_pressure, 0.5, 1e-12);
  EXPECT_TRUE(locus.in_equilibrium);
  EXPECT_EQ(locus.loaded_from, 0.0);
  EXPECT_EQ(locus.loaded_to, 1.0);
  EXPECT_EQ(locus.creases.size(), 2u);
  // The preprint's faces: the threshold search equals the brute-force count
  // (ground at the lowest centroid, as the reference).
  EXPECT_EQ(locus.oracle_faces, faces_within(b.mesh, rotation, 0.04));
}

TEST(ContactLocus, TiltedCylinderStandsOnARimPoint)
{
  const Body b = make("cylinder");
  const contact::ContactLocus locus = contact::contact_locus(
      b.circles, b.rolling.mass.centre_of_mass, b.rolling, resting_on(Eigen::Vector3d(1, 0, -0.2)), {});
  EXPECT_EQ(locus.support.kind, oracle::CircleSupportKind::point);
  EXPECT_FALSE(locus.ruling);
  ASSERT_EQ(locus.creases.size(), 1u);
  EXPECT_NE(locus.creases[0].find("rim"), std::string::npos);
}

TEST(ContactLocus, OloidAlongItsContactCurveHasTheStaticCentreOfPressure)
{
  const Body b = make("oloid");
  const oracle::TwoCircleBody pair = oracle::two_circle_body(b.circles);
  const Eigen::Vector3d centre = b.rolling.mass.centre_of_mass;
  std::set<std::size_t> crease_counts;
  for (const Eigen::Vector3d hint : {Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(0.3, -1, -0.2),
                                     Eigen::Vector3d(-1, 0.2, 0.4)})
  {
    const Eigen::Vector3d u = oracle::contact_curve_point(pair, hint);
    const contact::ContactLocus locus =
        contact::contact_locus(b.circles, centre, b.rolling, resting_on(u), {});
    ASSERT_EQ(locus.support.kind, oracle::CircleSupportKind::segment);
    const oracle::Ruling& r = *locus.ruling;
    // Independent: the centre of mass's foot on the segment, by least squares.
    const Eigen::Vector3d d = r.end_m - r.start_m;
    const double foot = d.dot(centre - r.start_m) / d.squaredNorm();
    EXPECT_NEAR(locus.centre_of_pressure, foot, 1e-12);
    EXPECT_TRUE(locus.in_equilibrium);
    // No-tension rule: the loaded part has length min(1, 3 c, 3 (1 - c)) of the ruling.
    const double c = foot;
    EXPECT_NEAR(locus.loaded_to - locus.loaded_from, std::min({1.0, 3 * c, 3 * (1 - c)}), 1e-12);
    EXPECT_EQ(locus.creases.size(), (c >= 1.0 / 3 && c <= 2.0 / 3) ? 2u : 1u);
    crease_counts.insert(locus.creases.size());
    // Every ruling point lies in a face whose cone holds it.
    const oracle::FaceCones cones = oracle::face_cones(b.mesh);
    const std::vector<double> fractions{0.1, 0.5, 0.9};
    const std::vector<int> faces = contact::faces_along_ruling(cones, locus, fractions);
    ASSERT_EQ(faces.size(), 3u);
    for (std::size_t k = 0; k < faces.size(); ++k)
    {
      const Eigen::Vector3d x = r.start_m + fractions[k] * d - cones.centre_m;
      for (int e = 0; e < 3; ++e)
        EXPECT_GE(cones.planes.row(faces[k]).segment<3>(3 * e).dot(x), -1e-12 * x.norm());
    }
  }
}

TEST(ContactLocus, FewerThanTwoCirclesIsAnInputError)
{
  const Body b = make("oloid");
  const std::vector<oracle::Circle> one{b.circles[0]};
  EXPECT_THROW(contact::contact_locus(one, Eigen::Vector3d::Zero(), b.rolling, Eigen::Matrix3d::Identity(), {}),
               InputError);
}

namespace
{
/// Largest x . n over points sampled densely on every circle, by brute force.
double sampled_support(const std::vector<oracle::Circle>& circles, const Eigen::Vector3d& n)
{
  double best = -1e300;
  for (const oracle::Circle& c : circles)
  {
    const Eigen::Vector3d e1 = c.normal.unitOrthogonal(), e2 = c.normal.cross(e1);
    for (int k = 0; k < 200000; ++k)
    {
      const double a = 2 * std::numbers::pi * k / 200000;
      best = std::max(best, (c.centre_m + c.radius_m * (std::cos(a) * e1 + std::sin(a) * e2)).dot(n));
    }
  }
  return best;
}
} // namespace

TEST(RimOverhang, CylinderRimsAreSquareAndTheOloidsOtherFaceSupportsTheHull)
{
  const Body cylinder = make("cylinder");
  const contact::ContactLocus side = contact::contact_locus(
      cylinder.circles, cylinder.rolling.mass.centre_of_mass, cylinder.rolling, resting_on(Eigen::Vector3d(1, 0.3, 0)), {});
  const auto square = contact::rim_overhang(cylinder.circles, side.support.circles[0], side.support.circles[1], *side.ruling);
  EXPECT_NEAR(square[0], 0.0, 1e-9);
  EXPECT_NEAR(square[1], 0.0, 1e-9);

  // The oloid: the other face at each ruling end is a supporting plane of the
  // hull through that end (checked on 200,000 points per circle), not the
  // ground's.
  const Body oloid = make("oloid");
  const oracle::TwoCircleBody pair = oracle::two_circle_body(oloid.circles);
  const Eigen::Vector3d u = oracle::contact_curve_point(pair, Eigen::Vector3d(0.3, -1, -0.2));
  const contact::ContactLocus locus =
      contact::contact_locus(oloid.circles, oloid.rolling.mass.centre_of_mass, oloid.rolling, resting_on(u), {});
  const oracle::Ruling& r = *locus.ruling;
  const std::array<Eigen::Vector3d, 2> ends{r.start_m, r.end_m};
  for (int e = 0; e < 2; ++e)
  {
    const Eigen::Vector3d n = contact::other_face_normal(oloid.circles, locus.support.circles[e], ends[e], r.direction);
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    EXPECT_GT((n - r.direction).norm(), 1e-3) << "end " << e; // a real edge
    EXPECT_NEAR(sampled_support(oloid.circles, n), ends[e].dot(n), 1e-6) << "end " << e;
  }
  const auto overhang = contact::rim_overhang(oloid.circles, locus.support.circles[0], locus.support.circles[1], r);
  for (double t : overhang)
    EXPECT_TRUE(std::abs(t) < std::numbers::pi / 2) << t;
  std::printf("oloid rim overhangs %.2f, %.2f deg\n", overhang[0] * 180 / std::numbers::pi,
              overhang[1] * 180 / std::numbers::pi);
}

namespace
{
/// The other face's normal by brute force, from its definition (the first
/// turn psi of u about the rim's tangent, away from the contact, at which
/// another circle's support reaches `point`, or the direction leaves the
/// circle's outward side): a march in steps of 2e-3 rad, then bisection.
Eigen::Vector3d other_face_normal_by_march(const std::vector<oracle::Circle>& circles, int on,
                                           const Eigen::Vector3d& point, const Eigen::Vector3d& u)
{
  const oracle::Circle& c = circles[static_cast<std::size_t>(on)];
  const Eigen::Vector3d radial = (point - c.centre_m - (point - c.centre_m).dot(c.normal) * c.normal).normalized();
  const Eigen::Vector3d turn = c.normal.cross(radial).cross(u).normalized();
  auto direction = [&](double sense, double psi) { return Eigen::Vector3d(std::cos(psi) * u + sense * std::sin(psi) * turn); };
  auto excess = [&](double sense, double psi) {
    double worst = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < circles.size(); ++k)
      if (static_cast<int>(k) != on)
        worst = std::max(worst, oracle::circle_support(circles[k], direction(sense, psi)) - point.dot(direction(sense, psi)));
    return worst;
  };
  const double sense = excess(1.0, 1e-3) < excess(-1.0, 1e-3) ? 1.0 : -1.0;
  auto done = [&](double psi) { return excess(sense, psi) >= 0 || direction(sense, psi).dot(radial) <= 0; };
  double lo = 1e-3, hi = 1e-3;
  while (!done(hi))
    lo = hi, hi += 2e-3;
  for (int i = 0; i < 80; ++i)
    (done(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
  return direction(sense, lo);
}
} // namespace

TEST(RimOverhang, OtherFaceNormalIsTheFirstTurnAtWhichAnotherCircleReachesTheEnd)
{
  // The closed form (a quadratic in tan(psi) per circle) against the march,
  // at the support points of both circles over the directions of the sphere,
  // on the oloid, the cylinder and rollers across the family.
  std::vector<geometry::BodySpec> specs(3);
  specs[0].body = "oloid";
  specs[1].body = "cylinder";
  specs[2].body = "paper-oloid";
  for (const geometry::RollerGenome& g : {geometry::RollerGenome{60, 0.7, 0.65}, geometry::RollerGenome{120, 1.3, 0.8},
                                          geometry::RollerGenome{100, 1.1, 1.4}})
  {
    geometry::BodySpec roller;
    roller.body = "roller";
    roller.genome = g;
    specs.push_back(roller);
  }
  int compared = 0;
  for (const geometry::BodySpec& spec : specs)
  {
    const std::vector<oracle::Circle> circles = oracle::line_contact_circles(spec);
    for (int i = 0; i < 400; ++i)
    {
      // Directions spread over the sphere (a Fibonacci lattice).
      const double z = 1 - (2 * i + 1) / 400.0, phi = i * std::numbers::pi * (3 - std::sqrt(5.0));
      const Eigen::Vector3d u(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
      for (int on = 0; on < 2; ++on)
      {
        const oracle::Circle& c = circles[static_cast<std::size_t>(on)];
        // The point must be a support point of the hull, off the circle's axis.
        if (oracle::circle_support(c, u) < oracle::circle_support(circles[1 - on], u) - 1e-12 ||
            (u - c.normal * c.normal.dot(u)).norm() < 1e-3)
          continue;
        const Eigen::Vector3d point = oracle::circle_support_point(c, u);
        const Eigen::Vector3d closed = contact::other_face_normal(circles, on, point, u);
        const Eigen::Vector3d marched = other_face_normal_by_march(circles, on, point, u);
        EXPECT_NEAR(closed.norm(), 1.0, 1e-12);
        EXPECT_LT((closed - marched).norm(), 1e-9) << geometry::body_label(spec) << " u " << u.transpose() << " on " << on;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 1000);
}
