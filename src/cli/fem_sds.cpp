// `rollcheck fem-sds`: SDS over a whole rolling loop under FEM contact stress,
// against the preprint's point-Hertz SDS and line-contact Hertz
// (docs/methods/fem-sds.md). Also the scene "fem-sds" of case files.
// The method, its tables and its report are study/loop_scores/fem_sds.h; here
// its parameters, the report in the log, the folder of plots and the JSON.
#include "cli/cli.h"
#include "cli/scenes.h"
#include "io/batch_report.h"
#include "io/surface_vtu.h"
#include "study/loop_scores/fem_sds.h"
#include "core/atomic_file.h"
#include <mpi.h>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
namespace
{
using study::loop_scores::FemSdsSettings;

const SceneSchema<FemSdsSettings>& fem_sds_schema()
{
  return kept_schema<FemSdsSettings>("fem-sds",
                                     "SDS over every sample of a rolling loop under FEM contact stress (plane-strain "
                                     "slices along the contact ruling through their exact scaling, a converged table of "
                                     "FEM solves), beside the preprint's point-Hertz SDS and line-contact Hertz; "
                                     "orientations solved directly check it",
                                     [](auto& s) {
    s.include(line_contact_body_schema(), &FemSdsSettings::body)
        .choice("oracle", "--oracle", &FemSdsSettings::oracle,
                "Where the orientations come from: rolling (real rolling without slipping, the body on a ruling at "
                "every instant) or rigid (the preprint's rigid-body oracle, whose orientations mostly stand on a rim "
                "point)",
                {{"rolling", study::loop_scores::OrientationOracle::rolling}, {"rigid", study::loop_scores::OrientationOracle::rigid}})
        .integer("samples_per_loop", "--samples-per-loop", &FemSdsSettings::samples_per_loop, "",
                 "Samples of the rolling loop (spread evenly in time over its period), every one scored",
                 io::loop_samples)
        .former("samples")
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
        .real("rolling_energy", "--rolling-energy", &FemSdsSettings::rolling_energy, "",
              "Rolling oracle: initial kinetic energy / potential barrier - 1 (docs/results/real-rolling.md#u-against-the-rolling-speed-rollcheck-oracle---oracle-rolling)",
              io::non_negative)
        .former("barrier_energy_excess")
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
        .real("end_margin", "--end-margin", &FemSdsSettings::end_margin, "",
              "Fraction of the ruling kept clear of each end of the loaded contact: the FEM peaks are taken inside, "
              "away from the creases (end effects decay within a few contact widths b, and b / L < 1e-3 here); "
              "the continuum value holds the pressure there too",
              io::Bounds{0, 0.25, true, true})
        .former("crease_margin")
        .choice("load_rule", "--load-rule", &FemSdsSettings::load_rule,
                "The continuum value's load on each ruling: dynamic (the normal force and centre of pressure of the "
                "same rolling motion, scaled to --load), static (--load through the centre of mass) or uniform "
                "(--load / L along the ruling); the template keeps the static load (docs/methods/fem-sds.md)",
                contact::load_rule_names())
        .choice("contact_width", "--contact-width", &FemSdsSettings::contact_width,
                "The continuum value's pass: geometric (each pass adds its peak pressure, as the template's samples "
                "do) or hertz (the pressure-time integral over the Hertz patch)",
                {{"geometric", oracle::ContactWidthModel::rigid}, {"hertz", oracle::ContactWidthModel::hertz}})
        .choice("time_law", "--time-law", &FemSdsSettings::time_law,
                "The continuum value's time law: free (the loop's own rolling) or uniform_rate (the same loop at a "
                "constant rolling rate, the limit of a fast roll; needs --load-rule static or uniform)",
                contact::time_law_names())
        .integer("continuum_pieces", "--continuum-pieces", &FemSdsSettings::continuum_pieces, "",
                 "Gauss pieces along each ruling of the continuum value (its convergence halves them)",
                 io::Bounds{2, 100000})
        .integer("map_points", "--map-points", &FemSdsSettings::map_points, "",
                 "Points along each ruling at which the peak pressures are mapped onto the faces (FEM-SDS)",
                 io::Bounds{2, 100000})
        .integer("refine", "--refine", &FemSdsSettings::refine, "",
                 "Plane-strain mesh level of the slices (hertz --refine); the error estimate runs one level finer",
                 io::Bounds{-1, 12})
        .include(penalty_schema(), &FemSdsSettings::penalty_c)
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
                  "Python with matplotlib for the plots (Debian's)"})
        .unbound({"vtu_file", "--vtu", std::string(), "",
                  "Write the body with its per-face loop sums (point-Hertz, line-Hertz and FEM pressure accumulated "
                  "over the samples, FEM fatigue damage, face areas) as named cell data to this .vtu (ParaView, "
                  "meshio); empty: none",
                  {}, {}, true});
  });
}

/// The loop's per-face sums (every rank's, study/loop_scores/loop_sds.h
/// LoopSamples and LoopSds) on the body's faces as a VTU's cell data
/// (io/surface_vtu.h): the accumulated pressures (Pa) whose spread over the
/// faces the SDS scores, and the FEM's Miner damage FEM-FDS scores.
void write_face_sums(const std::string& path, const FemSdsSettings& settings,
                     const study::loop_scores::FemSdsResult& result)
{
  const study::loop_scores::LoopSamples& samples = result.loop_samples;
  io::write_surface_vtu(path, geometry::make_body(settings.body),
                        {{"face_areas_m2", samples.face_areas},
                         {"accumulated_point_hertz_pressure_pa", samples.point_all},
                         {"accumulated_line_hertz_pressure_pa", samples.line_all},
                         {"accumulated_fem_pressure_pa", result.loop.accumulated_fem_pressure_pa},
                         {"accumulated_fem_fatigue_damage", result.loop.accumulated_fem_fatigue_damage}});
}

nlohmann::json run_fem_sds(const io::Parameters& params)
{
  const study::loop_scores::FemSdsResult result = study::loop_scores::run_fem_sds(MPI_COMM_WORLD, fem_sds_schema().bind(params));
  const nlohmann::json j = to_json(result);
  if (process_rank() != 0)
    return j;
  print_summary(study::loop_scores::report(result));
  if (const std::string& vtu = params.text("vtu_file"); !vtu.empty())
    write_face_sums(vtu, fem_sds_schema().bind(params), result);
  if (const std::string& out = params.text("out"); !out.empty())
    io::draw_folder(out, params.text("python"), io::default_scripts_folder() / "plot_fem_orientations.py", {},
                    "plot.log", [&](const std::filesystem::path& folder) {
                      write_file_atomically(folder / "fem_sds.json", j.dump(1) + "\n");
                      write_file_atomically(folder / "table.md", study::loop_scores::markdown_table(result));
                    });
  return j;
}
} // namespace

void add_fem_sds_command(CLI::App& app)
{
  add_scene_command(app, fem_sds_schema(), run_fem_sds);
  declare_outputs(fem_sds_schema().schema(), {{"out", OutputKind::folder}, {"vtu_file", OutputKind::file}});
}
} // namespace rollcheck::cli
