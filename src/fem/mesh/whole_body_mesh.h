#pragma once
// The whole body standing on the rigid plane z = 0 along its contact ruling,
// as an OpenCASCADE solid meshed by gmsh on rank 0 and distributed by
// DOLFINx (the whole-body check, study/whole_body/whole_body_check.h).
//
// Frame: the contact ruling runs along x from 0 to L, the body lies above
// z = 0, y is across the ruling. The body is modelled below the horizontal
// plane z = z_G through its centre of mass: that section is held rigid by the
// solver (fem/scenes/whole_body_contact.h), and a section whose every displacement
// is prescribed decouples the body above it exactly, so the part below is
// the whole body's mechanics at that loading (the slices' quarter discs,
// fem/scenes/slice_contact.h, are cut at their centre line the same way).
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
// Other convex bodies (build_mapped_body_mesh, the oloid): the same graded
// reference segment (radius r_ref, cut at z_G), extruded through the same
// layers, is MAPPED onto the body node by node, so that the elements stay long
// along the ruling and fine only across the strip. In the section plane of
// station a each reference node at angle psi (from straight down) and
// distance rho about the centre C = (a, 0, z_c) goes to
//   C + (rho / rho_ref(psi)) rho_body(a, psi') (sin psi', -cos psi'),
// rho_ref and rho_body the distances from C to the boundary of the reference
// segment and of the body below z_G along the ray (the body's by ray casting,
// geometry/convex_ray.h). psi' = psi + e2 psi^2 + e3 psi^3 on the curved
// part: unit slope at the contact line, so that the strip keeps its elements'
// size and shape across the ruling, and e2, e3 send the reference's corners
// (where its arc meets the cut) to the body's, the ends of its chord at z_G
// (the oloid's sections lean: at 5 % of the ruling the chord lies wholly on
// one side of the contact line); linear in angle over the cut. z_c = z_G / 2.
// Within end_zone of each end the section is frozen at the zone's station
// (the plane sections of a convex body degenerate towards its rims) and the
// layers are sheared,
//   x = a + z s(a),  s linear from -tan t_0 at a = 0 (tan t_L at a = L)
//                    to 0 at the zone's end,
// so that each end face is the plane through the ruling's end, containing the
// horizontal normal to the ruling and leaning out by the rim's overhang t
// (contact/rim_overhang.h): the plane the end model puts there
// (fem/scenes/rim_end_contact.h, interior angle 90 deg + t). The mesh's contact face
// is the faceted body's, at height z_f(a, y) (the lower end of the hull's
// vertical chord at the section's station); the exact sheet
// z_s = R(a) - sqrt(R(a)^2 - y^2) (R linear along the ruling) enters the
// contact's initial gap as z_s - z_f within |y| < R / 20 (beyond it the
// sheet stands R / 800, 12 um, above the plane: out of reach of an approach
// of 0.1 um): the gap z + u_z + z_s - z_f is the exact sheet's on the lower
// face, and still the height above it on an obtuse end's face, which faces
// the plane too.
//
// Grading: in the section, h(d) = min(far, contact + growth max(0, d - strip),
// edge + growth max(0, d - edge_zone)) with d the distance from the contact
// line (gmsh Distance + Threshold + Min);
// along the ruling, layers of end_layer at x = 0 and x = L growing by
// layer_growth towards the middle, up to largest_layer.
#include "fem/mesh/scene_mesh.h"
#include <Eigen/Core>
#include <array>
#include <functional>
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

/// A convex body standing on z = 0 along its contact ruling x in [0, L]
/// (the frame above), for build_mapped_body_mesh.
struct MappedBodyPose
{
  double length_m = 0;                         ///< L
  double cut_height_m = 0;                     ///< z_G, where the body is held
  double reference_radius_m = 0;               ///< r_ref of the reference segment (> z_G / 2)
  std::array<double, 2> radius_m{};            ///< R across the ruling at x = 0 and x = L
  std::array<double, 2> end_overhang_rad{};    ///< t_0, t_L: the rims' leans, outwards positive
  double end_zone_m = 0;                       ///< sheared, frozen end zones (> z_G |tan t|, < L / 2)
  /// The body's chord {t_min, t_max} on the line p + t d (d unit): the
  /// interval of t inside it (ComputationError if the line misses it).
  std::function<std::array<double, 2>(const Eigen::Vector3d& p, const Eigen::Vector3d& d)> chord;
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
  /// A point's position a along the ruling, whose node planes are
  /// planes_m (x itself unless the layers are sheared).
  std::function<double(const double* x)> along = [](const double* x) { return x[0]; };
  /// The contact's initial gap at a point (PenaltyContact::set_initial_gap),
  /// when the mesh's contact face is not the exact body's (none: it is).
  std::function<double(const double* x)> initial_gap;
  /// Whether a contact node lies on the body's lower face (the sheet), not up
  /// an end face that faces the plane (an obtuse end's): the edge pressure is
  /// the sheet's at the end, as the end model's.
  std::function<bool(const double* x)> on_sheet = [](const double*) { return true; };
};

/// Layer boundaries 0 = x_0 < ... < x_n = L: end_layer at both ends,
/// growing by layer_growth towards the middle, at most largest_layer, and
/// symmetric about L / 2. InputError for non-positive sizes.
std::vector<double> layer_planes(double length_m, const WholeBodySizes& sizes);

/// InputError for a bad pose or sizes (naming them), ComputationError when
/// gmsh fails; every rank gets its part.
WholeBodyMesh build_cylinder_body_mesh(MPI_Comm comm, const CylinderPose& pose, const WholeBodySizes& sizes);

/// The mapped mesh (above). Top facets the section z = z_G; contact facets
/// every other boundary facet facing the plane (outward normal's z < 0: the
/// body's lower surface and an obtuse end's face, as in the end model; a
/// square or acute end's face never faces it). InputError for a bad pose or
/// sizes (naming them), ComputationError when gmsh or the mapping fails (a
/// section whose centre lies outside the body, a fold); every rank gets its part.
WholeBodyMesh build_mapped_body_mesh(MPI_Comm comm, const MappedBodyPose& pose, const WholeBodySizes& sizes);

/// The body's own section at station_m as a plane-strain slab (the
/// sections' share rule, study/whole_body/section_share.h): the reference segment
/// mapped onto the section as build_mapped_body_mesh maps its node plane
/// there (frozen in the end zones the same way), one layer of thickness_m
/// along x. Its two faces are symmetry_x_facets: u_x = 0 on every node is
/// plane strain. Top: the cut z = z_G; contact: the facets facing down, with
/// the exact sheet's initial gap at the station the section is frozen at
/// (in the end zones R there, where the whole body takes R at its own a).
WholeBodyMesh build_mapped_section_mesh(MPI_Comm comm, const MappedBodyPose& pose, double station_m,
                                        double thickness_m, const WholeBodySizes& sizes);
} // namespace rollcheck::fem
