// The whole body's mesh (fem/mesh/whole_body_mesh.h): gmsh OpenCASCADE on rank 0,
// structured layers along the ruling, distributed by DOLFINx.
#include "fem/mesh/whole_body_mesh.h"
#include "core/error.h"
#include "fem/mesh/gmsh_raw_mesh.h"
#include "fem/mesh/scene_parts.h"
#include "fem/on_rank_zero.h"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/mesh/utils.h>
#include <fmt/format.h>
#include <functional>
#include <numbers>
#include <gmsh.h>

namespace rollcheck::fem
{
using scene_build::boundary_facets;

namespace
{
/// The disc segment z <= c of the circle of radius r about (0, r) in gmsh's
/// xy-plane (gmsh x is the body's y, gmsh y its z), graded about the contact
/// point, extruded along gmsh z through the given planes, meshed.
RawMesh mesh_extruded_segment(double r, double c, const std::vector<double>& planes, const WholeBodySizes& sizes)
{
  namespace occ = gmsh::model::occ;
  namespace field = gmsh::model::mesh::field;
  return run_gmsh_session("whole_body", "whole body", [&] {
    gmsh::option::setNumber("Mesh.Algorithm", 6); // Frontal-Delaunay in the section
    const double w = std::sqrt(std::max(0.0, r * r - (c - r) * (c - r)));
    const int pole = occ::addPoint(0, 0, 0);
    const int centre = occ::addPoint(0, r, 0);
    const int left = occ::addPoint(-w, c, 0);
    const int right = occ::addPoint(w, c, 0);
    const int arc_left = occ::addCircleArc(left, centre, pole);
    const int arc_right = occ::addCircleArc(pole, centre, right);
    const int top = occ::addLine(right, left);
    const int section = occ::addPlaneSurface({occ::addCurveLoop({arc_left, arc_right, top})});
    const double L = planes.back();
    std::vector<double> heights;
    for (std::size_t i = 1; i < planes.size(); ++i)
      heights.push_back(planes[i] / L);
    gmsh::vectorpair out;
    occ::extrude({{2, section}}, 0, 0, L, out, std::vector<int>(heights.size(), 1), heights, false);
    occ::synchronize();

    const int distance = field::add("Distance");
    field::setNumbers(distance, "PointsList", {static_cast<double>(pole)});
    const int threshold
        = add_threshold_field(distance, sizes.contact_m, sizes.far_m, sizes.strip_half_width_m, sizes.growth);
    int background = threshold;
    if (sizes.edge_m > 0)
    {
      const int edge = add_threshold_field(distance, sizes.edge_m, sizes.far_m, sizes.edge_zone_m, sizes.growth);
      background = field::add("Min");
      field::setNumbers(background, "FieldsList", {static_cast<double>(threshold), static_cast<double>(edge)});
    }
    field::setAsBackgroundMesh(background);
    sizes_from_fields_alone();
    gmsh::model::mesh::generate(3);

    RawMesh raw = read_gmsh_mesh(3);
    // gmsh (across, up, along) -> (along, across, up)
    for (std::size_t i = 0; i < raw.x.size(); i += 3)
      std::rotate(raw.x.begin() + i, raw.x.begin() + i + 2, raw.x.begin() + i + 3);
    // The extruded tetrahedra of gmsh keep the orientation of the section's
    // triangles, which may be either; DOLFINx needs none in particular.
    return raw;
  });
}

/// The mesh `make_raw` makes on rank 0 over the node planes `planes`
/// (0 ... length_m along the ruling), distributed over `comm` (rank 0's
/// error raised on every rank): symmetry multiplicity 1, no facets tagged.
/// gmsh_s: rank 0's time making it.
WholeBodyMesh distribute_layers(MPI_Comm comm, double length_m, std::vector<double> planes,
                                const std::function<RawMesh()>& make_raw)
{
  WholeBodyMesh result;
  result.length_m = length_m;
  result.planes_m = std::move(planes);
  const auto start = std::chrono::steady_clock::now();
  const RawMesh raw = on_rank_zero<RawMesh>(comm, make_raw);
  result.gmsh_s = seconds_since(start);
  MPI_Bcast(&result.gmsh_s, 1, MPI_DOUBLE, 0, comm);
  result.scene.mesh = distribute_raw_mesh(comm, 3, raw);
  result.scene.symmetry_multiplicity = 1;
  result.scene.wall_s = result.gmsh_s;
  result.section_nodes = result.scene.mesh->geometry().index_map()->size_global()
                         / static_cast<std::int64_t>(result.planes_m.size());
  return result;
}

/// Distance from (0, z_c) along (sin psi, -cos psi) to the boundary of the
/// disc segment z <= c of the circle of radius r about (0, r).
double segment_distance(double r, double c, double z_c, double psi)
{
  const double dz = -std::cos(psi);
  const double w = z_c - r; // the centre's height above the circle's centre
  const double along = w * dz;
  double t = -along + std::sqrt(along * along - w * w + r * r);
  if (dz > 0)
    t = std::min(t, (c - z_c) / dz);
  return t;
}

/// The angle from straight down of (y, z) about (0, z_c), in (-pi, pi].
double angle_from_down(double y, double z, double z_c) { return std::atan2(y, z_c - z); }

/// One station's map of the reference section's angles onto the body's
/// (fem/mesh/whole_body_mesh.h): psi' = psi + e2 psi^2 + e3 psi^3 between the
/// corners, linear beyond them over the cut.
struct SectionMap
{
  Eigen::Vector3d centre;
  std::array<double, 2> reference_corner{}, body_corner{}; ///< psi at the right (y > 0) end of the cut, the left
  double e2 = 0, e3 = 0;

  double body_angle(double psi) const
  {
    const double right = reference_corner[0], left = reference_corner[1];
    if (psi >= left && psi <= right)
      return psi + psi * psi * (e2 + e3 * psi);
    // Over the cut, from the right corner through the top to the left one.
    const double around = psi >= right ? psi : psi + 2 * std::numbers::pi;
    const double f = (around - right) / (left + 2 * std::numbers::pi - right);
    return body_corner[0] + f * (body_corner[1] + 2 * std::numbers::pi - body_corner[0]);
  }
};

/// The body's own section at station x (fem/mesh/whole_body_mesh.h).
SectionMap section_map(const MappedBodyPose& pose, double x, double z_c, double reference_half_width)
{
  const double z_G = pose.cut_height_m;
  SectionMap m;
  m.centre = Eigen::Vector3d(x, 0, z_c);
  const std::array<double, 2> vertical = pose.chord(m.centre, Eigen::Vector3d(0, 0, 1));
  if (!(vertical[0] <= 0 && vertical[1] >= 0))
    throw ComputationError(fmt::format("whole-body map: the section's centre (x = {:.6g} m, z = {:.6g} m) lies outside "
                                       "the body",
                                       x, z_c));
  m.reference_corner = {angle_from_down(reference_half_width, z_G, z_c), angle_from_down(-reference_half_width, z_G, z_c)};
  // The cut's chord; its right end counter-clockwise from the bottom in
  // (0, 2 pi), its left end clockwise in (-2 pi, 0).
  const std::array<double, 2> cut = pose.chord(Eigen::Vector3d(x, 0, z_G), Eigen::Vector3d(0, 1, 0));
  const double right = angle_from_down(cut[1], z_G, z_c), left = angle_from_down(cut[0], z_G, z_c);
  m.body_corner = {right < 0 ? right + 2 * std::numbers::pi : right, left > 0 ? left - 2 * std::numbers::pi : left};
  // e2 p^2 + e3 p^3 = q - p at both corners.
  const double p1 = m.reference_corner[0], p2 = m.reference_corner[1];
  const double r1 = (m.body_corner[0] - p1) / (p1 * p1), r2 = (m.body_corner[1] - p2) / (p2 * p2);
  m.e3 = (r1 - r2) / (p1 - p2);
  m.e2 = r1 - m.e3 * p1;
  // Monotone on [p2, p1] (its slope 1 + 2 e2 p + 3 e3 p^2 is positive at
  // both ends and at its extremum), or the mapped section folds.
  auto slope = [&](double p) { return 1 + p * (2 * m.e2 + 3 * m.e3 * p); };
  const double turn = m.e3 != 0 ? std::clamp(-m.e2 / (3 * m.e3), p2, p1) : p1;
  if (!(slope(p1) > 0 && slope(p2) > 0 && slope(turn) > 0))
    throw ComputationError(fmt::format("whole-body map: the section at x = {:.6g} m folds (cut's ends at {:.4f}, {:.4f} "
                                       "rad from the bottom against the reference's {:.4f}, {:.4f})",
                                       x, m.body_corner[0], m.body_corner[1], p1, p2));
  return m;
}

double reference_half_width(const MappedBodyPose& pose)
{
  const double r_ref = pose.reference_radius_m, z_G = pose.cut_height_m;
  return std::sqrt(r_ref * r_ref - (z_G - r_ref) * (z_G - r_ref));
}

/// The station whose section the mesh carries at a: a itself, frozen at the
/// end zones' inner ends within them.
double section_station(const MappedBodyPose& pose, double a)
{
  return std::clamp(a, pose.end_zone_m, pose.length_m - pose.end_zone_m);
}

/// z_f(a, y): the height of the mapped mesh's lower face at station a (its
/// section frozen in the end zones) and y, the lower end of the hull's
/// vertical chord there.
double faceted_sheet_height(const MappedBodyPose& pose, double a, double y)
{
  return pose.chord(Eigen::Vector3d(section_station(pose, a), y, 0), Eigen::Vector3d(0, 0, 1))[0];
}

/// The reference section's point (y, z) mapped onto the body's section of
/// map `m` (fem/mesh/whole_body_mesh.h): its (y, z) there.
Eigen::Vector2d map_section_point(const MappedBodyPose& pose, const SectionMap& m, double r_ref, double y, double z)
{
  const double z_G = pose.cut_height_m, z_c = m.centre.z();
  const double rho = std::hypot(y, z - z_c);
  Eigen::Vector3d p = m.centre;
  if (rho > 0)
  {
    const double psi = angle_from_down(y, z, z_c);
    const double body_psi = m.body_angle(psi);
    const Eigen::Vector3d d(0, std::sin(body_psi), -std::cos(body_psi));
    double reach = pose.chord(m.centre, d)[1];
    if (d.z() > 0)
      reach = std::min(reach, (z_G - z_c) / d.z());
    p += rho / segment_distance(r_ref, z_G, z_c, psi) * reach * d;
  }
  return {p.y(), p.z()};
}

/// The reference mesh's nodes (x, y, z) mapped onto the body and sheared at
/// the ends (fem/mesh/whole_body_mesh.h), in place.
void map_onto_body(std::vector<double>& nodes, const MappedBodyPose& pose, const std::vector<double>& planes,
                   double r_ref)
{
  const double z_c = 0.5 * pose.cut_height_m, L = pose.length_m, zone = pose.end_zone_m;
  const double t0 = std::tan(pose.end_overhang_rad[0]), tL = std::tan(pose.end_overhang_rad[1]);
  std::vector<SectionMap> maps;
  for (const double a : planes)
    maps.push_back(section_map(pose, section_station(pose, a), z_c, reference_half_width(pose)));
  const double same_plane = 1e-6 * (planes[1] - planes[0]);
  for (std::size_t i = 0; i < nodes.size(); i += 3)
  {
    const double a = nodes[i];
    const std::size_t k = std::lower_bound(planes.begin(), planes.end(), a - same_plane) - planes.begin();
    if (k >= planes.size() || std::abs(planes[k] - a) > same_plane)
      throw ComputationError(fmt::format("whole-body map: a node at x = {:.9g} m lies on no layer plane", a));
    const Eigen::Vector2d p = map_section_point(pose, maps[k], r_ref, nodes[i + 1], nodes[i + 2]);
    const double shear = a < zone ? -t0 * (1 - a / zone) : a > L - zone ? tL * (1 - (L - a) / zone) : 0.0;
    nodes[i] = a + p.y() * shear;
    nodes[i + 1] = p.x();
    nodes[i + 2] = p.y();
  }
}

/// The exact sheet z_s = R - sqrt(R^2 - y^2) at station a (R linear along the
/// ruling) over the mesh's faceted face there, within |y| < R / 20 (beyond it
/// 0: fem/mesh/whole_body_mesh.h).
double sheet_gap(const MappedBodyPose& pose, double a, double y)
{
  const double R = pose.radius_m[0] + (pose.radius_m[1] - pose.radius_m[0]) * a / pose.length_m;
  if (!(std::abs(y) < 0.05 * R))
    return 0.0;
  return R - std::sqrt(R * R - y * y) - faceted_sheet_height(pose, a, y);
}

/// The position a along the ruling of a point of the sheared mesh (the
/// inverse of x = a + z s(a) in map_onto_body).
double mapped_along(const MappedBodyPose& pose, const double* x)
{
  const double L = pose.length_m, zone = pose.end_zone_m;
  const double t0 = std::tan(pose.end_overhang_rad[0]), tL = std::tan(pose.end_overhang_rad[1]);
  const double z = x[2];
  const double from_start = (x[0] + z * t0) / (1 + z * t0 / zone);
  if (from_start < zone)
    return from_start;
  const double from_end = (x[0] + z * tL * (L - zone) / zone) / (1 + z * tL / zone);
  if (from_end > L - zone)
    return from_end;
  return x[0];
}

/// InputError for bad section sizes of a body of extent `size_m`.
void check_sizes(const WholeBodySizes& sizes, double size_m)
{
  if (!(sizes.contact_m > 0) || !(sizes.strip_half_width_m > 0) || !(sizes.growth > 0)
      || !(sizes.far_m >= sizes.contact_m))
    throw InputError(fmt::format("whole-body mesh sizes: contact {} m, strip {} m, growth {}, far {} m: need positive "
                                 "sizes and far >= contact",
                                 sizes.contact_m, sizes.strip_half_width_m, sizes.growth, sizes.far_m));
  if (sizes.contact_m < 1e-8 * size_m)
    throw InputError(fmt::format("whole-body mesh: contact elements of {:.3g} m are below 1e-8 of the body ({:.3g} m), "
                                 "which gmsh does not mesh reliably",
                                 sizes.contact_m, size_m));
}

/// How near a point of a mapped mesh lies to one of its planes (the cut, a
/// section's faces) to be on it.
double mapped_tolerance(const MappedBodyPose& pose)
{
  return 1e-9 * std::max(pose.reference_radius_m, pose.length_m);
}

/// A mapped mesh's top facets (the cut z = z_G) and contact facets (the
/// others facing down: the sheet, and an obtuse end's face).
void mark_cut_and_contact(SceneMesh& scene, const MappedBodyPose& pose)
{
  const dolfinx::mesh::Mesh& mesh = *scene.mesh;
  const double z_G = pose.cut_height_m, tol = mapped_tolerance(pose);
  scene.top_facets = boundary_facets(mesh, [&](double, double, double z) { return std::abs(z - z_G) < tol; });
  const std::vector<std::int32_t> others
      = boundary_facets(mesh, [&](double, double, double z) { return std::abs(z - z_G) >= tol; });
  const std::vector<double> normal_z = outward_normal_z(mesh, others);
  for (std::size_t i = 0; i < others.size(); ++i)
    if (normal_z[i] < -1e-6)
      scene.contact_facets.push_back(others[i]);
}

/// InputError for a mapped pose without a length, cut, reference or radii.
void check_pose(const MappedBodyPose& pose)
{
  const double L = pose.length_m, z_G = pose.cut_height_m, r_ref = pose.reference_radius_m;
  if (!(L > 0) || !(z_G > 0) || !(r_ref > 0.5 * z_G) || !(pose.radius_m[0] > 0 && pose.radius_m[1] > 0)
      || !pose.chord)
    throw InputError(fmt::format("whole-body mapped body: need L > 0 ({} m), a cut height z_G > 0 ({} m), a "
                                 "reference radius above z_G / 2 ({} m), radii R > 0 ({}, {} m) and the body's "
                                 "chords",
                                 L, z_G, r_ref, pose.radius_m[0], pose.radius_m[1]));
}
} // namespace

std::vector<double> layer_planes(double length_m, const WholeBodySizes& s)
{
  if (!(length_m > 0) || !(s.end_layer_m > 0) || !(s.layer_growth >= 1) || !(s.largest_layer_m >= s.end_layer_m))
    throw InputError(fmt::format("whole-body layers: length {} m, end layer {} m, growth {}, largest layer {} m: "
                                 "need positive sizes, growth >= 1 and largest >= end layer",
                                 length_m, s.end_layer_m, s.layer_growth, s.largest_layer_m));
  // Half the ruling from its end, then mirrored: symmetric about L / 2.
  std::vector<double> half = {0.0};
  while (half.back() < 0.5 * length_m)
    half.push_back(half.back() + std::min(s.largest_layer_m, s.end_layer_m + (s.layer_growth - 1) * half.back()));
  // The last layer ends at L / 2: merge it into the one before if it would be
  // thinner than half of that one.
  if (half.size() > 2 && 0.5 * length_m - half[half.size() - 2] < 0.5 * (half[half.size() - 2] - half[half.size() - 3]))
    half.pop_back();
  half.back() = 0.5 * length_m;
  std::vector<double> planes = half;
  for (std::size_t i = half.size() - 1; i-- > 0;)
    planes.push_back(length_m - half[i]);
  return planes;
}

WholeBodyMesh build_cylinder_body_mesh(MPI_Comm comm, const CylinderPose& pose, const WholeBodySizes& sizes)
{
  const double r = pose.radius_m, L = pose.length_m, c = pose.cut_height_m;
  if (!(r > 0) || !(L > 0) || !(c > 0 && c < 2 * r))
    throw InputError(fmt::format("whole-body cylinder: radius {} m and length {} m must be positive and the cut "
                                 "height {} m within (0, 2 r)",
                                 r, L, c));
  check_sizes(sizes, std::max(r, L));
  const std::vector<double> planes = layer_planes(L, sizes);
  WholeBodyMesh result
      = distribute_layers(comm, L, planes, [&] { return mesh_extruded_segment(r, c, planes, sizes); });
  SceneMesh& scene = result.scene;
  const dolfinx::mesh::Mesh& mesh = *scene.mesh;
  const double tol = 1e-9 * std::max(r, L);
  scene.top_facets = boundary_facets(mesh, [&](double, double, double z) { return std::abs(z - c) < tol; });
  const std::vector<std::int32_t> curved = boundary_facets(
      mesh, [&](double, double y, double z) { return std::abs(std::hypot(y, z - r) - r) < 1e-7 * r; });
  const std::vector<double> mid = dolfinx::mesh::compute_midpoints(mesh, 2, curved);
  for (std::size_t i = 0; i < curved.size(); ++i)
  {
    const double x = mid[3 * i], z = mid[3 * i + 2];
    if (std::abs(x) > tol && std::abs(x - L) > tol && std::abs(z - c) > tol)
      scene.contact_facets.push_back(curved[i]);
  }
  return result;
}

WholeBodyMesh build_mapped_body_mesh(MPI_Comm comm, const MappedBodyPose& pose, const WholeBodySizes& sizes)
{
  check_pose(pose);
  const double L = pose.length_m, z_G = pose.cut_height_m, r_ref = pose.reference_radius_m, zone = pose.end_zone_m;
  for (const double t : pose.end_overhang_rad)
    // The shear x = a + z s(a) stays monotone in a (no fold) while
    // 1 - z_G |tan t| / zone > 1/2 for an acute end (s growing along a).
    if (!(std::abs(t) < std::numbers::pi / 3) || !(zone > 2 * z_G * std::max(0.0, -std::tan(t))) || !(zone < 0.5 * L))
      throw InputError(fmt::format("whole-body mapped body: end zone {} m must lie below L / 2 ({} m) and above "
                                   "2 z_G tan(-t) ({} m) for the end's overhang t = {} deg (within +-60 deg)",
                                   zone, 0.5 * L, 2 * z_G * std::max(0.0, -std::tan(t)), t * 180 / std::numbers::pi));
  check_sizes(sizes, std::max(r_ref, L));
  const std::vector<double> planes = layer_planes(L, sizes);
  WholeBodyMesh result = distribute_layers(comm, L, planes, [&] {
    RawMesh raw = mesh_extruded_segment(r_ref, z_G, planes, sizes);
    map_onto_body(raw.x, pose, planes, r_ref);
    return raw;
  });
  mark_cut_and_contact(result.scene, pose);
  result.along = [pose](const double* x) { return mapped_along(pose, x); };
  result.initial_gap = [pose](const double* x) { return sheet_gap(pose, mapped_along(pose, x), x[1]); };
  // Up an end face an element above the edge: within a thousandth of the
  // end layer of the faceted sheet is on it.
  result.on_sheet = [pose, tol = 1e-3 * sizes.end_layer_m](const double* x) {
    return x[2] - faceted_sheet_height(pose, mapped_along(pose, x), x[1]) < tol;
  };
  return result;
}

WholeBodyMesh build_mapped_section_mesh(MPI_Comm comm, const MappedBodyPose& pose, double station_m,
                                        double thickness_m, const WholeBodySizes& sizes)
{
  check_pose(pose);
  const double L = pose.length_m, z_G = pose.cut_height_m, r_ref = pose.reference_radius_m;
  if (!(station_m >= 0 && station_m <= L) || !(thickness_m > 0))
    throw InputError(fmt::format("whole-body section: the station {} m must lie on the ruling [0, {}] m and the "
                                 "thickness {} m be positive",
                                 station_m, L, thickness_m));
  check_sizes(sizes, std::max(r_ref, L));
  const double a = section_station(pose, station_m);
  WholeBodyMesh result = distribute_layers(comm, thickness_m, {station_m, station_m + thickness_m}, [&] {
    RawMesh raw = mesh_extruded_segment(r_ref, z_G, {0.0, thickness_m}, sizes);
    const SectionMap map = section_map(pose, a, 0.5 * z_G, reference_half_width(pose));
    for (std::size_t i = 0; i < raw.x.size(); i += 3)
    {
      const Eigen::Vector2d p = map_section_point(pose, map, r_ref, raw.x[i + 1], raw.x[i + 2]);
      raw.x[i] += station_m;
      raw.x[i + 1] = p.x();
      raw.x[i + 2] = p.y();
    }
    return raw;
  });
  mark_cut_and_contact(result.scene, pose);
  const double tol = mapped_tolerance(pose);
  result.scene.symmetry_x_facets = boundary_facets(*result.scene.mesh, [&](double x, double, double) {
    return std::abs(x - station_m) < tol || std::abs(x - station_m - thickness_m) < tol;
  });
  result.along = [station_m](const double*) { return station_m; };
  result.initial_gap = [pose, a](const double* x) { return sheet_gap(pose, a, x[1]); };
  return result;
}
} // namespace rollcheck::fem
