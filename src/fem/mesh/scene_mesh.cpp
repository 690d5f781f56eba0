#include "fem/mesh/gmsh_raw_mesh.h"
#include "fem/on_rank_zero.h"
#include "fem/mesh/scene_mesh.h"
#include "core/error.h"
#include <fmt/format.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <dolfinx/fem/CoordinateElement.h>
#include <dolfinx/graph/AdjacencyList.h>
#include <dolfinx/io/cells.h>
#include <dolfinx/mesh/cell_types.h>
#include <dolfinx/mesh/utils.h>
#include <functional>
#include <gmsh.h>
#include <numbers>
#include <xtensor/xtensor.hpp>
#include <xtensor/xview.hpp>

namespace rollcheck::fem
{
namespace
{
/// The gmsh point entity at the origin (the first point of contact).
int point_at_origin(double radius)
{
  gmsh::vectorpair points;
  gmsh::model::getEntities(points, 0);
  for (const auto& [dim, tag] : points)
  {
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(dim, tag, x0, y0, z0, x1, y1, z1);
    if (std::max({std::abs(x0), std::abs(y0), std::abs(z0), std::abs(x1), std::abs(y1), std::abs(z1)})
        < 1e-9 * radius)
      return tag;
  }
  throw ComputationError("scene mesh: the geometry has no vertex at the point of contact");
}

/// Quarter disc in the xy-plane of gmsh (y is the model's z); returns the tag
/// of the point of contact.
int add_quarter_disc(double R)
{
  namespace occ = gmsh::model::occ;
  const int pole = occ::addPoint(0, 0, 0);
  const int centre = occ::addPoint(0, R, 0);
  const int rim = occ::addPoint(R, R, 0);
  const int arc = occ::addCircleArc(pole, centre, rim);
  const int top = occ::addLine(rim, centre);
  const int axis = occ::addLine(centre, pole);
  occ::addPlaneSurface({occ::addCurveLoop({arc, top, axis})});
  occ::synchronize();
  return pole;
}

/// The crease scene's polygon in the xy-plane of gmsh (y is the model's z);
/// returns the tag of the apex.
int add_half_crease(const CreaseGeometry& k)
{
  namespace occ = gmsh::model::occ;
  const double W = k.width_m, H = k.height_m;
  const int apex = occ::addPoint(0, 0, 0);
  const int face_end = occ::addPoint(W, W * std::tan(k.face_angle_rad), 0);
  const int top_right = occ::addPoint(W, H, 0);
  const int top_left = occ::addPoint(0, H, 0);
  const std::vector<int> lines = {occ::addLine(apex, face_end), occ::addLine(face_end, top_right),
                                  occ::addLine(top_right, top_left), occ::addLine(top_left, apex)};
  occ::addPlaneSurface({occ::addCurveLoop(lines)});
  occ::synchronize();
  return apex;
}

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

/// The size field (or callback) alone sets the element sizes.
void sizes_from_fields_alone()
{
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
}

void set_graded_size_field(int pole, const MeshGrading& g)
{
  namespace field = gmsh::model::mesh::field;
  const int distance = field::add("Distance");
  field::setNumbers(distance, "PointsList", {static_cast<double>(pole)});
  field::setAsBackgroundMesh(
      add_threshold_field(distance, g.contact_size_m, g.far_size_m, g.fine_radius_m, g.growth));
  sizes_from_fields_alone();
}

/// Quarter disc of radius 1 extruded along gmsh's z by `length` in the given
/// layers (structured, tetrahedra); returns the tag of the point of contact
/// on the section z = 0.
int add_extruded_quarter_disc(double length, const std::vector<double>& layer_fractions)
{
  const int pole = add_quarter_disc(1.0);
  gmsh::vectorpair out;
  gmsh::model::occ::extrude({{2, 1}}, 0, 0, length, out, std::vector<int>(layer_fractions.size(), 1),
                            layer_fractions, false);
  gmsh::model::occ::synchronize();
  return pole;
}

/// The rim end's solid (build_rim_end_mesh): the block x in [-L, H],
/// y in [0, H], z <= H, inside the cylinder of radius R about the line
/// (x, 0, R), cut by the other face's half-space, its edge filleted.
void add_rim_end(const RimEndGeometry& g)
{
  namespace occ = gmsh::model::occ;
  const double H = g.depth_m, L = g.length_m, R = g.radius_m;
  gmsh::vectorpair body, cut;
  std::vector<gmsh::vectorpair> map;
  if (g.flat_sheet)
    body = {{3, occ::addBox(-L, 0, 0, L + H, H, H)}};
  else
  {
    // The box overlaps the tangent plane z = 0 instead of touching it.
    const int box = occ::addBox(-L, 0, -0.1 * H, L + H, H, 1.1 * H);
    const int cylinder = occ::addCylinder(-L - H, 0, R, L + 3 * H, 0, 0, R);
    occ::intersect({{3, box}}, {{3, cylinder}}, body, map);
  }
  // Beyond the other face: n . p > 0, n = (sin a, 0, cos a) for the interior
  // angle a, which is +x (a square end) turned about y by a - 90 deg.
  const double span = 10 * (L + H);
  const int half_space = occ::addBox(0, -span, -span, span, 2 * span, 2 * span);
  occ::rotate({{3, half_space}}, 0, 0, 0, 0, 1, 0, g.interior_angle_rad - std::numbers::pi / 2);
  occ::cut(body, {{3, half_space}}, cut, map);
  occ::synchronize();
  if (cut.size() != 1)
    throw ComputationError(fmt::format("rim end: the cut left {} volumes, not one", cut.size()));
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
  gmsh::vectorpair filleted;
  occ::fillet({cut[0].second}, edges, {g.edge_radius_m}, filleted, true);
  occ::synchronize();
  if (filleted.size() != 1)
    throw ComputationError(fmt::format("rim end: the fillet of radius {:.3g} m failed", g.edge_radius_m));
}

/// gmsh compares lengths with its geometric tolerance, 1e-8 of the model's
/// size (Geometry.Tolerance); an element size near it makes the 2D mesher
/// throw from inside an OpenMP region, which aborts the process. Measured on
/// the plane-strain Hertz scene: h_c = 1.35e-8 of the model (1e-5 N) meshes
/// and solves (b within 0.05 % of Hertz), 1.35e-9 (1e-7 N) aborts. Sizes below
/// 1e-8 of the model are refused before meshing, as bad input.
void require_meshable(double smallest_size_m)
{
  constexpr double smallest_relative_size = 1e-8;
  double x0, y0, z0, x1, y1, z1;
  gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
  const double model_size = std::max({x1 - x0, y1 - y0, z1 - z0});
  if (!(smallest_size_m >= smallest_relative_size * model_size))
    throw InputError(fmt::format(
        "the contact element size {:.3g} is {:.3g} of the modelled body ({:.3g}), below the {:g} gmsh can mesh "
        "reliably: the load is too small (or the body too large) for the contact to be resolved; the smallest "
        "representable load gives a contact about {:g} times larger",
        smallest_size_m, smallest_size_m / model_size, model_size, smallest_relative_size,
        smallest_relative_size * model_size / smallest_size_m));
}

/// Meshes the current model's volumes one at a time, on one surface mesh
/// (conforming wherever volumes share a face). gmsh's Delaunay
/// tetrahedralises volumes that share a face together, and the surface
/// meshes of both must then stay apart by more than its tolerances: the rim
/// end's fillet on the steel block, lifting off tangentially from the
/// block's free top (d^2 / (2 r_e) above it at d beyond the fillet's start),
/// failed below edge elements of about 2 um ("Invalid boundary mesh
/// (overlapping facets)"). Each volume alone, the others hidden
/// (Mesh.MeshOnlyVisible), never sees the other's faces.
void generate_volume_by_volume()
{
  gmsh::vectorpair volumes;
  gmsh::model::getEntities(volumes, 3);
  gmsh::model::mesh::generate(2);
  gmsh::option::setNumber("Mesh.MeshOnlyVisible", 1);
  for (const auto& volume : volumes)
  {
    gmsh::model::setVisibility(volumes, 0);
    gmsh::model::setVisibility({volume}, 1);
    gmsh::model::mesh::generate(3);
  }
  gmsh::model::setVisibility(volumes, 1);
}

/// Runs gmsh on the geometry `add_geometry` builds, whose element sizes (and
/// any other meshing option) it sets too; it returns the smallest size.
/// Several volumes are tetrahedralised one at a time. The mesh as
/// read_gmsh_mesh(dim) reads it.
RawMesh mesh_with_gmsh(int dim, const std::function<double()>& add_geometry_and_sizes)
{
  gmsh::initialize();
  RawMesh raw;
  try
  {
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.NumThreads", 1);
    gmsh::model::add("scene");
    gmsh::option::setNumber("Mesh.Algorithm", 6);   // Frontal-Delaunay: near-equilateral triangles
    gmsh::option::setNumber("Mesh.Algorithm3D", 1); // Delaunay
    gmsh::option::setNumber("Mesh.Optimize", 1);
    require_meshable(add_geometry_and_sizes());
    gmsh::vectorpair volumes;
    gmsh::model::getEntities(volumes, 3);
    if (dim == 3 && volumes.size() > 1)
      generate_volume_by_volume();
    else
      gmsh::model::mesh::generate(dim);
    raw = read_gmsh_mesh(dim);
  }
  catch (const InputError&)
  {
    gmsh::finalize();
    throw;
  }
  catch (const std::exception& e)
  {
    gmsh::finalize();
    throw ComputationError(std::string("gmsh failed to mesh the scene: ") + e.what());
  }
  catch (...)
  {
    // gmsh 4.8 throws std::string from some algorithms; its last error
    // message says which.
    std::string last;
    gmsh::logger::getLastError(last);
    gmsh::finalize();
    throw ComputationError("gmsh failed to mesh the scene" + (last.empty() ? std::string() : ": " + last));
  }
  gmsh::finalize();
  return raw;
}

/// mesh_with_gmsh with the grading about the point of contact, whose tag
/// `add_geometry` returns.
RawMesh mesh_with_gmsh(int dim, const std::function<int()>& add_geometry, const MeshGrading& grading)
{
  return mesh_with_gmsh(dim, [&] {
    set_graded_size_field(add_geometry(), grading);
    return grading.contact_size_m;
  });
}

using Predicate = std::function<bool(double, double, double)>;

/// Boundary facets whose vertices all satisfy `on`.
std::vector<std::int32_t> boundary_facets(const dolfinx::mesh::Mesh& mesh, const Predicate& on)
{
  const int fdim = mesh.topology().dim() - 1;
  return dolfinx::mesh::locate_entities_boundary(mesh, fdim, [&](const xt::xtensor<double, 2>& x) {
    xt::xtensor<bool, 1> marked = xt::zeros<bool>({x.shape(1)});
    for (std::size_t i = 0; i < x.shape(1); ++i)
      marked(i) = on(x(0, i), x(1, i), x(2, i));
    return marked;
  });
}

/// The mesh `make_raw` returns on rank 0, distributed over `comm`.
SceneMesh distribute(MPI_Comm comm, int gdim, const std::function<RawMesh()>& make_raw)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const auto cell_type = gdim == 3 ? dolfinx::mesh::CellType::tetrahedron : dolfinx::mesh::CellType::triangle;
  const int nodes_per_cell = gdim + 1;

  // gmsh runs on rank 0 only; the other ranks enter create_mesh empty-handed.
  const RawMesh raw = on_rank_zero<RawMesh>(comm, make_raw);

  const std::size_t num_cells = raw.cells.size() / nodes_per_cell;
  const std::vector<std::uint8_t> perm = dolfinx::io::cells::perm_gmsh(cell_type, nodes_per_cell);
  std::vector<std::int64_t> cells
      = dolfinx::io::cells::apply_permutation(raw.cells, {num_cells, std::size_t(nodes_per_cell)}, perm);
  const dolfinx::fem::CoordinateElement cmap(cell_type, 1);
  auto mesh = std::make_shared<dolfinx::mesh::Mesh>(dolfinx::mesh::create_mesh(
      comm, dolfinx::graph::regular_adjacency_list(std::move(cells), nodes_per_cell), cmap, raw.x,
      {raw.x.size() / gdim, std::size_t(gdim)}, dolfinx::mesh::GhostMode::none));
  const int tdim = mesh->topology().dim();
  mesh->topology_mutable().create_entities(tdim - 1);
  mesh->topology_mutable().create_connectivity(tdim - 1, tdim);
  SceneMesh scene;
  scene.mesh = mesh;
  return scene;
}

/// Where a scene's boundary parts lie, as predicates on points (x, y, z)
/// (DOLFINx pads 2D points with z = 0; the 2D vertical is y).
struct SceneParts
{
  Predicate symmetry_x, symmetry_y, top;
  Predicate curved;   ///< on the surface that may touch the plane
  Predicate in_plane; ///< in one of the scene's planes
  /// 3D: keep only the facets facing the plane z = 0 (outward normal's z
  /// component negative). A face that is vertical or turned away can never
  /// touch it, and as a contact facet it would dilute the recovered nodal
  /// pressure of the nodes it shares with the sheet (a square end's edge
  /// read about half its pressure: 0.27 of the interior against 0.52 on a
  /// structured grid with the sheet alone).
  bool facing_plane_only = false;
};

/// Tags the parts; the contact facets are the facets with all vertices on the
/// curved surface except those lying in a plane (a plane facet can have all
/// its vertices on a rim).
void tag_parts(SceneMesh& scene, const SceneParts& parts)
{
  const dolfinx::mesh::Mesh& mesh = *scene.mesh;
  const int fdim = mesh.topology().dim() - 1;
  if (parts.symmetry_x)
    scene.symmetry_x_facets = boundary_facets(mesh, parts.symmetry_x);
  if (parts.symmetry_y)
    scene.symmetry_y_facets = boundary_facets(mesh, parts.symmetry_y);
  scene.top_facets = boundary_facets(mesh, parts.top);
  std::vector<std::int32_t> candidates = boundary_facets(mesh, parts.curved);
  const std::vector<double> mid = dolfinx::mesh::compute_midpoints(mesh, fdim, candidates);
  const std::vector<double> normal_z
      = parts.facing_plane_only ? outward_normal_z(mesh, candidates) : std::vector<double>(candidates.size(), -1.0);
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (!parts.in_plane(mid[3 * i], mid[3 * i + 1], mid[3 * i + 2]) && normal_z[i] < -1e-6)
      scene.contact_facets.push_back(candidates[i]);
}

/// The contact facets of two bodies meshed as twins along an interface:
/// the boundary facets `on` it whose cell lies above (coordinate `up` > 0);
/// the lower body's twins lie at the same place, on cells below.
void upper_interface_facets(SceneMesh& scene, const Predicate& on, int up)
{
  const dolfinx::mesh::Mesh& mesh = *scene.mesh;
  const int tdim = mesh.topology().dim();
  const std::vector<std::int32_t> interface = boundary_facets(mesh, on);
  auto facet_cells = mesh.topology().connectivity(tdim - 1, tdim);
  std::vector<std::int32_t> cells;
  for (std::int32_t f : interface)
    cells.push_back(facet_cells->links(f)[0]);
  const std::vector<double> mid = dolfinx::mesh::compute_midpoints(mesh, tdim, cells);
  for (std::size_t i = 0; i < interface.size(); ++i)
    if (mid[3 * i + up] > 0)
      scene.contact_facets.push_back(interface[i]);
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
} // namespace

std::vector<double> outward_normal_z(const dolfinx::mesh::Mesh& mesh, std::span<const std::int32_t> facets)
{
  const int tdim = mesh.topology().dim();
  const std::vector<std::int32_t> nodes = dolfinx::mesh::entities_to_geometry(mesh, tdim - 1, facets, false);
  auto facet_cells = mesh.topology().connectivity(tdim - 1, tdim);
  std::vector<std::int32_t> cells;
  for (std::int32_t f : facets)
    cells.push_back(facet_cells->links(f)[0]);
  const std::vector<double> cell_mid = dolfinx::mesh::compute_midpoints(mesh, tdim, cells);
  std::span<const double> x = mesh.geometry().x();
  std::vector<double> normal_z;
  for (std::size_t i = 0; i < facets.size(); ++i)
  {
    const double* p0 = &x[3 * nodes[3 * i]];
    const double* p1 = &x[3 * nodes[3 * i + 1]];
    const double* p2 = &x[3 * nodes[3 * i + 2]];
    const std::array<double, 3> a{p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
    const std::array<double, 3> c{p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
    std::array<double, 3> n{a[1] * c[2] - a[2] * c[1], a[2] * c[0] - a[0] * c[2], a[0] * c[1] - a[1] * c[0]};
    // Outward: away from the cell's midpoint.
    double away = 0;
    for (int k = 0; k < 3; ++k)
      away += n[k] * ((p0[k] + p1[k] + p2[k]) / 3 - cell_mid[3 * i + k]);
    normal_z.push_back((away < 0 ? -n[2] : n[2]) / std::hypot(n[0], n[1], n[2]));
  }
  return normal_z;
}

SceneMesh build_scene_mesh(MPI_Comm comm, Model model, double R, const MeshGrading& grading)
{
  const auto start = std::chrono::steady_clock::now();
  const bool solid = model == Model::solid;
  const int gdim = solid ? 3 : 2;
  SceneMesh scene = distribute(comm, gdim, [&] {
    return mesh_with_gmsh(
        gdim, [&] { return solid ? add_quarter_hemisphere(R) : add_quarter_disc(R); }, grading);
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

SceneMesh build_crease_mesh(MPI_Comm comm, const CreaseGeometry& crease, const MeshGrading& grading)
{
  const auto start = std::chrono::steady_clock::now();
  const double W = crease.width_m, H = crease.height_m, slope = std::tan(crease.face_angle_rad);
  if (!(W > 0 && H > 2 * W * slope && crease.face_angle_rad > 0 && crease.face_angle_rad <= std::numbers::pi / 4))
    throw InputError(fmt::format("crease scene: need W > 0, 0 < beta <= 45 deg and H above the face's end "
                                 "(W = {} m, H = {} m, beta = {} rad)",
                                 W, H, crease.face_angle_rad));
  SceneMesh scene = distribute(comm, 2, [&] { return mesh_with_gmsh(2, [&] { return add_half_crease(crease); }, grading); });
  const double tol = 1e-9 * W;
  SceneParts parts;
  parts.symmetry_x = [tol](double x, double, double) { return std::abs(x) < tol; };
  parts.top = [H, tol](double, double y, double) { return std::abs(y - H) < tol; };
  parts.curved = [slope, tol](double x, double y, double) { return std::abs(y - x * slope) < tol; };
  parts.in_plane = [W, tol](double x, double, double) { return std::abs(x) < tol || std::abs(x - W) < tol; };
  tag_parts(scene, parts);
  scene.symmetry_multiplicity = 2;
  scene.wall_s = seconds_since(start);
  return scene;
}

double slab_along(const SlabGeometry& slab, const double* x)
{
  // Inverse of x = a + z s(a), s(a) = -tan t_0 + (tan t_0 + tan t_L) a / L.
  const double t0 = std::tan(slab.end_overhang_rad[0]), tL = std::tan(slab.end_overhang_rad[1]);
  return (x[0] + x[2] * t0) / (1 + x[2] * (t0 + tL) / slab.length_m);
}

SceneMesh build_slab_mesh(MPI_Comm comm, const SlabGeometry& slab, const MeshGrading& section_grading)
{
  const auto start = std::chrono::steady_clock::now();
  const double L = slab.length_m;
  for (double overhang : slab.end_overhang_rad)
    if (!(std::abs(overhang) <= std::numbers::pi / 3))
      throw InputError(fmt::format("slab: end overhang must lie within +-60 deg, got {} rad", overhang));
  auto radius = [&](double a) { return slab.start_radius_m + (slab.end_radius_m - slab.start_radius_m) * a / L; };
  const double t0 = std::tan(slab.end_overhang_rad[0]), tL = std::tan(slab.end_overhang_rad[1]);
  SceneMesh scene = distribute(comm, 3, [&] {
    RawMesh raw = mesh_with_gmsh(
        3, [&] { return add_extruded_quarter_disc(L, slab.layer_fractions); }, section_grading);
    // gmsh (across, up, along) at unit radius -> (along, R across, R up),
    // then sheared along the ruling so that the end faces overhang.
    for (std::size_t i = 0; i < raw.x.size(); i += 3)
    {
      const double across = raw.x[i], up = raw.x[i + 1], along = raw.x[i + 2];
      const double z = radius(along) * up;
      raw.x[i] = along + z * (-t0 + (t0 + tL) * along / L);
      raw.x[i + 1] = radius(along) * across;
      raw.x[i + 2] = z;
    }
    return raw;
  });
  // Tolerances relative to the local radius: the section is the unit disc scaled.
  const double tol = 1e-9;
  auto along = [&](double x, double y, double z) {
    const double point[3] = {x, y, z};
    return slab_along(slab, point);
  };
  SceneParts parts;
  parts.symmetry_y = [&](double x, double y, double z) { return std::abs(y / radius(along(x, y, z))) < tol; };
  parts.top = [&](double x, double y, double z) { return std::abs(z / radius(along(x, y, z)) - 1) < tol; };
  parts.curved = [&](double x, double y, double z) {
    const double R = radius(along(x, y, z));
    return std::abs(std::hypot(y / R, z / R - 1) - 1) < 1e-7;
  };
  parts.in_plane = [&](double x, double y, double z) {
    const double a = along(x, y, z), R = radius(a);
    return std::abs(a) < tol * L || std::abs(a - L) < tol * L || std::abs(y / R) < tol || std::abs(z / R - 1) < tol;
  };
  tag_parts(scene, parts);
  scene.symmetry_multiplicity = 2;
  scene.wall_s = seconds_since(start);
  return scene;
}

namespace
{
/// The rim end built and meshed in units of H (`unit`), scaled back to
/// metres; with the block below it, graded as the body mirrored in the
/// interface.
RawMesh mesh_rim_end(const RimEndGeometry& unit, const RimEndSizes& sizes, double H, bool with_block)
{
  RawMesh raw = mesh_with_gmsh(3, [&] {
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
  });
  for (double& x : raw.x)
    x *= H;
  return raw;
}

/// The rim end's planes of symmetry: the far side x = -L and y = 0.
SceneParts rim_end_planes(double L, double tol)
{
  SceneParts parts;
  parts.symmetry_x = [=](double x, double, double) { return std::abs(x + L) < tol; };
  parts.symmetry_y = [=](double, double y, double) { return std::abs(y) < tol; };
  return parts;
}
} // namespace

double fillet_start_distance(double edge_radius_m, double interior_angle_rad)
{
  return edge_radius_m * std::tan((std::numbers::pi - interior_angle_rad) / 2);
}

double rim_end_element_size(const RimEndSizes& sizes, const double* x)
{
  // Distances from the loaded part of the edge's band (along y about
  // (edge_x_m, 0, 0)) and from the contact strip (along -x).
  const double to_edge = std::sqrt(std::pow(std::max(std::abs(x[0] - sizes.edge_x_m) - sizes.edge_band_m, 0.0), 2)
                                   + x[2] * x[2]
                                   + std::pow(std::max(x[1] - sizes.edge_zone_m, 0.0), 2));
  const double to_strip = std::sqrt(x[2] * x[2] + std::pow(std::max(x[1] - sizes.contact_zone_m, 0.0), 2)
                                    + std::pow(std::max(x[0], 0.0), 2));
  return std::min(
      {sizes.far_m, sizes.edge_m + sizes.growth * to_edge, sizes.contact_m + sizes.growth * to_strip});
}

SceneMesh build_rim_end_mesh(MPI_Comm comm, const RimEndGeometry& g, const RimEndSizes& sizes)
{
  const auto start = std::chrono::steady_clock::now();
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
  // OpenCASCADE's tolerances are absolute (1e-7): the geometry is built with
  // H as the unit and the mesh scaled back.
  const RimEndGeometry unit{g.radius_m / H, g.interior_angle_rad, g.edge_radius_m / H, 1.0, L / H, g.flat_sheet};
  SceneMesh scene = distribute(comm, 3, [&] { return mesh_rim_end(unit, sizes, H, false); });
  const double tol = 1e-9 * H;
  SceneParts parts = rim_end_planes(L, tol);
  parts.top = [=](double, double, double z) { return std::abs(z - H) < tol; };
  parts.curved = [](double, double, double) { return true; };
  parts.in_plane = [=](double x, double y, double z) {
    return std::abs(x + L) < tol || std::abs(x - H) < tol || std::abs(y) < tol || std::abs(y - H) < tol
           || std::abs(z - H) < tol;
  };
  parts.facing_plane_only = true;
  tag_parts(scene, parts);
  scene.symmetry_multiplicity = 2;
  scene.wall_s = seconds_since(start);
  return scene;
}

namespace
{
/// Nodes from 0 to `length`, spaced h(d) = min(h_max, h_0 + growth max(0,
/// d - fine)) at the distance d from 0; a last gap under half its size is
/// merged into the one before.
std::vector<double> graded_nodes(double length, double h_0, double fine, double growth, double h_max)
{
  std::vector<double> nodes{0.0};
  while (nodes.back() < length)
  {
    const double d = nodes.back();
    nodes.push_back(d + std::min(h_max, h_0 + growth * std::max(0.0, d - fine)));
  }
  if (nodes.size() > 2 && length - nodes[nodes.size() - 2] < 0.5 * (nodes.back() - nodes[nodes.size() - 2]))
    nodes.pop_back();
  nodes.back() = length;
  return nodes;
}
} // namespace

SceneMesh build_square_end_grid_mesh(MPI_Comm comm, const RimEndGeometry& g, const RimEndSizes& sizes)
{
  const auto start = std::chrono::steady_clock::now();
  const double H = g.depth_m, L = g.length_m;
  const double lean = g.interior_angle_rad - std::numbers::pi / 2;
  if (!g.flat_sheet || !(std::abs(lean) <= max_grid_end_lean_rad) || g.edge_radius_m != 0)
    throw InputError(fmt::format("rim end grid: only a sharp end within {:.0f} deg of square (interior angle {:.3f} "
                                 "deg, edge radius {} m) on the flat sheet",
                                 max_grid_end_lean_rad * 180 / std::numbers::pi,
                                 g.interior_angle_rad * 180 / std::numbers::pi, g.edge_radius_m));
  for (double v : {H, L, sizes.edge_m, sizes.contact_m, sizes.contact_zone_m, sizes.far_m, sizes.growth})
    if (!std::isfinite(v) || v <= 0)
      throw InputError(fmt::format("rim end grid: depth, length and element sizes must be positive and finite "
                                   "(H = {} m, L = {} m, sizes {} m, {} m, {} m, {} m, growth {})",
                                   H, L, sizes.edge_m, sizes.contact_m, sizes.contact_zone_m, sizes.far_m,
                                   sizes.growth));
  SceneMesh scene = distribute(comm, 3, [&] {
    // Across the edge (x from it, z from the sheet) h_e growing; along it
    // (y) the strip's size over the contact zone: the edge's field varies on
    // the scale b along the edge, and on the element's own scale across it.
    const std::vector<double> along_x = graded_nodes(L, sizes.edge_m, 0, sizes.growth, sizes.far_m);
    const std::vector<double> along_y = graded_nodes(H, sizes.contact_m, sizes.contact_zone_m, sizes.growth, sizes.far_m);
    const std::vector<double> along_z = graded_nodes(H, sizes.edge_m, 0, sizes.growth, sizes.far_m);
    const std::size_t nx = along_x.size(), ny = along_y.size(), nz = along_z.size();
    RawMesh raw;
    raw.x.reserve(3 * nx * ny * nz);
    for (std::size_t i = 0; i < nx; ++i)
      for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t k = 0; k < nz; ++k)
          // Sheared so that the end face x = 0 leans by a - 90 deg, the far side fixed.
          raw.x.insert(raw.x.end(),
                       {-along_x[i] + along_z[k] * std::tan(lean) * (1 - along_x[i] / L), along_y[j], along_z[k]});
    auto node = [&](std::size_t i, std::size_t j, std::size_t k) {
      return static_cast<std::int64_t>((i * ny + j) * nz + k);
    };
    // Kuhn's six tetrahedra about each box's diagonal, one per order of the
    // axes: conforming across the grid, and each a path simplex with no
    // obtuse dihedral angle whatever the box's aspect ratio.
    constexpr std::array<std::array<int, 3>, 6> orders{
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    raw.cells.reserve(24 * (nx - 1) * (ny - 1) * (nz - 1));
    for (std::size_t i = 0; i + 1 < nx; ++i)
      for (std::size_t j = 0; j + 1 < ny; ++j)
        for (std::size_t k = 0; k + 1 < nz; ++k)
          for (const std::array<int, 3>& order : orders)
          {
            std::array<std::size_t, 3> corner{i, j, k};
            raw.cells.push_back(node(corner[0], corner[1], corner[2]));
            for (int axis : order)
            {
              ++corner[axis];
              raw.cells.push_back(node(corner[0], corner[1], corner[2]));
            }
          }
    return raw;
  });
  const double tol = 1e-9 * H;
  SceneParts parts = rim_end_planes(L, tol);
  parts.top = [=](double, double, double z) { return std::abs(z - H) < tol; };
  // The sheet, and the end face where it faces the plane (obtuse, as in
  // build_rim_end_mesh; a square or acute end's face never does).
  parts.curved = [=](double x, double, double z) {
    return std::abs(z) < tol || std::abs(x - z * std::tan(lean)) < tol;
  };
  parts.in_plane = [](double, double, double) { return false; };
  parts.facing_plane_only = true;
  tag_parts(scene, parts);
  scene.symmetry_multiplicity = 2;
  scene.wall_s = seconds_since(start);
  return scene;
}

SceneMesh build_rim_block_mesh(MPI_Comm comm, const RimEndGeometry& g, const RimEndSizes& sizes)
{
  const auto start = std::chrono::steady_clock::now();
  if (!g.flat_sheet)
    throw InputError("rim end on a block: the sheet must be flat (its profile in the initial gap)");
  const double H = g.depth_m, L = g.length_m;
  const RimEndGeometry unit{g.radius_m / H, g.interior_angle_rad, g.edge_radius_m / H, 1.0, L / H, true};
  SceneMesh scene = distribute(comm, 3, [&] { return mesh_rim_end(unit, sizes, H, true); });
  const double tol = 1e-9 * H;
  SceneParts parts = rim_end_planes(L, tol);
  parts.top = [=](double, double, double z) { return std::abs(std::abs(z) - H) < tol; };
  parts.curved = [](double, double, double) { return false; };
  parts.in_plane = [](double, double, double) { return true; };
  tag_parts(scene, parts);
  // The body's face on the interface and, rounded, its fillet (which lifts
  // off the block's top: mortar pairs), the cylinder of radius r_e about
  // the line (-x_t, y, r_e), x_t = r_e tan((180 deg - a) / 2).
  const double r_e = g.edge_radius_m, x_t = fillet_start_distance(r_e, g.interior_angle_rad);
  upper_interface_facets(
      scene,
      [=](double x, double, double z) {
        return (std::abs(z) < tol && x < tol)
               || (r_e > 0 && x > -x_t - tol && z < r_e && std::abs(std::hypot(x + x_t, z - r_e) - r_e) < 1e-6 * r_e);
      },
      2);
  // A facet of the side planes y = 0, H whose corners all lie on the
  // fillet's end arc passes the corner test but is not on the fillet.
  const int fdim = scene.mesh->topology().dim() - 1;
  const std::vector<double> mid = dolfinx::mesh::compute_midpoints(*scene.mesh, fdim, scene.contact_facets);
  std::vector<std::int32_t> on_fillet_or_face;
  for (std::size_t i = 0; i < scene.contact_facets.size(); ++i)
    if (std::abs(mid[3 * i + 1]) > tol && std::abs(mid[3 * i + 1] - H) > tol)
      on_fillet_or_face.push_back(scene.contact_facets[i]);
  scene.contact_facets = std::move(on_fillet_or_face);
  scene.symmetry_multiplicity = 2;
  scene.wall_s = seconds_since(start);
  return scene;
}

SceneMesh build_line_block_mesh(MPI_Comm comm, double size_m, const MeshGrading& grading)
{
  const auto start = std::chrono::steady_clock::now();
  const double W = size_m;
  SceneMesh scene = distribute(comm, 2, [&] {
    return mesh_with_gmsh(2, [&] {
      namespace occ = gmsh::model::occ;
      const int body = occ::addRectangle(0, 0, 0, W, W);
      const int block = occ::addRectangle(0, -W, 0, W, W);
      gmsh::vectorpair out;
      std::vector<gmsh::vectorpair> map;
      occ::fragment({{2, body}}, {{2, block}}, out, map);
      occ::synchronize();
      set_graded_size_field(point_at_origin(W), grading);
      return grading.contact_size_m;
    });
  });
  const double tol = 1e-9 * W;
  SceneParts parts;
  parts.symmetry_x = [=](double x, double, double) { return std::abs(x) < tol; };
  parts.top = [=](double, double y, double) { return std::abs(std::abs(y) - W) < tol; };
  parts.curved = [](double, double, double) { return false; };
  parts.in_plane = [](double, double, double) { return true; };
  tag_parts(scene, parts);
  upper_interface_facets(scene, [=](double, double y, double) { return std::abs(y) < tol; }, 1);
  scene.symmetry_multiplicity = 2;
  scene.wall_s = seconds_since(start);
  return scene;
}
} // namespace rollcheck::fem
