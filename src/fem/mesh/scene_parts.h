#pragma once
// For the scene mesh builders (fem/mesh/scene_mesh.h) and the whole-body
// mesh: the mesh gmsh made on rank 0 distributed as a SceneMesh, and its
// boundary parts tagged from predicates on points. Not for the solvers: they
// read the tags SceneMesh carries.
#include "core/seconds_since.h"
#include "fem/mesh/gmsh_raw_mesh.h"
#include "fem/mesh/scene_facets.h"
#include <chrono>
#include <functional>
#include <mpi.h>

namespace rollcheck::fem::scene_build
{
/// Whether a point (x, y, z) lies on a part (DOLFINx pads 2D points with
/// z = 0; the 2D vertical is y).
using Predicate = std::function<bool(double, double, double)>;

/// Boundary facets whose vertices all satisfy `on`.
std::vector<std::int32_t> boundary_facets(const dolfinx::mesh::Mesh& mesh, const Predicate& on);

/// The mesh `make_raw` returns on rank 0 (gmsh runs there only; its failure
/// is raised on every rank), distributed over `comm`; nothing tagged yet.
SceneMesh distribute(MPI_Comm comm, int gdim, const std::function<RawMesh()>& make_raw);

/// Where a scene's boundary parts lie, as predicates on points.
struct SceneParts
{
  Predicate symmetry_x, symmetry_y, top;
  Predicate curved;   ///< on the surface that may touch the plane
  Predicate in_plane; ///< in one of the scene's planes
  /// 3D: keep only the facets facing the plane z = 0 (outward normal's z
  /// component negative). A face that is vertical or turned away can never
  /// touch it, and as a contact facet it would dilute the recovered nodal
  /// pressure of the nodes it shares with the sheet (a square end's edge
  /// read about half its pressure: 0.27 of the interior against 0.52 on a
  /// structured grid with the sheet alone).
  bool facing_plane_only = false;
};

/// Tags the parts; the contact facets are the facets with all vertices on the
/// curved surface except those lying in a plane (a plane facet can have all
/// its vertices on a rim).
void tag_parts(SceneMesh& scene, const SceneParts& parts);

/// The contact facets of two bodies meshed as twins along an interface:
/// the boundary facets `on` it whose cell lies above (coordinate `up` > 0);
/// the lower body's twins lie at the same place, on cells below.
void upper_interface_facets(SceneMesh& scene, const Predicate& on, int up);
} // namespace rollcheck::fem::scene_build
