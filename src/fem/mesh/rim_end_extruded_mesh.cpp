// The rim end's section extruded (fem/mesh/rim_end_extruded_mesh.h).
#include "fem/mesh/rim_end_extruded_mesh.h"
#include "core/error.h"
#include "fem/mesh/gmsh_raw_mesh.h"
#include "fem/mesh/mesh_grading.h"
#include "fem/mesh/oblique_end_angle.h"
#include "fem/mesh/rim_end_distribute.h"
#include "fem/mesh/rim_end_solid.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <gmsh.h>
#include <numbers>
#include <unordered_map>

namespace rollcheck::fem
{
using namespace scene_build;

namespace
{
namespace geo = gmsh::model::geo;

/// A transfinite curve from its fine end: `elements` elements whose sizes
/// grow by the factor `ratio` from one to the next.
void grade_curve(int curve, int elements, double ratio)
{
  geo::mesh::setTransfiniteCurve(curve, elements + 1, "Progression", ratio);
}

/// Elements of a curve of `length` graded from h_0 by `growth` per element
/// (a geometric progression of ratio 1 + growth), at least one.
int graded_elements(double length, double h_0, double growth)
{
  return std::max(1, static_cast<int>(std::ceil(std::log1p(growth * length / h_0) / std::log1p(growth))));
}

/// The section of the body (units of H, gmsh's x and y are the model's x
/// and z) as the near and far parts of fem/mesh/rim_end_extruded_mesh.h;
/// returns the surfaces' tags.
std::vector<int> add_section(const RimEndGeometry& unit, const RimEndSizes& sizes)
{
  const double L = unit.length_m, r_e = unit.edge_radius_m;
  const double theta = std::numbers::pi - unit.interior_angle_rad; // the other face's rise from +x
  const double x_t = fillet_start_distance(r_e, unit.interior_angle_rad);
  const double ux = std::cos(theta), uz = std::sin(theta);
  // The other face leaves the block through its end x = 1 (a flat rim, a >
  // 135 deg) or through its top z = 1.
  const bool through_end = ux > uz;
  const double face_x = through_end ? 1.0 : ux / uz, face_z = through_end ? uz / ux : 1.0;
  // The near part's left side: 2 contact zones from the fillet's start on the
  // sheet, and as far left of an acute rim's face at the top.
  const double margin = 2 * sizes.contact_zone_m;
  const double x_s = -x_t - margin, x_top = std::min(x_s, face_x - margin);
  if (!(x_s > -L && x_top > -L))
    throw InputError(fmt::format("rim end extruded: the block is too short for the edge (L = {} H)", L));

  const int near_bottom = geo::addPoint(x_s, 0, 0), near_top = geo::addPoint(x_top, 1, 0);
  const int far_bottom = geo::addPoint(-L, 0, 0), far_top = geo::addPoint(-L, 1, 0);
  const int start = geo::addPoint(-x_t, 0, 0);
  std::vector<int> boundary{geo::addLine(near_bottom, start)};
  int face_start = start;
  if (r_e > 0)
  {
    const int centre = geo::addPoint(-x_t, r_e, 0);
    face_start = geo::addPoint(x_t * ux, x_t * uz, 0);
    boundary.push_back(geo::addCircleArc(start, centre, face_start));
  }
  const int face_end = geo::addPoint(face_x, face_z, 0);
  boundary.push_back(geo::addLine(face_start, face_end));
  int top_right = face_end;
  if (through_end)
  {
    top_right = geo::addPoint(1, 1, 0);
    boundary.push_back(geo::addLine(face_end, top_right));
  }
  boundary.push_back(geo::addLine(top_right, near_top));
  const int interface = geo::addLine(near_bottom, near_top);
  boundary.push_back(-interface);
  const int near = geo::addPlaneSurface({geo::addCurveLoop(boundary)});

  // The far part: along x from the interface, graded from the strip's
  // elements to far_m, then far_m; across z from the sheet.
  const double h = sizes.contact_m, g = sizes.growth, far = sizes.far_m;
  const int across = graded_elements(1.0, h, g);
  const double graded_length = std::min((far - h) / g, x_s + L - far);
  const int mid_bottom = geo::addPoint(x_s - graded_length, 0, 0);
  const int mid_top = geo::addPoint(x_top - graded_length, 1, 0);
  const int graded_bottom = geo::addLine(near_bottom, mid_bottom), graded_top = geo::addLine(near_top, mid_top);
  const int mid_side = geo::addLine(mid_bottom, mid_top);
  const int uniform_bottom = geo::addLine(mid_bottom, far_bottom), uniform_top = geo::addLine(mid_top, far_top);
  const int far_side = geo::addLine(far_bottom, far_top);
  const int graded
      = geo::addPlaneSurface({geo::addCurveLoop({graded_bottom, mid_side, -graded_top, -interface})});
  const int uniform
      = geo::addPlaneSurface({geo::addCurveLoop({uniform_bottom, far_side, -uniform_top, -mid_side})});
  for (int curve : {graded_bottom, graded_top})
    grade_curve(curve, graded_elements(graded_length, h, g), 1 + g);
  const int uniform_elements = std::max(1, static_cast<int>(std::round((x_s + L - graded_length) / far)));
  for (int curve : {uniform_bottom, uniform_top})
    grade_curve(curve, uniform_elements, 1.0);
  for (int curve : {interface, mid_side, far_side})
    grade_curve(curve, across, 1 + g);
  for (int surface : {graded, uniform})
    geo::mesh::setTransfiniteSurface(surface);
  return {near, graded, uniform};
}

/// Every tetrahedron of the model, its nodes numbered in gmsh's order: the
/// extruded parts share their nodes (read_gmsh_mesh would part the volumes).
RawMesh read_single_body()
{
  RawMesh raw;
  std::vector<std::size_t> node_tags, element_tags, element_nodes;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
  std::unordered_map<std::size_t, std::int64_t> index;
  for (std::size_t i = 0; i < node_tags.size(); ++i)
    index[node_tags[i]] = static_cast<std::int64_t>(i);
  raw.x = std::move(coords);
  gmsh::model::mesh::getElementsByType(4, element_tags, element_nodes, -1);
  raw.cells.reserve(element_nodes.size());
  for (std::size_t tag : element_nodes)
    raw.cells.push_back(index.at(tag));
  return raw;
}

/// The section meshed and extruded in units of H, scaled back to metres
/// with the model's axes (gmsh's x, y, z are the model's x, z, y).
RawMesh mesh_extruded_section(const RimEndGeometry& unit, const RimEndSizes& sizes, double H)
{
  RimEndSizes in_h = sizes;
  for (double* size : {&in_h.edge_m, &in_h.edge_zone_m, &in_h.edge_x_m, &in_h.edge_band_m, &in_h.contact_m,
                       &in_h.contact_zone_m, &in_h.far_m})
    *size /= H;
  RawMesh raw = run_gmsh_session("rim_end_section", "rim end's section", [&] {
    gmsh::option::setNumber("Mesh.Algorithm", 6); // Frontal-Delaunay: near-equilateral triangles
    const std::vector<int> surfaces = add_section(unit, in_h);
    std::vector<double> layers;
    const std::vector<double> along_y = graded_nodes(1.0, in_h.contact_m, in_h.contact_zone_m, in_h.growth, in_h.far_m);
    layers.assign(along_y.begin() + 1, along_y.end());
    gmsh::vectorpair section, extruded;
    for (int surface : surfaces)
      section.push_back({2, surface});
    geo::extrude(section, 0, 0, 1, extruded, std::vector<int>(layers.size(), 1), layers, false);
    geo::synchronize();
    gmsh::model::mesh::setSizeCallback([in_h](int, int, double x, double z, double) {
      const double point[3] = {x, 0, z};
      return rim_end_element_size(in_h, point);
    });
    sizes_from_fields_alone();
    gmsh::model::mesh::generate(3);
    return read_single_body();
  });
  for (std::size_t i = 0; i < raw.x.size(); i += 3)
  {
    const double x = raw.x[i], z = raw.x[i + 1], y = raw.x[i + 2];
    raw.x[i] = x * H;
    raw.x[i + 1] = y * H;
    raw.x[i + 2] = z * H;
  }
  return raw;
}
} // namespace

SceneMesh build_rim_end_extruded_mesh(MPI_Comm comm, const RimEndGeometry& g, const RimEndSizes& sizes)
{
  const auto start = std::chrono::steady_clock::now();
  check_rim_end_input(g, sizes);
  if (!g.flat_sheet || crosses_obliquely(g.crossing_angle_rad))
    throw InputError("rim end extruded: the sheet must be flat and the edge square to the ruling");
  const double H = g.depth_m, L = g.length_m;
  const RimEndGeometry unit{g.radius_m / H, g.interior_angle_rad, g.edge_radius_m / H, 1.0, L / H, true};
  SceneMesh scene = distribute_quietly(comm, 3, [&] { return mesh_extruded_section(unit, sizes, H); });
  tag_rim_end(scene, H, L, [](double, double, double) { return true; }, rim_end_block_planes(H, L));
  scene.wall_s = seconds_since(start);
  return scene;
}
} // namespace rollcheck::fem
