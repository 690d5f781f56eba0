#include "contact/exact_curvature.h"
#include "core/error.h"
#include "geometry/face_centroids.h"
#include "geometry/gaussian_curvature.h"
#include "geometry/internal_angles.h"
#include "geometry/mean_curvature.h"
#include "geometry/vertex_areas.h"
#include <Eigen/Geometry>
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::contact
{
DevelopableCurvature developable_curvature(const oracle::Ruling& ruling, double s)
{
  if (!(s >= 0 && s <= 1))
    throw InputError(fmt::format("developable curvature: fraction along the ruling must lie in [0, 1], got {}", s));
  const double radius = (1 - s) * ruling.start_radius_m + s * ruling.end_radius_m;
  return {radius, 1 / radius, 1 / (2 * radius), 0.0};
}

FaceCurvatureComparison compare_face_curvatures(const geometry::SurfaceMesh& mesh, const oracle::TwoCircleBody& body)
{
  const Eigen::Index n_faces = mesh.faces.rows();
  const double size = std::max(body.first.radius_m, body.second.radius_m);
  // Which circle each vertex lies on (-1: neither).
  auto on_circle = [&](const oracle::Circle& c, const Eigen::Vector3d& p) {
    const Eigen::Vector3d d = p - c.centre_m;
    return std::abs(d.dot(c.normal)) < 1e-9 * size && std::abs(d.norm() - c.radius_m) < 1e-9 * size;
  };
  std::vector<int> circle_of(static_cast<std::size_t>(mesh.vertices.rows()), -1);
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
  {
    const Eigen::Vector3d p = mesh.vertices.row(v).transpose();
    circle_of[static_cast<std::size_t>(v)] = on_circle(body.first, p) ? 0 : on_circle(body.second, p) ? 1 : -1;
    if (circle_of[static_cast<std::size_t>(v)] < 0)
      throw InputError(fmt::format("curvature comparison: mesh vertex {} lies on neither circle", v));
  }

  const geometry::InternalAngles angles = geometry::internal_angles(mesh);
  const Eigen::VectorXd areas = geometry::mixed_voronoi_vertex_areas(mesh, angles);
  const Eigen::VectorXd vertex_mean = geometry::mean_curvature(mesh, angles, areas);
  const Eigen::VectorXd vertex_gaussian = geometry::gaussian_curvature(mesh, angles, areas);
  const geometry::Vertices centroids = geometry::face_centroids(mesh);

  FaceCurvatureComparison c;
  c.exact_mean_per_m = Eigen::VectorXd::Zero(n_faces);
  c.exact_gaussian_per_m2 = Eigen::VectorXd::Zero(n_faces);
  c.discrete_mean_per_m.resize(n_faces);
  c.discrete_gaussian_per_m2.resize(n_faces);
  c.ruled.assign(static_cast<std::size_t>(n_faces), false);
  for (Eigen::Index f = 0; f < n_faces; ++f)
  {
    int on_first = 0;
    for (int k = 0; k < 3; ++k)
    {
      c.discrete_mean_per_m[f] += vertex_mean[mesh.faces(f, k)] / 3;
      c.discrete_gaussian_per_m2[f] += vertex_gaussian[mesh.faces(f, k)] / 3;
      on_first += circle_of[static_cast<std::size_t>(mesh.faces(f, k))] == 0 ? 1 : 0;
    }
    if (on_first == 0 || on_first == 3)
      continue; // a flat piece of a circle's disc
    c.ruled[static_cast<std::size_t>(f)] = true;
    const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0)), b = mesh.vertices.row(mesh.faces(f, 1)),
                          d = mesh.vertices.row(mesh.faces(f, 2));
    const oracle::Ruling ruling = oracle::ruling_at(body, (b - a).cross(d - a).normalized());
    const double s = std::clamp((centroids.row(f).transpose() - ruling.start_m).dot(ruling.axis) / ruling.length_m, 0.0, 1.0);
    c.exact_mean_per_m[f] = developable_curvature(ruling, s).mean_per_m;
  }
  return c;
}
} // namespace rollcheck::contact
