// The loop's most oblique rim end, solved obliquely and by the perpendicular
// reduction (study/rims/oblique_end.h).
#include "study/rims/oblique_end.h"
#include "core/degree.h"
#include "contact/rim_dihedral_angle.h"
#include "contact/rim_overhang.h"
#include "contact/wedge_exponent.h"
#include "core/error.h"
#include "oracle/rolling_dynamics.h"
#include "oracle/support_set.h"
#include "study/rims/rim_end_json.h"
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

/// Edge nodal pressure over the far side's at a level (a sharp edge's end-to-interior ratio).
double edge_ratio(const fem::RimEndLevel& level) { return level.edge_pressure_pa / level.far_peak_pa; }
} // namespace

LoopRimEnd most_oblique_end(const geometry::BodySpec& spec, std::size_t samples)
{
  const std::vector<oracle::Circle> circles = body_circles(spec);
  const oracle::TwoCircleBody body = oracle::two_circle_body(circles);
  const oracle::ContactLoop loop = oracle::trace_contact_loop(
      body, oracle::contact_curve_point(body, -Eigen::Vector3d::UnitZ()), static_cast<int>(samples));
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
  fem::RimEndSettings oblique = s.end;
  // Room for the slanted edge between the far side and the edge (L / H > 1 +
  // cot c), the same block for both models.
  oblique.length_over_depth = std::max(s.end.length_over_depth, 1.5 + 1 / std::tan(study.end.crossing_angle_rad));
  oblique.interior_angle_rad = study.end.section_angle_rad;
  oblique.crossing_angle_rad = study.end.crossing_angle_rad;
  fem::RimEndSettings perpendicular = oblique;
  perpendicular.crossing_angle_rad = std::numbers::pi / 2;
  perpendicular.interior_angle_rad = study.end.dihedral_angle_rad;
  perpendicular.xdmf_path.clear();
  study.oblique = fem::solve_rim_end(comm, oblique);
  study.perpendicular = fem::solve_rim_end(comm, perpendicular);
  for (std::size_t k = 0; k < std::min(study.oblique.levels.size(), study.perpendicular.levels.size()); ++k)
  {
    ObliqueEndLevel level;
    level.edge_element_m = study.oblique.levels[k].edge_element_m;
    level.oblique_ratio = edge_ratio(study.oblique.levels[k]);
    level.perpendicular_ratio = edge_ratio(study.perpendicular.levels[k]);
    level.ratio_difference = level.oblique_ratio / level.perpendicular_ratio - 1;
    study.levels.push_back(level);
  }
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
  return {{"end",
           {{"section_angle_deg", e.section_angle_rad / degree},
            {"dihedral_angle_deg", e.dihedral_angle_rad / degree},
            {"crossing_angle_deg", e.crossing_angle_rad / degree},
            {"section_wedge_exponent", contact::edge_on_rigid_plane_exponent(e.section_angle_rad)},
            {"dihedral_wedge_exponent", contact::edge_on_rigid_plane_exponent(e.dihedral_angle_rad)},
            {"exponent_shift", e.exponent_shift},
            {"sample", e.sample},
            {"ruling_end", e.end == 0 ? "start" : "end"}}},
          {"oblique", to_json(study.oblique)},
          {"perpendicular", to_json(study.perpendicular)},
          {"levels", levels},
          {"wall_s", study.wall_s}};
}

std::string report(const ObliqueEndStudy& study)
{
  const LoopRimEnd& e = study.end;
  auto exponent = [](const fem::RimEndStudy& s) {
    return s.measured_exponent ? fmt::format("{:.3f}", *s.measured_exponent) : std::string("-");
  };
  std::string t = fmt::format(
      "\nThe loop's most oblique rim end: section {:.2f} deg, dihedral {:.2f} deg, crossing {:.2f} deg (wedge "
      "exponent {:.3f} at the dihedral, {:.3f} at the section). Measured edge exponent: oblique {}, perpendicular "
      "{}.\n\n| h_e / b | oblique edge / interior | perpendicular edge / interior | oblique / perpendicular - 1 |\n"
      "|---|---|---|---|\n",
      e.section_angle_rad / degree, e.dihedral_angle_rad / degree, e.crossing_angle_rad / degree,
      contact::edge_on_rigid_plane_exponent(e.dihedral_angle_rad),
      contact::edge_on_rigid_plane_exponent(e.section_angle_rad), exponent(study.oblique),
      exponent(study.perpendicular));
  for (const ObliqueEndLevel& l : study.levels)
    t += fmt::format("| {:.4g} | {:.4f} | {:.4f} | {:+.2f} % |\n", l.edge_element_m / study.oblique.half_width_m,
                     l.oblique_ratio, l.perpendicular_ratio, 100 * l.ratio_difference);
  return t;
}
} // namespace rollcheck::study::rims
