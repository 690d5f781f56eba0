// The rim end's solid meshed (fem/mesh/rim_end_solid.h).
#include "fem/mesh/rim_end_solid.h"
#include "core/error.h"
#include "fem/mesh/gmsh_scene.h"
#include "fem/mesh/oblique_end_angle.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <gmsh.h>
#include <numbers>

namespace rollcheck::fem::scene_build
{
namespace
{
/// The oblique edge (an edge crossing the ruling obliquely) of the volume
/// on the flat sheet: the one curve that bounds both the sheet, the plane
/// z = 0, and the other face, the plane through the origin normal to n
/// (fem/mesh/oblique_end_angle.h). Each face is told by its normal and a
/// point at its parametric centre, which for a plane hold everywhere on it
/// (the sign of gmsh's normal is the face's orientation, so both signs count).
int slanted_edge(int volume, double section_angle_rad, double crossing_angle_rad)
{
  const double D = oblique_dihedral_angle(section_angle_rad, crossing_angle_rad), c = crossing_angle_rad;
  const double n[3] = {std::sin(D) * std::sin(c), -std::sin(D) * std::cos(c), std::cos(D)};
  gmsh::vectorpair faces;
  gmsh::model::getBoundary({{3, volume}}, faces, false, false, false);
  int sheet = -1, other = -1, found_sheet = 0, found_other = 0;
  const double tol = 1e-9; // the model's unit is H
  for (const auto& [dim, tag] : faces)
  {
    std::vector<double> low, high, normal, point;
    gmsh::model::getParametrizationBounds(dim, tag, low, high);
    const std::vector<double> centre = {(low[0] + high[0]) / 2, (low[1] + high[1]) / 2};
    gmsh::model::getNormal(tag, centre, normal);
    gmsh::model::getValue(dim, tag, centre, point);
    const double along = normal[0] * n[0] + normal[1] * n[1] + normal[2] * n[2];
    if (std::abs(normal[2]) > 1 - tol && std::abs(point[2]) < tol)
      sheet = tag, ++found_sheet;
    else if (std::abs(along) > 1 - tol && std::abs(point[0] * n[0] + point[1] * n[1] + point[2] * n[2]) < tol)
      other = tag, ++found_other;
  }
  if (found_sheet != 1 || found_other != 1)
    throw ComputationError(fmt::format("rim end: found {} sheets and {} other faces on the oblique end, not one each",
                                       found_sheet, found_other));
  gmsh::vectorpair sheet_curves, other_curves;
  gmsh::model::getBoundary({{2, sheet}}, sheet_curves, false, false, false);
  gmsh::model::getBoundary({{2, other}}, other_curves, false, false, false);
  std::vector<int> shared;
  for (const auto& [dim, tag] : sheet_curves)
    if (std::find(other_curves.begin(), other_curves.end(), std::pair{dim, tag}) != other_curves.end())
      shared.push_back(tag);
  if (shared.size() != 1)
    throw ComputationError(fmt::format("rim end: the sheet and the other face share {} curves, not one", shared.size()));
  return shared.front();
}

/// The edge `edge` of the one volume `solid` rounded with a fillet of radius r (gmsh units).
void fillet_edge(gmsh::vectorpair& solid, int edge, double r)
{
  gmsh::vectorpair filleted;
  gmsh::model::occ::fillet({solid[0].second}, {edge}, {r}, filleted, true);
  gmsh::model::occ::synchronize();
  if (filleted.size() != 1)
    throw ComputationError(fmt::format("rim end: the fillet of radius {:.3g} m failed", r));
  solid = filleted;
}

/// The rim end's solid (build_rim_end_mesh): the block x in [-L, H],
/// y in [0, H], z <= H, inside the cylinder of radius R about the line
/// (x, 0, R), cut by the other face's half-space, its edge filleted; an
/// oblique edge's block x in [-L, H (1 + cot c)], y in [-H, H], on the flat
/// sheet when filleted.
void add_rim_end(const RimEndGeometry& g)
{
  namespace occ = gmsh::model::occ;
  const double H = g.depth_m, L = g.length_m, R = g.radius_m;
  // An oblique edge: both sides of the ruling, and H beyond the edge's
  // farthest point (fem/mesh/oblique_end_angle.h).
  const bool oblique = crosses_obliquely(g.crossing_angle_rad);
  const double y0 = oblique ? -H : 0, extra = oblique ? H / std::tan(g.crossing_angle_rad) : 0;
  gmsh::vectorpair body, cut;
  std::vector<gmsh::vectorpair> map;
  if (g.flat_sheet)
    body = {{3, occ::addBox(-L, y0, 0, L + H + extra, H - y0, H)}};
  else
  {
    // The box overlaps the tangent plane z = 0 instead of touching it.
    const int box = occ::addBox(-L, y0, -0.1 * H, L + H + extra, H - y0, 1.1 * H);
    const int cylinder = occ::addCylinder(-L - H, 0, R, L + 3 * H + extra, 0, 0, R);
    occ::intersect({{3, box}}, {{3, cylinder}}, body, map);
  }
  // Beyond the other face: n . p > 0, n = (sin a, 0, cos a) for the interior
  // angle a, which is +x (a square end) turned about y by a - 90 deg; an
  // oblique edge's at its dihedral angle, then turned about z with the edge.
  const double span = 10 * (L + H + extra);
  const int half_space = occ::addBox(0, -span, -span, span, 2 * span, 2 * span);
  occ::rotate({{3, half_space}}, 0, 0, 0, 0, 1, 0,
              oblique_dihedral_angle(g.interior_angle_rad, g.crossing_angle_rad) - std::numbers::pi / 2);
  if (oblique)
    occ::rotate({{3, half_space}}, 0, 0, 0, 0, 0, 1, g.crossing_angle_rad - std::numbers::pi / 2);
  occ::cut(body, {{3, half_space}}, cut, map);
  occ::synchronize();
  if (cut.size() != 1)
    throw ComputationError(fmt::format("rim end: the cut left {} volumes, not one", cut.size()));
  if (oblique)
  {
    // A rounded edge: the fillet leaves the sheet x_t from the edge along
    // its normal (fillet_start_distance at the dihedral), on the centre line
    // x_t / sin c from it; the sheet's centre line ends there.
    double sheet_end = 0;
    if (g.edge_radius_m > 0)
    {
      fillet_edge(cut, slanted_edge(cut[0].second, g.interior_angle_rad, g.crossing_angle_rad), g.edge_radius_m);
      sheet_end = -fillet_start_distance(g.edge_radius_m,
                                         oblique_dihedral_angle(g.interior_angle_rad, g.crossing_angle_rad))
                  / std::sin(g.crossing_angle_rad);
    }
    // The ruling's centre line on the sheet, where the pressures along the
    // ruling are read, as a line of mesh nodes: the sheet's face split along
    // it from the far side to the edge (one volume; two volumes split at
    // y = 0 would be meshed with twin nodes on their shared face, apart).
    const int centre_line = occ::addLine(occ::addPoint(-L, 0, 0), occ::addPoint(sheet_end, 0, 0));
    gmsh::vectorpair split;
    occ::fragment(cut, {{1, centre_line}}, split, map);
    occ::synchronize();
    gmsh::vectorpair volumes;
    gmsh::model::getEntities(volumes, 3);
    if (volumes.size() != 1)
      throw ComputationError(fmt::format("rim end: the centre line left {} volumes, not one", volumes.size()));
    return;
  }
  if (!(g.edge_radius_m > 0))
    return;
  // The edge: the one curve from the origin across the block in y. On the
  // cylinder sheet it rises with the sheet, and along a nearly level other
  // face (a -> 180 deg) it runs out in x: at 170 deg, R = 2.4 H, it leaves
  // the block through its end x = H at y = 0.9 H. So it is told by starting
  // at x = 0 on the bottom and reaching past y = H / 2 (the contact stays
  // within a few b of y = 0), which neither the far side's curve (x = -L)
  // nor the sheet's and the cut's centre lines (y = 0) do.
  gmsh::vectorpair curves;
  gmsh::model::getEntities(curves, 1);
  std::vector<int> edges;
  const double tol = 1e-5 * H;
  for (const auto& [dim, tag] : curves)
  {
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(dim, tag, x0, y0, z0, x1, y1, z1);
    if (y0 < tol && y1 > 0.5 * H && x0 < tol && x1 > -tol && z0 < tol)
      edges.push_back(tag);
  }
  if (edges.size() != 1)
    throw ComputationError(fmt::format("rim end: found {} edge curves, not one", edges.size()));
  fillet_edge(cut, edges.front(), g.edge_radius_m);
}
} // namespace

RawMesh mesh_rim_end(const RimEndGeometry& unit, const RimEndSizes& sizes, double H, bool with_block,
                     VolumeMesher mesher)
{
  RawMesh raw = mesh_with_gmsh(
      3,
      [&] {
    add_rim_end(unit);
    if (with_block)
    {
      namespace occ = gmsh::model::occ;
      gmsh::vectorpair bodies, out;
      gmsh::model::getEntities(bodies, 3);
      const int block = occ::addBox(-unit.length_m, 0, -1, unit.length_m + 1, 1, 1);
      std::vector<gmsh::vectorpair> map;
      occ::fragment(bodies, {{3, block}}, out, map);
      occ::synchronize();
    }
    gmsh::model::mesh::setSizeCallback([sizes, H](int, int, double x, double y, double z) {
      const double point[3] = {x * H, y * H, std::abs(z) * H};
      return rim_end_element_size(sizes, point) / H;
    });
    sizes_from_fields_alone();
    return std::min(sizes.edge_m, sizes.contact_m) / H;
      },
      mesher);
  for (double& x : raw.x)
    x *= H;
  return raw;
}

void check_rim_end_input(const RimEndGeometry& g, const RimEndSizes& sizes)
{
  const double H = g.depth_m, L = g.length_m;
  for (double v : {g.radius_m, H, L, sizes.edge_m, sizes.contact_m, sizes.far_m, sizes.growth})
    if (!std::isfinite(v) || v <= 0)
      throw InputError(fmt::format("rim end: radius, depth, length and element sizes must be positive and finite "
                                   "(R = {} m, H = {} m, L = {} m, sizes {} m, {} m, {} m, growth {})",
                                   g.radius_m, H, L, sizes.edge_m, sizes.contact_m, sizes.far_m, sizes.growth));
  if (!(g.interior_angle_rad >= std::numbers::pi / 3 && g.interior_angle_rad < std::numbers::pi))
    throw InputError(fmt::format("rim end: the interior angle must lie in [60, 180) deg, got {} deg",
                                 g.interior_angle_rad * 180 / std::numbers::pi));
  if (!(g.edge_radius_m >= 0 && g.edge_radius_m < largest_edge_radius_over_depth * H) || (!g.flat_sheet && g.radius_m < H))
    throw InputError(fmt::format("rim end: need 0 <= edge radius < {} H, and R >= H for the cylinder sheet (edge "
                                 "radius {} m, R = {} m, H = {} m)",
                                 largest_edge_radius_over_depth, g.edge_radius_m, g.radius_m, H));
  if (crosses_obliquely(g.crossing_angle_rad) && g.edge_radius_m > 0 && !g.flat_sheet)
    throw InputError("rim end: an oblique rounded edge is modelled on the flat sheet only (the fillet of a plane and "
                     "a cylinder crossing it obliquely is no cylinder)");
}

Predicate rim_end_block_planes(double H, double L)
{
  const double tol = 1e-9 * H;
  return [=](double x, double y, double z) {
    return std::abs(x + L) < tol || std::abs(x - H) < tol || std::abs(y) < tol || std::abs(y - H) < tol
           || std::abs(z - H) < tol;
  };
}

SceneParts rim_end_planes(double L, double tol)
{
  SceneParts parts;
  parts.symmetry_x = [=](double x, double, double) { return std::abs(x + L) < tol; };
  parts.symmetry_y = [=](double, double y, double) { return std::abs(y) < tol; };
  return parts;
}

void tag_rim_end(SceneMesh& scene, double H, double L, const Predicate& curved, const Predicate& in_plane,
                 bool full_width)
{
  const double tol = 1e-9 * H;
  SceneParts parts = rim_end_planes(L, tol);
  parts.top = [=](double, double, double z) { return std::abs(z - H) < tol; };
  parts.curved = curved;
  parts.in_plane = in_plane;
  parts.facing_plane_only = true;
  tag_parts(scene, parts);
  // An oblique end covers both sides of the ruling: no face at y = 0.
  scene.symmetry_multiplicity = full_width ? 1 : 2;
}
} // namespace rollcheck::fem::scene_build
