#pragma once
// Where a line crosses a closed convex triangle mesh. The mesh is the
// intersection of its faces' half-spaces n_f . x <= h_f (n_f the outward unit
// normal), so the line p + t d lies inside it for
//   max over n_f . d < 0 of (h_f - n_f . p) / (n_f . d)  <=  t  <=
//   min over n_f . d > 0 of (h_f - n_f . p) / (n_f . d),
// and n_f . p <= h_f for the faces parallel to d (Cyrus-Beck clipping).
// Used to map a reference mesh onto a convex body section by section
// (fem/mesh/whole_body_mesh.h build_mapped_body_mesh).
#include "geometry/surface_mesh.h"
#include <Eigen/Core>
#include <array>
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

/// The interval {t_min, t_max} above for a unit `direction`;
/// ComputationError if the line misses the body.
std::array<double, 2> line_chord(const HalfSpaces& body, const Eigen::Vector3d& point, const Eigen::Vector3d& direction);
} // namespace rollcheck::geometry
