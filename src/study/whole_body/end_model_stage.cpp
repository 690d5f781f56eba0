// The end models of a whole-body check at its loaded ends
// (study/whole_body/check_stages.h solve_end_model_stage, EndComparison).
#include "study/whole_body/check_stages.h"
#include "core/degree.h"
#include "contact/wedge_exponent.h"
#include "fem/mesh/scene_mesh.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <spdlog/spdlog.h>

namespace rollcheck::study::whole_body
{
namespace
{
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

/// The k-th loaded end (e) as the rule loads it: at the locus's loaded end,
/// the rule's q and line Hertz's b at its reading point, the slice there.
EndComparison end_under_rule(const CheckContext& context, const LineLoad& load_at, const SliceReadings& slices,
                             std::size_t k)
{
  const int e = slices.loaded_ends[k];
  EndComparison end;
  end.position_m = context.end_fractions[e] * context.length_m();
  end.radius_m = context.radius_at(context.end_fractions[e]);
  end.load_n_per_m = load_at(slices.read_at_fraction[e]);
  end.half_width_m = line_half_width(end.load_n_per_m, end.radius_m, context.effective_modulus_pa);
  end.interior_angle_deg = 90 + context.orientation.rim_overhang_rad[e] / degree;
  end.slice_peak_pa = slices.slices[slices.stations + k].peak_pressure_pa;
  return end;
}

/// The end model's settings (fem/scenes/rim_end_contact.h) at one end.
fem::RimEndSettings end_model_settings(const CheckContext& context, const EndComparison& end)
{
  const WholeBodyCheckSettings& s = context.settings;
  fem::RimEndSettings rim;
  rim.radius_m = end.radius_m;
  rim.load_n_per_m = end.load_n_per_m;
  rim.interior_angle_rad = end.interior_angle_deg * degree;
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
    rim.edge_element_over_half_width = context.sizing.sizes.end_layer_m / end.half_width_m;
  }
  rim.contact_elements = s.end_contact_elements;
  rim.tolerance = s.tolerance;
  if (s.end_depth == EndModelDepth::body)
  {
    rim.depth_over_half_width = context.orientation.centre_of_mass_height_m / end.half_width_m;
    rim.petsc_options = "-hertz_ksp_type preonly -hertz_pc_type lu -hertz_pc_factor_mat_solver_type mumps";
  }
  // Square and near-square ends on the structured grid (sheared): gmsh's
  // Delaunay end at the body's depth has about 1e6 DOFs a level.
  if (std::abs(end.interior_angle_deg - 90) * degree <= fem::max_grid_end_lean_rad)
    rim.mesh = fem::RimEndMesh::grid;
  return rim;
}

/// The end model's reading (EndComparison): its ratio over its reference
/// (far side, or its own pressure at d_m) where converged, the predicted
/// edge, and for a singular end the level nearest the body's end layer
/// (`end_layer_m`) with its edge pressure.
void read_end_model(EndComparison& end, double tolerance, double end_layer_m)
{
  const fem::RimEndStudy& model = end.end_model;
  auto reference = [&](const fem::RimEndLevel& l) {
    return end.rule_match_distance_m ? fem::centre_line_pressure_at(l, -*end.rule_match_distance_m) : l.far_peak_pa;
  };
  if (!model.singular && (end.near_edge_peak || end.rule_match_distance_m))
  {
    if (const auto ratio = ratio_over_levels(model, [&](const fem::RimEndLevel& l) {
          return (end.near_edge_peak ? l.end_peak_pa : l.edge_pressure_pa) / reference(l);
        }))
    {
      end.end_model_ratio_change = ratio->change;
      if (std::abs(ratio->change) < tolerance)
        end.end_model_ratio = ratio->last;
    }
  }
  else if (!model.singular)
  {
    end.end_model_ratio_change = model.end_change;
    if (model.converged)
      end.end_model_ratio = model.end_to_interior;
  }
  if (end.end_model_ratio)
    end.predicted_edge_pa = *end.end_model_ratio * end.slice_peak_pa;
  if (model.singular && !model.levels.empty())
  {
    auto mismatch = [&](const fem::RimEndLevel& l) { return std::abs(std::log(l.edge_element_m / end_layer_m)); };
    const auto nearest = std::ranges::min_element(model.levels, {}, mismatch);
    end.matched_level = static_cast<std::size_t>(nearest - model.levels.begin());
    end.matched_edge_pa = nearest->edge_pressure_pa / reference(*nearest) * end.slice_peak_pa;
  }
}

void log_end_model(const EndComparison& end, int e)
{
  const fem::RimEndSettings& setup = end.end_model.setup;
  spdlog::info("end model at {} (a = {:.2f} deg, H = {:.4g} b, {} mesh): {}{}", e == 0 ? "the start" : "the end",
               end.interior_angle_deg, setup.depth_over_half_width,
               setup.mesh == fem::RimEndMesh::grid ? "grid" : "Delaunay",
               end.end_model.singular ? std::string("singular")
               : end.end_model_ratio
                   ? fmt::format("{} / reference {:.4f}", end.near_edge_peak ? "near-edge peak" : "edge",
                                 *end.end_model_ratio)
                   : std::string("NOT converged"),
               end.rule_match_distance_m
                   ? fmt::format(" (matched to the rule {:.4g} m from the edge)", *end.rule_match_distance_m)
                   : std::string(" (against its far side)"));
}
} // namespace

std::vector<EndComparison> solve_end_model_stage(const CheckContext& context, const LineLoad& load_at,
                                                 const SliceReadings& slices, bool match_near_edge)
{
  const WholeBodyCheckSettings& s = context.settings;
  std::vector<EndComparison> ends;
  for (std::size_t k = 0; k < slices.loaded_ends.size(); ++k)
  {
    const int e = slices.loaded_ends[k];
    EndComparison end = end_under_rule(context, load_at, slices, k);
    // Identical ends (the cylinder's) share one end model; a rule read from
    // a mesh gives them loads 0.2 % apart (the coarse body's, gmsh's split
    // of its prisms), against which the ratio's dependence on q is nil (the
    // oloid's acute end: 0.944086 at 3495 N/m, 0.944079 at 3854 N/m).
    const auto same = std::ranges::find_if(ends, [&](const EndComparison& other) {
      return std::abs(other.load_n_per_m / end.load_n_per_m - 1) < 0.01 && other.radius_m == end.radius_m
             && other.interior_angle_deg == end.interior_angle_deg;
    });
    end.end_model = same != ends.end() ? same->end_model : fem::solve_rim_end(context.comm, end_model_settings(context, end));
    end.near_edge_peak = !end.end_model.singular && end.interior_angle_deg < 90;
    if (match_near_edge)
      end.rule_match_distance_m = s.end_match_over_half_width * context.orientation.end_half_width_m[e];
    read_end_model(end, s.tolerance, context.sizing.sizes.end_layer_m);
    if (context.log)
      log_end_model(end, e);
    ends.push_back(std::move(end));
  }
  return ends;
}
} // namespace rollcheck::study::whole_body
