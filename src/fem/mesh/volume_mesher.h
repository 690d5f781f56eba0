#pragma once
// Which of gmsh's 3D algorithms tetrahedralises a scene's volumes, on the same
// surface mesh and size field:
// - delaunay: gmsh's Delaunay (Mesh.Algorithm3D 1), the scenes' default;
// - hxt: HXT (Mesh.Algorithm3D 10; T. Marot, J. Pellerin, J.-F. Remacle,
//   "One machine, one minute, three billion tetrahedra", Int. J. Numer.
//   Meth. Engng 117 (2019) 967-990), a Delaunay kernel with its own boundary
//   recovery and optimisation, run on one thread as every gmsh session here
//   (fem/mesh/gmsh_raw_mesh.h). On the rim loop's first rounded end (1.2M
//   DOFs) it meshed in 59.6 s against Delaunay's 351.3 s. gmsh 4.8's HXT is
//   not reproducible: the same end meshed twice, even with OMP_NUM_THREADS=1,
//   has a few dozen nodes more or less (docs/methods/rims.md); Delaunay's
//   meshes are the same from run to run.
namespace rollcheck::fem
{
enum class VolumeMesher
{
  delaunay,
  hxt
};
} // namespace rollcheck::fem
