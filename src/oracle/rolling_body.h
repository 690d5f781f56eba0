#pragma once
// A convex body prepared for rolling: face areas, and face centroids and
// vertices relative to the point it turns about (the surface centroid in
// paper-compatible mode, else the centre of mass), stored as separate x, y, z
// arrays for the height kernels; the vertex graph for the support search; mass
// properties for the dynamics.
#include "geometry/mass_properties.h"
#include "geometry/surface_mesh.h"
#include "oracle/paper_compat.h"
#include <Eigen/Core>
#include <vector>

namespace rollcheck::oracle
{
struct PointSet
{
  std::vector<double> x, y, z;
  std::size_t size() const { return x.size(); }
  Eigen::Vector3d point(std::size_t i) const { return {x[i], y[i], z[i]}; }
};

struct RollingBody
{
  Eigen::VectorXd face_areas;       ///< m^2
  Eigen::Vector3d origin;           ///< the point turned about, in mesh coordinates (m)
  PointSet centroids;               ///< face centroids minus origin (m)
  /// The centroids in single precision, for the contact prefilter.
  std::vector<float> centroid_x, centroid_y, centroid_z;
  PointSet vertices;                ///< vertices minus origin (m)
  /// Vertex graph (compressed rows): the neighbours of v are
  /// neighbours[neighbour_offsets[v] .. neighbour_offsets[v+1]).
  std::vector<int> neighbour_offsets, neighbours;
  /// Faces around each vertex (compressed rows, as the neighbours).
  std::vector<int> face_offsets, faces_around;
  bool every_vertex_on_a_face = true; ///< else the support search scans all vertices
  double size_m = 1.0;              ///< largest |coordinate| relative to origin, for tie tolerances
  geometry::MassProperties mass;    ///< in mesh coordinates, inertia for density 1
  Eigen::Vector3d centre_of_mass;   ///< minus origin (m)
};

/// InputError if the mesh has no faces or non-finite vertices.
RollingBody make_rolling_body(const geometry::SurfaceMesh& mesh, const PaperCompat& compat);
} // namespace rollcheck::oracle
