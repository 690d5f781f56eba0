#pragma once
// Which of gmsh's 3D algorithms tetrahedralises a scene's volumes, on the same
// surface mesh and size field:
// - delaunay: gmsh's Delaunay (Mesh.Algorithm3D 1), the scenes' default;
// - hxt: HXT (Mesh.Algorithm3D 10; T. Marot, J. Pellerin, J.-F. Remacle,
//   "One machine, one minute, three billion tetrahedra", Int. J. Numer.
//   Meth. Engng 117 (2019) 967-990), a Delaunay kernel with its own boundary
//   recovery and optimisation, run on one thread as every gmsh session here
//   (fem/mesh/gmsh_raw_mesh.h), so that a mesh does not depend on the
//   machine's threads. On the rim loop's first rounded end (1.2M DOFs) it
//   meshed in 59.6 s against Delaunay's 351.3 s (docs/methods/rims.md).
namespace rollcheck::fem
{
enum class VolumeMesher
{
  delaunay,
  hxt
};
} // namespace rollcheck::fem
