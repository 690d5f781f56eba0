#pragma once
// The whole body standing on the rigid plane z = 0 along its contact ruling,
// as an OpenCASCADE solid meshed by gmsh on rank 0 and distributed by
// DOLFINx (issue 14's whole-body check, study/whole_body_check.h).
//
// Frame: the contact ruling runs along x from 0 to L, the body lies above
// z = 0, y is across the ruling. The body is modelled below the horizontal
// plane z = z_G through its centre of mass: that section is held rigid by the
// solver (fem/whole_body_contact.h), and a section whose every displacement
// is prescribed decouples the body above it exactly, so the part below is
// the whole body's mechanics at that loading (the slices' quarter discs,
// fem/slice_contact.h, are cut at their centre line the same way).
//
// Cylinder (radius r, length L, axis at height r): the solid is the disc
// segment z <= z_G of the end face x = 0 extruded along the axis by L with
// OpenCASCADE (occ::extrude), the same solid as addCylinder cut at z_G, but
// with gmsh's structured layers along the ruling (each prism split into
// tetrahedra): elements as long as the pressure's slow variation along the
// ruling allows in the middle, thin at the ends, and fine only across the
// contact strip. gmsh 4.8's Delaunay and HXT mesh isotropically: elements of
// b / 6 along a 20 mm ruling at b = 20 um would be 6000 per row of the strip
// (millions of tetrahedra), which no 10-minute run solves.
//
// Grading: in the section, h(d) = min(far, contact + growth max(0, d - strip),
// edge + growth max(0, d - edge_zone)) with d the distance from the contact
// line (gmsh Distance + Threshold + Min);
// along the ruling, layers of end_layer at x = 0 and x = L growing by
// layer_growth towards the middle, up to largest_layer.
#include "fem/scene_mesh.h"
#include <mpi.h>
#include <vector>

namespace rollcheck::fem
{
struct WholeBodySizes
{
  double contact_m = 0;         ///< element size across the ruling within the strip
  double strip_half_width_m = 0; ///< the strip |y| < this along the ruling (1.5 b)
  double growth = 0.3;          ///< section element size per distance beyond the strip
  double far_m = 0;             ///< largest section element
  /// The section also refined to edge_m within edge_zone_m of the contact
  /// line (0: not), so that the end layers' elements are as small across and
  /// in depth as along the ruling there (isotropic at the ends, as the end
  /// model's edge elements): growth as above.
  double edge_m = 0;
  double edge_zone_m = 0;
  double end_layer_m = 0;       ///< thickness of the layers at x = 0 and x = L
  double layer_growth = 1.5;    ///< ratio of neighbouring layers' thicknesses
  double largest_layer_m = 0;   ///< in the middle of the ruling
};

/// A cylinder lying on the plane along a generator: radius r, length L, axis
/// (x, 0, r); modelled below z = cut_height (the centre of mass's height r).
struct CylinderPose
{
  double radius_m = 0;
  double length_m = 0;
  double cut_height_m = 0; ///< in (0, 2 r)
};

struct WholeBodyMesh
{
  /// Model::solid conventions, symmetry multiplicity 1, no symmetry planes;
  /// top facets the section z = cut_height; contact facets the curved surface.
  SceneMesh scene;
  double length_m = 0;
  std::vector<double> planes_m; ///< node planes along the ruling, 0 ... L
  std::int64_t section_nodes = 0;
  double gmsh_s = 0;           ///< gmsh on rank 0
};

/// Layer boundaries 0 = x_0 < ... < x_n = L: end_layer at both ends,
/// growing by layer_growth towards the middle, at most largest_layer, and
/// symmetric about L / 2. InputError for non-positive sizes.
std::vector<double> layer_planes(double length_m, const WholeBodySizes& sizes);

/// InputError for a bad pose or sizes (naming them), ComputationError when
/// gmsh fails; every rank gets its part.
WholeBodyMesh build_cylinder_body_mesh(MPI_Comm comm, const CylinderPose& pose, const WholeBodySizes& sizes);
} // namespace rollcheck::fem
