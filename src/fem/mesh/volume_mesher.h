#pragma once
// Which of gmsh's 3D algorithms tetrahedralises a scene's volumes, on the same
// surface mesh and size field:
// - delaunay: gmsh's Delaunay (Mesh.Algorithm3D 1), the scenes' default;
// - hxt: HXT (Mesh.Algorithm3D 10; T. Marot, J. Pellerin, J.-F. Remacle,
//   "One machine, one minute, three billion tetrahedra", Int. J. Numer.
//   Meth. Engng 117 (2019) 967-990), a Delaunay kernel with its own boundary
//   recovery and optimisation, run on one thread as every gmsh session here
//   (fem/mesh/gmsh_raw_mesh.h): the faster on large volumes, but in gmsh 4.8
//   not reproducible (the same geometry and sizes give slightly different
//   meshes from run to run), where Delaunay's meshes are the same every run.
//   Measurements: docs/methods/rims.md, "Where a rounded loop's time goes".
namespace rollcheck::fem
{
enum class VolumeMesher
{
  delaunay,
  hxt
};
} // namespace rollcheck::fem
