#pragma once
// The gmsh pieces shared by the scene meshes (fem/mesh/scene_mesh.h) and the
// whole-body mesh (fem/mesh/whole_body_mesh.h), which run gmsh on rank 0
// (fem/on_rank_zero.h): a gmsh session, graded size fields, the mesh gmsh
// holds read into the arrays DOLFINx builds a mesh from, and that mesh
// distributed.
#include <dolfinx/mesh/Mesh.h>
#include <cstdint>
#include <functional>
#include <memory>
#include <mpi.h>
#include <string>
#include <vector>

namespace rollcheck::fem
{
/// Nodes and cells of a gmsh mesh in DOLFINx input form.
struct RawMesh
{
  std::vector<double> x;           ///< row-major, gdim columns
  std::vector<std::int64_t> cells; ///< rows into x, in gmsh's node order
};

/// The current gmsh model's mesh: its nodes with their first `dim`
/// coordinates, in gmsh's order, and its simplices of dimension `dim`
/// (tetrahedra, or triangles in 2D), volume by volume (surface by surface
/// in 2D), highest first. A node shared with a volume met before is given a
/// twin of its own, so that the volumes are separate bodies touching at their
/// shared faces. ComputationError for an element of dimension `dim` that is
/// not that simplex.
RawMesh read_gmsh_mesh(int dim);

/// A gmsh Threshold field on the distance field `distance_field`: size_min
/// up to the distance dist_min, then growing linearly by `growth` per unit of
/// distance until size_max. Returns its tag.
int add_threshold_field(int distance_field, double size_min, double size_max, double dist_min, double growth);

/// The size fields (or callback) alone set the element sizes: none from the
/// boundary, the points or the curvature.
void sizes_from_fields_alone();

/// `make` run in a gmsh session of its own: gmsh initialised, quiet, one
/// thread, the model `model_name` added; finalised afterwards whatever
/// happens. InputError passes through; any other failure is a
/// ComputationError "gmsh failed to mesh the `what`: ..." (gmsh 4.8 throws
/// std::string from some algorithms: its last error message says which).
RawMesh run_gmsh_session(const std::string& model_name, const std::string& what, const std::function<RawMesh()>& make);

/// Rank 0's mesh `raw` (the other ranks pass an empty one) distributed over
/// `comm` by DOLFINx: P1 tetrahedra (triangles for gdim 2) in gmsh's node
/// order, no ghosts, its facets and their cells connected.
std::shared_ptr<dolfinx::mesh::Mesh> distribute_raw_mesh(MPI_Comm comm, int gdim, const RawMesh& raw);
} // namespace rollcheck::fem
