#include "geometry/convex_hull.h"
#include "core/error.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdio>
#include <fmt/format.h>
#include <unordered_map>
#include <vector>

extern "C"
{
#include <libqhull_r/qhull_ra.h>
}

namespace rollcheck::geometry
{
SurfaceMesh convex_hull(const Vertices& points, std::string_view what)
{
  if (points.rows() < 4)
    throw InputError(fmt::format("{}: a convex hull needs at least 4 points, got {}", what, points.rows()));
  if (!points.allFinite())
    throw InputError(fmt::format("{}: points contain NaN or infinity", what));

  std::vector<coordT> coords(points.data(), points.data() + points.size());
  qhT qh_storage;
  qhT* qh = &qh_storage;
  QHULL_LIB_CHECK
  qh_zero(qh, nullptr);
  // Qhull reports errors on this stream; keep its messages out of our output.
  FILE* errors = std::tmpfile();
  // Triangulated output. Coplanar facets (a roller's flat disc) are fanned
  // from another apex than trimesh picks, so face sets can differ there from
  // the reference's meshes (docs/methods/oracles.md#limits).
  char options[] = "qhull Qt";
  const int status = qh_new_qhull(qh, 3, static_cast<int>(points.rows()), coords.data(), False, options,
                                  nullptr, errors);
  std::string qhull_message;
  if (status != 0 && errors)
  {
    std::rewind(errors);
    char line[256];
    if (std::fgets(line, sizeof line, errors))
      qhull_message = line;
  }
  if (errors)
    std::fclose(errors);
  if (status != 0)
  {
    qh_freeqhull(qh, !qh_ALL);
    int curlong, totlong;
    qh_memfreeshort(qh, &curlong, &totlong);
    throw InputError(fmt::format("{}: the convex hull is flat or degenerate (qhull: {})", what,
                                 qhull_message.empty() ? "error" : qhull_message.substr(0, qhull_message.find('\n'))));
  }

  // Hull vertices are renumbered in order of their input index, so the mesh
  // does not depend on Qhull's internal ordering.
  std::vector<int> used;
  vertexT* vertex;
  FORALLvertices used.push_back(qh_pointid(qh, vertex->point));
  std::sort(used.begin(), used.end());
  std::unordered_map<int, int> index_of;
  SurfaceMesh hull;
  hull.vertices.resize(static_cast<Eigen::Index>(used.size()), 3);
  for (std::size_t i = 0; i < used.size(); ++i)
  {
    index_of[used[i]] = static_cast<int>(i);
    hull.vertices.row(static_cast<Eigen::Index>(i)) = points.row(used[i]);
  }

  std::vector<std::array<int, 3>> triangles;
  facetT* facet;
  FORALLfacets
  {
    std::array<int, 3> tri{};
    int k = 0;
    vertexT** vertexp;
    FOREACHvertex_(facet->vertices)
    {
      if (k < 3)
        tri[k] = index_of.at(qh_pointid(qh, vertex->point));
      ++k;
    }
    if (k != 3)
      continue;
    // Orient by the facet's outward normal, not by Qhull's vertex order.
    const Eigen::Vector3d a = hull.vertices.row(tri[0]), b = hull.vertices.row(tri[1]),
                          c = hull.vertices.row(tri[2]);
    const Eigen::Vector3d normal(facet->normal[0], facet->normal[1], facet->normal[2]);
    if ((b - a).cross(c - a).dot(normal) < 0)
      std::swap(tri[1], tri[2]);
    triangles.push_back(tri);
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong, totlong;
  qh_memfreeshort(qh, &curlong, &totlong);

  hull.faces.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t f = 0; f < triangles.size(); ++f)
    for (int j = 0; j < 3; ++j)
      hull.faces(static_cast<Eigen::Index>(f), j) = triangles[f][j];
  return hull;
}
} // namespace rollcheck::geometry
