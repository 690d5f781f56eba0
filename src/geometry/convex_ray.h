#pragma once
// Where a ray from inside a closed convex triangle mesh leaves it. The mesh
// is the intersection of its faces' half-spaces n_f . x <= h_f (n_f the
// outward unit normal), so the ray p + t d (d unit) leaves it at
//   t = min over faces with n_f . d > 0 of (h_f - n_f . p) / (n_f . d).
// Used to map a reference mesh onto a convex body section by section
// (fem/whole_body_mesh.h build_mapped_body_mesh).
#include "geometry/surface_mesh.h"
#include <Eigen/Core>
#include <vector>

namespace rollcheck::geometry
{
struct HalfSpaces
{
  std::vector<Eigen::Vector3d> normals; ///< outward, unit
  std::vector<double> offsets;          ///< h_f = n_f . (a vertex of face f)
};

/// The faces' half-spaces of a closed convex mesh with outward faces
/// (geometry::make_body's); InputError for a degenerate face.
HalfSpaces half_spaces(const SurfaceMesh& mesh);

/// t above for a unit `direction`; ComputationError if `from` lies outside
/// (beyond a face by more than 1e-12 of the body's offsets) or no face faces
/// the ray.
double ray_exit_distance(const HalfSpaces& body, const Eigen::Vector3d& from, const Eigen::Vector3d& direction);
} // namespace rollcheck::geometry
