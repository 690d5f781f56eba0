// Exact support sets: polyhedra against hand-made cases, the circle hulls
// against their closed forms and against their own inscribed meshes.
#include "geometry/convex_hull.h"
#include "core/error.h"
#include "geometry/primitives.h"
#include "geometry/two_circle_roller.h"
#include "oracle/rolling_dynamics.h"
#include "oracle/support_set.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;
using namespace rollcheck::oracle;
constexpr double pi = std::numbers::pi;

namespace
{
geometry::SurfaceMesh unit_cube()
{
  geometry::Vertices corners(8, 3);
  for (int i = 0; i < 8; ++i)
    corners.row(i) << (i & 1 ? 1 : -1), (i & 2 ? 1 : -1), (i & 4 ? 1 : -1);
  return geometry::convex_hull(corners, "cube");
}

/// A rotation whose body-frame image of world -z is `down` (unit).
Eigen::Matrix3d resting_on(const Eigen::Vector3d& down)
{
  return Eigen::Quaterniond::FromTwoVectors(down, -Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

std::vector<int> sorted(std::vector<int> v)
{
  std::sort(v.begin(), v.end());
  return v;
}
} // namespace

TEST(MeshSupportSet, CubeOnAFaceIsThatFace)
{
  const geometry::SurfaceMesh cube = unit_cube();
  const MeshSupportSet s = mesh_support_set(cube, Eigen::Matrix3d::Identity());
  ASSERT_EQ(s.kind, MeshSupportKind::facet);
  ASSERT_EQ(s.vertices.size(), 4u);
  for (int v : s.vertices)
    EXPECT_EQ(cube.vertices(v, 2), -1.0);
  ASSERT_EQ(s.faces.size(), 2u) << "the bottom square is two triangles";
  for (int f : s.faces)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(cube.vertices(cube.faces(f, k), 2), -1.0);
  EXPECT_DOUBLE_EQ(s.lowest_height_m, -1.0);
  // The ring is the square's boundary in order: consecutive corners differ in one coordinate.
  for (std::size_t i = 0; i < 4; ++i)
  {
    const Eigen::Vector3d d = cube.vertices.row(s.vertices[i]) - cube.vertices.row(s.vertices[(i + 1) % 4]);
    EXPECT_DOUBLE_EQ(d.norm(), 2.0);
  }
}

TEST(MeshSupportSet, CubeOnAnEdgeIsThatEdge)
{
  const geometry::SurfaceMesh cube = unit_cube();
  const Eigen::Matrix3d r = resting_on(Eigen::Vector3d(0, -1, -1).normalized());
  const MeshSupportSet s = mesh_support_set(cube, r);
  ASSERT_EQ(s.kind, MeshSupportKind::edge);
  ASSERT_EQ(s.vertices.size(), 2u);
  for (int v : s.vertices)
  {
    EXPECT_EQ(cube.vertices(v, 1), -1.0);
    EXPECT_EQ(cube.vertices(v, 2), -1.0);
  }
  EXPECT_NEAR(s.lowest_height_m, -std::sqrt(2.0), 1e-15);
  EXPECT_EQ(s.faces.size(), 2u) << "the two faces sharing the edge";
}

TEST(MeshSupportSet, CubeOnACornerIsThatVertex)
{
  const geometry::SurfaceMesh cube = unit_cube();
  const MeshSupportSet s = mesh_support_set(cube, resting_on(Eigen::Vector3d(1, 1, -1).normalized()));
  ASSERT_EQ(s.kind, MeshSupportKind::vertex);
  ASSERT_EQ(s.vertices.size(), 1u);
  EXPECT_EQ(Eigen::Vector3d(cube.vertices.row(s.vertices[0])), Eigen::Vector3d(1, 1, -1));
  EXPECT_NEAR(s.lowest_height_m, -std::sqrt(3.0), 1e-15);
}

TEST(MeshSupportSet, ToleranceIsRelativeToTheBodySize)
{
  // Tilting the resting cube by 1e-7 rad lifts one edge by ~2e-7 of its size:
  // a facet at tolerance 1e-6, an edge at the default.
  for (double scale : {1e-3, 1.0, 1e3})
  {
    geometry::SurfaceMesh cube = unit_cube();
    cube.vertices *= scale;
    const Eigen::Matrix3d tilt = Eigen::AngleAxisd(1e-7, Eigen::Vector3d::UnitX()).toRotationMatrix();
    EXPECT_EQ(mesh_support_set(cube, tilt, 1e-6).kind, MeshSupportKind::facet) << scale;
    EXPECT_EQ(mesh_support_set(cube, tilt).kind, MeshSupportKind::edge) << scale;
  }
}

TEST(MeshSupportSet, SphereTouchesAtAPoint)
{
  const geometry::SurfaceMesh sphere = geometry::icosphere(1.0, 3);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const MeshSupportSet s = mesh_support_set(sphere, r);
  EXPECT_EQ(s.kind, MeshSupportKind::vertex);
  EXPECT_TRUE(s.faces.size() == 5 || s.faces.size() == 6) << "a vertex of an icosphere has 5 or 6 faces";
  const Eigen::VectorXd z = sphere.vertices * r.row(2).transpose();
  EXPECT_EQ(z.minCoeff(), z[s.vertices[0]]);
}

TEST(MeshSupportSet, RejectsBadInput)
{
  const geometry::SurfaceMesh cube = unit_cube();
  EXPECT_THROW(mesh_support_set(cube, 2 * Eigen::Matrix3d::Identity()), InputError);
  EXPECT_THROW(mesh_support_set(cube, Eigen::Matrix3d::Identity(), -1), InputError);
  EXPECT_THROW(mesh_support_set(geometry::SurfaceMesh{}, Eigen::Matrix3d::Identity()), InputError);
}

TEST(CircleSupportSet, OloidOnARulingTouchesAlongASegmentBetweenItsCircles)
{
  const auto circles = roller_circles({90, 1, 1, 2}, geometry::RollerFamily::centre_line, 1.0);
  const TwoCircleBody body = two_circle_body(circles);
  for (const Eigen::Vector3d hint : {Eigen::Vector3d(0.3, -0.8, 0.1), Eigen::Vector3d(-0.2, 0.1, -0.9)})
  {
    const Eigen::Vector3d u = contact_curve_point(body, hint);
    const CircleSupportSet s = circle_hull_support_set(circles, resting_on(u));
    ASSERT_EQ(s.kind, CircleSupportKind::segment);
    ASSERT_EQ(s.circles, (std::vector<int>{0, 1}));
    for (int i = 0; i < 2; ++i)
    {
      const Circle& c = circles[static_cast<std::size_t>(i)];
      const Eigen::Vector3d p = s.points_m[static_cast<std::size_t>(i)];
      EXPECT_NEAR((p - c.centre_m).norm(), c.radius_m, 1e-14) << "end point on its circle";
      EXPECT_NEAR((p - c.centre_m).dot(c.normal), 0, 1e-14) << "end point in its circle's plane";
      EXPECT_NEAR(p.dot(u), -s.lowest_height_m, 1e-14) << "end point on the plane";
    }
  }
}

TEST(CircleSupportSet, OffTheCurveTheOloidTouchesAtOneRimPoint)
{
  // And the inscribed mesh's lowest vertex is within the sagitta r (1 - cos(pi/N)) of it.
  const auto circles = roller_circles({90, 1, 1, 2}, geometry::RollerFamily::centre_line, 1.0);
  const int n = 400;
  const geometry::SurfaceMesh mesh = geometry::two_circle_roller({90, 1, 1, 2}, geometry::RollerFamily::centre_line, 1.0, n);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.2, 0.9, -0.4).normalized()).toRotationMatrix();
  const CircleSupportSet s = circle_hull_support_set(circles, r);
  EXPECT_EQ(s.kind, CircleSupportKind::point);
  const MeshSupportSet m = mesh_support_set(mesh, r);
  EXPECT_GE(m.lowest_height_m, s.lowest_height_m - 1e-15) << "an inscribed mesh is never lower";
  EXPECT_LE(m.lowest_height_m - s.lowest_height_m, 1 - std::cos(pi / n) + 1e-15);
}

TEST(CircleSupportSet, FlatRimsAreDiscsAndTheCylinderSideIsARuling)
{
  const auto rims = cylinder_rims(1.0, 2.0);
  const CircleSupportSet on_cap = circle_hull_support_set(rims, Eigen::Matrix3d::Identity());
  EXPECT_EQ(on_cap.kind, CircleSupportKind::disc);
  EXPECT_EQ(on_cap.circles, std::vector<int>{0});
  EXPECT_DOUBLE_EQ(on_cap.lowest_height_m, -1.0);

  const CircleSupportSet on_side = circle_hull_support_set(rims, resting_on(Eigen::Vector3d::UnitX()));
  ASSERT_EQ(on_side.kind, CircleSupportKind::segment);
  EXPECT_NEAR((on_side.points_m[0] - Eigen::Vector3d(1, 0, -1)).norm(), 0, 1e-15);
  EXPECT_NEAR((on_side.points_m[1] - Eigen::Vector3d(1, 0, 1)).norm(), 0, 1e-15);

  // The preprint's (90, 1, 1) member rests on the flat disc of its second circle,
  // which the first circle touches at the disc's centre.
  const auto paper = roller_circles({90, 1, 1, 2}, geometry::RollerFamily::paper, 1.0);
  const CircleSupportSet on_disc = circle_hull_support_set(paper, resting_on(Eigen::Vector3d::UnitX()));
  EXPECT_EQ(on_disc.kind, CircleSupportKind::disc);
  EXPECT_EQ(on_disc.circles, (std::vector<int>{0, 1}));
}

TEST(CircleSupportSet, CirclesMatchTheMeshGenerator)
{
  // Every generated vertex lies on one of the analytic circles.
  for (const auto family : {geometry::RollerFamily::paper, geometry::RollerFamily::centre_line})
    for (const geometry::RollerGenome genome :
         {geometry::RollerGenome{120, 1.3, 0.8, 2}, geometry::RollerGenome{75, 0.7, 1.2, 3}})
    {
      const auto circles = roller_circles(genome, family, 0.5);
      const geometry::Vertices points = geometry::roller_points(genome, family, 0.5, 17);
      for (Eigen::Index i = 0; i < points.rows(); ++i)
      {
        const Circle& c = circles[static_cast<std::size_t>(i / 17)];
        const Eigen::Vector3d p = points.row(i).transpose() - c.centre_m;
        EXPECT_NEAR(p.norm(), c.radius_m, 1e-14);
        EXPECT_NEAR(p.dot(c.normal), 0, 1e-14);
      }
    }
}

TEST(CircleSupportSet, HessianIsTheDerivativeOfTheSupportPoint)
{
  const Circle c{Eigen::Vector3d(0.3, -0.2, 0.1), Eigen::Vector3d(1, 2, 2) / 3.0, 0.7};
  const Eigen::Vector3d u = Eigen::Vector3d(0.4, -0.5, 0.77).normalized();
  const Eigen::Matrix3d h = circle_support_hessian(c, u);
  const double step = 1e-6;
  for (int k = 0; k < 3; ++k)
  {
    const Eigen::Vector3d du = step * Eigen::Vector3d::Unit(k);
    const Eigen::Vector3d fd = (circle_support_point(c, u + du) - circle_support_point(c, u - du)) / (2 * step);
    EXPECT_NEAR((fd - h.col(k)).norm(), 0, 1e-8);
  }
  EXPECT_NEAR((h * u).norm(), 0, 1e-15) << "the support point does not move along u";
}
