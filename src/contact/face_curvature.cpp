#include "contact/face_curvature.h"
#include "geometry/gaussian_curvature.h"
#include "geometry/internal_angles.h"
#include "geometry/mean_curvature.h"
#include "geometry/vertex_areas.h"
#include <cmath>
#include <limits>

namespace rollcheck::contact
{
FaceCurvature face_curvature(const geometry::SurfaceMesh& mesh, const HertzParameters& hertz,
                             const oracle::PaperCompat& compat)
{
  const geometry::InternalAngles angles = geometry::internal_angles(mesh);
  const Eigen::VectorXd areas = compat.barycentric_vertex_area ? geometry::barycentric_vertex_areas(mesh, angles)
                                                               : geometry::mixed_voronoi_vertex_areas(mesh, angles);
  FaceCurvature c;
  c.vertex_mean = geometry::mean_curvature(mesh, angles, areas);
  if (compat.doubled_mean_curvature)
    c.vertex_mean *= 2.0;
  c.vertex_gaussian = geometry::gaussian_curvature(mesh, angles, areas);

  const Eigen::Index n = mesh.faces.rows();
  c.mean.resize(n);
  c.gaussian.resize(n);
  c.kappa1.resize(n);
  c.kappa2.resize(n);
  c.effective_radius_m.resize(n);
  for (Eigen::Index f = 0; f < n; ++f)
  {
    const int a = mesh.faces(f, 0), b = mesh.faces(f, 1), d = mesh.faces(f, 2);
    if (compat.face_curvature_vertex_mean)
    {
      c.mean[f] = (c.vertex_mean[a] + c.vertex_mean[b] + c.vertex_mean[d]) / 3;
      c.gaussian[f] = (c.vertex_gaussian[a] + c.vertex_gaussian[b] + c.vertex_gaussian[d]) / 3;
    }
    else
    {
      const double w = areas[a] + areas[b] + areas[d];
      c.mean[f] = w > 0 ? (areas[a] * c.vertex_mean[a] + areas[b] * c.vertex_mean[b] + areas[d] * c.vertex_mean[d]) / w
                        : 0.0;
      c.gaussian[f] = w > 0 ? (areas[a] * c.vertex_gaussian[a] + areas[b] * c.vertex_gaussian[b]
                               + areas[d] * c.vertex_gaussian[d])
                                  / w
                            : 0.0;
    }
    const double root = std::sqrt(std::max(c.mean[f] * c.mean[f] - c.gaussian[f], 0.0));
    c.kappa1[f] = c.mean[f] + root;
    c.kappa2[f] = c.mean[f] - root;
    const double k1 = std::abs(c.kappa1[f]), k2 = std::abs(c.kappa2[f]);
    const double floor = hertz.curvature_floor_per_m;
    if (k1 > floor && k2 > floor)
      c.effective_radius_m[f] = 1.0 / std::sqrt(k1 * k2);
    else if (k1 > floor)
      c.effective_radius_m[f] = 1.0 / k1;
    else
    {
      c.effective_radius_m[f] = std::numeric_limits<double>::infinity();
      ++c.flat_faces;
    }
  }
  return c;
}
} // namespace rollcheck::contact
