// The whole body's mesh (fem/whole_body_mesh.h): gmsh OpenCASCADE on rank 0,
// structured layers along the ruling, distributed by DOLFINx.
#include "fem/gmsh_raw_mesh.h"
#include "fem/on_rank_zero.h"
#include "fem/whole_body_mesh.h"
#include "core/error.h"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/CoordinateElement.h>
#include <dolfinx/graph/AdjacencyList.h>
#include <dolfinx/io/cells.h>
#include <dolfinx/mesh/cell_types.h>
#include <dolfinx/mesh/utils.h>
#include <fmt/format.h>
#include <functional>
#include <gmsh.h>
#include <xtensor/xtensor.hpp>

namespace rollcheck::fem
{
namespace
{
double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The disc segment z <= c of the circle of radius r about (0, r) in gmsh's
/// xy-plane (gmsh x is the body's y, gmsh y its z), graded about the contact
/// point, extruded along gmsh z through the given planes, meshed.
RawMesh mesh_extruded_segment(double r, double c, const std::vector<double>& planes, const WholeBodySizes& sizes)
{
  namespace occ = gmsh::model::occ;
  namespace field = gmsh::model::mesh::field;
  gmsh::initialize();
  RawMesh raw;
  try
  {
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.NumThreads", 1);
    gmsh::model::add("whole_body");
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
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::model::mesh::generate(3);

    raw = read_gmsh_mesh(3);
    // gmsh (across, up, along) -> (along, across, up)
    for (std::size_t i = 0; i < raw.x.size(); i += 3)
      std::rotate(raw.x.begin() + i, raw.x.begin() + i + 2, raw.x.begin() + i + 3);
    // The extruded tetrahedra of gmsh keep the orientation of the section's
    // triangles, which may be either; DOLFINx needs none in particular.
  }
  catch (const InputError&)
  {
    gmsh::finalize();
    throw;
  }
  catch (const std::exception& e)
  {
    gmsh::finalize();
    throw ComputationError(std::string("gmsh failed to mesh the whole body: ") + e.what());
  }
  catch (...)
  {
    gmsh::finalize();
    throw ComputationError("gmsh failed to mesh the whole body");
  }
  gmsh::finalize();
  return raw;
}

/// Rank 0's raw mesh distributed over `comm`; rank 0's error raised on every
/// rank. `gmsh_s`: rank 0's time making it.
std::shared_ptr<dolfinx::mesh::Mesh> distribute(MPI_Comm comm, const std::function<RawMesh()>& make_raw,
                                                double& gmsh_s)
{
  const auto start = std::chrono::steady_clock::now();
  const RawMesh raw = on_rank_zero<RawMesh>(comm, make_raw);
  gmsh_s = seconds_since(start);
  MPI_Bcast(&gmsh_s, 1, MPI_DOUBLE, 0, comm);
  const auto cell_type = dolfinx::mesh::CellType::tetrahedron;
  const std::size_t num_cells = raw.cells.size() / 4;
  const std::vector<std::uint8_t> perm = dolfinx::io::cells::perm_gmsh(cell_type, 4);
  std::vector<std::int64_t> cells = dolfinx::io::cells::apply_permutation(raw.cells, {num_cells, 4}, perm);
  const dolfinx::fem::CoordinateElement cmap(cell_type, 1);
  auto mesh = std::make_shared<dolfinx::mesh::Mesh>(
      dolfinx::mesh::create_mesh(comm, dolfinx::graph::regular_adjacency_list(std::move(cells), 4), cmap, raw.x,
                                 {raw.x.size() / 3, 3}, dolfinx::mesh::GhostMode::none));
  mesh->topology_mutable().create_entities(2);
  mesh->topology_mutable().create_connectivity(2, 3);
  return mesh;
}

using Predicate = std::function<bool(double, double, double)>;

std::vector<std::int32_t> boundary_facets(const dolfinx::mesh::Mesh& mesh, const Predicate& on)
{
  return dolfinx::mesh::locate_entities_boundary(mesh, 2, [&](const xt::xtensor<double, 2>& x) {
    xt::xtensor<bool, 1> marked = xt::zeros<bool>({x.shape(1)});
    for (std::size_t i = 0; i < x.shape(1); ++i)
      marked(i) = on(x(0, i), x(1, i), x(2, i));
    return marked;
  });
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
  if (!(sizes.contact_m > 0) || !(sizes.strip_half_width_m > 0) || !(sizes.growth > 0)
      || !(sizes.far_m >= sizes.contact_m))
    throw InputError(fmt::format("whole-body mesh sizes: contact {} m, strip {} m, growth {}, far {} m: need positive "
                                 "sizes and far >= contact",
                                 sizes.contact_m, sizes.strip_half_width_m, sizes.growth, sizes.far_m));
  if (sizes.contact_m < 1e-8 * std::max(r, L))
    throw InputError(fmt::format("whole-body mesh: contact elements of {:.3g} m are below 1e-8 of the body ({:.3g} m), "
                                 "which gmsh does not mesh reliably",
                                 sizes.contact_m, std::max(r, L)));
  WholeBodyMesh result;
  result.length_m = L;
  result.planes_m = layer_planes(L, sizes);
  result.scene.mesh = distribute(comm, [&] { return mesh_extruded_segment(r, c, result.planes_m, sizes); },
                                 result.gmsh_s);
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
  scene.symmetry_multiplicity = 1;
  const std::int64_t nodes = mesh.geometry().index_map()->size_global();
  result.section_nodes = nodes / static_cast<std::int64_t>(result.planes_m.size());
  scene.wall_s = result.gmsh_s;
  return result;
}
} // namespace rollcheck::fem
