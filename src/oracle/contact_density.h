#pragma once
// Contact time as a density on the body's surface, represented on a mesh.
//
// The rigid contact set C(t) of a rolling body (rolling_dynamics.h) is a ruling
// (line contact) or a point; it has no area, so the time a given surface
// point spends in contact is only defined once the contact has a width. Two
// measures are offered:
//
//  - ContactWidthModel::hertz (default, the physical one): the elastic contact
//    patch. Across a ruling of length L at fraction s in [0, 1], with line load
//    p(s) (N/m) and radius of normal curvature R(s) across the ruling, the
//    plane-strain Hertz half-width is b = sqrt(4 p R / (pi E*)) (K. L. Johnson,
//    "Contact Mechanics", CUP 1985, eq. 4.43). The measure is patch area x time,
//      mu(S) = integral dt integral over the ruling in S of 2 b(s) L ds  (m^2 s),
//    and its density rho = d mu / dA (s) is the time each point spends inside
//    the patch. The ruling sweeps the surface at speed |sigma'| R, so a point is
//    inside for rho = 2 b / (|sigma'| R) per pass. The load along the ruling is
//    the rigid-body normal force N placed with its centre of pressure c
//    (rolling_dynamics.h) by the no-tension linear (Winkler) rule of a rigid
//    footing: p linear over the whole ruling if 1/3 <= c <= 2/3, otherwise
//    triangular over the 3c (or 3(1 - c)) of it nearest the loaded end, the
//    rest of the ruling being out of contact. Point contact: a disc of radius
//    a = (3 N R / (4 E*))^(1/3) (Johnson eq. 4.22), R = sqrt(R_1 R_2); its
//    area pi a^2 is carried along the track of the contact point (the patch is
//    far smaller than any face).
//  - ContactWidthModel::rigid: unit width, the geometric sweep measure
//    mu(S) = integral dt length(C(t) n S) (m s), or for point contact the time
//    the contact point spends in S (s). Its line-contact density
//    1 / (|sigma'| R) grows like 1/R where a ruling end pivots on a rim
//    (R -> 0), which makes mesh scores converge slowly.
//
// Representation on a mesh: each face f collects mu of its radial cone, the
// surface points X with X - O in the cone spanned by f's corners minus O, for
// an interior centre O (the mesh's centre of mass). A convex surface and any
// convex mesh of it are radial graphs over the same sphere of directions, so
// the cones tile the true surface exactly, whatever the mesh. Between two
// samples each ruling sweeps a strip; it is cut into `strip_slices` slices
// along the ruling, each carrying its measure (two-point Gauss-Legendre on
// 1/64 of the ruling, mean of the two samples) uniformly over its two triangles (A0, A1, B1), (A0, B1, B0).
// A triangle's share in a face's cone is found exactly by clipping it, in
// barycentric coordinates, against the cone's three planes
// X . (P_k x P_k+1) >= 0 (Sutherland-Hodgman): nothing is lost or counted
// twice, and no hit-count aliasing arises however fine the mesh. The faces a
// triangle meets are found by walking across edges from the face containing
// its centroid. A point track is clipped the same way in one dimension.
#include "geometry/surface_mesh.h"
#include "oracle/line_load.h"
#include "oracle/rolling_dynamics.h"
#include <Eigen/Core>
#include <limits>

namespace rollcheck::oracle
{
enum class ContactWidthModel
{
  hertz,
  rigid
};

struct ContactWidth
{
  ContactWidthModel model = ContactWidthModel::hertz;
  /// E* of steel on steel, E / (2 (1 - nu^2)) with E = 200 GPa, nu = 0.3 (the
  /// preprint's material); normalised scores do not depend on it.
  double effective_modulus_pa = 200e9 / (2 * (1 - 0.3 * 0.3));
  int strip_slices = 16; ///< slices of each swept strip along the ruling (hertz; divides 64)
};

/// d mu / dt of the part [s0, s1] of a sample's contact ruling: the patch area
/// (m^2, hertz) or the length (m, rigid); for point contact the patch area
/// pi a^2 (hertz) or 1 (rigid), whatever s0 and s1.
double contact_measure_rate(const RollingSample& sample, ContactMode mode, const ContactWidth& width, double s0 = 0,
                            double s1 = 1);

/// Every face cut into parts^2 similar triangles (edges in `parts` equal
/// segments, shared edges cut once, so the mesh stays closed and conforming;
/// the new vertices lie in the old faces' planes). The hull meshes of the
/// two-circle rollers have faces that run the whole length of a ruling from one
/// circle to the other, so adding points per circle never resolves the density
/// along the rulings; subdividing the faces does.
geometry::SurfaceMesh subdivide_faces(const geometry::SurfaceMesh& mesh, int parts);

/// The radial cones of a closed convex mesh's faces.
struct FaceCones
{
  Eigen::Vector3d centre_m;            ///< O, the mesh's centre of mass
  geometry::Vertices corners;          ///< vertices minus O
  geometry::Faces faces;
  geometry::Faces neighbours;          ///< (f, k): the face across f's edge from corner k to corner k+1
  Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor> planes; ///< P_k x P_k+1, k = 0, 1, 2
};

/// InputError unless the mesh is closed, consistently oriented and has O inside.
FaceCones face_cones(const geometry::SurfaceMesh& mesh);

/// Face whose cone holds `point` (body frame), walking from `guess`.
int locate_face(const FaceCones& cones, const Eigen::Vector3d& point, int guess = 0);

struct ContactDensity
{
  Eigen::VectorXd measure;       ///< mu per face: m^2 s (hertz), m s or s (rigid line or point)
  Eigen::VectorXd face_areas_m2;
  ContactWidth width;
  double total_measure = 0;      ///< the accumulated contact measure; equals measure.sum()
  long fallback_scans = 0;       ///< elements the edge walk could not finish (scanned over all faces)
};

/// Contact measure of `trajectory` up to `end_time_s` (the last strip is cut by
/// linear interpolation of its end ruling), on `mesh` (same body frame).
ContactDensity contact_density(const geometry::SurfaceMesh& mesh, const RollingTrajectory& trajectory,
                               const ContactWidth& width = {},
                               double end_time_s = std::numeric_limits<double>::infinity());

/// rho per face, measure / area (s for hertz).
Eigen::VectorXd density_per_area(const ContactDensity& density);
} // namespace rollcheck::oracle
