// Issue 14's whole-body check (study/whole_body/whole_body_check.h): the locus of one
// orientation, its slices and end models, the whole body, the comparison.
#include "study/whole_body/whole_body_check.h"
#include "contact/hertz.h"
#include "contact/rim_overhang.h"
#include "contact/wedge_exponent.h"
#include "core/error.h"
#include "core/json_number.h"
#include "fem/all_gather.h"
#include "fem/load_control.h"
#include "fem/petsc_session.h"
#include "geometry/convex_ray.h"
#include "oracle/contact_density.h"
#include "oracle/rolling_dynamics.h"
#include "oracle/rolling_study.h"
#include "study/loop_scores/fem_sds.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <numbers>
#include <spdlog/spdlog.h>

namespace rollcheck::study::whole_body
{
namespace
{
constexpr double deg = std::numbers::pi / 180;

/// How a rigid-plane solve starts: the approach and its load exponent, and
/// the body's first shift down.
struct RigidStart
{
  double approach_m, exponent, shift_m;
};

void check_settings(const WholeBodyCheckSettings& s)
{
  if (s.body.body != "cylinder" && s.body.body != "oloid")
    throw InputError(fmt::format(
        "body '{}': the whole-body check meshes the cylinder (extruded) and the oloid (mapped); other bodies have no "
        "whole-body mesh (docs/whole-body.md)",
        s.body.body));
  if (s.body.body == "oloid" && s.body.points < 64)
    throw InputError(fmt::format("points {}: the oloid's sections are ray cast against its hull, which needs at least "
                                 "64 points per circle (default 400)",
                                 s.body.points));
  if (!s.body.mesh_file.empty())
    throw InputError("the whole-body check needs the exact body, not a mesh file");
  auto require = [](bool ok, const std::string& what) {
    if (!ok)
      throw InputError(what);
  };
  require(s.body.radius_m > 0 && s.body.height_m > 0, "radius_m and height_m must be positive");
  require(s.normal_load_n > 0, fmt::format("normal_load_n must be positive, got {}", s.normal_load_n));
  require(s.youngs_modulus_pa > 0, "youngs_modulus_pa must be positive");
  require(s.poisson_ratio >= 0 && s.poisson_ratio < 0.5, "poisson_ratio must lie in [0, 0.5)");
  require(s.contact_elements >= 2 && s.contact_elements <= 40, "contact_elements must lie in [2, 40]");
  require(s.strip_over_half_width >= 1, "strip_over_half_width must be at least 1");
  require(s.section_growth > 0 && s.section_growth <= 1, "section_growth must lie in (0, 1]");
  require(s.layer_growth >= 1 && s.layer_growth <= 3, "layer_growth must lie in [1, 3]");
  require(s.layers_across_length >= 2, "layers_across_length must be at least 2");
  require(s.penalty_c > 0, "penalty_c must be positive");
  require(s.stations >= 2, "stations must be at least 2");
  require(s.rule_stations >= 4 && s.rule_stations <= 200, "rule_stations must lie in [4, 200]");
  require(s.rule_contact_elements >= 2 && s.rule_contact_elements <= 40, "rule_contact_elements must lie in [2, 40]");
  require(s.rule_end_layer > 0 && s.rule_end_layer <= 1, "rule_end_layer must lie in (0, 1]");
  require(s.end_match_over_half_width >= 1 && s.end_match_over_half_width <= 100,
          "end_match_over_half_width must lie in [1, 100]");
  require(s.crease_margin > 0 && s.crease_margin < 0.25, "crease_margin must lie in (0, 0.25)");
  require(s.end_levels >= 1 && s.end_levels <= 6, "end_levels must lie in [1, 6]");
  require(s.end_edge_element > 0 && s.end_edge_element <= 1, "end_edge_element must lie in (0, 1]");
  require(s.end_contact_elements >= 2 && s.end_contact_elements <= 40, "end_contact_elements must lie in [2, 40]");
  require(s.body_end_layer > 0 && s.body_end_layer <= 1, "body_end_layer must lie in (0, 1]");
  require(s.end_zone_over_half_width > 0 && s.end_zone_over_half_width <= 20,
          "end_zone_over_half_width must lie in (0, 20]");
  require(s.tolerance > 0 && s.tolerance < 1, "tolerance must lie in (0, 1)");
}

double half_width(double q, double R, double E_star) { return std::sqrt(4 * q * R / (std::numbers::pi * E_star)); }

struct RatioOverLevels
{
  double last, change;
};

/// An end model's reading over its reference pressure at its last level,
/// and that ratio's change from the level before over the larger of it and
/// 1 (the rim scene's measure, fem::end_to_interior_change: a square edge's
/// ratio of about 0.5 is judged against the interior); none with one level.
std::optional<RatioOverLevels> ratio_over_levels(const fem::RimEndStudy& end,
                                                 const std::function<double(const fem::RimEndLevel&)>& ratio)
{
  if (end.levels.size() < 2)
    return std::nullopt;
  const double last = ratio(end.levels.back()), before = ratio(end.levels[end.levels.size() - 2]);
  return RatioOverLevels{last, (last - before) / std::max(last, 1.0)};
}

/// largest = max(largest, x), but a NaN x wins (std::max would drop it),
/// so that a NaN comparison fails the check.
void keep_largest(double& largest, double x)
{
  if (!(x <= largest))
    largest = x;
}

std::string load_rule_name(LoadRule rule)
{
  return rule == LoadRule::sections ? "sections" : rule == LoadRule::coarse_body ? "coarse-body" : "locus";
}

/// The body in the whole body's frame (fem/mesh/whole_body_mesh.h): x along the
/// ruling b from its start s_1, z = -u up from the plane, y = z x x; its
/// sections ray cast against the hull of s.body.points n per circle (the
/// mesh the centre of mass comes from), within r (pi / n)^2 / 2 of the exact
/// body (0.3 um at n = 400, r = 10 mm: 3e-5 of r for the elastic body; the
/// contact's sheet is exact, in the initial gap).
fem::MappedBodyPose mapped_pose(const WholeBodyCheckSettings& s, const oracle::Ruling& ruling, double cut_height_m,
                                const std::array<double, 2>& overhang_rad)
{
  const Eigen::Vector3d ex = ruling.axis, ez = -ruling.direction, ey = ez.cross(ex);
  geometry::SurfaceMesh body = geometry::make_body(s.body);
  for (Eigen::Index i = 0; i < body.vertices.rows(); ++i)
  {
    const Eigen::Vector3d p = body.vertices.row(i).transpose() - ruling.start_m;
    body.vertices.row(i) = Eigen::RowVector3d(p.dot(ex), p.dot(ey), p.dot(ez));
  }
  auto hull = std::make_shared<const geometry::HalfSpaces>(geometry::half_spaces(body));
  fem::MappedBodyPose pose;
  pose.length_m = ruling.length_m;
  pose.cut_height_m = cut_height_m;
  pose.reference_radius_m = s.body.radius_m;
  pose.radius_m = {ruling.start_radius_m, ruling.end_radius_m};
  pose.end_overhang_rad = overhang_rad;
  pose.end_zone_m = s.crease_margin * ruling.length_m;
  pose.chord = [hull](const Eigen::Vector3d& p, const Eigen::Vector3d& d) { return geometry::line_chord(*hull, p, d); };
  return pose;
}
} // namespace

bool softens_ends(LoadRule rule) { return rule != LoadRule::locus; }

double WholeBodyOrientation::interior_angle_deg(int end) const
{
  return 90 + rim_overhang_rad[static_cast<std::size_t>(end)] / deg;
}

namespace
{
/// What every orientation of one body shares: its circles and centre of mass.
struct OrientedBody
{
  std::vector<oracle::Circle> circles;
  oracle::TwoCircleBody two;
  Eigen::Vector3d centre_of_mass_m;

  explicit OrientedBody(const geometry::BodySpec& body)
      : circles(oracle::line_contact_circles(body)), two(oracle::two_circle_body(circles)),
        centre_of_mass_m(oracle::mass_model_of_mesh(geometry::make_body(body), 1.0).centre_of_mass_m)
  {
  }
};

WholeBodyOrientation orientation_of(const OrientedBody& body, const WholeBodyCheckSettings& s, double direction_deg)
{
  const std::vector<oracle::Circle>& circles = body.circles;
  const oracle::TwoCircleBody& two = body.two;
  WholeBodyOrientation o;
  o.direction_deg = direction_deg;
  const Eigen::Vector3d hint(std::cos(direction_deg * deg), std::sin(direction_deg * deg), 0.0);
  o.ruling = oracle::ruling_at(two, oracle::contact_curve_point(two, hint));
  const Eigen::Vector3d& G = body.centre_of_mass_m;
  const double L = o.ruling.length_m, c = (G - o.ruling.start_m).dot(o.ruling.axis) / L;
  o.centre_of_pressure = c;
  o.centre_of_mass_height_m = (o.ruling.start_m - G).dot(o.ruling.direction);
  o.rim_overhang_rad = contact::rim_overhang(circles, 0, 1, o.ruling);
  // c within 1e-9 of an end (the preprint's body at direction 0, where its
  // sheet's radius at the other end is unbounded): balanced on a point.
  o.in_equilibrium = c > 1e-9 && c < 1 - 1e-9;
  if (!o.in_equilibrium)
    return o;
  o.loaded_from = c < 1.0 / 3 ? 0.0 : c > 2.0 / 3 ? 1 - 3 * (1 - c) : 0.0;
  o.loaded_to = c < 1.0 / 3 ? 3 * c : 1.0;
  const double E_star = contact::effective_modulus(s.youngs_modulus_pa, s.poisson_ratio, false);
  for (int e = 0; e < 2; ++e)
    if (const double q = oracle::line_load(s.normal_load_n, c, L, e); q > 0)
    {
      o.end_load_n_per_m[e] = q;
      // R rounds to about -1e-19 m at an apex (the oloid's vertex): b = 0 there.
      o.end_half_width_m[e] = half_width(q, std::max(o.radius_m(e), 0.0), E_star);
    }
  return o;
}

} // namespace

WholeBodyOrientation whole_body_orientation(const WholeBodyCheckSettings& s, double direction_deg)
{
  return orientation_of(OrientedBody(s.body), s, direction_deg);
}

std::vector<WholeBodyOrientation> scan_whole_body_orientations(const WholeBodyCheckSettings& s, double step_deg)
{
  if (!(step_deg > 0 && step_deg <= 360))
    throw InputError(fmt::format("scan step {} deg: must lie in (0, 360]", step_deg));
  const OrientedBody body(s.body);
  std::vector<WholeBodyOrientation> scan;
  for (int k = 0; k * step_deg < 360 - 1e-9; ++k)
    scan.push_back(orientation_of(body, s, k * step_deg));
  return scan;
}

std::string orientation_table(std::span<const WholeBodyOrientation> orientations)
{
  std::string t = "| direction (deg) | c | loaded part | R start, end (mm) | interior angle start, end (deg) | q start, "
                  "end (N/m) | b start, end (um) | wedge exponent at a loaded obtuse end |\n"
                  "|---|---|---|---|---|---|---|---|\n";
  for (const WholeBodyOrientation& o : orientations)
  {
    std::string exponents;
    for (int e = 0; e < 2; ++e)
      if (const double angle = o.interior_angle_deg(e); o.end_load_n_per_m[e] > 0 && angle > 90)
        // At 180 deg (the oloid's vertex) the rim is flat: no wedge.
        exponents += fmt::format("{}{}: {}", exponents.empty() ? "" : ", ", e == 0 ? "start" : "end",
                                 angle < 180 - 1e-6
                                     ? fmt::format("{:.3f}", contact::edge_on_rigid_plane_exponent(angle * deg))
                                     : "flat, no wedge");
    t += fmt::format("| {:.2f} | {:.4f} | {} | {:.3f}, {:.3f} | {:.2f}, {:.2f} | {:.4g}, {:.4g} | {:.3f}, {:.3f} | {} "
                     "|\n",
                     o.direction_deg, o.centre_of_pressure,
                     o.in_equilibrium ? fmt::format("{:.3f}-{:.3f}", o.loaded_from, o.loaded_to) : "none (c at or beyond an end)",
                     std::max(o.ruling.start_radius_m, 0.0) * 1e3, std::max(o.ruling.end_radius_m, 0.0) * 1e3,
                     o.interior_angle_deg(0),
                     o.interior_angle_deg(1), o.end_load_n_per_m[0], o.end_load_n_per_m[1],
                     o.end_half_width_m[0] * 1e6, o.end_half_width_m[1] * 1e6, exponents.empty() ? "-" : exponents);
  }
  return t;
}

nlohmann::json to_json(const WholeBodyOrientation& o)
{
  return {{"direction_deg", o.direction_deg},
          {"length_m", o.ruling.length_m},
          {"start_radius_m", o.ruling.start_radius_m},
          {"end_radius_m", o.ruling.end_radius_m},
          {"centre_of_pressure", o.centre_of_pressure},
          {"in_equilibrium", o.in_equilibrium},
          {"loaded_from", o.loaded_from},
          {"loaded_to", o.loaded_to},
          {"rim_overhang_deg", {o.rim_overhang_rad[0] / deg, o.rim_overhang_rad[1] / deg}},
          {"interior_angle_deg", {o.interior_angle_deg(0), o.interior_angle_deg(1)}},
          {"end_load_n_per_m", o.end_load_n_per_m},
          {"end_half_width_m", o.end_half_width_m}};
}

WholeBodyCheck run_whole_body_check(MPI_Comm comm, const WholeBodyCheckSettings& s)
{
  check_settings(s);
  const auto start = std::chrono::steady_clock::now();
  fem::ensure_petsc();
  const bool log = fem::world_rank() == 0;
  WholeBodyCheck r;
  r.settings = s;
  r.body = geometry::body_label(s.body);
  const double F = s.normal_load_n, E_star = contact::effective_modulus(s.youngs_modulus_pa, s.poisson_ratio, false);
  r.effective_modulus_pa = E_star;

  r.orientation = whole_body_orientation(s, s.direction_deg);
  const WholeBodyOrientation& o = r.orientation;
  const oracle::Ruling& ruling = o.ruling;
  const double L = ruling.length_m, c = o.centre_of_pressure;
  if (!o.in_equilibrium)
    throw InputError(fmt::format("direction {} deg: the centre of mass's foot lies outside the ruling (c = {:.4f}): "
                                 "the body tips, no line contact in equilibrium",
                                 s.direction_deg, c));
  auto radius_at = [&](double f) { return (1 - f) * ruling.start_radius_m + f * ruling.end_radius_m; };
  auto locus_load_at = [&](double f) { return oracle::line_load(F, c, L, f); };
  std::function<double(double)> load_at = locus_load_at;
  const std::vector<double> fractions = loop_scores::slice_fractions(o.loaded_from, o.loaded_to, s.crease_margin, s.stations);
  // The whole body's section sizes, from the locus's b at the stations and
  // the loaded ends (its end layers too, below) whichever the load rule: one
  // reference for both rules (its station readings move by 0.13 % at most
  // on a finer strip, docs/whole-body.md).
  double smallest_b = INFINITY, largest_b = 0;
  std::vector<double> sized_at = fractions;
  sized_at.insert(sized_at.end(), {o.loaded_from, o.loaded_to});
  for (const double f : sized_at)
    if (const double q = locus_load_at(f); q > 0)
    {
      const double b = half_width(q, radius_at(f), E_star);
      smallest_b = std::min(smallest_b, b);
      largest_b = std::max(largest_b, b);
    }
  // The locus's b at the loaded ends (0 where the locus leaves an end
  // unloaded): the whole body's end layers, d_m and the near-edge reach.
  const std::array<double, 2> end_fractions{o.loaded_from, o.loaded_to};
  const std::array<double, 2>& locus_end_b = o.end_half_width_m;
  double smallest_end_b = INFINITY;
  for (const double b : locus_end_b)
    if (b > 0)
      smallest_end_b = std::min(smallest_end_b, b);
  if (!std::isfinite(smallest_end_b))
    smallest_end_b = smallest_b;
  fem::WholeBodySizes& sizes = r.sizes;
  sizes.contact_m = smallest_b / s.contact_elements;
  sizes.strip_half_width_m = s.strip_over_half_width * largest_b;
  sizes.growth = s.section_growth;
  sizes.far_m = s.body.radius_m / 8;
  sizes.layer_growth = s.layer_growth;
  sizes.largest_layer_m = L / s.layers_across_length;
  sizes.end_layer_m = s.body_end_layer * smallest_end_b;
  if (!s.end_layers_only)
  {
    sizes.edge_m = sizes.end_layer_m;
    sizes.edge_zone_m = s.end_zone_over_half_width * largest_b;
  }
  // The line-contact estimate of the approach of a section's top at height
  // R (fem/load_control.h) starts load control; the body starts shifted down
  // by the height of its surface at the contact's edge (the slab's start).
  auto rigid_start = [&](double b, double R) {
    const fem::LineApproach estimate = fem::line_contact_approach(load_at(c), R, b, E_star);
    return RigidStart{estimate.approach_m, estimate.exponent, 0.5 * b * b / R};
  };
  // The whole body at `body_sizes`, its load control started from line
  // contact at b.
  struct BodySolve
  {
    fem::WholeBodyFem fem;
    std::size_t node_planes;
    std::int64_t section_nodes;
    double gmsh_s;
  };
  // The body's sections ray cast against its hull, built once: the oloid's
  // whole bodies and any body's sections' rule share it.
  const bool extruded = s.body.body == "cylinder";
  const std::optional<fem::MappedBodyPose> pose
      = extruded && s.load_rule != LoadRule::sections
            ? std::nullopt
            : std::optional(mapped_pose(s, ruling, o.centre_of_mass_height_m, o.rim_overhang_rad));
  auto solve_body = [&](const fem::WholeBodySizes& body_sizes, double b) {
    const fem::WholeBodyMesh mesh
        = extruded ? fem::build_cylinder_body_mesh(comm, {s.body.radius_m, L, o.centre_of_mass_height_m}, body_sizes)
                   : fem::build_mapped_body_mesh(comm, *pose, body_sizes);
    if (log)
      spdlog::info("whole-body mesh: {} node planes, {} nodes per section, contact elements {:.3g} m (b / {:.3g}), "
                   "end layers {:.3g} m, gmsh {:.1f} s",
                   mesh.planes_m.size(), mesh.section_nodes, body_sizes.contact_m, b / body_sizes.contact_m,
                   body_sizes.end_layer_m, mesh.gmsh_s);
    fem::WholeBodyLoad load;
    load.force_n = F;
    load.centre_of_mass_along_m = c * L;
    load.youngs_modulus_pa = s.youngs_modulus_pa;
    load.poisson_ratio = s.poisson_ratio;
    load.penalty_c = s.penalty_c;
    load.contact_element_m = body_sizes.contact_m;
    const RigidStart rigid = rigid_start(b, radius_at(c));
    load.first_approach_m = rigid.approach_m;
    load.approach_exponent = rigid.exponent;
    load.first_shift_m = rigid.shift_m;
    load.edge_half_width_m = 0.5 * smallest_end_b;
    return BodySolve{fem::solve_whole_body(comm, mesh, load), mesh.planes_m.size(), mesh.section_nodes, mesh.gmsh_s};
  };
  // The rules that soften the ends read their q at the locus's stations and
  // d_m inside its loaded ends: a ruling loaded end to end.
  if (softens_ends(s.load_rule) && (o.loaded_from > 0 || o.loaded_to < 1))
    throw InputError(fmt::format("load_rule {}: direction {} deg loads only part of the ruling (c = {:.4f} outside "
                                 "[1/3, 2/3]); the rule is matched to the end models at both rim ends, loaded end to "
                                 "end",
                                 load_rule_name(s.load_rule), s.direction_deg, c));
  if (s.load_rule == LoadRule::sections)
  {
    const double b = half_width(load_at(c), radius_at(c), E_star);
    fem::SectionSettings section;
    section.youngs_modulus_pa = s.youngs_modulus_pa;
    section.poisson_ratio = s.poisson_ratio;
    section.penalty_c = s.penalty_c;
    const RigidStart rigid = rigid_start(b, radius_at(c));
    section.first_shift_m = rigid.shift_m;
    SectionLoadRuleSettings rule;
    rule.stations = s.rule_stations;
    // Each section as the whole body's interior (without its end refinement).
    fem::WholeBodySizes interior = sizes;
    interior.edge_m = interior.edge_zone_m = 0;
    r.section_rule = section_load_rule(comm, *pose, F, c * L, rigid.approach_m, interior, section, rule);
    load_at = [&r, L](double f) { return r.section_rule->load_at(f * L); };
    if (log)
      spdlog::info("section load rule: {} sections of {} DOFs, {} passes, F {:.6g} N, centre of pressure {:.6f} L, "
                   "{:.1f} s",
                   s.rule_stations, r.section_rule->section_dofs, r.section_rule->passes, r.section_rule->force_n,
                   r.section_rule->centre_of_pressure_m / L, r.section_rule->wall_s);
  }
  if (s.load_rule == LoadRule::coarse_body)
  {
    auto clock = std::chrono::steady_clock::now();
    fem::WholeBodySizes coarse = sizes;
    coarse.contact_m = smallest_b / s.rule_contact_elements;
    coarse.end_layer_m = s.rule_end_layer * smallest_end_b;
    coarse.edge_m = coarse.edge_zone_m = 0;
    BodySolve solved = solve_body(coarse, half_width(load_at(c), radius_at(c), E_star));
    r.coarse_body = WholeBodyCheck::CoarseBody{coarse, solved.node_planes, std::move(solved.fem),
                                               fem::wall_seconds_since(comm, clock)};
    load_at = [&r, L](double f) {
      return fem::interpolate_planes(r.coarse_body->fem.plane_x_m, r.coarse_body->fem.plane_load_n_per_m, f * L);
    };
    if (log)
      spdlog::info("coarse body load rule: {} DOFs, {:.1f} s", r.coarse_body->fem.dofs, r.coarse_body->wall_s);
  }
  r.half_width_m = half_width(load_at(c), radius_at(c), E_star);
  if (log)
    spdlog::info("whole-body check, {}: ruling L = {:.5g} m, R = {:.5g}..{:.5g} m, c = {:.4f}, loaded {:.3f}..{:.3f}, "
                 "rim leans {:.2f}, {:.2f} deg, b = {:.4g} m (b / L = {:.3g})",
                 r.body, L, ruling.start_radius_m, ruling.end_radius_m, c, o.loaded_from, o.loaded_to,
                 o.rim_overhang_rad[0] / deg, o.rim_overhang_rad[1] / deg, r.half_width_m, r.half_width_m / L);

  // Slices at the stations and at both loaded ends, or under a rule that
  // softens the ends d_m inside them (EndComparison). The rim ends loaded
  // are the locus's.
  const bool match_near_edge = softens_ends(s.load_rule);
  std::vector<fem::SliceLoad> loads;
  for (const double f : fractions)
    loads.push_back({f * L, radius_at(f), load_at(f)});
  std::vector<int> loaded_ends;
  std::array<double, 2> read_at_fraction{}; // where each end's q and slice are taken
  for (int e = 0; e < 2; ++e)
    if (locus_end_b[e] > 0)
    {
      loaded_ends.push_back(e);
      const double inward = (e == 0 ? 1 : -1) * s.end_match_over_half_width * locus_end_b[e] / L;
      read_at_fraction[e] = end_fractions[e] + (match_near_edge ? inward : 0.0);
      loads.push_back({read_at_fraction[e] * L, radius_at(read_at_fraction[e]), load_at(read_at_fraction[e])});
    }
  fem::SliceSettings slice;
  slice.youngs_modulus_pa = s.youngs_modulus_pa;
  slice.poisson_ratio = s.poisson_ratio;
  slice.refine = s.slice_refine;
  auto clock = std::chrono::steady_clock::now();
  const std::vector<fem::SliceFem> slices = fem::solve_slices(comm, loads, slice);
  r.slices_s = fem::wall_seconds_since(comm, clock);
  if (log)
    spdlog::info("slices: {} solved in {:.1f} s", slices.size(), r.slices_s);

  // The end models at the loaded ends.
  clock = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < loaded_ends.size(); ++k)
  {
    const int e = loaded_ends[k];
    EndComparison end;
    end.position_m = end_fractions[e] * L;
    end.radius_m = radius_at(end_fractions[e]);
    end.load_n_per_m = load_at(read_at_fraction[e]);
    end.half_width_m = half_width(end.load_n_per_m, end.radius_m, E_star);
    end.interior_angle_deg = 90 + o.rim_overhang_rad[e] / deg;
    end.slice_peak_pa = slices[fractions.size() + k].peak_pressure_pa;
    fem::RimEndSettings rim;
    rim.radius_m = end.radius_m;
    rim.load_n_per_m = end.load_n_per_m;
    rim.interior_angle_rad = end.interior_angle_deg * deg;
    rim.youngs_modulus_pa = s.youngs_modulus_pa;
    rim.poisson_ratio = s.poisson_ratio;
    rim.levels = s.end_levels;
    rim.edge_element_over_half_width = s.end_edge_element;
    // A singular end is never compared as a number: its only reading, the
    // secondary one at matched edge elements, needs one level, at the body's
    // end layer (its exponent under refinement is the rim scene's). That
    // layer is set in the smallest b of the locus's ends, and the end model's
    // b is the rule's at its reading point: in the end model's b it is their
    // ratio times the setting (at the oloid's obtuse end under the coarse
    // body's rule the setting alone was 5.6 % off).
    if (contact::edge_on_rigid_plane_exponent(rim.interior_angle_rad) < 0)
    {
      rim.levels = 1;
      rim.edge_element_over_half_width = sizes.end_layer_m / end.half_width_m;
    }
    rim.contact_elements = s.end_contact_elements;
    rim.tolerance = s.tolerance;
    if (s.end_depth == EndModelDepth::body)
    {
      rim.depth_over_half_width = o.centre_of_mass_height_m / end.half_width_m;
      rim.petsc_options = "-hertz_ksp_type preonly -hertz_pc_type lu -hertz_pc_factor_mat_solver_type mumps";
    }
    // Square and near-square ends on the structured grid (sheared): gmsh's
    // Delaunay end at the body's depth has about 1e6 DOFs a level.
    if (std::abs(end.interior_angle_deg - 90) * deg <= fem::max_grid_end_lean_rad)
      rim.mesh = fem::RimEndMesh::grid;
    // Identical ends (the cylinder's) share one end model; a rule read from
    // a mesh gives them loads 0.2 % apart (the coarse body's, gmsh's split
    // of its prisms), against which the ratio's dependence on q is nil (the
    // oloid's acute end: 0.944086 at 3495 N/m, 0.944079 at 3854 N/m).
    const auto same = std::find_if(r.ends.begin(), r.ends.end(), [&](const EndComparison& other) {
      return std::abs(other.load_n_per_m / end.load_n_per_m - 1) < 0.01 && other.radius_m == end.radius_m
             && other.interior_angle_deg == end.interior_angle_deg;
    });
    end.end_model = same != r.ends.end() ? same->end_model : fem::solve_rim_end(comm, rim);
    end.near_edge_peak = !end.end_model.singular && end.interior_angle_deg < 90;
    const fem::RimEndSettings& setup = end.end_model.setup;
    if (match_near_edge)
      end.rule_match_distance_m = s.end_match_over_half_width * locus_end_b[e];
    auto reference = [&](const fem::RimEndLevel& l) {
      return end.rule_match_distance_m ? fem::centre_line_pressure_at(l, -*end.rule_match_distance_m) : l.far_peak_pa;
    };
    if (!end.end_model.singular)
    {
      if (end.near_edge_peak || end.rule_match_distance_m)
      {
        if (const auto ratio = ratio_over_levels(end.end_model, [&](const fem::RimEndLevel& l) {
              return (end.near_edge_peak ? l.end_peak_pa : l.edge_pressure_pa) / reference(l);
            }))
        {
          end.end_model_ratio_change = ratio->change;
          if (std::abs(ratio->change) < s.tolerance)
            end.end_model_ratio = ratio->last;
        }
      }
      else
      {
        end.end_model_ratio_change = end.end_model.end_change;
        if (end.end_model.converged)
          end.end_model_ratio = end.end_model.end_to_interior;
      }
    }
    if (end.end_model_ratio)
      end.predicted_edge_pa = *end.end_model_ratio * end.slice_peak_pa;
    if (end.end_model.singular && !end.end_model.levels.empty())
    {
      const auto& levels = end.end_model.levels;
      auto mismatch = [&](const fem::RimEndLevel& l) { return std::abs(std::log(l.edge_element_m / sizes.end_layer_m)); };
      const auto nearest = std::min_element(levels.begin(), levels.end(), [&](const auto& a, const auto& b) {
        return mismatch(a) < mismatch(b);
      });
      end.matched_level = static_cast<std::size_t>(nearest - levels.begin());
      end.matched_edge_pa = nearest->edge_pressure_pa / reference(*nearest) * end.slice_peak_pa;
    }
    if (log)
      spdlog::info("end model at {} (a = {:.2f} deg, H = {:.4g} b, {} mesh): {}{}", e == 0 ? "the start" : "the end",
                   end.interior_angle_deg, setup.depth_over_half_width,
                   setup.mesh == fem::RimEndMesh::grid ? "grid" : "Delaunay",
                   end.end_model.singular ? std::string("singular")
                   : end.end_model_ratio  ? fmt::format("{} / reference {:.4f}", end.near_edge_peak ? "near-edge peak" : "edge",
                                                       *end.end_model_ratio)
                                          : std::string("NOT converged"),
                   end.rule_match_distance_m
                       ? fmt::format(" (matched to the rule {:.4g} m from the edge)", *end.rule_match_distance_m)
                                    : std::string(" (against its far side)"));
    r.ends.push_back(std::move(end));
  }
  r.ends_s = fem::wall_seconds_since(comm, clock);

  // The whole body (the reference).
  clock = std::chrono::steady_clock::now();
  BodySolve body = solve_body(sizes, r.half_width_m);
  r.fem = std::move(body.fem);
  r.node_planes = body.node_planes;
  r.section_nodes = body.section_nodes;
  r.gmsh_s = body.gmsh_s;
  r.body_s = fem::wall_seconds_since(comm, clock);

  // The comparison.
  for (std::size_t k = 0; k < fractions.size(); ++k)
  {
    StationComparison st;
    st.position_m = loads[k].position_m;
    st.radius_m = loads[k].radius_m;
    st.rule_load_n_per_m = loads[k].load_n_per_m;
    st.slice_peak_pa = slices[k].peak_pressure_pa;
    st.hertz_peak_pa = slices[k].hertz_peak_pressure_pa;
    st.body_peak_pa = fem::interpolate_planes(r.fem.plane_x_m, r.fem.plane_peak_pa, st.position_m);
    st.body_load_n_per_m = fem::interpolate_planes(r.fem.plane_x_m, r.fem.plane_load_n_per_m, st.position_m);
    keep_largest(r.worst_along, std::abs(st.peak_difference()));
    keep_largest(r.worst_load, std::abs(st.load_difference()));
    r.stations.push_back(st);
  }
  r.largest_peak_difference = largest_peak_difference(r.stations);
  bool ends_compared = true;
  double worst_end = 0;
  std::vector<std::string> singular_ends, unconverged_ends;
  for (EndComparison& end : r.ends)
  {
    const bool at_start = end.position_m < 0.5 * L;
    end.body_edge_pa = r.fem.edge_pressure_pa[at_start ? 0 : 1];
    end.body_interior_pa = at_start ? r.stations.front().body_peak_pa : r.stations.back().body_peak_pa;
    for (std::size_t k = 0; k < r.fem.plane_x_m.size(); ++k)
      if (std::abs(r.fem.plane_x_m[k] - end.position_m) <= 2 * locus_end_b[at_start ? 0 : 1])
        end.body_near_edge_peak_pa = std::max(end.body_near_edge_peak_pa, r.fem.plane_peak_pa[k]);
    const std::string where
        = fmt::format("the ruling's {} ({:.2f} deg)", at_start ? "start" : "end", end.interior_angle_deg);
    if (end.predicted_edge_pa)
    {
      end.difference = (end.near_edge_peak ? end.body_near_edge_peak_pa : end.body_edge_pa) / *end.predicted_edge_pa - 1;
      keep_largest(worst_end, std::abs(*end.difference));
    }
    else
    {
      ends_compared = false;
      if (end.end_model.singular)
        singular_ends.push_back(
            fmt::format("{} singular (the wedge's exponent {:.3f})", where, end.end_model.wedge_exponent));
      else
        unconverged_ends.push_back(fmt::format("the end model at {} did not converge", where));
    }
    if (end.matched_edge_pa)
      end.matched_difference = end.body_edge_pa / *end.matched_edge_pa - 1;
  }
  if (ends_compared && !r.ends.empty())
    r.worst_end = worst_end;
  r.outcome = check_outcome(r.worst_along, r.ends, s.tolerance);
  r.pass = r.outcome == WholeBodyOutcome::pass;
  std::vector<std::string> at_ends;
  if (r.ends.size() > singular_ends.size() + unconverged_ends.size())
    at_ends.push_back(fmt::format("the compared ends within {:.2f} % of the end models' reading", 100 * worst_end));
  at_ends.insert(at_ends.end(), singular_ends.begin(), singular_ends.end());
  at_ends.insert(at_ends.end(), unconverged_ends.begin(), unconverged_ends.end());
  r.verdict = fmt::format(
      "{}: along the ruling the whole body's peak is within {:.2f} % of the slices' ({} stations; the largest over "
      "them, fem-sds's peak, {:+.2f} %); at the ends {}; tolerance {:.1f} %",
      outcome_name(r.outcome), 100 * r.worst_along, r.stations.size(), 100 * r.largest_peak_difference,
      r.ends.empty() ? std::string("no loaded end") : fmt::format("{}", fmt::join(at_ends, ", ")), 100 * s.tolerance);
  r.wall_s = fem::wall_seconds_since(comm, start);
  if (log)
    spdlog::info("{} ({:.1f} s: slices {:.1f}, end models {:.1f}, whole body {:.1f})", r.verdict, r.wall_s, r.slices_s,
                 r.ends_s, r.body_s);
  return r;
}

namespace
{
nlohmann::json planes_json(const fem::WholeBodyFem& fem)
{
  nlohmann::json planes = nlohmann::json::array();
  for (std::size_t k = 0; k < fem.plane_x_m.size(); ++k)
    planes.push_back({fem.plane_x_m[k], fem.plane_peak_pa[k], fem.plane_load_n_per_m[k]});
  return planes;
}

/// The end model's centre-line pressure within 100 b of the edge (x <= 0),
/// where a rule may be matched to it.
nlohmann::json centre_line_json(const fem::RimEndLevel& level, double half_width_m)
{
  nlohmann::json line = nlohmann::json::array();
  const double reach = 100 * half_width_m;
  for (const fem::CentreLineNode& node : level.centre_line)
    if (node.x_m >= -reach)
      line.push_back({node.x_m, node.pressure_pa});
  return line;
}

nlohmann::json coarse_body_json(const WholeBodyCheck::CoarseBody& coarse, double length_m)
{
  return {{"contact_element_m", coarse.sizes.contact_m},
          {"end_layer_m", coarse.sizes.end_layer_m},
          {"node_planes", coarse.node_planes},
          {"dofs", coarse.fem.dofs},
          {"reaction_n", coarse.fem.reaction_n},
          {"centre_of_pressure", coarse.fem.centre_of_pressure_m / length_m},
          {"approach_m", coarse.fem.approach_m},
          {"tilt_rad", coarse.fem.tilt_rad},
          {"planes_x_m_peak_pa_load_n_per_m", planes_json(coarse.fem)},
          {"wall_s", coarse.wall_s}};
}
} // namespace

nlohmann::json to_json(const WholeBodyCheck& r)
{
  nlohmann::json stations = nlohmann::json::array();
  for (const StationComparison& st : r.stations)
    stations.push_back({{"position_m", st.position_m},
                        {"radius_m", st.radius_m},
                        {"rule_load_n_per_m", st.rule_load_n_per_m},
                        {"hertz_peak_pa", st.hertz_peak_pa},
                        {"slice_peak_pa", st.slice_peak_pa},
                        {"body_peak_pa", st.body_peak_pa},
                        {"body_load_n_per_m", st.body_load_n_per_m},
                        {"peak_difference", json_number(st.peak_difference())},
                        {"load_difference", json_number(st.load_difference())},
                        {"peak_difference_at_body_load", json_number(st.peak_difference_at_body_load())}});
  nlohmann::json ends = nlohmann::json::array();
  for (const EndComparison& e : r.ends)
  {
    nlohmann::json levels = nlohmann::json::array();
    for (const fem::RimEndLevel& l : e.end_model.levels)
      levels.push_back({{"edge_element_m", l.edge_element_m},
                        {"dofs", l.dofs},
                        {"far_peak_pa", l.far_peak_pa},
                        {"edge_pressure_pa", l.edge_pressure_pa},
                        {"end_peak_pa", l.end_peak_pa},
                        {"end_peak_x_m", l.end_peak_x_m},
                        {"centre_line_x_m_pressure_pa", centre_line_json(l, e.end_model.half_width_m)},
                        {"wall_s", l.wall_s}});
    ends.push_back({{"position_m", e.position_m},
                    {"radius_m", e.radius_m},
                    {"load_n_per_m", e.load_n_per_m},
                    {"half_width_m", e.half_width_m},
                    {"interior_angle_deg", e.interior_angle_deg},
                    {"end_model_depth_over_half_width", e.end_model.setup.depth_over_half_width},
                    {"end_model_mesh", e.end_model.setup.mesh == fem::RimEndMesh::grid ? "grid" : "delaunay"},
                    {"end_model_singular", e.end_model.singular},
                    {"end_model_converged", e.end_model.converged},
                    {"end_model_end_to_interior", json_number(e.end_model.end_to_interior)},
                    {"end_model_change", json_number(e.end_model.end_change)},
                    {"end_model_levels", levels},
                    {"rule_match_distance_m", json_number(e.rule_match_distance_m)},
                    {"end_model_ratio", json_number(e.end_model_ratio)},
                    {"end_model_ratio_change", json_number(e.end_model_ratio_change)},
                    {"slice_peak_pa", e.slice_peak_pa},
                    {"predicted_edge_pa", json_number(e.predicted_edge_pa)},
                    {"compared", e.near_edge_peak ? "near-edge peak (acute end)" : "edge"},
                    {"body_near_edge_peak_pa", e.body_near_edge_peak_pa},
                    {"body_edge_pa", e.body_edge_pa},
                    {"body_interior_pa", e.body_interior_pa},
                    {"body_edge_to_interior", e.body_edge_pa / e.body_interior_pa},
                    {"difference", json_number(e.difference)},
                    {"end_model_measured_exponent", json_number(e.end_model.measured_exponent)},
                    {"wedge_exponent", e.end_model.wedge_exponent},
                    {"matched_level", e.matched_level ? nlohmann::json(*e.matched_level) : nlohmann::json()},
                    {"matched_edge_pa", json_number(e.matched_edge_pa)},
                    {"matched_difference", json_number(e.matched_difference)}});
  }
  const WholeBodyCheckSettings& s = r.settings;
  nlohmann::json ruling = to_json(r.orientation);
  ruling["half_width_m"] = r.half_width_m;
  ruling["half_width_over_length"] = r.half_width_m / r.orientation.ruling.length_m;
  return {{"body", r.body},
          {"direction_deg", s.direction_deg},
          {"normal_load_n", s.normal_load_n},
          {"youngs_modulus_pa", s.youngs_modulus_pa},
          {"poisson_ratio", s.poisson_ratio},
          {"end_depth", s.end_depth == EndModelDepth::body ? "body" : "local"},
          {"effective_modulus_pa", r.effective_modulus_pa},
          {"ruling", ruling},
          {"mesh",
           {{"contact_element_m", r.sizes.contact_m},
            {"strip_half_width_m", r.sizes.strip_half_width_m},
            {"section_growth", r.sizes.growth},
            {"far_element_m", r.sizes.far_m},
            {"end_layer_m", r.sizes.end_layer_m},
            {"layer_growth", r.sizes.layer_growth},
            {"largest_layer_m", r.sizes.largest_layer_m},
            {"section_edge_element_m", r.sizes.edge_m},
            {"section_edge_zone_m", r.sizes.edge_zone_m},
            {"node_planes", r.node_planes},
            {"section_nodes", r.section_nodes},
            {"dofs", r.fem.dofs},
            {"cut_height_m", r.orientation.centre_of_mass_height_m},
            {"gmsh_s", r.gmsh_s}}},
          {"whole_body",
           {{"force_n", r.fem.force_n},
            {"reaction_n", r.fem.reaction_n},
            {"centre_of_pressure", r.fem.centre_of_pressure_m / r.orientation.ruling.length_m},
            {"approach_m", r.fem.approach_m},
            {"tilt_rad", r.fem.tilt_rad},
            {"load_steps", r.fem.load_steps},
            {"newton_iterations", r.fem.newton_iterations},
            {"edge_pressure_pa", {r.fem.edge_pressure_pa[0], r.fem.edge_pressure_pa[1]}},
            {"planes_x_m_peak_pa_load_n_per_m", planes_json(r.fem)},
            {"solve_s", r.fem.solve_s}}},
          {"load_rule", load_rule_name(s.load_rule)},
          {"section_load_rule", r.section_rule ? to_json(*r.section_rule) : nlohmann::json()},
          {"coarse_body_load_rule", r.coarse_body ? coarse_body_json(*r.coarse_body, r.orientation.ruling.length_m) : nlohmann::json()},
          {"stations", stations},
          {"ends", ends},
          {"worst_along", r.worst_along},
          {"worst_end", json_number(r.worst_end)},
          {"worst_load", r.worst_load},
          {"largest_peak_difference", r.largest_peak_difference},
          {"tolerance", s.tolerance},
          {"end_match_over_half_width", s.end_match_over_half_width},
          {"outcome", outcome_name(r.outcome)},
          {"pass", r.pass},
          {"verdict", r.verdict},
          {"wall_s", {{"slices", r.slices_s}, {"end_models", r.ends_s}, {"whole_body", r.body_s}, {"total", r.wall_s}}}};
}

WholeBodyOutcome check_outcome(double worst_along, std::span<const EndComparison> ends, double tolerance)
{
  if (ends.empty() || !(worst_along <= tolerance))
    return WholeBodyOutcome::fail;
  bool singular = false;
  for (const EndComparison& end : ends)
  {
    if (end.difference)
    {
      if (!(std::abs(*end.difference) <= tolerance))
        return WholeBodyOutcome::fail;
    }
    else if (end.end_model.singular)
      singular = true;
    else
      return WholeBodyOutcome::fail; // did not converge: no value, and no reason why none exists
  }
  return singular ? WholeBodyOutcome::singular_ends : WholeBodyOutcome::pass;
}

std::string outcome_name(WholeBodyOutcome outcome)
{
  return outcome == WholeBodyOutcome::pass            ? "PASS"
         : outcome == WholeBodyOutcome::singular_ends ? "SINGULAR ENDS"
                                                      : "FAIL";
}

double largest_peak_difference(std::span<const StationComparison> stations)
{
  if (stations.empty())
    return 0;
  return std::ranges::max(stations, {}, &StationComparison::body_peak_pa).body_peak_pa
             / std::ranges::max(stations, {}, &StationComparison::slice_peak_pa).slice_peak_pa
         - 1;
}

std::string markdown_table(const WholeBodyCheck& r)
{
  std::string t = "| station s / L | R (m) | q rule (N/m) | q body / rule - 1 | slice p (MPa) | body p (MPa) | body / "
                  "slice - 1 | the same at the body's q |\n|---|---|---|---|---|---|---|---|\n";
  for (const StationComparison& st : r.stations)
    t += fmt::format("| {:.4f} | {:.5g} | {:.5g} | {:+.2f} % | {:.5g} | {:.5g} | {:+.2f} % | {:+.2f} % |\n",
                     st.position_m / r.orientation.ruling.length_m, st.radius_m, st.rule_load_n_per_m, 100 * st.load_difference(),
                     st.slice_peak_pa / 1e6, st.body_peak_pa / 1e6, 100 * st.peak_difference(),
                     100 * st.peak_difference_at_body_load());
  t += fmt::format("\nThe largest over the stations (fem-sds's peak): body / slices - 1 = {:+.2f} %\n",
                   100 * r.largest_peak_difference);
  t += "\n| end | interior angle (deg) | end model | end model edge / its reference (far side, or at d_m from the edge) | predicted edge (MPa) | body edge "
       "(MPa) | body edge / its interior | body / predicted - 1 | singular only: body / end model at matched h_e - 1 "
       "(secondary) |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const EndComparison& e : r.ends)
    t += fmt::format("| {:.4f} | {:.2f} | {} | {} | {} | {:.5g} | {:.4f} | {} | {} |\n", e.position_m / r.orientation.ruling.length_m,
                     e.interior_angle_deg,
                     e.near_edge_peak ? fmt::format("acute: near-edge peak {}, body's {:.5g} MPa",
                                                    e.predicted_edge_pa ? "converged" : "NOT converged",
                                                    e.body_near_edge_peak_pa / 1e6)
                     : e.end_model.singular
                         ? fmt::format("singular (exponent {} measured, {:.3f} wedge)",
                                       e.end_model.measured_exponent
                                           ? fmt::format("{:.3f}", *e.end_model.measured_exponent)
                                           : std::string("not"),
                                       e.end_model.wedge_exponent)
                     : e.end_model_ratio ? "converged"
                                         : "NOT converged",
                     e.end_model_ratio ? fmt::format("{:.4f}{}", *e.end_model_ratio,
                                                     e.rule_match_distance_m
                                                         ? fmt::format(" (d_m {:.3g} m)", *e.rule_match_distance_m)
                                                         : std::string())
                                       : "-",
                     e.predicted_edge_pa ? fmt::format("{:.5g}", *e.predicted_edge_pa / 1e6) : "-",
                     e.body_edge_pa / 1e6, e.body_edge_pa / e.body_interior_pa,
                     e.difference ? fmt::format("{:+.2f} %", 100 * *e.difference) : "-",
                     e.matched_difference
                         ? fmt::format("{:+.2f} % (level {}, h_e {:.3g} b)", 100 * *e.matched_difference,
                                       *e.matched_level,
                                       e.end_model.levels[*e.matched_level].edge_element_m / e.half_width_m)
                         : "-");
  return t;
}
} // namespace rollcheck::study::whole_body
