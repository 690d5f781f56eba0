// `rollcheck rim` (and the case files' scene "rim"): one end of a loaded ruling
// in 3D on the rigid plane or a steel block, sharp or rounded, at several sizes
// of the edge elements (fem/scenes/rim_end_contact.h); with --body every loaded
// end of the body's rolling loop and the end-aware FEM-SDS and FEM-FDS
// (study/rims/rim_loop.h). Its tables are the rims wing's (study/rims/rim_report.h).
#include "cli/cli.h"
#include "core/degree.h"
#include "cli/scenes.h"
#include "contact/continuum_loop_scores.h"
#include "core/error.h"
#include "core/process_rank.h"
#include "core/progress_beat.h"
#include "fem/scenes/rim_end_contact.h"
#include "study/rims/rim_end_json.h"
#include "study/rims/oblique_end.h"
#include "study/rims/rim_loop.h"
#include "study/rims/rim_report.h"
#include <fmt/format.h>
#include <functional>
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
  bool oblique_study = false; ///< with --body: its loop's most oblique end, obliquely and perpendicular
  bool oblique_loop_load = false; ///< with --oblique-study: the end's own q and R in the loop under --load
};
using RimSchema = io::BoundSchema<RimCommand>;
using fem::RimEndSettings;

/// A member of the end models' settings, bound through the command's `end`.
template <typename Member>
auto end(Member member)
{
  return [member](RimCommand& c) -> auto& { return std::invoke(member, c.end); };
}

/// With --body: the body, its loop, the orientations solved directly and F.
void add_loop_options(RimSchema& s)
{
  s.include(line_contact_body_schema(), [](RimCommand& c) -> geometry::BodySpec& { return c.loop.body; });
  s.integer("orientations", "--orientations", [](RimCommand& c) -> std::size_t& { return c.loop.orientations; }, "",
            "With --body: orientations of the loop solved directly (slices and an end model at each loaded rim end), "
            "one per equal stratum of the loop",
            io::Bounds{1, 1000})
      .integer("seed", "--seed", [](RimCommand& c) -> std::uint64_t& { return c.loop.seed; }, "",
               "With --body: seed of the stratified sampling of those orientations", io::non_negative)
      .integer("fem_slices", "--fem-slices", [](RimCommand& c) -> int& { return c.loop.fem_slices; }, "",
               "With --body: plane-strain FEM slices per orientation solved directly, evenly spread over the loaded "
               "ruling away from its ends (the interior's check against the table)",
               io::Bounds{2, 1000})
      .integer("samples_per_loop", "--samples-per-loop", [](RimCommand& c) -> long& { return c.loop.samples_per_loop; }, "",
               "With --body: samples of the rolling loop, every one scored", io::loop_samples)
      .former("samples")
      .flag("oblique_study", "--oblique-study", &RimCommand::oblique_study,
            "With --body: instead of the loop, its most oblique rim end (study/rims/oblique_end.h) solved with the "
            "edge crossing the ruling at its real angle and by the perpendicular reduction at the dihedral angle, at "
            "the end options' q, R, material, edge (--edge-radius: rounded both ways) and levels")
      .flag("oblique_loop_load", "--oblique-loop-load", &RimCommand::oblique_loop_load,
            "With --oblique-study: the end at its own line load and sheet radius in the loop, as the rim loop takes "
            "them (--load through the centre of mass, the static rule; the hull's R, at least --edge-radius), instead "
            "of --load-per-length and --sheet-radius")
      .choice("load_rule", "--load-rule", [](RimCommand& c) -> contact::LoadRule& { return c.loop.load_rule; },
              "With --body: the load on each ruling of the loop, which sets each loaded end's line load and the "
              "interior's: dynamic (the normal force and centre of pressure of the same rolling motion, scaled to "
              "--load), static (--load through the centre of mass) or uniform (--load / L along the ruling), as "
              "fem-sds's (docs/methods/rims.md)",
              contact::load_rule_names())
      .flag("each_load_rule", "--each-load-rule", [](RimCommand& c) -> bool& { return c.each_load_rule; },
            "With --body: also score the loop under the two other load rules (the JSON's load_rules), sharing the "
            "interior's FEM and the end and flat-rim tables, whose nodes then cover every rule's ends")
      .real("normal_load_n", "--load", [](RimCommand& c) -> double& { return c.loop.normal_load_n; }, "N",
            "With --body: force F pressing the body onto the counter-face (the preprint's; its fatigue load is "
            "5000 N), spread along each ruling by --load-rule",
            io::positive);
}

/// With --body: the FEM end table's nodes, its blocks, and where the
/// flat-rim table takes over.
void add_end_table_options(RimSchema& s)
{
  s.real("end_table_step_deg", "--end-table-step", &RimCommand::end_table_step_rad, "deg",
         "With --body: largest spacing of the end table's dihedral angles (end models across the loop's range of "
         "loaded ends, each end's angle normal to its rim; the check halves it)",
         io::Bounds{0.5, 60}, degree)
      .real("end_table_acute_step_deg", "--end-table-acute-step", &RimCommand::end_table_acute_step_rad, "deg",
            "With --body: below 90 deg, largest spacing of the end table's dihedral angles instead (a node at 90 deg), "
            "where an acute rounded end's ratio bends; 0: --end-table-step throughout",
            io::Bounds{0, 60}, degree)
      .real("end_table_radius_step", "--end-table-radius-step", &RimCommand::end_table_radius_step, "",
            "With --body and a rounded edge: largest ratio between neighbouring columns of the end table over the "
            "sheet's R (end models across the range of R at the loop's ends, all at the direct ends' median q; the "
            "check halves them; columns at small R cost most, their block --block-depth r_e deep); 0: one column at "
            "the direct ends' median q and R",
            io::Bounds{0, 100})
      .real("depth_over_edge_radius", "--block-depth", &RimCommand::depth_over_edge_radius, "",
            "With --body and a rounded edge: each end model's block at least this many edge radii deep (H >= c r_e at "
            "every end, however small its b; above 4 for the fillet to fit). As the block deepens an acute end's ratio "
            "falls and an obtuse end's rises (2-3 % per doubling; docs/notes/rim-ends-tables.md)",
            io::Bounds{4, 100, true, false})
      .real("flat_rim_from_deg", "--flat-rim-from", &RimCommand::flat_rim_from_rad, "deg",
            "With --body and a rounded edge: loaded ends of at least this interior angle take the flat-rim table, the "
            "body's own ends solved in 3D by half-space theory (its surface near the end, its load along the ruling, "
            "its balance: `rollcheck flat-rim`), nodes 2.5 deg apart up to the loop's flattest end, instead of the FEM "
            "end table (a straight rim under a uniform load); 180: never",
            io::Bounds{150, 180}, degree)
      .real("half_space_ends_from_deg", "--half-space-ends-from", &RimCommand::half_space_from_rad, "deg",
            "With --body and a rounded edge: ends (direct and end table nodes) of at least this dihedral angle whose "
            "fillet is at least 20 b take the end by half-space theory held as deep as their block (`rollcheck "
            "rounded-end`: seconds where the FEM end model takes minutes to hours) instead of the FEM end model; "
            "0.6-3.4 % above it from 120 deg where measured (R / r_e = 1 to 100; unmeasured beyond), further off "
            "below 120 deg (docs/methods/rims.md); compared with the end's modelled angle, at most 170 deg: above "
            "170, never",
            io::Bounds{110, 180}, degree);
}

/// One end: its sheet, load and angle; the edge, the counter-face and the
/// material (with --body, of every end).
void add_end_options(RimSchema& s)
{
  s.real("sheet_radius_m", "--sheet-radius", end(&RimEndSettings::radius_m), "m",
         "One end: R, the contacting sheet's radius across the ruling at the end (the Hertz scenes' 10 mm cylinder)",
         io::positive)
      .real("load_n_per_m", "--load-per-length", end(&RimEndSettings::load_n_per_m), "N/m",
            "One end: q, the line load at the end (the preprint's F = 100 N over a 10 mm ruling)", io::positive)
      .real("interior_angle_deg", "--interior-angle", end(&RimEndSettings::interior_angle_rad), "deg",
            "One end: a, between the contact sheet and the rim's other face through the body: 90 a square end, below "
            "it an acute rim, towards 180 the other face rises gently; measured normal to the edge, which is square to "
            "the ruling (with --body each end's dihedral angle normal to its rim)",
            io::Bounds{60, 180, false, true}, degree)
      .real("crossing_angle_deg", "--crossing-angle", end(&RimEndSettings::crossing_angle_rad), "deg",
            "One end: c, the angle in the contact plane between the ruling and the rim's edge; 90 the edge square to "
            "the ruling (--interior-angle then normal to it), below 90 an oblique end: --interior-angle is the "
            "section in the ruling's vertical plane, the wedge's angle the dihedral normal to the edge, both sides of "
            "the ruling modelled (sharp edge, rigid plane, gmsh mesh; --length above 1 + cot c)",
            io::Bounds{0, 90, true, false}, degree)
      .real("edge_radius_m", "--edge-radius", end(&RimEndSettings::edge_radius_m), "m",
            "r_e of the edge's fillet, the way a part is finished; 0: the sharp edge of the ideal hull. With --body "
            "the part is the hull rounded by a ball of r_e rolled inside it: no radius of its surface is below r_e, so "
            "an end near a sheet's apex is taken at R = r_e",
            io::Bounds{0, 1, false, false});
  s.choice("counter_face", "--counter-face", end(&RimEndSettings::counter_face),
           "What the body presses on: rigid (the frictionless rigid plane) or steel (a block of the body's own "
           "material, a second elastic body, frictionless; sharp or rounded edges, any number of processes; a rounded "
           "edge meshes down to h_e of about 2 um for now)",
           {{"rigid", fem::CounterFace::rigid}, {"steel", fem::CounterFace::block}});
  add_material(s, end(&RimEndSettings::youngs_modulus_pa), end(&RimEndSettings::poisson_ratio));
}

/// The end model: its block, its sheet and mesh, its levels and their
/// convergence, its penalty and its fields.
void add_end_model_options(RimSchema& s)
{
  s.real("depth_over_half_width", "--depth", end(&RimEndSettings::depth_over_half_width), "",
         "H / b: the block's depth and half-width in units of line Hertz's half-width b", io::Bounds{4, 1000})
      .real("length_over_depth", "--length", end(&RimEndSettings::length_over_depth), "",
            "L / H: the contact modelled from the far side (plane strain) to the edge", io::Bounds{1, 20})
      .choice("sheet", "--sheet", end(&RimEndSettings::sheet),
              "The contact sheet as a cylinder, or flattened onto z = 0 with its height in the contact's initial gap "
              "(half-space theory's profile, for b << R); auto: flat where R >= 20 H or R < H, the cylinder between; "
              "the steel counter-face is always flat (the sheet's profile in the pairs' gap)",
              {{"auto", fem::SheetModel::automatic}, {"cylinder", fem::SheetModel::cylinder},
               {"flat", fem::SheetModel::flat}})
      .choice("end_mesh", "--end-mesh", end(&RimEndSettings::mesh),
              "How the end is meshed: gmsh (Delaunay tetrahedra graded about the edge and the strip, any end), hxt "
              "(the same surface mesh and sizes tetrahedralised by gmsh's HXT: several times faster on large ends), grid "
              "(a structured grid of tetrahedra built without gmsh, h_e across the edge and b / contact_elements along "
              "it, sheared for an end within 15 deg of square: an independent check of the sharp square or near-square "
              "end on the rigid plane, flat sheet), extruded (the section meshed in 2D and extruded along the edge: "
              "any angle, sharp or rounded, flat sheet, rigid plane, edge square to the ruling) or auto (extruded "
              "where it applies, gmsh elsewhere)",
              fem::rim_end_mesh_names())
      .integer("contact_elements", "--contact-elements", end(&RimEndSettings::contact_elements), "",
               "Elements across b along the contact strip", io::Bounds{2, 40})
      .real("edge_element_over_half_width", "--edge-element", end(&RimEndSettings::edge_element_over_half_width), "",
            "h_e / b at the first level; each further level halves it", io::Bounds{1e-3, 1, false, false})
      .integer("levels", "--levels", end(&RimEndSettings::levels), "", "Edge mesh levels (convergence needs 2)",
               io::Bounds{1, 6})
      .integer("extra_levels", "--extra-levels", end(&RimEndSettings::extra_levels), "",
               "Levels beyond --levels, added one at a time while the end/interior ratio changes by --tolerance or "
               "more between the last two (or a fillet's boundary layer is not resolved); with --body every end model "
               "takes at least 1, as the flat-rim table does",
               io::Bounds{0, 2})
      .real("tolerance", "--tolerance", end(&RimEndSettings::tolerance), "",
            "Largest relative change of the end/interior pressure ratio between the last two levels that counts as "
            "converged",
            io::Bounds{0, 1, true, false})
      .real("penalty_c", "--penalty-c", end(&RimEndSettings::penalty_c), "",
            "Penalty kappa = c E / h(x), h the local element size", io::positive)
      .text("xdmf", "--xdmf", end(&RimEndSettings::xdmf_path),
            "Write the last level's displacement, stress and contact pressure to this .xdmf, their data to the .h5 "
            "beside it (ParaView)");
}

const SceneSchema<RimCommand>& rim_schema()
{
  return kept_schema<RimCommand>("rim",
                                 "FEM of a loaded ruling end at the body's rim in 3D on the rigid plane or a steel "
                                 "block (gmsh OpenCASCADE, sharp or rounded edge, several edge mesh levels): singular "
                                 "with its exponent, or the converged end/interior pressure ratio. With --body: every "
                                 "loaded end of the body's rolling loop, and FEM-SDS and FEM-FDS with the ends",
                                 [](RimSchema& s) {
    for (auto add_options : {add_loop_options, add_end_table_options, add_end_options, add_end_model_options})
      add_options(s);
  });
}

/// One end model's progress: each level as it starts, repeated while it
/// runs (meshing a deep block takes minutes and logs nothing); the oblique
/// study's names its model too.
void beat_levels(fem::RimEndSettings& end, ProgressBeat& beat)
{
  end.on_level = [&beat](int level, double edge_element_m) {
    beat.step(fmt::format("level {} (h_e = {:.3g} m)", level + 1, edge_element_m));
  };
}

nlohmann::json run_rim(const io::Parameters& p)
{
  RimCommand command = rim_schema().bind(p);
  if (command.oblique_loop_load && !command.oblique_study)
    throw InputError("rim: --oblique-loop-load needs --body and --oblique-study");
  if (command.loop.body.body.empty())
  {
    ProgressBeat beat("rim", process_rank() == 0);
    beat_levels(command.end, beat);
    const fem::RimEndStudy study = fem::solve_rim_end(MPI_COMM_WORLD, command.end);
    print_summary(study::rims::report(study));
    return study::rims::to_json(study);
  }
  if (command.oblique_study)
  {
    ProgressBeat beat("rim oblique end", process_rank() == 0);
    study::rims::ObliqueEndSettings settings;
    settings.body = command.loop.body;
    settings.end = command.end;
    settings.on_model_level = [&beat](const char* model, int level, double edge_element_m) {
      beat.step(fmt::format("{} model, level {} (h_e = {:.3g} m)", model, level + 1, edge_element_m));
    };
    settings.depth_over_edge_radius = command.depth_over_edge_radius;
    if (command.oblique_loop_load)
      settings.loop_load_n = command.loop.normal_load_n;
    const study::rims::ObliqueEndStudy study = study::rims::oblique_end_study(MPI_COMM_WORLD, settings);
    print_summary(study::rims::report(study));
    return study::rims::to_json(study);
  }
  command.loop.youngs_modulus_pa = command.end.youngs_modulus_pa;
  command.loop.poisson_ratio = command.end.poisson_ratio;
  const study::rims::RimLoopResult r = study::rims::run_rim_loop(MPI_COMM_WORLD, command);
  const nlohmann::json j = to_json(r);
  print_summary(study::rims::report(r));
  return j;
}
} // namespace

void add_rim_command(CLI::App& app)
{
  add_scene_command(app, rim_schema(), run_rim);
  declare_outputs(rim_schema().schema(), {{"xdmf", OutputKind::file}});
}
} // namespace rollcheck::cli
