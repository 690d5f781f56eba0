#pragma once
// Exact support set of a convex body resting on the horizontal plane z = 0:
// the part of its surface that is lowest in the world frame, i.e. the face of
// the body exposed in direction -e_z (R. Schneider, "Convex Bodies: the
// Brunn-Minkowski Theory", 2nd ed., CUP 2014, sec. 1.7).
//
// For a body given in its body frame and turned by a rotation R (body to world),
// the exposed direction in the body frame is u = R^T (-e_z), and
//   support function      h(u) = max_{X in body} X . u,
//   support set           F(u) = { X in body : X . u = h(u) },
//   lowest world height   z_min = -h(u).
//
// Polyhedra (a closed convex triangle mesh): F(u) is a vertex, an edge or a
// facet. Vertices within `relative_tolerance` times the body's bounding-box
// diagonal of the lowest one are taken as lowest; this replaces the preprint's
// "face centroid within 0.04 m of the lowest centroid", which is a band of
// fixed thickness whatever the body's size or resolution.
//
// Convex hulls of circles (the two-circle rollers of geometry/two_circle_roller.h
// and the cylinder as the hull of its two rims): the support function of a
// hull of sets is the maximum of theirs, and its support set is the hull of the
// support sets of the sets that reach the maximum. A circle with centre c, unit
// normal m and radius r has
//   h(u) = c . u + r |P u|,   P = I - m m^T,
//   support point s(u) = c + r P u / |P u|   (the gradient of h),
//   ds/du = r (P / |P u| - (P u)(P u)^T / |P u|^3)   (the Hessian of h),
// and when P u = 0 (the circle lies flat) its whole disc rim is lowest. So the
// analytic support set is a point (one circle reaches the minimum), a segment
// (two do: a ruling of the developable surface), a polygon (three or more of the
// n-circle rollers), or a disc (a circle lies flat on the plane).
#include "geometry/surface_mesh.h"
#include "geometry/two_circle_roller.h"
#include <Eigen/Core>
#include <span>
#include <vector>

namespace rollcheck::oracle
{
/// Relative tolerance that separates "lowest" from "not lowest": exact rotations
/// of exact vertices differ by rounding (~1e-16 of the size), so 1e-9 only
/// merges what is lowest up to rounding.
inline constexpr double default_support_tolerance = 1e-9;

enum class MeshSupportKind
{
  vertex,
  edge,
  facet
};

struct MeshSupportSet
{
  MeshSupportKind kind = MeshSupportKind::vertex;
  /// vertex: the vertex; edge: its two end vertices; facet: the vertices of its
  /// boundary polygon, counter-clockwise seen from below.
  std::vector<int> vertices;
  /// Faces whose closure meets the plane in the support set: vertex: the faces
  /// around it; edge: the faces sharing it; facet: the faces lying in the plane.
  std::vector<int> faces;
  double lowest_height_m = 0; ///< z_min of the turned (not translated) body
};

/// Support set of the convex mesh turned by `rotation` (body to world).
/// InputError for an empty mesh, a non-finite rotation or a negative tolerance.
MeshSupportSet mesh_support_set(const geometry::SurfaceMesh& mesh, const Eigen::Matrix3d& rotation,
                                double relative_tolerance = default_support_tolerance);

/// A circle in the body frame.
struct Circle
{
  Eigen::Vector3d centre_m;
  Eigen::Vector3d normal; ///< unit normal of its plane
  double radius_m;
};

/// The generating circles of geometry::roller_points (same frame, same order).
std::vector<Circle> roller_circles(const geometry::RollerGenome& genome, geometry::RollerFamily family, double r1);
/// The rims of geometry::cylinder(radius, height, ...): z = -height/2 and +height/2.
std::vector<Circle> cylinder_rims(double radius_m, double height_m);

/// h(u) of one circle (m); `direction` need not be unit.
double circle_support(const Circle& circle, const Eigen::Vector3d& direction);
/// s(u); requires |P u| > 0 (ComputationError otherwise).
Eigen::Vector3d circle_support_point(const Circle& circle, const Eigen::Vector3d& direction);
/// ds/du for a unit direction u (1/m^0: m per unit change of u).
Eigen::Matrix3d circle_support_hessian(const Circle& circle, const Eigen::Vector3d& direction);

enum class CircleSupportKind
{
  point,
  segment,
  polygon,
  disc
};

struct CircleSupportSet
{
  CircleSupportKind kind = CircleSupportKind::point;
  /// Indices of the circles that reach the lowest height.
  std::vector<int> circles;
  /// Body-frame support points of those circles, in the same order (for a flat
  /// circle: its centre, the whole rim being lowest).
  std::vector<Eigen::Vector3d> points_m;
  double lowest_height_m = 0;
};

/// Support set of the hull of `circles` turned by `rotation`; circles within
/// relative_tolerance * (largest radius + largest centre distance) of the lowest
/// height, or with |P u| below relative_tolerance, count as lowest or flat.
CircleSupportSet circle_hull_support_set(std::span<const Circle> circles, const Eigen::Matrix3d& rotation,
                                         double relative_tolerance = default_support_tolerance);
} // namespace rollcheck::oracle
