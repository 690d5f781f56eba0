// The Hertz scenes' mesh (fem/mesh/hertz_mesh.h).
#include "fem/mesh/hertz_mesh.h"
#include "fem/mesh/gmsh_scene.h"
#include "fem/mesh/scene_parts.h"
#include "core/error.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <gmsh.h>
#include <numbers>

namespace rollcheck::fem
{
using namespace scene_build;

namespace
{
/// Quarter hemisphere x, y >= 0, z <= R of the sphere about (0, 0, R). The cut
/// box overlaps the tangent plane z = 0 instead of touching it (an OCC cut
/// exactly at a tangent plane is fragile).
int add_quarter_hemisphere(double R)
{
  namespace occ = gmsh::model::occ;
  const int sphere = occ::addSphere(0, 0, R, R);
  // Parametric poles from (0, 0, 0) and (0, 0, 2R) to (0, -R, R) and (0, R, R).
  occ::rotate({{3, sphere}}, 0, 0, R, 1, 0, 0, std::numbers::pi / 2);
  const int box = occ::addBox(0, 0, -0.1 * R, 1.1 * R, 1.1 * R, 1.1 * R);
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  occ::intersect({{3, sphere}}, {{3, box}}, out, map);
  occ::synchronize();
  return point_at_origin(R);
}

/// The structured cap's face and the curves that bound it: the arcs in the
/// planes y = 0 and x = 0 from the pole out, and the ring s = s_cap.
struct CapEntities
{
  int pole, face, arc_y0, arc_x0, ring;
};

/// Quarter hemisphere x, y >= 0, z <= R of the sphere about (0, 0, R), as the
/// meridian section (x, z) revolved about the z axis by 90 degrees, its arc
/// split at s = s_cap (hertz_mesh.h): the cap s < s_cap is a face of its own.
CapEntities add_revolved_quarter_hemisphere(double R, double s_cap)
{
  namespace occ = gmsh::model::occ;
  const double z_cap = R - std::sqrt(R * R - s_cap * s_cap);
  const int pole = occ::addPoint(0, 0, 0), centre = occ::addPoint(0, 0, R);
  const int cap_point = occ::addPoint(s_cap, 0, z_cap), rim = occ::addPoint(R, 0, R);
  const int cap_arc = occ::addCircleArc(pole, centre, cap_point);
  const int section = occ::addPlaneSurface({occ::addCurveLoop(
      {cap_arc, occ::addCircleArc(cap_point, centre, rim), occ::addLine(rim, centre), occ::addLine(centre, pole)})});
  gmsh::vectorpair out;
  occ::revolve({{2, section}}, 0, 0, 0, 0, 0, 1, std::numbers::pi / 2, out);
  occ::synchronize();
  // The cap is the face that stays near the plane; of its curves, the ring
  // ends at s_cap at both ends, the arcs end at the pole and in y = 0 or
  // x = 0 (the pole's degenerate curve ends at the pole twice).
  const double tol = 1e-9 * R;
  CapEntities cap{point_at_origin(R), -1, -1, -1, -1};
  gmsh::vectorpair faces;
  gmsh::model::getEntities(faces, 2);
  for (const auto& [dim, tag] : faces)
  {
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(dim, tag, x0, y0, z0, x1, y1, z1);
    if (z1 < 0.5 * R)
      cap.face = tag;
  }
  gmsh::vectorpair curves;
  gmsh::model::getBoundary({{2, cap.face}}, curves, false, false, false);
  for (const auto& [dim, signed_tag] : curves)
  {
    const int curve = std::abs(signed_tag);
    gmsh::vectorpair ends;
    gmsh::model::getBoundary({{1, curve}}, ends, false, false, false);
    double s_far = 0, x_far = 0, y_far = 0;
    int at_cap = 0;
    for (const auto& [point_dim, point] : ends)
    {
      std::vector<double> x;
      gmsh::model::getValue(0, std::abs(point), {}, x);
      const double s = std::hypot(x[0], x[1]);
      at_cap += std::abs(s - s_cap) < 1e-6 * s_cap;
      if (s > s_far)
        s_far = s, x_far = x[0], y_far = x[1];
    }
    if (at_cap == 2)
      cap.ring = curve;
    else if (s_far > tol && std::abs(y_far) < tol)
      cap.arc_y0 = curve;
    else if (s_far > tol && std::abs(x_far) < tol)
      cap.arc_x0 = curve;
  }
  if (std::min({cap.face, cap.ring, cap.arc_y0, cap.arc_x0}) < 0)
    throw ComputationError("hertz mesh: the revolved quarter hemisphere has no contact cap face and curves");
  return cap;
}

/// The largest tag of gmsh's nodes so far.
std::size_t largest_node_tag()
{
  std::vector<std::size_t> tags;
  std::vector<double> x, u;
  gmsh::model::mesh::getNodes(tags, x, u);
  return tags.empty() ? 0 : *std::max_element(tags.begin(), tags.end());
}

/// The largest tag of gmsh's elements so far.
std::size_t largest_element_tag()
{
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::model::mesh::getElements(types, tags, nodes);
  std::size_t largest = 0;
  for (const auto& of_type : tags)
    for (std::size_t tag : of_type)
      largest = std::max(largest, tag);
  return largest;
}

/// Nodes added to gmsh's entity (dim, tag) at the points x, with their
/// parametric coordinates on it.
void add_nodes(int dim, int tag, const std::vector<std::size_t>& nodes, const std::vector<double>& x)
{
  std::vector<double> u;
  gmsh::model::getParametrization(dim, tag, x, u);
  gmsh::model::mesh::addNodes(dim, tag, nodes, x, u);
}

/// The cap's surface mesh by rings (hertz_mesh.h), given to gmsh after its
/// 1D mesh: the cap's three curves re-meshed through the rings' nodes, the
/// face's nodes and triangles added; every other entity left to gmsh
/// (Mesh.MeshOnlyEmpty).
void mesh_cap_by_rings(const CapEntities& cap, const CapRings& rings, double R)
{
  namespace mesh = gmsh::model::mesh;
  mesh::generate(1);
  mesh::clear({{1, cap.arc_y0}, {1, cap.arc_x0}, {1, cap.ring}});
  const auto point_node = [](int point) {
    std::vector<std::size_t> tags;
    std::vector<double> x, u;
    mesh::getNodes(tags, x, u, 0, point);
    return tags.at(0);
  };
  // The ring's ends are the arcs' outer ends.
  gmsh::vectorpair ends_y0, ends_x0;
  gmsh::model::getBoundary({{1, cap.arc_y0}}, ends_y0, false, false, false);
  gmsh::model::getBoundary({{1, cap.arc_x0}}, ends_x0, false, false, false);
  const auto outer_end = [&](const gmsh::vectorpair& ends) {
    const int first = std::abs(ends.at(0).second), second = std::abs(ends.at(1).second);
    return point_node(first == cap.pole ? second : first);
  };
  const std::size_t pole_node = point_node(cap.pole);
  const std::size_t ring_end_y0 = outer_end(ends_y0), ring_end_x0 = outer_end(ends_x0);
  std::size_t next_node = largest_node_tag() + 1, next_element = largest_element_tag() + 1;
  const std::vector<double>& s = rings.radius_m;
  const std::size_t n = s.size();
  // nodes[j][k]: ring j's node k, at the angle (pi / 2) k / m_j.
  std::vector<std::vector<std::size_t>> nodes(n);
  nodes[0] = {pole_node};
  struct NewNodes
  {
    std::vector<std::size_t> tags;
    std::vector<double> x;
  } arc_y0, arc_x0, ring, face;
  for (std::size_t j = 1; j < n; ++j)
  {
    const std::vector<double>& angles = rings.angles_rad[j];
    const std::size_t m = angles.size() - 1;
    const double z = R - std::sqrt(R * R - s[j] * s[j]);
    for (std::size_t k = 0; k <= m; ++k)
    {
      const bool last = j + 1 == n;
      if (last && (k == 0 || k == m))
      {
        nodes[j].push_back(k == 0 ? ring_end_y0 : ring_end_x0);
        continue;
      }
      const double t = angles[k];
      NewNodes& on = last ? ring : k == 0 ? arc_y0 : k == m ? arc_x0 : face;
      on.tags.push_back(next_node);
      on.x.insert(on.x.end(), {k == m ? 0.0 : s[j] * std::cos(t), k == 0 ? 0.0 : s[j] * std::sin(t), z});
      nodes[j].push_back(next_node++);
    }
  }
  add_nodes(1, cap.arc_y0, arc_y0.tags, arc_y0.x);
  add_nodes(1, cap.arc_x0, arc_x0.tags, arc_x0.x);
  add_nodes(1, cap.ring, ring.tags, ring.x);
  add_nodes(2, cap.face, face.tags, face.x);
  const auto add_lines = [&](int curve, const std::vector<std::size_t>& chain) {
    std::vector<std::size_t> elements, line_nodes;
    for (std::size_t i = 0; i + 1 < chain.size(); ++i)
    {
      elements.push_back(next_element++);
      line_nodes.insert(line_nodes.end(), {chain[i], chain[i + 1]});
    }
    mesh::addElementsByType(curve, 1, elements, line_nodes);
  };
  std::vector<std::size_t> chain_y0, chain_x0;
  for (const auto& on_ring : nodes)
  {
    chain_y0.push_back(on_ring.front());
    chain_x0.push_back(on_ring.back());
  }
  add_lines(cap.arc_y0, chain_y0);
  add_lines(cap.arc_x0, chain_x0);
  add_lines(cap.ring, nodes[n - 1]);
  // Between rings j and j + 1, the next triangle takes the segment (inner
  // or outer) whose midpoint angle comes first (cap_rings.h).
  std::vector<std::size_t> triangles, triangle_nodes;
  for (std::size_t j = 0; j + 1 < n; ++j)
  {
    const std::vector<std::size_t>&inner = nodes[j], &outer = nodes[j + 1];
    const std::vector<double>&t_in = rings.angles_rad[j], &t_out = rings.angles_rad[j + 1];
    const std::size_t m_in = inner.size() - 1, m_out = outer.size() - 1;
    std::size_t i = 0, k = 0;
    while (i < m_in || k < m_out)
    {
      const bool take_inner
          = i < m_in && (k == m_out || t_in[i] + t_in[i + 1] < t_out[k] + t_out[k + 1]);
      triangles.push_back(next_element++);
      triangle_nodes.insert(triangle_nodes.end(), {inner[i], outer[k], take_inner ? inner[i + 1] : outer[k + 1]});
      (take_inner ? i : k) += 1;
    }
  }
  mesh::addElementsByType(cap.face, 2, triangles, triangle_nodes);
  gmsh::option::setNumber("Mesh.MeshOnlyEmpty", 1);
}

/// The grading's size field about the point `pole`, refined as `refinement`
/// says (hertz_mesh.h), as the background mesh.
void set_refined_size_field(int pole, double R, const MeshGrading& g, const ContactRefinement& refinement)
{
  namespace field = gmsh::model::mesh::field;
  const int from_pole = field::add("Distance");
  field::setNumbers(from_pole, "PointsList", {static_cast<double>(pole)});
  std::vector<double> sizes = {
      static_cast<double>(add_threshold_field(from_pole, g.contact_size_m, g.far_size_m, g.fine_radius_m, g.growth))};
  if (refinement.pole_size_m > 0)
    sizes.push_back(add_threshold_field(from_pole, refinement.pole_size_m, g.far_size_m, refinement.pole_radius_m,
                                        g.growth));
  if (refinement.edge_size_m > 0)
  {
    const double c = refinement.edge_radius_m;
    const int from_edge = field::add("MathEval");
    field::setString(from_edge, "F",
                     fmt::format("Sqrt((Sqrt(x * x + y * y) - {0:.17g})^2 + (z - {1:.17g})^2)", c,
                                 R - std::sqrt(R * R - c * c)));
    sizes.push_back(add_threshold_field(from_edge, refinement.edge_size_m, g.far_size_m,
                                        refinement.edge_half_width_m, g.growth));
  }
  const int smallest = field::add("Min");
  field::setNumbers(smallest, "FieldsList", sizes);
  field::setAsBackgroundMesh(smallest);
  sizes_from_fields_alone();
}
} // namespace

SceneMesh build_scene_mesh(MPI_Comm comm, Model model, double R, const MeshGrading& grading,
                           const ContactRefinement& refinement)
{
  const auto start = std::chrono::steady_clock::now();
  const bool solid = model == Model::solid;
  const int gdim = solid ? 3 : 2;
  SceneMesh scene = distribute(comm, gdim, [&] {
    if (!solid)
      return mesh_with_gmsh(gdim, [&] { return add_quarter_disc(R); }, grading);
    return mesh_with_gmsh(gdim, [&] {
      const std::vector<double>& rings = refinement.cap.radius_m;
      double smallest = std::min({grading.contact_size_m, refinement.pole_size_m > 0 ? refinement.pole_size_m : R,
                                  refinement.edge_size_m > 0 ? refinement.edge_size_m : R});
      if (rings.empty())
        set_refined_size_field(add_quarter_hemisphere(R), R, grading, refinement);
      else
      {
        const CapEntities cap = add_revolved_quarter_hemisphere(R, rings.back());
        set_refined_size_field(cap.pole, R, grading, refinement);
        mesh_cap_by_rings(cap, refinement.cap, R);
        for (std::size_t j = 1; j < rings.size(); ++j)
          smallest = std::min(smallest, rings[j] - rings[j - 1]);
      }
      return smallest;
    });
  });
  const double tol = 1e-9 * R;
  auto z_of = [solid](double y, double z) { return solid ? z : y; };
  SceneParts parts;
  parts.symmetry_x = [tol](double x, double, double) { return std::abs(x) < tol; };
  if (solid)
    parts.symmetry_y = [tol](double, double y, double) { return std::abs(y) < tol; };
  parts.top = [&](double, double y, double z) { return std::abs(z_of(y, z) - R) < tol; };
  parts.curved = [&](double x, double y, double z) {
    const double h = z_of(y, z) - R;
    const double r2 = solid ? x * x + y * y : x * x;
    return std::abs(std::sqrt(r2 + h * h) - R) < 1e-7 * R;
  };
  parts.in_plane = [&](double x, double y, double z) {
    return std::abs(x) < tol || (solid && std::abs(y) < tol) || std::abs(z_of(y, z) - R) < tol;
  };
  tag_parts(scene, parts);
  scene.symmetry_multiplicity = model == Model::axisymmetric ? 1 : model == Model::plane_strain ? 2 : 4;
  scene.wall_s = seconds_since(start);
  return scene;
}
} // namespace rollcheck::fem
