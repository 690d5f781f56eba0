// Which mesh an end model is built on: the option's names and the mesh
// `auto` resolves to (fem/scenes/rim_end_contact.h).
#include "fem/scenes/rim_end_contact.h"
#include "fem/mesh/oblique_end_angle.h"

namespace rollcheck::fem
{
const NamedValues<RimEndMesh>& rim_end_mesh_names()
{
  static const NamedValues<RimEndMesh> names = {{"gmsh", RimEndMesh::delaunay},
                                                {"hxt", RimEndMesh::hxt},
                                                {"grid", RimEndMesh::grid},
                                                {"extruded", RimEndMesh::extruded},
                                                {"auto", RimEndMesh::automatic}};
  return names;
}

RimEndMesh rim_end_mesh_used(const RimEndStudy& study)
{
  const RimEndSettings& s = study.setup;
  if (s.counter_face == CounterFace::block)
    return s.mesh == RimEndMesh::hxt ? RimEndMesh::hxt : RimEndMesh::delaunay;
  if (s.mesh == RimEndMesh::automatic)
    return study.flat_sheet && !crosses_obliquely(s.crossing_angle_rad) ? RimEndMesh::extruded : RimEndMesh::delaunay;
  return s.mesh;
}
} // namespace rollcheck::fem
