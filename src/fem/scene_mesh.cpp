#include "fem/scene_mesh.h"
#include "geometry/error.h"
#include <chrono>
#include <cmath>
#include <dolfinx/fem/CoordinateElement.h>
#include <dolfinx/graph/AdjacencyList.h>
#include <dolfinx/io/cells.h>
#include <dolfinx/mesh/cell_types.h>
#include <dolfinx/mesh/utils.h>
#include <gmsh.h>
#include <numbers>
#include <unordered_map>
#include <xtensor/xtensor.hpp>
#include <xtensor/xview.hpp>

namespace rollcheck::fem
{
namespace
{
/// Nodes and cells of a gmsh mesh in DOLFINx input form.
struct RawMesh
{
  std::vector<double> x;        ///< row-major, gdim columns
  std::vector<std::int64_t> cells;
};

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

void set_graded_size_field(int pole, const MeshGrading& g)
{
  namespace field = gmsh::model::mesh::field;
  const int distance = field::add("Distance");
  field::setNumbers(distance, "PointsList", {static_cast<double>(pole)});
  const int threshold = field::add("Threshold");
  field::setNumber(threshold, "InField", distance);
  field::setNumber(threshold, "SizeMin", g.contact_size_m);
  field::setNumber(threshold, "SizeMax", g.far_size_m);
  field::setNumber(threshold, "DistMin", g.fine_radius_m);
  field::setNumber(threshold, "DistMax", g.fine_radius_m + (g.far_size_m - g.contact_size_m) / g.growth);
  field::setAsBackgroundMesh(threshold);
  // The field alone sets the sizes.
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
}

RawMesh mesh_with_gmsh(Model model, double R, const MeshGrading& grading)
{
  const bool solid = model == Model::solid;
  gmsh::initialize();
  RawMesh raw;
  try
  {
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.NumThreads", 1);
    gmsh::model::add("hertz");
    const int pole = solid ? add_quarter_hemisphere(R) : add_quarter_disc(R);
    set_graded_size_field(pole, grading);
    gmsh::option::setNumber("Mesh.Algorithm", 6);   // Frontal-Delaunay: near-equilateral triangles
    gmsh::option::setNumber("Mesh.Algorithm3D", 1); // Delaunay
    gmsh::option::setNumber("Mesh.Optimize", 1);
    const int dim = solid ? 3 : 2;
    gmsh::model::mesh::generate(dim);

    std::vector<std::size_t> node_tags;
    std::vector<double> coords, parametric;
    gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
    std::unordered_map<std::size_t, std::int64_t> index;
    index.reserve(node_tags.size());
    for (std::size_t i = 0; i < node_tags.size(); ++i)
      index[node_tags[i]] = static_cast<std::int64_t>(i);
    raw.x.reserve(node_tags.size() * dim);
    for (std::size_t i = 0; i < node_tags.size(); ++i)
      for (int j = 0; j < dim; ++j)
        raw.x.push_back(coords[3 * i + j]);

    const int gmsh_type = solid ? 4 : 2; // 4-node tetrahedron, 3-node triangle
    std::vector<std::size_t> element_tags, element_nodes;
    gmsh::model::mesh::getElementsByType(gmsh_type, element_tags, element_nodes);
    raw.cells.reserve(element_nodes.size());
    for (std::size_t tag : element_nodes)
      raw.cells.push_back(index.at(tag));
  }
  catch (const std::exception& e)
  {
    gmsh::finalize();
    throw ComputationError(std::string("gmsh failed to mesh the scene: ") + e.what());
  }
  catch (...)
  {
    // gmsh 4.8 throws std::string from some algorithms.
    gmsh::finalize();
    throw ComputationError("gmsh failed to mesh the scene");
  }
  gmsh::finalize();
  return raw;
}

/// Boundary facets whose vertices all satisfy `on`.
std::vector<std::int32_t> boundary_facets(const dolfinx::mesh::Mesh& mesh,
                                          const std::function<bool(double, double, double)>& on)
{
  const int fdim = mesh.topology().dim() - 1;
  return dolfinx::mesh::locate_entities_boundary(mesh, fdim, [&](const xt::xtensor<double, 2>& x) {
    xt::xtensor<bool, 1> marked = xt::zeros<bool>({x.shape(1)});
    for (std::size_t i = 0; i < x.shape(1); ++i)
      marked(i) = on(x(0, i), x(1, i), x(2, i));
    return marked;
  });
}
} // namespace

SceneMesh build_scene_mesh(MPI_Comm comm, Model model, double R, const MeshGrading& grading)
{
  const auto start = std::chrono::steady_clock::now();
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const bool solid = model == Model::solid;
  const int gdim = solid ? 3 : 2;
  const auto cell_type = solid ? dolfinx::mesh::CellType::tetrahedron : dolfinx::mesh::CellType::triangle;
  const int nodes_per_cell = solid ? 4 : 3;

  // gmsh runs on rank 0 only; the other ranks enter create_mesh empty-handed.
  RawMesh raw;
  int failed = 0;
  std::string message;
  if (rank == 0)
  {
    try
    {
      raw = mesh_with_gmsh(model, R, grading);
    }
    catch (const std::exception& e)
    {
      failed = 1;
      message = e.what();
    }
  }
  MPI_Bcast(&failed, 1, MPI_INT, 0, comm);
  if (failed)
    throw ComputationError(rank == 0 ? message : "gmsh failed on rank 0");

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
  const double tol = 1e-9 * R;
  // The vertical coordinate is x[1] in 2D, x[2] in 3D (DOLFINx pads to 3).
  const int zi = gdim - 1;
  auto z_of = [zi](double, double y, double z) { return zi == 1 ? y : z; };
  auto on_sphere = [&](double x, double y, double z) {
    const double h = z_of(x, y, z) - R;
    const double r2 = solid ? x * x + y * y : x * x;
    return std::abs(std::sqrt(r2 + h * h) - R) < 1e-7 * R;
  };
  scene.symmetry_x_facets = boundary_facets(*mesh, [&](double x, double, double) { return std::abs(x) < tol; });
  if (solid)
    scene.symmetry_y_facets = boundary_facets(*mesh, [&](double, double y, double) { return std::abs(y) < tol; });
  scene.top_facets = boundary_facets(*mesh, [&](double x, double y, double z) { return std::abs(z_of(x, y, z) - R) < tol; });

  // Facets with all vertices on the sphere, except those lying in a plane of
  // the scene (a plane facet can have all its vertices on the rim circle).
  std::vector<std::int32_t> candidates = boundary_facets(*mesh, on_sphere);
  const std::vector<double> mid = dolfinx::mesh::compute_midpoints(*mesh, tdim - 1, candidates);
  for (std::size_t i = 0; i < candidates.size(); ++i)
  {
    const double x = mid[3 * i], y = mid[3 * i + 1], z = mid[3 * i + 2];
    const bool in_plane = std::abs(x) < tol || (solid && std::abs(y) < tol) || std::abs(z_of(x, y, z) - R) < tol;
    if (!in_plane)
      scene.contact_facets.push_back(candidates[i]);
  }
  scene.symmetry_multiplicity = model == Model::axisymmetric ? 1 : model == Model::plane_strain ? 2 : 4;
  scene.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return scene;
}
} // namespace rollcheck::fem
