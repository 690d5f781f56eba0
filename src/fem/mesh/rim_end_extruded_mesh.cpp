// The rim end's section extruded (fem/mesh/rim_end_extruded_mesh.h).
#include "fem/mesh/rim_end_extruded_mesh.h"
#include "core/error.h"
#include "fem/mesh/gmsh_raw_mesh.h"
#include "fem/mesh/mesh_grading.h"
#include "fem/mesh/oblique_end_angle.h"
#include "fem/mesh/rim_end_distribute.h"
#include "fem/mesh/rim_end_solid.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <gmsh.h>
#include <numbers>
#include <numeric>
#include <unordered_map>

namespace rollcheck::fem
{
using namespace scene_build;

namespace
{
namespace geo = gmsh::model::geo;

/// The section's elements at the sheet away from the edge, across it (z),
/// are b / (contact_elements sheet_refinement), growing by `growth` from
/// the sheet. The far side is a plane-strain line contact, whose P1 section
/// reads its peak below p0 until the first layer under the sheet is thin:
/// the sharp square end's far side (6 elements across b, every (y, z) cut
/// rising) read 0.935 p0 with the layer b / 6, 0.962 with b / 24.
constexpr int sheet_refinement = 4;

/// The layers along the edge (y) over the contact zone are b /
/// (contact_elements along_edge_refinement): the square end's far side,
/// with the layer under the sheet b / 24, read 0.962 p0 at b / 6 along y
/// (cuts all rising), 1.010 at b / 12 (cuts as a union jack).
constexpr int along_edge_refinement = 2;

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
/// and z) as the near and far parts of fem/mesh/rim_end_extruded_mesh.h.
void add_section(const RimEndGeometry& unit, const RimEndSizes& sizes)
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
  geo::addPlaneSurface({geo::addCurveLoop(boundary)});

  // The far part: along x from the interface, graded from the strip's
  // elements to far_m, then far_m; across z from the sheet.
  const double h = sizes.contact_m, g = sizes.growth, far = sizes.far_m;
  const int across = graded_elements(1.0, h / sheet_refinement, g);
  const double graded_length = std::min((far - h) / g, x_s + L - far);
  const int mid_bottom = geo::addPoint(x_s - graded_length, 0, 0);
  const int mid_top = geo::addPoint(x_top - graded_length, 1, 0);
  const int graded_bottom = geo::addLine(near_bottom, mid_bottom), graded_top = geo::addLine(near_top, mid_top);
  const int mid_side = geo::addLine(mid_bottom, mid_top);
  const int uniform_bottom = geo::addLine(mid_bottom, far_bottom), uniform_top = geo::addLine(mid_top, far_top);
  const int far_side = geo::addLine(far_bottom, far_top);
  const int graded = geo::addPlaneSurface({geo::addCurveLoop({graded_bottom, mid_side, -graded_top, -interface})});
  const int uniform = geo::addPlaneSurface({geo::addCurveLoop({uniform_bottom, far_side, -uniform_top, -mid_side})});
  for (int curve : {graded_bottom, graded_top})
    grade_curve(curve, graded_elements(graded_length, h, g), 1 + g);
  const int uniform_elements = std::max(1, static_cast<int>(std::round((x_s + L - graded_length) / far)));
  for (int curve : {uniform_bottom, uniform_top})
    grade_curve(curve, uniform_elements, 1.0);
  for (int curve : {interface, mid_side, far_side})
    grade_curve(curve, across, 1 + g);
  for (int surface : {graded, uniform})
    geo::mesh::setTransfiniteSurface(surface);
}

/// The section's triangulation (units of H), every surface's triangles on
/// the nodes the surfaces share: x holds (x, z) rows, cells the triangles.
RawMesh read_section()
{
  RawMesh section;
  std::vector<std::size_t> node_tags, element_tags, element_nodes;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
  std::unordered_map<std::size_t, std::int64_t> index;
  for (std::size_t i = 0; i < node_tags.size(); ++i)
  {
    index[node_tags[i]] = static_cast<std::int64_t>(i);
    section.x.insert(section.x.end(), {coords[3 * i], coords[3 * i + 1]});
  }
  gmsh::model::mesh::getElementsByType(2, element_tags, element_nodes, -1);
  section.cells.reserve(element_nodes.size());
  for (std::size_t tag : element_nodes)
    section.cells.push_back(index.at(tag));
  return section;
}

/// The section's nodes by height: each one's rank (a strict order, by z)
/// and row (the index of its z among the section's heights, equal within
/// 1e-9 in units of H: the structured part's rows; in the unstructured part
/// mostly a row per node).
struct HeightOrder
{
  std::vector<std::int64_t> rank, row;
};

HeightOrder order_by_height(const RawMesh& section)
{
  const std::size_t nodes = section.x.size() / 2;
  std::vector<std::int64_t> by_height(nodes);
  std::iota(by_height.begin(), by_height.end(), 0);
  std::stable_sort(by_height.begin(), by_height.end(),
                   [&](std::int64_t p, std::int64_t q) { return section.x[2 * p + 1] < section.x[2 * q + 1]; });
  HeightOrder order{std::vector<std::int64_t>(nodes), std::vector<std::int64_t>(nodes)};
  std::int64_t k = 0;
  for (std::size_t r = 0; r < nodes; ++r)
  {
    if (r > 0 && section.x[2 * by_height[r] + 1] - section.x[2 * by_height[r - 1] + 1] > 1e-9)
      ++k;
    order.rank[by_height[r]] = static_cast<std::int64_t>(r);
    order.row[by_height[r]] = k;
  }
  return order;
}

/// The prism of the triangle `bottom` and its copy `top` one layer up cut
/// into three tetrahedra, each quadrilateral face by the diagonal from its
/// node of least `key` (J. Dompierre et al., "How to subdivide pyramids,
/// prisms and hexahedra into tetrahedra", 8th International Meshing
/// Roundtable, 1999): neighbouring prisms cut their shared face alike.
void add_prism(const std::array<std::int64_t, 3>& bottom, const std::array<std::int64_t, 3>& top,
               const std::vector<std::int64_t>& key, std::vector<std::int64_t>& cells)
{
  const auto less = [&](std::int64_t p, std::int64_t q) { return key[p] < key[q]; };
  std::array<std::int64_t, 6> all{bottom[0], bottom[1], bottom[2], top[0], top[1], top[2]};
  const auto least = std::min_element(all.begin(), all.end(), less) - all.begin();
  // The least node's level as "lower" (a prism has no up or down) and its
  // triangle turned so that it comes first: A B C below, A' B' C' above.
  const auto& lower = least < 3 ? bottom : top;
  const auto& upper = least < 3 ? top : bottom;
  const int i = static_cast<int>(least % 3);
  const std::int64_t A = lower[i], B = lower[(i + 1) % 3], C = lower[(i + 2) % 3];
  const std::int64_t B1 = upper[(i + 1) % 3], C1 = upper[(i + 2) % 3];
  cells.insert(cells.end(), {A, upper[i], B1, C1});
  const std::int64_t face_least = std::min({B, C, B1, C1}, less);
  if (face_least == B || face_least == C1)
    cells.insert(cells.end(), {A, B, C, C1, A, B, C1, B1});
  else
    cells.insert(cells.end(), {A, B, C, B1, A, C, C1, B1});
}

/// The section extruded along y through the nodes `layers` (units of H),
/// each prism cut by add_prism. The nodes' keys lay a union jack over the
/// structured part's (y, z) rectangles: first the nodes whose layer and row
/// sum to an even number, then the rest, each set by height. Every
/// tetrahedron of a prism between two rows then projects onto (y, z) as one
/// of the two triangles of one cut of that rectangle, the same for every
/// prism of it, so that a plane-strain field u(y, z) P1 on that 2D
/// triangulation is P1 on the tetrahedra; and the cuts alternate from one
/// rectangle to the next. Cut all the same way, the (y, z) triangulation
/// leans: the far side of the square end read 0.935 p0 with every cut
/// rising in z along y, 1.087 p0 with every cut falling (6 elements across
/// b; gmsh's own extrusion, which cuts by its node numbers, 0.929).
RawMesh extrude_section(const RawMesh& section, const std::vector<double>& layers)
{
  const std::size_t nodes = section.x.size() / 2, ny = layers.size();
  const HeightOrder height = order_by_height(section);
  const auto node = [ny](std::int64_t s, std::size_t j) {
    return s * static_cast<std::int64_t>(ny) + static_cast<std::int64_t>(j);
  };
  RawMesh raw;
  raw.x.resize(3 * nodes * ny);
  std::vector<std::int64_t> key(nodes * ny);
  const std::int64_t half = static_cast<std::int64_t>(nodes * ny);
  for (std::size_t s = 0; s < nodes; ++s)
    for (std::size_t j = 0; j < ny; ++j)
    {
      double* x = raw.x.data() + 3 * node(static_cast<std::int64_t>(s), j);
      x[0] = section.x[2 * s];
      x[1] = layers[j];
      x[2] = section.x[2 * s + 1];
      const bool odd = (height.row[s] + static_cast<std::int64_t>(j)) % 2 != 0;
      key[node(static_cast<std::int64_t>(s), j)] = (odd ? half : 0) + node(height.rank[s], j);
    }
  raw.cells.reserve(section.cells.size() / 3 * 12 * (ny - 1));
  for (std::size_t t = 0; t < section.cells.size(); t += 3)
    for (std::size_t j = 0; j + 1 < ny; ++j)
    {
      std::array<std::int64_t, 3> bottom{}, top{};
      for (int v = 0; v < 3; ++v)
      {
        bottom[v] = node(section.cells[t + v], j);
        top[v] = node(section.cells[t + v], j + 1);
      }
      add_prism(bottom, top, key, raw.cells);
    }
  return raw;
}

/// The section meshed in 2D and extruded in units of H, scaled back to
/// metres (the model's x, y, z).
RawMesh mesh_extruded_section(const RimEndGeometry& unit, const RimEndSizes& sizes, double H)
{
  RimEndSizes in_h = sizes;
  for (double* size : {&in_h.edge_m, &in_h.edge_zone_m, &in_h.edge_x_m, &in_h.edge_band_m, &in_h.contact_m,
                       &in_h.contact_zone_m, &in_h.far_m})
    *size /= H;
  const RawMesh section = run_gmsh_session("rim_end_section", "rim end's section", [&] {
    gmsh::option::setNumber("Mesh.Algorithm", 6); // Frontal-Delaunay: near-equilateral triangles
    add_section(unit, in_h);
    geo::synchronize();
    gmsh::model::mesh::setSizeCallback([in_h](int, int, double x, double z, double) {
      const double point[3] = {x, 0, z};
      return rim_end_element_size(in_h, point);
    });
    sizes_from_fields_alone();
    gmsh::model::mesh::generate(2);
    return read_section();
  });
  // Along the edge (y) layers graded as the structured grid's, b /
  // (contact_elements along_edge_refinement) over the contact zone, then growing.
  RawMesh raw = extrude_section(
      section, graded_nodes(1.0, in_h.contact_m / along_edge_refinement, in_h.contact_zone_m, in_h.growth, in_h.far_m));
  for (double& x : raw.x)
    x *= H;
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
