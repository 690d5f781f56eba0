// The loop's most oblique rim end, solved obliquely and by the perpendicular
// reduction (study/rims/oblique_end.h).
#include "study/rims/oblique_end.h"
#include "core/degree.h"
#include "contact/rim_dihedral_angle.h"
#include "contact/rim_overhang.h"
#include "contact/wedge_exponent.h"
#include "core/error.h"
#include "core/json_number.h"
#include "oracle/line_load.h"
#include "oracle/rolling_dynamics.h"
#include "oracle/rolling_study.h"
#include "oracle/support_set.h"
#include "study/rims/rim_end_json.h"
#include "study/rims/rim_loop.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace rollcheck::study::rims
{
namespace
{

std::vector<oracle::Circle> body_circles(const geometry::BodySpec& body)
{
  if (body.body == "oloid")
    return oracle::roller_circles({90, 1, 1, 2}, geometry::RollerFamily::centre_line, body.radius_m);
  if (body.body == "roller")
    return oracle::roller_circles(body.genome, body.family, body.radius_m);
  throw InputError(fmt::format("rim --oblique-study: the body must be a two-circle body (oloid or roller), got '{}'",
                               body.body));
}

/// The end models' settings: the end's angles (obliquely: the section and
/// the crossing), its q and R if taken from the loop, and a rounded edge's
/// resolution and block as the rim loop sets them (study/rims/rim_loop.h
/// resolved_as_loop_end).
fem::RimEndSettings oblique_settings(const ObliqueEndSettings& s, const LoopRimEnd& end)
{
  fem::RimEndSettings oblique = s.end;
  // Room for the slanted edge between the far side and the edge (L / H > 1 +
  // cot c), the same block for both models.
  oblique.length_over_depth = std::max(s.end.length_over_depth, 1.5 + 1 / std::tan(end.crossing_angle_rad));
  oblique.interior_angle_rad = end.section_angle_rad;
  oblique.crossing_angle_rad = end.crossing_angle_rad;
  if (s.loop_load_n)
  {
    oblique.radius_m = std::max(end.sheet_radius_m, s.end.edge_radius_m);
    oblique.load_n_per_m = oracle::line_load(*s.loop_load_n, end.centre_of_pressure, end.ruling_length_m, end.end);
    if (!(oblique.load_n_per_m > 0))
      throw InputError(fmt::format("rim --oblique-study: the most oblique end (sample {}, the ruling's {}) carries no "
                                   "load under the static rule (centre of pressure {:.3f})",
                                   end.sample, end.end == 0 ? "start" : "end", end.centre_of_pressure));
  }
  if (s.end.edge_radius_m > 0)
  {
    // The oblique fillet is built on the flat sheet alone
    // (fem/mesh/rim_end_solid.h): both models take it, the sheet's height in
    // the contact's initial gap, unless the cylinder is asked for by name.
    if (oblique.sheet == fem::SheetModel::automatic)
      oblique.sheet = fem::SheetModel::flat;
    oblique = resolved_as_loop_end(oblique, s.depth_over_edge_radius);
  }
  return oblique;
}

/// Rounded, both models converged: |d| between their last levels plus each
/// ratio's change over its last level.
std::optional<double> difference_bound(const ObliqueEndStudy& study)
{
  if (!study.rounded || !study.oblique.converged || !study.perpendicular.converged || !study.difference)
    return std::nullopt;
  return std::abs(*study.difference) + std::abs(study.oblique.end_change.value())
         + std::abs(study.perpendicular.end_change.value());
}
} // namespace

LoopRimEnd most_oblique_end(const geometry::BodySpec& spec, std::size_t samples)
{
  const std::vector<oracle::Circle> circles = body_circles(spec);
  const oracle::TwoCircleBody body = oracle::two_circle_body(circles);
  const oracle::ContactLoop loop = oracle::trace_contact_loop(
      body, oracle::contact_curve_point(body, -Eigen::Vector3d::UnitZ()), static_cast<int>(samples));
  const Eigen::Vector3d centre_of_mass_m = oracle::rolling_centre_of_mass(spec);
  LoopRimEnd worst;
  worst.exponent_shift = -1;
  for (std::size_t k = 0; k < loop.directions.size(); ++k)
  {
    const oracle::Ruling ruling = oracle::ruling_at(body, loop.directions[k]);
    const std::array<double, 2> dihedral = contact::rim_dihedral_angle(circles, 0, 1, ruling);
    const std::array<double, 2> overhang = contact::rim_overhang(circles, 0, 1, ruling);
    for (const int e : {0, 1})
    {
      const oracle::Circle& on = circles[static_cast<std::size_t>(e)];
      const Eigen::Vector3d point = e == 0 ? ruling.start_m : ruling.end_m;
      const Eigen::Vector3d rim_tangent = on.normal.cross(point - on.centre_m).normalized();
      if (std::abs(rim_tangent.dot(ruling.axis)) > 0.97) // the vertex: the ruling runs along the rim
        continue;
      LoopRimEnd candidate;
      candidate.section_angle_rad = std::numbers::pi / 2 + overhang[static_cast<std::size_t>(e)];
      candidate.dihedral_angle_rad = dihedral[static_cast<std::size_t>(e)];
      const double cos_phi = std::min(1.0, std::abs(ruling.axis.dot(rim_tangent.cross(ruling.direction))));
      candidate.crossing_angle_rad = std::asin(cos_phi);
      candidate.exponent_shift = contact::edge_on_rigid_plane_exponent(candidate.dihedral_angle_rad)
                                 - contact::edge_on_rigid_plane_exponent(candidate.section_angle_rad);
      candidate.sample = k;
      candidate.end = e;
      candidate.sheet_radius_m = e == 0 ? ruling.start_radius_m : ruling.end_radius_m;
      candidate.ruling_length_m = ruling.length_m;
      candidate.centre_of_pressure = (centre_of_mass_m - ruling.start_m).dot(ruling.axis) / ruling.length_m;
      if (candidate.exponent_shift > worst.exponent_shift)
        worst = candidate;
    }
  }
  if (worst.exponent_shift < 0)
    throw ComputationError("rim --oblique-study: no rim end away from the vertex on the loop");
  return worst;
}

ObliqueEndStudy oblique_end_study(MPI_Comm comm, const ObliqueEndSettings& s)
{
  const auto start = std::chrono::steady_clock::now();
  ObliqueEndStudy study;
  study.end = most_oblique_end(s.body, s.samples);
  study.rounded = s.end.edge_radius_m > 0;
  study.loop_load_n = s.loop_load_n;
  fem::RimEndSettings oblique = oblique_settings(s, study.end);
  fem::RimEndSettings perpendicular = oblique;
  perpendicular.crossing_angle_rad = std::numbers::pi / 2;
  perpendicular.interior_angle_rad = study.end.dihedral_angle_rad;
  perpendicular.xdmf_path.clear();
  if (s.on_model_level)
    for (auto [model, name] : {std::pair{&oblique, "oblique"}, std::pair{&perpendicular, "perpendicular"}})
      model->on_level = [&s, name](int level, double edge_element_m) { s.on_model_level(name, level, edge_element_m); };
  study.oblique = fem::solve_rim_end(comm, oblique);
  study.perpendicular = fem::solve_rim_end(comm, perpendicular);
  for (std::size_t k = 0; k < std::min(study.oblique.levels.size(), study.perpendicular.levels.size()); ++k)
  {
    ObliqueEndLevel level;
    level.edge_element_m = study.oblique.levels[k].edge_element_m;
    level.oblique_ratio = fem::end_to_interior(study.oblique.levels[k], !study.rounded);
    level.perpendicular_ratio = fem::end_to_interior(study.perpendicular.levels[k], !study.rounded);
    level.ratio_difference = level.oblique_ratio / level.perpendicular_ratio - 1;
    study.levels.push_back(level);
  }
  if (study.rounded && study.oblique.end_to_interior && study.perpendicular.end_to_interior)
    study.difference = *study.oblique.end_to_interior / *study.perpendicular.end_to_interior - 1;
  study.difference_bound = difference_bound(study);
  study.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return study;
}

nlohmann::json to_json(const ObliqueEndStudy& study)
{
  const LoopRimEnd& e = study.end;
  nlohmann::json levels = nlohmann::json::array();
  for (const ObliqueEndLevel& l : study.levels)
    levels.push_back({{"edge_element_m", l.edge_element_m},
                      {"oblique_edge_to_interior", l.oblique_ratio},
                      {"perpendicular_edge_to_interior", l.perpendicular_ratio},
                      {"ratio_difference", l.ratio_difference}});
  // Where across the ruling the oblique model's end peak lies, at each of its levels.
  nlohmann::json peak_y = nlohmann::json::array();
  for (const fem::RimEndLevel& l : study.oblique.levels)
    peak_y.push_back(l.end_peak_y_m);
  const nlohmann::json verdict = {{"both_converged", study.oblique.converged && study.perpendicular.converged},
                                   {"tolerance", study.oblique.setup.tolerance},
                                   {"oblique_levels", study.oblique.levels.size()},
                                   {"perpendicular_levels", study.perpendicular.levels.size()},
                                   {"difference", json_number(study.difference)},
                                   {"difference_bound", json_number(study.difference_bound)}};
  return {{"end",
           {{"section_angle_deg", e.section_angle_rad / degree},
            {"dihedral_angle_deg", e.dihedral_angle_rad / degree},
            {"crossing_angle_deg", e.crossing_angle_rad / degree},
            {"section_wedge_exponent", contact::edge_on_rigid_plane_exponent(e.section_angle_rad)},
            {"dihedral_wedge_exponent", contact::edge_on_rigid_plane_exponent(e.dihedral_angle_rad)},
            {"exponent_shift", e.exponent_shift},
            {"sample", e.sample},
            {"ruling_end", e.end == 0 ? "start" : "end"},
            {"hull_sheet_radius_m", e.sheet_radius_m},
            {"ruling_length_m", e.ruling_length_m},
            {"centre_of_pressure", e.centre_of_pressure}}},
          {"rounded", study.rounded},
          {"edge_radius_m", study.oblique.setup.edge_radius_m},
          {"loop_load_n", json_number(study.loop_load_n)},
          {"oblique", to_json(study.oblique)},
          {"perpendicular", to_json(study.perpendicular)},
          {"levels", levels},
          {"oblique_end_peak_y_m", peak_y},
          {"verdict", verdict},
          {"wall_s", study.wall_s}};
}

std::string report(const ObliqueEndStudy& study)
{
  const LoopRimEnd& e = study.end;
  auto exponent = [](const fem::RimEndStudy& s) {
    return s.measured_exponent ? fmt::format("{:.3f}", *s.measured_exponent) : std::string("-");
  };
  auto status = [](const fem::RimEndStudy& s) {
    return fmt::format("{} ({}{})", s.converged ? "converged" : "NOT converged",
                       s.end_change ? fmt::format("{:+.2f} % last level", 100 * *s.end_change) : std::string("one level"),
                       s.resolved ? "" : ", boundary layer not resolved");
  };
  const char* what = study.rounded ? "end" : "edge";
  std::string t = fmt::format(
      "\nThe loop's most oblique rim end: section {:.2f} deg, dihedral {:.2f} deg, crossing {:.2f} deg (wedge "
      "exponent {:.3f} at the dihedral, {:.3f} at the section); q = {:.6g} N/m, R = {:.4g} m, {}.",
      e.section_angle_rad / degree, e.dihedral_angle_rad / degree, e.crossing_angle_rad / degree,
      contact::edge_on_rigid_plane_exponent(e.dihedral_angle_rad),
      contact::edge_on_rigid_plane_exponent(e.section_angle_rad), study.oblique.setup.load_n_per_m,
      study.oblique.setup.radius_m,
      study.rounded ? fmt::format("r_e = {:.4g} m", study.oblique.setup.edge_radius_m) : std::string("sharp edge"));
  if (study.rounded)
    t += fmt::format(" Oblique: {}; perpendicular: {}.", status(study.oblique), status(study.perpendicular));
  else
    t += fmt::format(" Measured edge exponent: oblique {}, perpendicular {}.", exponent(study.oblique),
                     exponent(study.perpendicular));
  t += fmt::format("\n\n| h_e / b | oblique {0} / interior | perpendicular {0} / interior | oblique / perpendicular - 1 "
                   "|\n|---|---|---|---|\n",
                   what);
  for (const ObliqueEndLevel& l : study.levels)
    t += fmt::format("| {:.4g} | {:.4f} | {:.4f} | {:+.2f} % |\n", l.edge_element_m / study.oblique.half_width_m,
                     l.oblique_ratio, l.perpendicular_ratio, 100 * l.ratio_difference);
  if (study.difference)
    t += fmt::format("\nAt each model's last level (oblique {}, perpendicular {}): {:.4f} and {:.4f}, oblique / "
                     "perpendicular - 1 = {:+.2f} %.\n",
                     study.oblique.levels.size(), study.perpendicular.levels.size(), *study.oblique.end_to_interior,
                     *study.perpendicular.end_to_interior, 100 * *study.difference);
  if (study.difference_bound)
    t += fmt::format("The perpendicular reduction is within {:.2f} % of the oblique model on this end (both "
                     "converged within {:.0f} %; the difference plus each ratio's last change).\n",
                     100 * *study.difference_bound, 100 * study.oblique.setup.tolerance);
  return t;
}
} // namespace rollcheck::study::rims
