#pragma once
// What every scene mesh builder returns (fem/mesh/scene_mesh.h): the
// distributed mesh and the boundary facets its solver needs, tagged by the
// builder. A facet list is local to the rank (owned facets, sorted); a
// builder whose scene has no such part leaves its list empty.
#include <dolfinx/mesh/Mesh.h>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace rollcheck::fem
{
struct SceneMesh
{
  std::shared_ptr<dolfinx::mesh::Mesh> mesh;
  /// Local facet indices (sorted) of the curved surface that may touch the plane.
  std::vector<std::int32_t> contact_facets;
  /// Loaded face z = R, where the prescribed approach acts.
  std::vector<std::int32_t> top_facets;
  /// Symmetry planes: x = 0 (the Hertz scenes; the axis in the axisymmetric
  /// one) and y = 0 (solid and slab).
  std::vector<std::int32_t> symmetry_x_facets;
  std::vector<std::int32_t> symmetry_y_facets;
  /// The model covers 1 / multiplicity of the body (plane strain 2, solid 4).
  int symmetry_multiplicity = 1;
  double wall_s = 0; ///< gmsh and mesh distribution
};

/// The unit outward normals' z components of the given boundary facets (3D,
/// triangles): outward is away from the midpoint of the facet's cell.
std::vector<double> outward_normal_z(const dolfinx::mesh::Mesh& mesh, std::span<const std::int32_t> facets);
} // namespace rollcheck::fem
