// The whole-body check's tables and text reports (study/whole_body/whole_body_check.h),
// which `rollcheck whole-body` prints.
#include "study/whole_body/whole_body_check.h"
#include "core/degree.h"
#include "contact/wedge_exponent.h"
#include <algorithm>
#include <fmt/format.h>

namespace rollcheck::study::whole_body
{
namespace
{
/// The end table's "end model" cell: what was compared and whether it converged.
std::string end_model_state(const EndComparison& e)
{
  if (e.near_edge_peak)
    return fmt::format("acute: near-edge peak {}, body's {:.5g} MPa", e.predicted_edge_pa ? "converged" : "NOT converged",
                       e.body_near_edge_peak_pa / 1e6);
  if (e.end_model.singular)
    return fmt::format("singular (exponent {} measured, {:.3f} wedge)",
                       e.end_model.measured_exponent ? fmt::format("{:.3f}", *e.end_model.measured_exponent)
                                                     : std::string("not"),
                       e.end_model.wedge_exponent);
  return e.end_model_ratio ? "converged" : "NOT converged";
}
} // namespace

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
                                     ? fmt::format("{:.3f}", contact::edge_on_rigid_plane_exponent(angle * degree))
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
                     end_model_state(e),
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

std::string report(const WholeBodyCheck& check)
{
  return fmt::format("\nwhole-body check, {}:\n\n{}\n{}\n", check.body, markdown_table(check), check.verdict);
}

std::string scan_report(const WholeBodyCheckSettings& settings, std::span<const WholeBodyOrientation> scan)
{
  return fmt::format("\norientations of {}:\n\n{}", geometry::body_label(settings.body), orientation_table(scan));
}
} // namespace rollcheck::study::whole_body
