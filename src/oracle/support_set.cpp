#include "oracle/support_set.h"
#include "core/error.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace rollcheck::oracle
{
namespace
{
void require_tolerance(double relative_tolerance, const char* what)
{
  if (!std::isfinite(relative_tolerance) || relative_tolerance < 0)
    throw InputError(fmt::format("{}: relative tolerance must be finite and non-negative, got {}", what,
                                 relative_tolerance));
}

void require_rotation(const Eigen::Matrix3d& rotation, const char* what)
{
  if (!rotation.allFinite())
    throw InputError(fmt::format("{}: rotation matrix has non-finite entries", what));
  if ((rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).norm() > 1e-6 || rotation.determinant() < 0)
    throw InputError(fmt::format("{}: matrix is not a rotation (R^T R != I or det R < 0)", what));
}

double cross2(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

/// Andrew's monotone chain: indices into `points` of their convex hull,
/// counter-clockwise in the (x, y) plane, collinear points dropped.
std::vector<int> hull_2d(const std::vector<Eigen::Vector2d>& points)
{
  std::vector<int> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return points[a].x() < points[b].x() || (points[a].x() == points[b].x() && points[a].y() < points[b].y());
  });
  std::vector<int> hull(2 * order.size());
  std::size_t k = 0;
  for (int i : order)
  {
    while (k >= 2 && cross2(points[hull[k - 2]], points[hull[k - 1]], points[i]) <= 0)
      --k;
    hull[k++] = i;
  }
  for (std::size_t j = order.size() - 1, lower = k + 1; j-- > 0;)
  {
    const int i = order[j];
    while (k >= lower && cross2(points[hull[k - 2]], points[hull[k - 1]], points[i]) <= 0)
      --k;
    hull[k++] = i;
  }
  hull.resize(k - 1);
  return hull;
}
} // namespace

MeshSupportSet mesh_support_set(const geometry::SurfaceMesh& mesh, const Eigen::Matrix3d& rotation,
                                double relative_tolerance)
{
  require_tolerance(relative_tolerance, "mesh support set");
  require_rotation(rotation, "mesh support set");
  if (mesh.vertices.rows() == 0 || mesh.faces.rows() == 0)
    throw InputError("mesh support set: the mesh has no vertices or no faces");

  const Eigen::VectorXd z = mesh.vertices * rotation.row(2).transpose();
  const double size = (mesh.vertices.colwise().maxCoeff() - mesh.vertices.colwise().minCoeff()).norm();
  const double tolerance = relative_tolerance * size;
  MeshSupportSet support;
  support.lowest_height_m = z.minCoeff();

  std::vector<int> lowest;
  for (Eigen::Index i = 0; i < z.size(); ++i)
    if (z[i] <= support.lowest_height_m + tolerance)
      lowest.push_back(static_cast<int>(i));
  std::vector<bool> is_lowest(static_cast<std::size_t>(z.size()), false);
  for (int i : lowest)
    is_lowest[static_cast<std::size_t>(i)] = true;

  // World (x, y) of the lowest vertices: one point, a line or a polygon.
  std::vector<Eigen::Vector2d> xy;
  for (int i : lowest)
  {
    const Eigen::Vector3d p = rotation * mesh.vertices.row(i).transpose();
    xy.emplace_back(p.x(), p.y());
  }
  std::size_t far_a = 0, far_b = 0;
  for (std::size_t i = 1; i < xy.size(); ++i)
    if ((xy[i] - xy[0]).norm() > (xy[far_a] - xy[0]).norm())
      far_a = i;
  for (std::size_t i = 0; i < xy.size(); ++i)
    if ((xy[i] - xy[far_a]).norm() > (xy[far_b] - xy[far_a]).norm())
      far_b = i;
  const Eigen::Vector2d axis = xy[far_b] - xy[far_a];
  double off_line = 0;
  if (axis.norm() > tolerance)
    for (const auto& p : xy)
      off_line = std::max(off_line, std::abs(cross2(xy[far_a], xy[far_b], p)) / axis.norm());

  auto faces_with_lowest_corners = [&](int needed) {
    std::vector<int> faces;
    for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    {
      int count = 0;
      for (int k = 0; k < 3; ++k)
        count += is_lowest[static_cast<std::size_t>(mesh.faces(f, k))] ? 1 : 0;
      if (count >= needed)
        faces.push_back(static_cast<int>(f));
    }
    return faces;
  };

  if (axis.norm() <= tolerance)
  {
    // All lowest vertices coincide in plan (one vertex, or duplicates).
    support.kind = MeshSupportKind::vertex;
    const auto lowest_one = std::min_element(lowest.begin(), lowest.end(), [&](int a, int b) { return z[a] < z[b]; });
    support.vertices = {*lowest_one};
    std::fill(is_lowest.begin(), is_lowest.end(), false);
    is_lowest[static_cast<std::size_t>(*lowest_one)] = true;
    support.faces = faces_with_lowest_corners(1);
  }
  else if (off_line <= tolerance)
  {
    support.kind = MeshSupportKind::edge;
    const int a = lowest[far_a], b = lowest[far_b];
    support.vertices = {a, b};
    std::fill(is_lowest.begin(), is_lowest.end(), false);
    is_lowest[static_cast<std::size_t>(a)] = is_lowest[static_cast<std::size_t>(b)] = true;
    support.faces = faces_with_lowest_corners(2);
  }
  else
  {
    support.kind = MeshSupportKind::facet;
    // Seen from below (looking up +z) the world (x, y) frame is mirrored:
    // reverse the counter-clockwise-from-above hull.
    std::vector<int> ring = hull_2d(xy);
    std::reverse(ring.begin(), ring.end());
    for (int i : ring)
      support.vertices.push_back(lowest[static_cast<std::size_t>(i)]);
    support.faces = faces_with_lowest_corners(3);
  }
  return support;
}

std::vector<Circle> roller_circles(const geometry::RollerGenome& genome, geometry::RollerFamily family, double r1)
{
  // Validate through the mesh generator's own checks (same messages).
  geometry::roller_points(genome, family, r1, 3);
  const double theta = genome.theta_deg * std::numbers::pi / 180;
  const double r2 = genome.ratio * r1;
  std::vector<Circle> circles;
  if (genome.n_circles == 2)
  {
    const Eigen::Vector3d turn_axis =
        family == geometry::RollerFamily::paper ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(theta, turn_axis).toRotationMatrix();
    circles.push_back({Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY(), r1});
    circles.push_back({Eigen::Vector3d(genome.offset * r1, 0, 0), turn * Eigen::Vector3d::UnitY(), r2});
    return circles;
  }
  const Eigen::Matrix3d tilt = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitX()).toRotationMatrix();
  for (int i = 0; i < genome.n_circles; ++i)
  {
    const double azimuth = 2 * std::numbers::pi * i / genome.n_circles;
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(azimuth, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Vector3d centre(genome.offset * r1 * std::cos(azimuth), genome.offset * r1 * std::sin(azimuth), 0);
    circles.push_back({centre, turn * tilt * Eigen::Vector3d::UnitY(), i == 0 ? r1 : r2});
  }
  return circles;
}

std::vector<Circle> cylinder_rims(double radius_m, double height_m)
{
  if (!std::isfinite(radius_m) || radius_m <= 0)
    throw InputError(fmt::format("cylinder: radius (m) must be positive and finite, got {}", radius_m));
  if (!std::isfinite(height_m) || height_m <= 0)
    throw InputError(fmt::format("cylinder: height (m) must be positive and finite, got {}", height_m));
  return {{Eigen::Vector3d(0, 0, -height_m / 2), Eigen::Vector3d::UnitZ(), radius_m},
          {Eigen::Vector3d(0, 0, height_m / 2), Eigen::Vector3d::UnitZ(), radius_m}};
}

double circle_support(const Circle& circle, const Eigen::Vector3d& direction)
{
  const Eigen::Vector3d in_plane = direction - circle.normal * circle.normal.dot(direction);
  return circle.centre_m.dot(direction) + circle.radius_m * in_plane.norm();
}

Eigen::Vector3d circle_support_point(const Circle& circle, const Eigen::Vector3d& direction)
{
  const Eigen::Vector3d in_plane = direction - circle.normal * circle.normal.dot(direction);
  const double length = in_plane.norm();
  if (!(length > 0))
    throw ComputationError("circle support point: the direction is normal to the circle's plane, the whole rim "
                           "is extreme");
  return circle.centre_m + circle.radius_m * in_plane / length;
}

Eigen::Matrix3d circle_support_hessian(const Circle& circle, const Eigen::Vector3d& direction)
{
  const Eigen::Matrix3d projector = Eigen::Matrix3d::Identity() - circle.normal * circle.normal.transpose();
  const Eigen::Vector3d in_plane = projector * direction;
  const double length = in_plane.norm();
  if (!(length > 0))
    throw ComputationError("circle support Hessian: the direction is normal to the circle's plane");
  return circle.radius_m * (projector / length - in_plane * in_plane.transpose() / (length * length * length));
}

CircleSupportSet circle_hull_support_set(std::span<const Circle> circles, const Eigen::Matrix3d& rotation,
                                         double relative_tolerance)
{
  require_tolerance(relative_tolerance, "circle hull support set");
  require_rotation(rotation, "circle hull support set");
  if (circles.empty())
    throw InputError("circle hull support set: no circles");
  double size = 0;
  for (const Circle& c : circles)
    size = std::max(size, c.radius_m + (c.centre_m - circles[0].centre_m).norm());
  const double tolerance = relative_tolerance * size;

  const Eigen::Vector3d down = -rotation.row(2).transpose(); // body-frame direction of world -z
  std::vector<double> support(circles.size());
  for (std::size_t i = 0; i < circles.size(); ++i)
    support[i] = circle_support(circles[i], down);
  const double highest_support = *std::max_element(support.begin(), support.end());

  CircleSupportSet set;
  set.lowest_height_m = -highest_support;
  bool flat = false;
  for (std::size_t i = 0; i < circles.size(); ++i)
  {
    if (support[i] < highest_support - tolerance)
      continue;
    const Circle& c = circles[i];
    const Eigen::Vector3d in_plane = down - c.normal * c.normal.dot(down);
    set.circles.push_back(static_cast<int>(i));
    if (in_plane.norm() <= relative_tolerance)
    {
      flat = true;
      set.points_m.push_back(c.centre_m);
    }
    else
      set.points_m.push_back(circle_support_point(c, down));
  }
  if (flat)
    set.kind = CircleSupportKind::disc;
  else if (set.points_m.size() == 1)
    set.kind = CircleSupportKind::point;
  else
  {
    // Two or more lowest points: a segment unless they span an area.
    const Eigen::Vector3d& p0 = set.points_m[0];
    std::size_t far = 0;
    for (std::size_t i = 1; i < set.points_m.size(); ++i)
      if ((set.points_m[i] - p0).norm() > (set.points_m[far] - p0).norm())
        far = i;
    const Eigen::Vector3d axis = set.points_m[far] - p0;
    double off_line = 0;
    for (const auto& p : set.points_m)
      off_line = std::max(off_line, axis.norm() > 0 ? axis.cross(p - p0).norm() / axis.norm() : (p - p0).norm());
    if (axis.norm() <= tolerance)
      set.kind = CircleSupportKind::point;
    else
      set.kind = off_line <= tolerance ? CircleSupportKind::segment : CircleSupportKind::polygon;
  }
  return set;
}
} // namespace rollcheck::oracle
