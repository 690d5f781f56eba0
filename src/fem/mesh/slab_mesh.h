#pragma once
// The slab's mesh (build_slab_mesh, fem/scenes/slab_contact.h), built with
// the gmsh C++ API on rank 0 and distributed by DOLFINx.
//
// Geometry: the neighbourhood of a contact ruling of length L along
// x in [0, L], the y >= 0 half by symmetry: the quarter disc of the
// plane-strain scene (fem/mesh/hertz_mesh.h), of radius
// R(x) = R_0 + (R_L - R_0) x / L in each section x = const, stacked along the
// ruling. It is a cone (a cylinder if R_0 = R_L) touching z = 0 along the
// ruling, whose sections across the ruling are exactly the slices of
// fem/scenes/slice_contact.h. Its end faces are free; they are the planes
// x = 0 and x = L, meeting the curved surface at a right-angled edge, or,
// with an overhang t, sheared so that the end face leans out by t from the
// vertical (an edge of interior angle 90 deg + t):
// x = a + z s(a), s linear from -tan t_0 at a = 0 to tan t_L at a = L.
//
// Grading: the plane-strain section meshed at unit radius with the section
// grading (MeshGrading in units of the local radius) and extruded in layers
// (gmsh structured extrusion, each prism split into tetrahedra), then scaled
// by R(x) and sheared.
//
// Tags (SceneMesh, Model::solid conventions): contact, the curved surface off
// the end faces, y = 0 and the top; top, z = R(x); symmetry_y, y = 0; no
// symmetry_x (the end faces are free). Symmetry multiplicity 2.
#include "fem/mesh/mesh_grading.h"
#include "fem/mesh/scene_facets.h"
#include <array>
#include <mpi.h>
#include <vector>

namespace rollcheck::fem
{
struct SlabGeometry
{
  double length_m = 0;        ///< L, along the ruling
  double start_radius_m = 0;  ///< R_0, at x = 0
  double end_radius_m = 0;    ///< R_L, at x = L
  /// Layer boundaries along the ruling as fractions of L, increasing, ending at 1.
  std::vector<double> layer_fractions;
  /// Lean of the end faces at x = 0 and x = L from the vertical, outwards
  /// positive, within +-60 deg.
  std::array<double, 2> end_overhang_rad{0.0, 0.0};
};

/// The position a along the ruling of a point x of the slab (the inverse of
/// its shear; x[0] itself without overhang).
double slab_along(const SlabGeometry& slab, const double* x);

/// `section_grading` in units of the local radius (the section at unit
/// radius). InputError for an end overhang beyond +-60 deg.
SceneMesh build_slab_mesh(MPI_Comm comm, const SlabGeometry& slab, const MeshGrading& section_grading);
} // namespace rollcheck::fem
