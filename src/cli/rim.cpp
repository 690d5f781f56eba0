// `rollcheck rim`: one end of a loaded ruling in 3D on the rigid plane or a
// steel block, the edge sharp or rounded, at several sizes of the edge
// elements (fem/scenes/rim_end_contact.h). A sharp singular edge is reported singular
// with its measured growth exponent beside the wedge's, never as a peak; a
// square or a rounded edge has a converged end/interior pressure ratio, or
// says it has not. With --body: every loaded end of the body's rolling loop
// and the end-aware FEM-SDS and FEM-FDS (study/rims/rim_loop.h).
// Also the scene "rim" of case files.
#include "cli/cli.h"
#include "cli/scenes.h"
#include "contact/edge_on_elastic_block_exponent.h"
#include "core/json_number.h"
#include "fem/scenes/rim_end_contact.h"
#include "study/rims/rim_loop.h"
#include <algorithm>
#include <fmt/format.h>
#include <mpi.h>
#include <numbers>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
namespace
{
/// The command's settings: without a body, one end (`end`); with one, every
/// loaded end of its loop.
struct RimCommand : study::rims::RimLoopSettings
{
  RimCommand() { loop.body.body.clear(); }
};

const io::BoundSchema<RimCommand>& rim_schema()
{
  using fem::RimEndSettings;
  auto end = [](auto member) {
    return [member](RimCommand& c) -> auto& { return std::invoke(member, c.end); };
  };
  static const io::BoundSchema<RimCommand> schema = [&] {
    io::BoundSchema<RimCommand> s("rim");
    s.include(body_schema(), [](RimCommand& c) -> geometry::BodySpec& { return c.loop.body; });
    s.integer("orientations", "--orientations", [](RimCommand& c) -> std::size_t& { return c.loop.orientations; }, "",
              "With --body: orientations of the loop solved directly (slices and an end model at each loaded rim "
              "end), one per equal stratum of the loop",
              io::Bounds{1, 1000})
        .integer("seed", "--seed", [](RimCommand& c) -> std::uint64_t& { return c.loop.seed; }, "",
                 "With --body: seed of the stratified sampling of those orientations", io::non_negative)
        .integer("samples_per_loop", "--samples", [](RimCommand& c) -> long& { return c.loop.samples_per_loop; }, "",
                 "With --body: samples of the rolling loop, every one scored", io::Bounds{2, 1e7})
        .real("normal_load_n", "--load", [](RimCommand& c) -> double& { return c.loop.normal_load_n; }, "N",
              "With --body: force F pressing the body onto the counter-face through its centre of mass (the "
              "preprint's; its fatigue load is 5000 N)",
              io::positive)
        .real("end_table_step_deg", "--end-table-step", &RimCommand::end_table_step_rad, "deg",
              "With --body: largest spacing of the end table's interior angles (end models across the loop's "
              "range of loaded ends; the check halves it)",
              io::Bounds{0.5, 60}, std::numbers::pi / 180)
        .real("end_table_acute_step_deg", "--end-table-acute-step", &RimCommand::end_table_acute_step_rad, "deg",
              "With --body: below 90 deg, largest spacing of the end table's interior angles instead (a node at 90 "
              "deg), where an acute rounded end's ratio bends; 0: --end-table-step throughout",
              io::Bounds{0, 60}, std::numbers::pi / 180)
        .real("end_table_radius_step", "--end-table-radius-step", &RimCommand::end_table_radius_step, "",
              "With --body and a rounded edge: largest ratio between neighbouring columns of the end table over the "
              "sheet's R (end models across the range of R at the loop's ends, all at the direct ends' median q; "
              "the check halves them; columns at small R cost most, their block --block-depth r_e deep); 0: one column "
              "at the direct ends' median q and R",
              io::Bounds{0, 100})
        .real("depth_over_edge_radius", "--block-depth", &RimCommand::depth_over_edge_radius, "",
              "With --body and a rounded edge: each end model's block at least this many edge radii deep (H >= c r_e "
              "at every end, however small its b; above 4 for the fillet to fit). An acute end's ratio falls as the "
              "block deepens (docs/rims.md, \"The block's depth\")",
              io::Bounds{4, 100, true, false})
        .real("flat_rim_from_deg", "--flat-rim-from", &RimCommand::flat_rim_from_rad, "deg",
              "With --body and a rounded edge: loaded ends of at least this interior angle take the flat-rim table, "
              "the body's own ends solved in 3D by half-space theory (its surface near the end, its load along the "
              "ruling, its balance: `rollcheck flat-rim`), nodes 2.5 deg apart up to the loop's flattest end, instead "
              "of the FEM end table (a straight rim under a uniform load); 180: never",
              io::Bounds{150, 180}, std::numbers::pi / 180);
    s.real("sheet_radius_m", "--sheet-radius", end(&RimEndSettings::radius_m), "m",
           "One end: R, the contacting sheet's radius across the ruling at the end (the Hertz scenes' 10 mm "
           "cylinder)",
           io::positive)
        .real("load_n_per_m", "--load-per-length", end(&RimEndSettings::load_n_per_m), "N/m",
              "One end: q, the line load at the end (the preprint's F = 100 N over a 10 mm ruling)", io::positive)
        .real("interior_angle_deg", "--interior-angle", end(&RimEndSettings::interior_angle_rad), "deg",
              "One end: a, between the contact sheet and the rim's other face through the body: 90 a square end, "
              "below it an acute rim, towards 180 the other face rises gently (fem-sds reports 90 + each end's rim "
              "lean)",
              io::Bounds{60, 180, false, true}, std::numbers::pi / 180)
        .real("edge_radius_m", "--edge-radius", end(&RimEndSettings::edge_radius_m), "m",
              "r_e of the edge's fillet, the way a part is finished; 0: the sharp edge of the ideal hull. With --body "
              "the part is the hull rounded by a ball of r_e rolled inside it: no radius of its surface is below r_e, "
              "so an end near a sheet's apex is taken at R = r_e",
              io::Bounds{0, 1, false, false});
    s.choice("counter_face", "--counter-face", end(&RimEndSettings::counter_face),
             "What the body presses on: rigid (the frictionless rigid plane) or steel (a block of the body's own "
             "material, a second elastic body, frictionless; sharp or rounded edges, any number of processes; a rounded "
             "edge meshes down to h_e of about 2 um for now)",
             {{"rigid", fem::CounterFace::rigid}, {"steel", fem::CounterFace::block}});
    add_material(s, end(&RimEndSettings::youngs_modulus_pa), end(&RimEndSettings::poisson_ratio));
    s.real("depth_over_half_width", "--depth", end(&RimEndSettings::depth_over_half_width), "",
           "H / b: the block's depth and half-width in units of line Hertz's half-width b", io::Bounds{4, 1000})
        .real("length_over_depth", "--length", end(&RimEndSettings::length_over_depth), "",
              "L / H: the contact modelled from the far side (plane strain) to the edge", io::Bounds{1, 20})
        .choice("sheet", "--sheet", end(&RimEndSettings::sheet),
                "The contact sheet as a cylinder, or flattened onto z = 0 with its height in the contact's initial "
                "gap (half-space theory's profile, for b << R); auto: flat where R >= 20 H or R < H, the cylinder "
                "between; the steel counter-face is always flat (the sheet's profile in the pairs' gap)",
                {{"auto", fem::SheetModel::automatic}, {"cylinder", fem::SheetModel::cylinder},
                 {"flat", fem::SheetModel::flat}})
        .choice("end_mesh", "--end-mesh", end(&RimEndSettings::mesh),
                "How the end is meshed: gmsh (Delaunay tetrahedra graded about the edge and the strip, any end) or "
                "grid (a structured grid of tetrahedra built without gmsh, h_e across the edge and b / "
                "contact_elements along it, sheared for an end within 15 deg of square: an independent check of the "
                "sharp square or near-square end on the rigid plane, flat sheet)",
                {{"gmsh", fem::RimEndMesh::delaunay}, {"grid", fem::RimEndMesh::grid}})
        .integer("contact_elements", "--contact-elements", end(&RimEndSettings::contact_elements), "",
                 "Elements across b along the contact strip", io::Bounds{2, 40})
        .real("edge_element_over_half_width", "--edge-element", end(&RimEndSettings::edge_element_over_half_width), "",
              "h_e / b at the first level; each further level halves it", io::Bounds{1e-3, 1, false, false})
        .integer("levels", "--levels", end(&RimEndSettings::levels), "", "Edge mesh levels (convergence needs 2)",
                 io::Bounds{1, 6})
        .integer("extra_levels", "--extra-levels", end(&RimEndSettings::extra_levels), "",
                 "Levels beyond --levels, added one at a time while the end/interior ratio changes by --tolerance or "
                 "more between the last two (or a fillet's boundary layer is not resolved); with --body every end "
                 "model takes at least 1, as the flat-rim table does",
                 io::Bounds{0, 2})
        .real("tolerance", "--tolerance", end(&RimEndSettings::tolerance), "",
              "Largest relative change of the end/interior pressure ratio between the last two levels that counts as converged",
              io::Bounds{0, 1, true, false})
        .real("penalty_c", "--penalty-c", end(&RimEndSettings::penalty_c), "",
              "Penalty kappa = c E / h(x), h the local element size", io::positive)
        .text("xdmf", "--xdmf", end(&RimEndSettings::xdmf_path),
              "Write the last level's displacement, stress and contact pressure to this self-contained .xdmf "
              "(ParaView)");
    return s;
  }();
  return schema;
}

/// The end table's columns in words: its R, or its range of R.
std::string table_columns_text(const study::rims::RimLoopResult& r)
{
  if (r.table.empty() || r.table.front().sheet_radius_m == r.table.back().sheet_radius_m)
    return fmt::format("R = {:.4g} m", r.reference_radius_m);
  const auto angles = static_cast<std::size_t>(std::ranges::count_if(
      r.table, [&](const study::rims::EndTableNode& n) { return n.sheet_radius_m == r.table.front().sheet_radius_m; }));
  return fmt::format("{} columns of R from {:.4g} to {:.4g} m ({} angles each)", r.table.size() / angles,
                     r.table.front().sheet_radius_m, r.table.back().sheet_radius_m, angles);
}

nlohmann::json run_one_end(const fem::RimEndSettings& setup)
{
  const fem::RimEndStudy study = fem::solve_rim_end(MPI_COMM_WORLD, setup);
  const double b = study.half_width_m;

  nlohmann::json levels = nlohmann::json::array();
  std::string table = "| h_e / b | DOFs | Newton | s | far q (N/m) | far p / p0 | scatter | mid / far | end peak / far "
                      "| at x / b | edge / far |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const fem::RimEndLevel& l : study.levels)
  {
    nlohmann::json centre_line = nlohmann::json::array();
    // As far as 3 b beyond where the sheet ends: an acute rim's fillet, and
    // the peak at its start, lie further from the edge than 3 b.
    for (const fem::CentreLineNode& n : l.centre_line)
      if (n.x_m > -3 * b - study.fillet_start_m)
        centre_line.push_back({n.x_m, n.pressure_pa});
    levels.push_back({{"edge_element_m", l.edge_element_m},
                      {"dofs", l.dofs},
                      {"approach_m", l.approach_m},
                      {"start_load_n_per_m", l.start_load_n_per_m},
                      {"load_steps", l.load_steps},
                      {"newton_iterations", l.newton_iterations},
                      {"krylov_iterations", l.krylov_iterations},
                      {"wall_s", l.wall_s},
                      {"far_load_n_per_m", l.far_load_n_per_m},
                      {"far_peak_pa", l.far_peak_pa},
                      {"far_scatter", l.far_scatter},
                      {"mid_peak_pa", l.mid_peak_pa},
                      {"end_peak_pa", l.end_peak_pa},
                      {"end_peak_x_m", l.end_peak_x_m},
                      {"edge_pressure_pa", l.edge_pressure_pa > 0 ? json_number(l.edge_pressure_pa) : nlohmann::json(nullptr)},
                      {"centre_line_x_m_pressure_pa", centre_line}});
    table += fmt::format("| {:.4f} | {} | {} | {:.1f} | {:.5g} | {:.4f} | {:.3f} | {:.4f} | {:.4f} | {:.3f} | {} |\n",
                         l.edge_element_m / b, l.dofs, l.newton_iterations, l.wall_s, l.far_load_n_per_m,
                         l.far_peak_pa / study.hertz_peak_pa, l.far_scatter, l.mid_peak_pa / l.far_peak_pa,
                         l.end_peak_pa / l.far_peak_pa, l.end_peak_x_m / b,
                         l.edge_pressure_pa > 0 ? fmt::format("{:.4f}", l.edge_pressure_pa / l.far_peak_pa) : "-");
  }
  const bool sharp = !(setup.edge_radius_m > 0);
  const std::string verdict
      = study.singular
            ? fmt::format("singular: the edge's pressure grows as h_e^{:.3f} (the wedge's eigenvalue: {:.3f}); no peak value",
                          study.measured_exponent.value_or(std::nan("")), study.wedge_exponent)
        : !study.end_change
            ? fmt::format("one level: end pressure / interior {:.4f}, convergence not checked", *study.end_to_interior)
        : !study.resolved
            ? fmt::format("NOT resolved: the rounded edge's boundary layer s = {:.3g} b needs edge elements of s / 4, "
                          "the last level has {:.3g} b; end pressure / interior {:.4f} is a number of the mesh",
                          study.boundary_layer_m / b, study.levels.back().edge_element_m / b, *study.end_to_interior)
        : study.converged
            ? fmt::format("converged: end pressure / interior {:.4f} (last change {:+.2f} %; {})", *study.end_to_interior,
                          100 * *study.end_change, sharp ? "the sharp edge's own" : "the rounded edge's peak")
            : fmt::format("NOT converged: end pressure / interior {:.4f} changed {:+.2f} % at the last level",
                          *study.end_to_interior, 100 * *study.end_change);
  // Tables go to the log (stderr), so that `--json -` stays JSON alone.
  if (process_rank() == 0)
    spdlog::info("\nrim end, interior angle {:.4g} deg, edge radius {:.3g} m ({:.3g} b), R = {:.4g} m, q = {:.5g} "
                 "N/m (b = {:.4g} m, p0 = {:.5g} Pa):\n\n{}\n{}; far side in plane strain to {:.2f} % (standard error {:.2f} %).\n\n",
                 setup.interior_angle_rad * 180 / std::numbers::pi, setup.edge_radius_m, setup.edge_radius_m / b,
                 setup.radius_m, setup.load_n_per_m, b, study.hertz_peak_pa, table, verdict,
                 100 * study.plane_strain_change, 100 * study.plane_strain_noise);
  return {{"counter_face", setup.counter_face == fem::CounterFace::rigid ? "rigid" : "steel"},
          {"interior_angle_deg", setup.interior_angle_rad * 180 / std::numbers::pi},
          {"edge_radius_m", setup.edge_radius_m},
          {"sheet_radius_m", setup.radius_m},
          {"load_n_per_m", setup.load_n_per_m},
          {"effective_modulus_pa", study.effective_modulus_pa},
          {"half_width_m", b},
          {"hertz_peak_pa", study.hertz_peak_pa},
          {"singular", study.singular},
          {"wedge_exponent", study.wedge_exponent},
          {"measured_exponent", json_number(study.measured_exponent)},
          // What a block of the body's own material would make of a sharp
          // edge (analytic; the elastic counter-face is not modelled here).
          {"same_material_block_exponent",
           setup.edge_radius_m > 0 ? nlohmann::json(nullptr)
                                   : json_number(contact::edge_on_elastic_block_exponent(
                                         setup.interior_angle_rad, setup.youngs_modulus_pa, setup.poisson_ratio,
                                         setup.youngs_modulus_pa, setup.poisson_ratio))},
          {"end_to_interior",
           study.singular || !study.resolved ? nlohmann::json(nullptr) : json_number(study.end_to_interior)},
          {"end_change", json_number(study.end_change)},
          {"sheet", study.flat_sheet ? "flat" : "cylinder"},
          {"end_mesh", setup.mesh == fem::RimEndMesh::grid ? "grid" : "gmsh"},
          {"fillet_start_m", study.fillet_start_m},
          {"boundary_layer_m", study.boundary_layer_m},
          {"resolved", study.resolved},
          {"converged", study.converged},
          {"plane_strain_change", study.plane_strain_change},
          {"plane_strain_noise", study.plane_strain_noise},
          {"verdict", verdict},
          {"levels", levels}};
}
std::string end_verdict(const fem::RimEndStudy& study)
{
  if (study.singular)
    return fmt::format("singular, measured {:.3f}", study.measured_exponent.value_or(std::nan("")));
  if (!study.end_to_interior || !study.resolved)
    return "rounded edge not resolved";
  return fmt::format("{:.3f}{}", *study.end_to_interior, study.converged ? "" : " (NOT converged)");
}

/// The loop's largest end pressure over its largest interior pressure, in words.
std::string loop_ratio_text(const study::rims::RimLoopResult& r)
{
  if (const auto ratio = r.loop_end_to_interior())
  {
    // A ratio implies end-aware scores (loop_end_to_interior).
    const study::loop_scores::EndAwareScores& all = r.loop.end_aware[0];
    if (all.finished_ends == 0)
      return fmt::format("{:.3f}", *ratio);
    return fmt::format("{:.3f}; {} of the {} loaded ends lie near a sheet's apex, taken at R = r_e (the finish's "
                       "least radius): their largest {:.3f}, the other ends' {:.3f}",
                       *ratio, all.finished_ends, r.loop.loaded_ends, all.finished_peak_pa / r.loop.fem_peak_pa,
                       all.unfinished_peak_pa / r.loop.fem_peak_pa);
  }
  if (r.loop.end_aware.empty() || r.loop.loaded_ends == 0)
    return "none (no loaded end)";
  const study::loop_scores::EndAwareScores& all = r.loop.end_aware[0];
  if (all.singular_ends > 0)
    return "singular";
  std::string covered = "none";
  if (const auto ratio = r.covered_end_to_interior())
  {
    covered = fmt::format("{:.3f}", *ratio);
    if (const auto change = r.covered_limit_change())
      covered += std::abs(*change) < r.fem_sds.loop.tolerance
                     ? fmt::format(" (halving the limit on b / R changes it by {:+.2f} %)", 100 * *change)
                     : fmt::format(", {:.1f} % above the ends within half the limit on b / R: set by the limit, "
                                   "no peak (line Hertz grows as R^-1/2 towards a sheet's apex)",
                                   100 * *change);
  }
  return fmt::format("undefined: {} of the {} loaded ends (in {} of the {} samples) lie outside the line-contact "
                     "model; over the ends it covers {}",
                     all.outside_model_ends, r.loop.loaded_ends, all.outside_model_samples, r.loop.samples, covered);
}

nlohmann::json run_loop(study::rims::RimLoopSettings settings)
{
  settings.loop.youngs_modulus_pa = settings.end.youngs_modulus_pa;
  settings.loop.poisson_ratio = settings.end.poisson_ratio;
  const study::rims::RimLoopResult r = study::rims::run_rim_loop(MPI_COMM_WORLD, settings);
  const nlohmann::json j = to_json(r);
  if (process_rank() != 0)
    return j;
  constexpr double degree = std::numbers::pi / 180;
  std::string ends = "| orientation | end | interior angle (deg) | q (N/m) | R (mm) | b (um) | wedge exponent | FEM: "
                     "exponent or end/interior | end peak / orientation's peak | end table | run time (s) |\n"
                     "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const study::rims::RimLoopEnd& e : r.ends)
  {
    ends += fmt::format("| {} | {} | {:.1f}{} | {:.4g} | {:.3g} | {:.3g} | {:.3f} | {} | {} | {} | {:.0f} |\n",
                        e.orientation, e.end == 0 ? "start" : "end", e.interior_angle_rad / degree,
                        e.modelled_angle_rad != e.interior_angle_rad
                            ? fmt::format(" (modelled {:.1f})", e.modelled_angle_rad / degree)
                            : "",
                        e.study.setup.load_n_per_m, e.study.setup.radius_m * 1e3, e.study.half_width_m * 1e6,
                        e.study.wedge_exponent, e.outside_model.empty() ? end_verdict(e.study) : e.outside_model,
                        e.end_peak_pa ? fmt::format("{:.3f}", *e.end_peak_pa / e.interior_peak_pa) : "-",
                        e.table_ratio ? fmt::format("{:.3f}", *e.table_ratio) : "-", e.study.wall_s());
  }
  const study::loop_scores::LoopSds& loop = r.loop;
  // A missing score: a singular end, or an end outside the model (undefined).
  const std::string missing
      = !loop.end_aware.empty() && loop.end_aware[0].singular_ends == 0 && loop.end_aware[0].outside_model_ends > 0
            ? "undefined"
            : "singular";
  auto score = [](const study::loop_scores::ConvergedScore& c, const std::string& missing_word = "singular") {
    if (!c.value)
      return missing_word;
    if (std::isinf(*c.value))
      return std::string("infinite (no stress amplitude above the endurance limit)");
    return fmt::format("{:.5g} (halving the samples {:+.2f} %)", *c.value, 100 * c.sample_change());
  };
  std::string scores = fmt::format("interior only: FEM-SDS {}, FEM-FDS {}", score(loop.fem_rulings),
                                   score(loop.fem_fds_rulings));
  if (!loop.end_aware.empty())
    scores += fmt::format("\nwith the ends:  FEM-SDS {}, FEM-FDS {}; {}\nover the loop: largest end pressure / "
                          "largest interior pressure {}",
                          score(loop.end_aware[0].sds, missing), score(loop.end_aware[0].fds, missing), r.end_aware_status(),
                          loop_ratio_text(r));
  std::string flat = r.flat_rim_refused.empty() ? "" : "; no flat-rim table (" + r.flat_rim_refused + ")";
  if (!r.flat_table.empty())
  {
    flat = fmt::format("; from {:.1f} deg the flat-rim table (the loop's own ends, half-space theory), peak / line "
                       "Hertz:",
                       r.flat_from_rad / degree);
    for (const study::rims::FlatRimNode& n : r.flat_table)
      flat += fmt::format(" {:.3f} at {:.1f}{}", n.ratio(), n.interior_angle_rad / degree,
                          n.converged() ? "" : " (NOT converged)");
    if (const nlohmann::json& seam = j["flat_rim_seam"]; !seam.is_null())
      flat += fmt::format(" deg; where the tables meet the end table gives {:.3f}", seam["end_table_ratio"].get<double>());
    else
      flat += " deg";
    if (!r.flat_rim_refused.empty())
      flat += " (" + r.flat_rim_refused + ")";
  }
  spdlog::info("\nrims of {} ({}), counter-face {}, edge {}:\n\n{}\nloaded rim ends over the loop: {} in {} of {} "
               "samples, interior angles {:.1f} to {:.1f} deg (singular above {:.2f} deg); end table of {} nodes "
               "at q = {:.4g} N/m, {}, against the direct ends {}{}\n{}\n\n",
               r.fem_sds.body, r.fem_sds.source, j["counter_face"].get<std::string>(),
               r.end_setup.edge_radius_m > 0 ? fmt::format("rounded, r_e = {:.3g} m", r.end_setup.edge_radius_m)
                                             : "sharp",
               ends, loop.loaded_ends, loop.loaded_end_samples, loop.samples, loop.loaded_end_angle_min_rad / degree,
               loop.loaded_end_angle_max_rad / degree, r.singular_from_rad / degree, r.table.size(),
               r.reference_load_n_per_m, table_columns_text(r),
               r.table_vs_direct ? fmt::format("{:.2f} %", 100 * *r.table_vs_direct) : "-", flat, scores);
  return j;
}

nlohmann::json run_rim(const io::Parameters& p)
{
  const RimCommand command = rim_schema().bind(p);
  return command.loop.body.body.empty() ? run_one_end(command.end) : run_loop(command);
}
} // namespace

void add_rim_command(CLI::App& app)
{
  add_scene_command(app, "rim",
                    "FEM of a loaded ruling end at the body's rim in 3D on the rigid plane or a steel block (gmsh "
                    "OpenCASCADE, sharp or rounded edge, several edge mesh levels): singular with its exponent, or "
                    "the converged end/interior pressure ratio. With --body: every loaded end of the body's rolling "
                    "loop, and FEM-SDS and FEM-FDS with the ends",
                    rim_schema().schema(), run_rim);
}
} // namespace rollcheck::cli
