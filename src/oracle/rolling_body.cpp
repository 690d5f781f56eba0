#include "oracle/rolling_body.h"
#include "core/error.h"
#include "geometry/face_areas.h"
#include "geometry/face_centroids.h"
#include <algorithm>
#include <cmath>

namespace rollcheck::oracle
{
namespace
{
PointSet relative_to(const geometry::Vertices& points, const Eigen::Vector3d& origin)
{
  PointSet set;
  const auto n = static_cast<std::size_t>(points.rows());
  set.x.resize(n);
  set.y.resize(n);
  set.z.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    set.x[i] = points(static_cast<Eigen::Index>(i), 0) - origin.x();
    set.y[i] = points(static_cast<Eigen::Index>(i), 1) - origin.y();
    set.z[i] = points(static_cast<Eigen::Index>(i), 2) - origin.z();
  }
  return set;
}
} // namespace

RollingBody make_rolling_body(const geometry::SurfaceMesh& mesh, const PaperCompat& compat)
{
  if (mesh.faces.rows() == 0 || mesh.vertices.rows() < 4)
    throw InputError("rolling body: the mesh has no faces");
  if (!mesh.vertices.allFinite())
    throw InputError("rolling body: the mesh has non-finite vertices");
  RollingBody body;
  body.mass = geometry::mass_properties(mesh);
  body.face_areas = geometry::face_areas(mesh);
  body.origin = compat.rotate_about_surface_centroid ? body.mass.surface_centroid : body.mass.centre_of_mass;
  body.centre_of_mass = body.mass.centre_of_mass - body.origin;
  body.centroids = relative_to(geometry::face_centroids(mesh), body.origin);
  body.vertices = relative_to(mesh.vertices, body.origin);

  for (std::size_t f = 0; f < body.centroids.size(); ++f)
  {
    body.centroid_x.push_back(static_cast<float>(body.centroids.x[f]));
    body.centroid_y.push_back(static_cast<float>(body.centroids.y[f]));
    body.centroid_z.push_back(static_cast<float>(body.centroids.z[f]));
  }

  const auto nv = static_cast<std::size_t>(mesh.vertices.rows());
  std::vector<std::vector<int>> adjacent(nv), around(nv);
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    for (int c = 0; c < 3; ++c)
    {
      const int a = mesh.faces(f, c), b = mesh.faces(f, (c + 1) % 3);
      if (a < 0 || b < 0 || static_cast<std::size_t>(a) >= nv || static_cast<std::size_t>(b) >= nv)
        throw InputError("rolling body: a face refers to a vertex that does not exist");
      adjacent[static_cast<std::size_t>(a)].push_back(b);
      adjacent[static_cast<std::size_t>(b)].push_back(a);
      around[static_cast<std::size_t>(a)].push_back(static_cast<int>(f));
    }
  body.neighbour_offsets.assign(nv + 1, 0);
  body.face_offsets.assign(nv + 1, 0);
  for (std::size_t v = 0; v < nv; ++v)
  {
    auto& list = adjacent[v];
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    if (list.empty())
      body.every_vertex_on_a_face = false;
    body.neighbours.insert(body.neighbours.end(), list.begin(), list.end());
    body.neighbour_offsets[v + 1] = static_cast<int>(body.neighbours.size());
    body.faces_around.insert(body.faces_around.end(), around[v].begin(), around[v].end());
    body.face_offsets[v + 1] = static_cast<int>(body.faces_around.size());
  }
  double size = 0;
  for (std::size_t i = 0; i < nv; ++i)
    size = std::max({size, std::abs(body.vertices.x[i]), std::abs(body.vertices.y[i]), std::abs(body.vertices.z[i])});
  for (std::size_t i = 0; i < body.centroids.size(); ++i)
    size = std::max({size, std::abs(body.centroids.x[i]), std::abs(body.centroids.y[i]), std::abs(body.centroids.z[i])});
  body.size_m = size > 0 ? size : 1.0;
  return body;
}
} // namespace rollcheck::oracle
