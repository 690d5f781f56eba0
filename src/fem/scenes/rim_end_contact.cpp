#include "fem/scenes/rim_end_contact.h"
#include "fem/scenes/rim_end_oblique_peak.h"
#include "contact/edge_on_elastic_block_exponent.h"
#include "contact/hertz.h"
#include "contact/wedge_exponent.h"
#include "core/error.h"
#include "core/refinement_series.h"
#include "fem/all_gather.h"
#include "fem/field_output.h"
#include "fem/load_control.h"
#include "fem/nodal_fields.h"
#include "fem/penalty_contact.h"
#include "fem/petsc_session.h"
#include "fem/mesh/oblique_end_angle.h"
#include "fem/mesh/rim_end_extruded_mesh.h"
#include "fem/mesh/scene_mesh.h"
#include "fem/write_fields.h"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace rollcheck::fem
{
namespace
{
void validate(const RimEndSettings& s)
{
  for (const auto& [value, name] :
       {std::pair{s.radius_m, "radius_m"}, std::pair{s.load_n_per_m, "load_n_per_m"},
        std::pair{s.youngs_modulus_pa, "youngs_modulus_pa"}, std::pair{s.depth_over_half_width, "depth_over_half_width"},
        std::pair{s.length_over_depth, "length_over_depth"},
        std::pair{s.edge_element_over_half_width, "edge_element_over_half_width"},
        std::pair{s.tolerance, "tolerance"}, std::pair{s.penalty_c, "penalty_c"},
        std::pair{s.first_approach_scale, "first_approach_scale"}})
    if (!std::isfinite(value) || value <= 0)
      throw InputError(fmt::format("rim: {} must be positive and finite, got {}", name, value));
  if (!(s.interior_angle_rad >= std::numbers::pi / 3 && s.interior_angle_rad < std::numbers::pi))
    throw InputError(fmt::format("rim: interior_angle_deg must lie in [60, 180), got {}",
                                 s.interior_angle_rad * 180 / std::numbers::pi));
  if (!(s.poisson_ratio >= 0 && s.poisson_ratio < 0.5))
    throw InputError(fmt::format("rim: poisson_ratio must lie in [0, 0.5), got {}", s.poisson_ratio));
  if (!(s.edge_radius_m >= 0) || !std::isfinite(s.edge_radius_m))
    throw InputError(fmt::format("rim: edge_radius_m must be >= 0 and finite, got {}", s.edge_radius_m));
  if (s.depth_over_half_width < 4 || s.length_over_depth < 1)
    throw InputError(fmt::format("rim: the block must be at least 4 b deep and H long (depth_over_half_width {}, "
                                 "length_over_depth {})",
                                 s.depth_over_half_width, s.length_over_depth));
  if (s.mesh == RimEndMesh::grid
      && (s.counter_face != CounterFace::rigid || s.sheet == SheetModel::cylinder || s.edge_radius_m != 0
          || !(std::abs(s.interior_angle_rad - std::numbers::pi / 2) <= max_grid_end_lean_rad)))
    throw InputError(fmt::format("rim: end_mesh = grid models only a sharp end within {:.0f} deg of square "
                                 "(interior_angle_deg 90 +- {:.0f}, edge_radius_m 0) on the flat sheet against the "
                                 "rigid plane",
                                 max_grid_end_lean_rad * 180 / std::numbers::pi,
                                 max_grid_end_lean_rad * 180 / std::numbers::pi));
  if (s.mesh == RimEndMesh::extruded && (s.counter_face != CounterFace::rigid || s.sheet == SheetModel::cylinder))
    throw InputError("rim: end_mesh = extruded models an end on the flat sheet against the rigid plane");
  if (crosses_obliquely(s.crossing_angle_rad)
      && (!(s.crossing_angle_rad > 0 && s.crossing_angle_rad < std::numbers::pi / 2)
          || s.counter_face != CounterFace::rigid
          || (s.mesh != RimEndMesh::delaunay && s.mesh != RimEndMesh::hxt && s.mesh != RimEndMesh::automatic)
          || !(s.length_over_depth > 1 + 1 / std::tan(s.crossing_angle_rad))))
    throw InputError(fmt::format("rim: crossing_angle_deg must lie in (0, 90]; below 90 the end model is on the "
                                 "rigid plane, end_mesh gmsh or hxt, with length_over_depth above 1 + cot c (got crossing {} "
                                 "deg, length_over_depth {})",
                                 s.crossing_angle_rad * 180 / std::numbers::pi, s.length_over_depth));
  if (!s.xdmf_path.empty())
  {
    check_field_output(s.xdmf_path, "rim: the field output (--xdmf)");
  }
  if (s.contact_elements < 2 || s.contact_elements > 40 || s.levels < 1 || s.levels > 6 || s.extra_levels < 0
      || s.extra_levels > 2)
    throw InputError(fmt::format("rim: contact_elements must be 2 to 40, levels 1 to 6 and extra_levels 0 to 2, got "
                                 "{}, {} and {}",
                                 s.contact_elements, s.levels, s.extra_levels));
}

struct Sample
{
  double mean, sd;
  int count;
  double standard_error() const { return sd / std::sqrt(count); }
};

/// Mean and standard deviation of the centre-line pressures with x in [from,
/// to], at least `least` of them.
Sample centre_line_mean(const std::vector<CentreLineNode>& line, double from, double to, int least = 2)
{
  double sum = 0, sum2 = 0;
  int n = 0;
  for (const CentreLineNode& node : line)
    if (node.x_m >= from && node.x_m <= to)
    {
      sum += node.pressure_pa;
      sum2 += node.pressure_pa * node.pressure_pa;
      ++n;
    }
  if (n < least)
    throw ComputationError(fmt::format("rim: fewer than {} centre-line nodes in [{:.3g}, {:.3g}] m", least, from, to));
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(sum2 / n - mean * mean, 0.0)), n};
}

/// The line load carried by the far side's first depth H, x in [-L, -L + H]:
///   q_far = 2 sum_i p_i A_i w(x_i) / int w dx,
/// w = 1 on [-L, -L + H / 2], falling linearly to 0 at -L + H (int w dx =
/// 3 H / 4), over the y >= 0 half's contact nodes (`halves` 2; an oblique
/// end's both sides, 1). p_i A_i is node i's share
/// of the contact force (the pairs' forces; the recovered pressure times its
/// lumped area on the rigid plane), so the sum is the force weighted by w's
/// P1 interpolant: exact for the penalty's own pressure up to w's two kinks,
/// where a trapezoid of p across one section, over the contact edge's
/// square root, missed by a few per cent and differently on each mesh
/// (docs/notes/rims-log.md#speed).
double far_line_load(const std::vector<SurfacePressureNode>& nodes, double far_x, double depth_m, double halves)
{
  double force = 0;
  for (const SurfacePressureNode& n : nodes)
  {
    const double into = n.x[0] - far_x;
    const double w = into <= depth_m / 2 ? 1.0 : std::max(0.0, 2 * (1 - into / depth_m));
    force += n.pressure_pa * n.weight * w;
  }
  return halves * force / (0.75 * depth_m);
}

/// The end's b and its block's depth H = (H / b) b and length L = (L / H) H (m).
struct BlockSize
{
  double half_width_m, depth_m, length_m;
};

BlockSize block_size(const RimEndStudy& study)
{
  const double b = study.half_width_m, H = study.setup.depth_over_half_width * b;
  return {b, H, study.setup.length_over_depth * H};
}

/// The flattened sheet's height at y, R - sqrt(R^2 - y^2); beyond y = R (a
/// block deeper than R) the sheet has turned away and its gap R never
/// closes against b << R.
double sheet_height(double radius_m, double y)
{
  const double on_sheet = std::min(std::abs(y), radius_m);
  return radius_m - std::sqrt(radius_m * radius_m - on_sheet * on_sheet);
}

/// A rounded edge on the block: the body's contact face up to r_e / 8 above
/// the block's top (on the fillet, within about r_e / 2 of its start, some
/// 20 boundary layers s at the bearing's load) meets it by mortar pairs,
/// the sheet's conforming part too: where a node-to-node pair shares facets
/// with a mortar pair, each lumps the other's share of them (measured on
/// the preprint's 60 deg end: the seam's node read 0.8 of the sheet beside
/// it, the fillet's first node 1.1 of the next). The contact must stay well
/// inside the zone (check_contact_inside_mortar_zone).
double mortar_zone_height(const RimEndSettings& s) { return s.edge_radius_m / 8; }

/// A level's element sizes, its edge elements h_e.
RimEndSizes level_sizes(const RimEndStudy& study, double edge_element_m)
{
  const RimEndSettings& s = study.setup;
  const BlockSize block = block_size(study);
  const double b = block.half_width_m;
  RimEndSizes sizes;
  sizes.contact_m = b / s.contact_elements;
  sizes.contact_zone_m = 1.5 * b;
  sizes.edge_m = std::min(edge_element_m, sizes.contact_m);
  sizes.edge_zone_m = 1.5 * b;
  sizes.edge_x_m = -study.fillet_start_m;
  // A rounded edge's peak lies where the fillet leaves the sheet, within
  // about its boundary layer s on either side (on the steel block at a
  // square end 1.3 s onto the fillet, graded from the line alone at 4 h_e):
  // the edge's elements cover +-2 s about that line (sharp: s = 0, the line).
  sizes.edge_band_m = 2 * study.boundary_layer_m;
  sizes.far_m = block.depth_m / 4;
  sizes.crossing_angle_rad = s.crossing_angle_rad;
  return sizes;
}

/// The level's mesh: the body and the block, or the body alone on the rigid
/// plane (gmsh's, the structured grid, or the section extruded).
SceneMesh level_mesh(MPI_Comm comm, const RimEndStudy& study, const RimEndSizes& sizes)
{
  const RimEndSettings& s = study.setup;
  const BlockSize block = block_size(study);
  const RimEndGeometry geometry{
      s.radius_m, s.interior_angle_rad, s.edge_radius_m, block.depth_m, block.length_m, study.flat_sheet,
      s.crossing_angle_rad};
  const RimEndMesh used = rim_end_mesh_used(study);
  const VolumeMesher mesher = used == RimEndMesh::hxt ? VolumeMesher::hxt : VolumeMesher::delaunay;
  if (s.counter_face == CounterFace::block)
    return build_rim_block_mesh(comm, geometry, sizes, mesher);
  switch (used)
  {
  case RimEndMesh::extruded:
    return build_rim_end_extruded_mesh(comm, geometry, sizes);
  case RimEndMesh::grid:
    return build_square_end_grid_mesh(comm, geometry, sizes);
  default:
    return build_rim_end_mesh(comm, geometry, sizes, mesher);
  }
}

/// kappa = c E / h(x) with the mesh's own size, over the strip's c E / h_c:
/// a penalty as soft as at the strip's elements would cut the edge's
/// singular pressure off at h_c / c.
double penalty_scale(const RimEndSizes& sizes, const double* x)
{
  return sizes.contact_m / rim_end_element_size(sizes, x);
}

/// The block counter-face: its top stays still, no rigid plane; the body's
/// contact face meets the block's top by node pairs (mortar pairs in a
/// rounded edge's zone), their gap the fillet's height plus the flattened
/// sheet's.
void pair_with_block(PenaltyContact& problem, const RimEndStudy& study, const RimEndSizes& sizes)
{
  const RimEndSettings& s = study.setup;
  // The block's top stays still: its bottom is the "top" face of weight 0.
  problem.set_approach_profile([](const double* x) { return x[2] > 0 ? 1.0 : 0.0; });
  problem.set_penalty_scale([](const double*) { return 0.0; }); // no rigid plane
  std::function<bool(const double*)> mortar_zone;
  if (s.edge_radius_m > 0)
    mortar_zone = [zone = mortar_zone_height(s)](const double* x) { return x[2] <= zone; };
  // The fillet's height (0 on the sheet) plus the flattened sheet's.
  const double r_e = s.edge_radius_m, x_t = study.fillet_start_m;
  auto initial_gap = [&](const double* x) {
    const double along_fillet = std::clamp(x[0] + x_t, 0.0, r_e);
    return r_e - std::sqrt(r_e * r_e - along_fillet * along_fillet) + sheet_height(s.radius_m, x[1]);
  };
  std::vector<NodePair> pairs = interface_node_pairs(
      problem, rim_interface_tolerance(block_size(study).depth_m, sizes.edge_m, s.edge_radius_m), initial_gap,
      mortar_zone);
  for (NodePair& pair : pairs)
    pair.stiffness_pa_per_m = s.penalty_c * s.youngs_modulus_pa / sizes.contact_m * penalty_scale(sizes, pair.x.data());
  problem.set_node_pairs(std::move(pairs));
}

/// The rigid plane: the penalty graded with the mesh, and a flattened
/// sheet's height in the gap.
void press_on_rigid_plane(PenaltyContact& problem, const RimEndStudy& study, const RimEndSizes& sizes)
{
  problem.set_penalty_scale([&](const double* x) { return penalty_scale(sizes, x); });
  if (study.flat_sheet)
    problem.set_initial_gap([&](const double* x) { return sheet_height(study.setup.radius_m, x[1]); });
}

/// The contact face's nodal pressures: the pairs' (block), or the rigid
/// plane's recovered pressure (from `fields` when given). Collective.
std::vector<SurfacePressureNode> contact_face_pressures(MPI_Comm comm, const PenaltyContact& problem, bool block,
                                                        const NodalFields* fields = nullptr)
{
  if (!block)
    return fields ? gather_surface_pressure(comm, *fields)
                  : gather_surface_pressure(comm, recover_contact_pressure(problem));
  std::vector<SurfacePressureNode> nodes;
  for (const PairPressure& pair : gather_pair_pressures(problem))
    nodes.push_back({pair.x, pair.pressure_pa, pair.area_m2});
  return nodes;
}

/// Load control until the far side carries q, from the level before's
/// solution and approach (`previous` and `state`), or at the first level as
/// the slices start: the sheet's height at the contact edge as the shift,
/// and that plus a line contact's approach (times first_approach_scale) for
/// the top. Sets the level's load-control record; `state` becomes its
/// solution.
void load_to_line_load(MPI_Comm comm, PenaltyContact& problem, const RimEndStudy& study, const RimEndLevel* previous,
                       std::shared_ptr<const dolfinx::fem::Function<double>>& state, RimEndLevel& level)
{
  const RimEndSettings& s = study.setup;
  const BlockSize block = block_size(study);
  const double b = block.half_width_m;
  const double shift = 0.5 * b * b / s.radius_m;
  const LineApproach line = line_contact_approach(s.load_n_per_m, block.depth_m, b, study.effective_modulus_pa);
  level.estimated_approach_m = shift + line.approach_m;
  if (previous && state)
    // The body is z > 0, the block z < 0: twin nodes on z = 0 take their own body's values.
    problem.start_interpolated(*state, previous->approach_m, [](const double* x) { return x[2] > 0 ? 1 : 0; });
  else
    problem.start_translated(shift, s.first_approach_scale * level.estimated_approach_m);
  const bool on_block = s.counter_face == CounterFace::block;
  const LoadControlReport report
      = continue_to_force(problem, s.load_n_per_m, line.exponent, 2e-3,
                          world_rank() == 0 ? spdlog::level::info : spdlog::level::debug, [&] {
                            return far_line_load(contact_face_pressures(comm, problem, on_block), -block.length_m,
                                                 block.depth_m, crosses_obliquely(s.crossing_angle_rad) ? 1 : 2);
                          });
  state = problem.displacement();
  level.approach_m = report.approach_m;
  level.load_steps = report.load_steps;
  level.newton_iterations = report.newton.newton_iterations;
  level.krylov_iterations = report.newton.krylov_iterations;
  level.far_load_n_per_m = report.force;
  level.start_load_n_per_m = report.first_force;
}

/// ComputationError where a rounded edge's contact on the block runs above
/// half its mortar zone.
void check_contact_inside_mortar_zone(const PenaltyContact& problem, const RimEndSettings& s)
{
  const double zone = mortar_zone_height(s);
  for (const PairPressure& pair : gather_pair_pressures(problem))
    if (pair.x[2] > zone / 2 && pair.pressure_pa > 0)
      throw ComputationError(fmt::format("rim: the contact runs up the fillet to {:.3g} m above the block, beyond "
                                         "half the mortar pairs' zone ({:.3g} m)",
                                         pair.x[2], zone));
}

/// The level's centre line (sorted by x) and a sharp edge's mean pressure
/// over its nodes with y <= b / 2, from the contact face's nodes.
void read_contact_face(const RimEndStudy& study, const std::vector<SurfacePressureNode>& nodes,
                       double edge_element_m, RimEndLevel& level)
{
  const RimEndSettings& s = study.setup;
  const BlockSize block = block_size(study);
  const double b = block.half_width_m, tol = 1e-9 * block.depth_m;
  double edge_sum = 0;
  int edge_nodes = 0;
  for (const SurfacePressureNode& n : nodes)
  {
    if (std::abs(n.x[1]) < tol)
      level.centre_line.push_back({n.x[0], n.pressure_pa});
    // A sharp edge at y: on the sheet, z_e = R - sqrt(R^2 - y^2) (0 flat),
    // and on the other face, x_e = -z_e cot a (oblique: oblique_edge_x).
    const double z_edge = study.flat_sheet ? 0.0 : sheet_height(s.radius_m, n.x[1]);
    const double x_edge = oblique_edge_x(s.interior_angle_rad, s.crossing_angle_rad, n.x[1], z_edge);
    // The structured grid puts a node at y = b / 2 exactly: the tolerance
    // keeps it in whatever the last bit of b (the edge pressure moved by 1 %
    // between two runs whose q differed in its last bits).
    if (!(s.edge_radius_m > 0) && std::abs(n.x[1]) <= 0.5 * b * (1 + 1e-9)
        && std::hypot(n.x[0] - x_edge, n.x[2] - z_edge) < 1e-3 * edge_element_m)
    {
      edge_sum += n.pressure_pa;
      ++edge_nodes;
    }
  }
  if (edge_nodes > 0)
    level.edge_pressure_pa = edge_sum / edge_nodes;
  std::sort(level.centre_line.begin(), level.centre_line.end(),
            [](const CentreLineNode& a, const CentreLineNode& c) { return a.x_m < c.x_m; });
  if (level.centre_line.size() < 3)
    throw ComputationError(fmt::format("rim: unresolved contact (h_e = {:.3g} m, b = {:.3g} m)", edge_element_m, b));
}

/// The centre line's pressures as means over a stretch of the ruling: the far
/// side's and the middle's (over H) and the end's peak. P1 tetrahedra
/// scatter the nodal pressure by about 2 % from node to node (measured along
/// the far strip: 2.3-2.5 % at 6 and 10 elements across b, penalty c = 10),
/// so each node near the end is read as the mean over +-b / 4 about it, the
/// scale on which a square end's pressure falls (a rounded edge: at most
/// half its boundary layer; +-b / 8 left the square end's peak changing by
/// 2-4 % from level to level, the scatter's size).
void read_centre_line(const RimEndStudy& study, double edge_element_m, RimEndLevel& level)
{
  const RimEndSettings& s = study.setup;
  const BlockSize block = block_size(study);
  const double b = block.half_width_m, H = block.depth_m, L = block.length_m;
  const double window = s.edge_radius_m > 0 ? std::min(b / 4, study.boundary_layer_m / 2) : b / 4;
  const Sample far = centre_line_mean(level.centre_line, -L, -L + H);
  const Sample mid = centre_line_mean(level.centre_line, -L / 2 - H / 2, -L / 2 + H / 2);
  level.far_peak_pa = far.mean;
  level.far_scatter = far.sd / far.mean;
  level.mid_peak_pa = mid.mean;
  level.mid_to_far_standard_error
      = std::hypot(far.standard_error() / far.mean, mid.standard_error() / mid.mean) * mid.mean / far.mean;
  // Where the sheet ends: an acute rim's fillet starts further out than r_e
  // (x_t = r_e tan((180 deg - a) / 2) > r_e below 90 deg). The sheet and the
  // fillet (beyond them lies the other face, out of contact).
  const double end_zone = 2 * b + std::max(s.edge_radius_m, study.fillet_start_m);
  for (const CentreLineNode& node : level.centre_line)
    if (node.x_m > -end_zone && node.x_m <= s.edge_radius_m)
    {
      const double smoothed = centre_line_mean(level.centre_line, node.x_m - window, node.x_m + window, 1).mean;
      if (smoothed > level.end_peak_pa)
      {
        level.end_peak_pa = smoothed;
        level.end_peak_x_m = node.x_m;
      }
    }
  if (!(level.end_peak_pa > 0))
    throw ComputationError(fmt::format("rim: no pressure near the edge (h_e = {:.3g} m, b = {:.3g} m)",
                                       edge_element_m, b));
}

/// `fields_out`, if given, receives the level's recovered fields (the caller
/// writes the last level's once the study has finished). `previous`: the
/// level before, whose approach and solution (`state`, on its own mesh) start
/// this one's load control: the levels differ only near
/// the edge, so its approach carries q_far to within a few per mille (line
/// contact's estimate overshot by 40 %) and its displacement, interpolated
/// onto this mesh, leaves Newton only the edge's correction. `state` is
/// replaced by this level's.
RimEndLevel solve_level(MPI_Comm comm, const RimEndStudy& study, double edge_element_m,
                        std::optional<NodalFields>* fields_out, const RimEndLevel* previous,
                        std::shared_ptr<const dolfinx::fem::Function<double>>& state)
{
  const auto start = std::chrono::steady_clock::now();
  const RimEndSettings& s = study.setup;
  RimEndLevel level;
  level.edge_element_m = edge_element_m;
  const RimEndSizes sizes = level_sizes(study, edge_element_m);
  const SceneMesh scene = level_mesh(comm, study, sizes);
  level.mesh_wall_s = wall_seconds_since(comm, start);
  PenaltyContact problem(scene, Model::solid, 1, s.youngs_modulus_pa, s.poisson_ratio,
                         s.penalty_c * s.youngs_modulus_pa / sizes.contact_m, s.petsc_options);
  const bool block = s.counter_face == CounterFace::block;
  if (block)
    pair_with_block(problem, study, sizes);
  else
  {
    // gmsh's tetrahedra are graded from the fillet to 10 b: GAMG took 18-27
    // GMRES iterations a solve, and MUMPS LU was 1.38-1.44x faster from 19k
    // to 193k unknowns (scripts/bench/bench_rim_solver.sh). On the extruded
    // section LU was slower and filled more (docs/methods/rims.md); with the
    // block's pairs BoomerAMG stays (fem/solver_defaults.h).
    const RimEndMesh used = rim_end_mesh_used(study);
    if (used == RimEndMesh::delaunay || used == RimEndMesh::hxt)
      problem.prefer_direct_solver(s.direct_solver_max_dofs);
    press_on_rigid_plane(problem, study, sizes);
  }
  level.dofs = problem.num_dofs();
  load_to_line_load(comm, problem, study, previous, state, level);
  if (block && s.edge_radius_m > 0)
    check_contact_inside_mortar_zone(problem, s);
  std::optional<NodalFields> fields;
  if (fields_out)
    fields = recover_nodal_fields(problem);
  const std::vector<SurfacePressureNode> face
      = contact_face_pressures(comm, problem, block, fields ? &*fields : nullptr);
  read_contact_face(study, face, edge_element_m, level);
  read_centre_line(study, edge_element_m, level);
  if (crosses_obliquely(s.crossing_angle_rad) && s.edge_radius_m > 0)
    read_oblique_end_peak(study, face, level);
  if (fields_out)
    *fields_out = std::move(fields);
  level.wall_s = wall_seconds_since(comm, start);
  return level;
}

/// One quantity of every level against its edge elements h_e.
template <typename Quantity>
RefinementSeries level_series(const std::vector<RimEndLevel>& levels, Quantity quantity)
{
  RefinementSeries series;
  for (const RimEndLevel& l : levels)
    series.add(l.edge_element_m, quantity(l));
  return series;
}

/// What the levels so far say: the resolution, the plane strain of the far
/// side, a sharp edge's exponent, and a non-singular end's ratio, its change
/// over the last level and whether it converged.
void judge_levels(RimEndStudy& study, bool sharp)
{
  const RimEndLevel& last = study.levels.back();
  study.resolved = sharp || last.edge_element_m <= study.boundary_layer_m / 4;
  study.plane_strain_change = std::abs(last.mid_peak_pa / last.far_peak_pa - 1);
  study.plane_strain_noise = last.mid_to_far_standard_error;
  if (!study.singular)
    study.end_to_interior = end_to_interior(last, sharp);
  if (study.levels.size() < 2)
    return; // one level: nothing to say of convergence
  const bool edge_loaded = std::all_of(study.levels.begin(), study.levels.end(),
                                       [](const RimEndLevel& l) { return l.edge_pressure_pa > 0; });
  if (study.singular && !edge_loaded)
    throw ComputationError("rim: a singular edge without pressure at some level (the contact does not reach it)");
  // An acute edge lifts off the plane under refinement: no growth to
  // measure. Least squares of ln p_edge on ln h_e over every level: the
  // nodal pressures scatter by a few per cent, which two levels alone would
  // carry into the exponent (at 120 deg the pairs gave -0.39, -0.47 and -0.36).
  if (sharp && edge_loaded)
    study.measured_exponent
        = fitted_exponent(level_series(study.levels, [](const RimEndLevel& l) { return l.edge_pressure_pa; }));
  if (!study.singular)
  {
    const RefinementSeries ratio
        = level_series(study.levels, [sharp](const RimEndLevel& l) { return end_to_interior(l, sharp); });
    study.end_change = last_change(ratio, end_to_interior_ratio_change);
    study.converged = study.resolved && converged(ratio, study.setup.tolerance, end_to_interior_ratio_change);
  }
}
} // namespace

double rim_interface_tolerance(double depth_m, double edge_element_m, double edge_radius_m)
{
  double tol = 1e-9 * depth_m;
  if (edge_radius_m > 0)
    tol = std::min(tol, 1e-3 * edge_element_m * edge_element_m / (2 * edge_radius_m));
  if (!(tol >= 1e-13 * depth_m))
    throw ComputationError(fmt::format("rim: edge elements of {:.3g} m on a fillet of radius {:.3g} m leave its first "
                                       "nodes within {:.3g} m of the interface, below what a block {:.3g} m deep "
                                       "resolves (1e-13 of it)",
                                       edge_element_m, edge_radius_m, tol, depth_m));
  return tol;
}

RimEndStudy solve_rim_end(MPI_Comm comm, const RimEndSettings& setup)
{
  validate(setup);
  ensure_petsc(); // MPI too
  RimEndStudy study;
  study.setup = setup;
  study.setup.on_level = nullptr; // the caller's progress, not the study's: it may outlive what it refers to
  const bool block = setup.counter_face == CounterFace::block;
  study.effective_modulus_pa = contact::effective_modulus(setup.youngs_modulus_pa, setup.poisson_ratio, block);
  const contact::LineHertz hertz
      = contact::line_contact(setup.load_n_per_m, setup.radius_m, study.effective_modulus_pa, setup.poisson_ratio);
  study.half_width_m = hertz.half_width_m;
  study.hertz_peak_pa = hertz.peak_pressure_pa;
  if (setup.edge_radius_m >= largest_edge_radius_over_depth * setup.depth_over_half_width * study.half_width_m)
    throw InputError(fmt::format("rim: edge_radius_m {} m is not small against the block's depth H = {:.3g} m "
                                 "(at most {} H)",
                                 setup.edge_radius_m, setup.depth_over_half_width * study.half_width_m,
                                 largest_edge_radius_over_depth));
  const bool sharp = !(setup.edge_radius_m > 0);
  const double depth_m = setup.depth_over_half_width * study.half_width_m;
  // Flat where the cylinder hardly rises across the block (R >= 20 H), and
  // where it cannot hold the block at all (R < H: a fillet's block deepened
  // to a few r_e at an end of small R, rim --body): half-space theory's
  // reduction, exact in the gap wherever the contact can reach (b << R).
  study.flat_sheet
      = setup.sheet == SheetModel::flat || block || setup.mesh == RimEndMesh::grid
        || (setup.sheet == SheetModel::automatic && (setup.radius_m >= 20 * depth_m || setup.radius_m < depth_m));
  // Two bodies meet on the flat interface with the sheet's profile in the
  // pairs' gap (half-space theory's reduction, as in line Hertz between two
  // bodies), whatever R / H: the flattened geometry differs from the
  // cylinder only away from the contact strip (at y = H by H^2 / (2 R)).
  if (block && setup.sheet == SheetModel::cylinder)
    throw InputError("rim: the block counter-face needs the flat sheet (sheet cylinder)");
  if (!study.flat_sheet && setup.mesh == RimEndMesh::extruded)
    throw InputError(fmt::format("rim: end_mesh = extruded needs the flat sheet (R = {} m, H = {:.3g} m: the "
                                 "cylinder's range, H <= R < 20 H)",
                                 setup.radius_m, depth_m));
  if (!study.flat_sheet && setup.radius_m < depth_m)
    throw InputError(fmt::format("rim: the cylinder sheet needs R >= H (R = {} m, H = {:.3g} m): use the flat sheet",
                                 setup.radius_m, depth_m));
  if (study.flat_sheet && !(study.half_width_m < largest_half_width_over_radius * setup.radius_m))
    throw InputError(fmt::format("rim: the flat sheet is half-space theory's, for b << R; here b = {:.3g} m against "
                                 "R = {} m",
                                 study.half_width_m, setup.radius_m));
  // Along the edge's normal, at the wedge's angle there (the dihedral; the
  // interior angle itself where the edge is square to the ruling).
  study.fillet_start_m = fillet_start_distance(setup.edge_radius_m,
                                               oblique_dihedral_angle(setup.interior_angle_rad, setup.crossing_angle_rad));
  study.boundary_layer_m = 4 * study.hertz_peak_pa * setup.edge_radius_m / (std::numbers::pi * study.effective_modulus_pa);
  const double E = setup.youngs_modulus_pa, nu = setup.poisson_ratio;
  study.dihedral_angle_rad = oblique_dihedral_angle(setup.interior_angle_rad, setup.crossing_angle_rad);
  study.wedge_exponent = !sharp ? 0.0
                         : block ? contact::edge_on_elastic_block_exponent(study.dihedral_angle_rad, E, nu, E, nu)
                                 : contact::edge_on_rigid_plane_exponent(study.dihedral_angle_rad);
  study.singular = study.wedge_exponent < 0;
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  double first_edge_element = setup.edge_element_over_half_width * study.half_width_m;
  if (setup.resolve_boundary_layer && !sharp)
    // Just below s / 4 at the last level, so that the comparison below holds in floating point.
    first_edge_element = std::min(first_edge_element, 0.999 * std::pow(2.0, setup.levels - 1) * study.boundary_layer_m / 4);
  std::shared_ptr<const dolfinx::fem::Function<double>> state;
  // Written once the study has finished, so that a level that fails leaves no
  // field file behind that looks like the study's.
  std::optional<NodalFields> last_fields;
  for (int k = 0; k < setup.levels + setup.extra_levels; ++k)
  {
    if (k >= setup.levels && (study.converged || !study.end_change))
      break;
    if (k >= setup.levels && rank == 0)
      spdlog::info("rim: not converged at {} levels ({}), one level more", k,
                   study.resolved ? fmt::format("ratio change {:+.2f} %", 100 * *study.end_change)
                                  : std::string("boundary layer not resolved"));
    const double h_e = first_edge_element / std::pow(2.0, k);
    if (setup.on_level)
      setup.on_level(k, h_e);
    // Any level from the last asked for may be the last: each keeps its fields.
    study.levels.push_back(solve_level(comm, study, h_e,
                                       k + 1 >= setup.levels && !setup.xdmf_path.empty() ? &last_fields : nullptr,
                                       study.levels.empty() ? nullptr : &study.levels.back(), state));
    const RimEndLevel& l = study.levels.back();
    if (rank == 0)
      spdlog::info("rim level {}: h_e = {:.3g} b, {} dofs, far q {:.5g} N/m, far p {:.5g} Pa, end peak {:.5g} Pa "
                   "at x = {:.3g} b, edge {:.5g} Pa, {:.1f} s ({:.1f} s meshing)",
                   k, h_e / study.half_width_m, l.dofs, l.far_load_n_per_m, l.far_peak_pa, l.end_peak_pa,
                   l.end_peak_x_m / study.half_width_m, l.edge_pressure_pa, l.wall_s, l.mesh_wall_s);
    if (k + 1 >= setup.levels)
      judge_levels(study, sharp);
  }
  if (last_fields)
    write_fields(setup.xdmf_path, *last_fields);
  return study;
}
} // namespace rollcheck::fem
