// `rollcheck fem-sds`: SDS over a whole rolling loop under FEM contact stress,
// against the preprint's point-Hertz SDS and line-contact Hertz
// (docs/fem-sds.md). Also the scene "fem-sds" of case files.
// The method is study/loop_scores/fem_sds.h; here its parameters, its tables in the log,
// its plots and its JSON.
#include "cli/cli.h"
#include "cli/scenes.h"
#include "io/batch_report.h"
#include "study/loop_scores/fem_sds.h"
#include <fmt/format.h>
#include <fstream>
#include <mpi.h>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
namespace
{
const io::BoundSchema<study::loop_scores::FemSdsSettings>& fem_sds_schema()
{
  using study::loop_scores::FemSdsSettings;
  static const io::BoundSchema<FemSdsSettings> schema = [] {
    io::BoundSchema<FemSdsSettings> s("fem-sds");
    s.include(body_schema(), &FemSdsSettings::body)
        .choice("oracle", "--oracle", &FemSdsSettings::oracle,
                "Where the orientations come from: rolling (real rolling without slipping, the body on a ruling at "
                "every instant) or rigid (the preprint's rigid-body oracle, whose orientations mostly stand on a rim "
                "point)",
                {{"rolling", study::loop_scores::OrientationOracle::rolling}, {"rigid", study::loop_scores::OrientationOracle::rigid}})
        .integer("samples_per_loop", "--samples", &FemSdsSettings::samples_per_loop, "",
                 "Samples of the rolling loop (spread evenly in time over its period), every one scored",
                 io::Bounds{2, 1e7})
        .integer("table_nodes_per_decade", "--table-nodes", &FemSdsSettings::table_nodes_per_decade, "",
                 "FEM solves per decade of the load ratio q / (E* R) to start the nondimensional slice table with "
                 "(fem/scenes/slice_scaling.h); doubled until FEM-SDS changes by less than the tolerance",
                 io::Bounds{1, 64})
        .real("tolerance", "--tolerance", &FemSdsSettings::tolerance, "",
              "Relative change of FEM-SDS, doubling the table or the samples, that counts as converged",
              io::Bounds{1e-6, 0.5})
        .integer("orientations", "--orientations", &FemSdsSettings::orientations, "",
                 "Orientations solved directly, slice by slice at two mesh levels, one per equal stratum of the loop: "
                 "the check of the table against direct FEM, and the per-orientation table",
                 io::Bounds{1, 10000})
        .integer("seed", "--seed", &FemSdsSettings::seed, "",
                 "Seed of the stratified sampling (the same seed, the same picks)", io::non_negative)
        .real("barrier_energy_excess", "--energy-excess", &FemSdsSettings::barrier_energy_excess, "",
              "Rolling oracle: initial kinetic energy / potential barrier - 1 (README real-rolling table)",
              io::non_negative)
        .integer("runs", "--runs", &FemSdsSettings::runs, "",
                 "Rigid oracle: runs with the reference's initial spins (the preprint: 3)", io::Bounds{1, 5})
        .real("threshold_m", "--threshold", &FemSdsSettings::contact_threshold_m, "m",
              "The preprint's contact threshold eps: the faces its SDS counts at an orientation", io::non_negative)
        .flag("paper_compat", "--paper-compat", &FemSdsSettings::paper_compat,
              "The preprint's face pressures (doubled mean curvature, E / (2 (1 - nu^2)), ground at the lowest "
              "centroid) for the analytic SDS; otherwise every quirk corrected");
    add_material(s, &FemSdsSettings::youngs_modulus_pa, &FemSdsSettings::poisson_ratio);
    s.real("normal_load_n", "--load", &FemSdsSettings::normal_load_n, "N",
           "Force F pressing the body onto the rigid plane through its centre of mass (the preprint's)",
           io::positive)
        .integer("fem_slices", "--fem-slices", &FemSdsSettings::fem_slices, "",
                 "Plane-strain FEM slices per orientation, evenly spread over the loaded ruling away from its ends",
                 io::Bounds{2, 1000})
        .real("crease_margin", "--crease-margin", &FemSdsSettings::crease_margin, "",
              "Fraction of the ruling kept clear of each end of the loaded contact: the FEM peaks are taken inside, "
              "away from the creases (end effects decay within a few contact widths b, and b / L < 1e-3 here)",
              io::Bounds{0, 0.25, true, true})
        .integer("map_points", "--map-points", &FemSdsSettings::map_points, "",
                 "Points along each ruling at which the peak pressures are mapped onto the faces (FEM-SDS)",
                 io::Bounds{2, 100000})
        .integer("refine", "--refine", &FemSdsSettings::refine, "",
                 "Plane-strain mesh level of the slices (hertz --refine); the error estimate runs one level finer",
                 io::Bounds{-1, 12})
        .real("penalty_c", "--penalty-c", &FemSdsSettings::penalty_c, "",
              "Penalty kappa = c E / h_c (README: penalty study)", io::positive)
        .integer("slab_orientations", "--slab-check", &FemSdsSettings::slab_orientations, "",
                 "The first N solved orientations whose b / R varies at most 2-fold along the ruling are also solved "
                 "as one 3D slab of the whole ruling (fem/scenes/slab_contact.h, square end faces) at two section levels: "
                 "the fuller model the slices must agree with (peak within 2 %), and the pressure at the ruling's "
                 "ends; 0: none",
                 io::Bounds{0, 10000})
        .integer("slab_refine", "--slab-refine", &FemSdsSettings::slab_refine, "",
                 "Section level of the 3D slab (elements across the narrowest half-width: 10 * 2^(level / 2)); the "
                 "second solve is one level finer",
                 io::Bounds{0, 8})
        .flag("elastic_plane", "--elastic-plane", &FemSdsSettings::elastic_plane,
              "FEM against the E* of two identical steel bodies (the preprint's) instead of a rigid plane")
        .unbound({"out", "--out", std::string(), "",
                  "Folder for fem_sds.json, table.md and the plots (written whole or not at all); empty: none"})
        .unbound({"python", "--python", std::string("/usr/bin/python3"), "",
                  "Python with matplotlib for the plots (Debian's)"});
    return s;
  }();
  return schema;
}

std::string markdown_table(const std::vector<study::loop_scores::FemSdsOrientation>& results)
{
  std::string t = "| # | t (s) | support | c | creases | point-Hertz p0 (MPa) | line-Hertz p0 (MPa) | FEM p0 (MPa) | "
                  "FEM finer (MPa) | change | FEM / line - 1 | length (m) | width (um) | DOFs | Newton | s |\n"
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const study::loop_scores::FemSdsOrientation& r : results)
  {
    t += fmt::format("| {} | {:.4g} | {} | {} | {} | {:.4g} |", r.index, r.locus.time_s,
                     study::loop_scores::support_name(r.locus.support.kind),
                     r.locus.ruling ? fmt::format("{:.3f}", r.locus.centre_of_pressure) : std::string("-"),
                     r.locus.creases.size(), r.point_hertz_peak_pa / 1e6);
    if (r.solved)
      t += fmt::format(" {:.4g} | {:.4g} | {:.4g} | {:+.2f} % | {:+.2f} % | {:.4g} | {:.3g} | {} | {} | {:.1f} |\n",
                       r.line_hertz_peak_pa / 1e6, r.fem_peak_pa / 1e6, r.fem_peak_refined_pa / 1e6,
                       100 * (r.fem_peak_refined_pa / r.fem_peak_pa - 1),
                       100 * (r.fem_peak_pa / r.line_hertz_peak_pa - 1), r.contact_length_m, 1e6 * r.contact_width_m,
                       r.dofs, r.newton_iterations, r.wall_s);
    else
      t += " - | - | - | - | - | - | - | - | - | - |\n";
  }
  return t;
}

std::string slab_table(const std::vector<study::loop_scores::FemSdsOrientation>& results)
{
  std::string t = "| # | level | DOFs | layers | Newton | s | approach factor | c (slab / locus) | slab peak / slices' - 1 "
                  "| max over slices of abs(slab / slice - 1) | end p at s = 0, L (MPa) |\n"
                  "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const study::loop_scores::FemSdsOrientation& r : results)
    for (const fem::SlabFem& slab : r.slab)
      t += fmt::format("| {} | {} | {} | {} | {} | {:.1f} | {:.4f} | {:.4f} / {:.4f} | {:+.2f} % | {:.2f} % | {:.4g}, "
                       "{:.4g} |\n",
                       r.index, slab.refine, slab.dofs, slab.layers, slab.newton_iterations, slab.wall_s,
                       slab.approach_factor, slab.centre_of_pressure, r.locus.centre_of_pressure,
                       100 * r.slab_peak_difference(slab), 100 * r.slab_slice_difference(slab),
                       slab.end_peak_pressure_pa[0] / 1e6, slab.end_peak_pressure_pa[1] / 1e6);
  return t;
}

nlohmann::json run_fem_sds(const io::Parameters& params)
{
  const study::loop_scores::FemSdsResult result = study::loop_scores::run_fem_sds(MPI_COMM_WORLD, fem_sds_schema().bind(params));
  const nlohmann::json j = to_json(result);
  std::string table = markdown_table(result.orientations);
  if (result.slab_checked > 0)
    table += "\n3D slab of the whole ruling against the slices (fem/scenes/slab_contact.h; square end faces; README "
             "\"Creases\"):\n\n"
             + slab_table(result.orientations);
  if (process_rank() != 0)
    return j;
  // Tables go to the log (stderr), so that `--json -` stays JSON alone.
  spdlog::info("\nfem-sds {} ({}):\n\n{}\nover the {} samples of the loop: point-Hertz SDS (the preprint's) {}, "
               "line-Hertz SDS {}, FEM-SDS {} ({}; {} FEM solves, K-to-2K change {}); table against direct FEM at "
               "the orientations above: {:.3f} %\n\n",
               result.body, result.source, table, result.loop.samples, j["analytic_sds"].dump(),
               j["line_hertz_sds"].dump(), j["fem_sds"].dump(), j["fem_sds_status"].get<std::string>(),
               result.loop.fem_solves, j["fem_sds_table_change"].dump(), 100 * result.table_vs_direct_worst);
  if (const std::string& out = params.text("out"); !out.empty())
    io::draw_folder(out, params.text("python"), io::default_scripts_folder() / "plot_fem_orientations.py", {},
                    "plot.log", [&](const std::filesystem::path& folder) {
                      std::ofstream(folder / "fem_sds.json") << j.dump(1) << "\n";
                      std::ofstream(folder / "table.md") << table;
                    });
  return j;
}
} // namespace

void add_fem_sds_command(CLI::App& app)
{
  add_scene_command(app, "fem-sds",
                    "SDS over every sample of a rolling loop under FEM contact stress (plane-strain slices along the "
                    "contact ruling through their exact scaling, a converged table of FEM solves), beside the "
                    "preprint's point-Hertz SDS and line-contact Hertz; orientations solved directly check it",
                    fem_sds_schema().schema(), run_fem_sds);
}
} // namespace rollcheck::cli
