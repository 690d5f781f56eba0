// `rollcheck whole-body`: issue 14's fuller check at small scale
// (study/whole_body/whole_body_check.h): one orientation of the body meshed whole and
// pressed on the rigid plane in 3D, against the plane-strain slices along
// the ruling and the end models at its loaded ends; PASS, SINGULAR ENDS
// (every comparison with a value within the tolerance, 3 %, an end singular)
// or FAIL. Also the scene "whole-body" of case files. Exit 0 when
// the check ran (its verdict is in the output), 1 when a solve failed.
#include "cli/cli.h"
#include "cli/scenes.h"
#include "fem/petsc_session.h"
#include "study/whole_body/whole_body_check.h"
#include <mpi.h>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
namespace
{
using study::whole_body::WholeBodyCheckSettings;
using WholeBodySchema = io::BoundSchema<WholeBodyCheckSettings>;

/// F, and the whole body's mesh: its strip along the ruling, its section and
/// layers, its penalty.
void add_whole_body_options(WholeBodySchema& s)
{
  s.real("normal_load_n", "--load", &WholeBodyCheckSettings::normal_load_n, "N",
         "Force F pressing the body onto the rigid plane along the vertical through its centre of mass (the "
         "preprint's 100 N)",
         io::positive)
      .integer("contact_elements", "--contact-elements", &WholeBodyCheckSettings::contact_elements, "",
               "Whole body: elements across the contact half-width b in the strip along the ruling",
               io::Bounds{2, 40})
      .real("strip_over_half_width", "--strip", &WholeBodyCheckSettings::strip_over_half_width, "",
            "Whole body: half-width of the fine strip along the ruling, in units of b", io::Bounds{1, 20})
      .real("section_growth", "--section-growth", &WholeBodyCheckSettings::section_growth, "",
            "Whole body: element size per distance beyond the strip, in the section across the ruling",
            io::Bounds{0.05, 1})
      .real("layer_growth", "--layer-growth", &WholeBodyCheckSettings::layer_growth, "",
            "Whole body: thickness ratio of neighbouring layers along the ruling, from the ends to the middle",
            io::Bounds{1, 3})
      .integer("layers_across_length", "--layers", &WholeBodyCheckSettings::layers_across_length, "",
               "Whole body: the thickest layer (in the middle of the ruling) is L / this", io::Bounds{2, 10000})
      .real("penalty_c", "--penalty-c", &WholeBodyCheckSettings::penalty_c, "",
            "Whole body: penalty kappa = c E / h_c, h_c the strip's element size (the slices' 100)", io::positive);
}

/// The reduced models it is compared with: the slices, the rule that shares F
/// along the ruling, and the end models.
void add_reduced_model_options(WholeBodySchema& s)
{
  s.integer("stations", "--stations", &WholeBodyCheckSettings::stations, "",
            "Plane-strain slices along the loaded ruling, compared with the whole body's peak there",
            io::Bounds{2, 200})
      .choice("share_rule", "--share-rule", &WholeBodyCheckSettings::share_rule,
              "How the slices and end models share F along the ruling: locus (the contact locus's no-tension "
              "linear rule, fem-sds's), sections (each section across the ruling in plane strain under one "
              "rigid approach and tilt of the held cut, balanced for F and its moment; both ends loaded) or "
              "coarse-body (the whole body meshed coarsely, its line load on each node plane). Under sections "
              "and coarse-body an end model is matched to the rule near the edge (--end-match)",
              {{"locus", study::whole_body::ShareRule::locus},
               {"sections", study::whole_body::ShareRule::sections},
               {"coarse-body", study::whole_body::ShareRule::coarse_body}})
      .former("load_rule")
      .integer("rule_stations", "--rule-stations", &WholeBodyCheckSettings::rule_stations, "",
               "Sections of the sections' share rule (midpoint rule along the ruling)", io::Bounds{4, 200})
      .integer("rule_contact_elements", "--rule-contact-elements",
               &WholeBodyCheckSettings::rule_contact_elements, "",
               "The coarse-body load rule's elements across b (the whole body's: --contact-elements)",
               io::Bounds{2, 40})
      .real("rule_end_layer", "--rule-end-layer", &WholeBodyCheckSettings::rule_end_layer, "",
            "The coarse-body load rule's end layers, h / b (the whole body's: --body-end-layer)",
            io::Bounds{0, 1, true, false})
      .real("end_match_over_half_width", "--end-match", &WholeBodyCheckSettings::end_match_over_half_width, "",
            "Under the sections and coarse-body rules: the end models are matched to the rule this many b (the "
            "locus's at the end) from the edge, their reading over their own pressure there times the slice at "
            "the rule's q there",
            io::Bounds{1, 100})
      .real("end_margin", "--end-margin", &WholeBodyCheckSettings::end_margin, "",
            "Fraction of the ruling kept clear inside each loaded end for the stations (fem-sds's 5 %)",
            io::Bounds{0, 0.25, true, true})
      .former("crease_margin")
      .integer("slice_refine", "--refine", &WholeBodyCheckSettings::slice_refine, "",
               "The slices' mesh level (-1: the plane-strain default)", io::Bounds{-1, 8})
      .choice("end_depth", "--end-depth", &WholeBodyCheckSettings::end_depth,
              "The end models' block: body (as deep as the whole body's held section, the cut through its centre "
              "of mass; square ends on rim's structured grid, MUMPS LU) or local (rim's default 10 b, which "
              "overstates a deep body's square end by about 10 %)",
              {{"body", study::whole_body::EndModelDepth::body}, {"local", study::whole_body::EndModelDepth::local}})
      .integer("end_levels", "--end-levels", &WholeBodyCheckSettings::end_levels, "",
               "The end models' edge mesh levels (rollcheck rim --levels)", io::Bounds{1, 6})
      .real("end_edge_element", "--end-edge-element", &WholeBodyCheckSettings::end_edge_element, "",
            "The end models' first edge element h_e / b (rollcheck rim --edge-element); each level halves it",
            io::Bounds{1e-3, 1, false, true})
      .integer("end_contact_elements", "--end-contact-elements", &WholeBodyCheckSettings::end_contact_elements, "",
               "The end models' elements per b along the edge and the strip (rollcheck rim --contact-elements)",
               io::Bounds{2, 40});
}

const SceneSchema<WholeBodyCheckSettings>& whole_body_schema()
{
  return kept_schema<WholeBodyCheckSettings>("whole-body",
                                             "Issue 14's whole-body check: one orientation of the body (r1 = 10 mm) "
                                             "meshed whole (gmsh OpenCASCADE, layers along the ruling) and pressed on "
                                             "the rigid plane in 3D under F through its centre of mass, against the "
                                             "plane-strain slices along the ruling and the end models (rollcheck rim) "
                                             "at its loaded ends; PASS, SINGULAR ENDS (every comparison that has a "
                                             "value within --tolerance, a sharp obtuse end singular: no value to "
                                             "compare) or FAIL",
                                             [](WholeBodySchema& s) {
    s.include(line_contact_body_schema(), &WholeBodyCheckSettings::body)
        .real("direction_deg", "--direction", &WholeBodyCheckSettings::direction_deg, "deg",
              "The orientation: the ground's normal (body frame) nearest to (cos a, sin a, 0) on the body's contact "
              "curve; the cylinder's axis is the body's z, so every a is a generator",
              io::Bounds{-360, 360})
        .real("scan_step_deg", "--scan-directions", &WholeBodyCheckSettings::scan_step_deg, "deg",
              "Above 0: solve nothing; list the orientations of the directions 0, step, ... below 360 deg (the "
              "locus's c and loaded part, R, interior angle, q and b at each end, the wedge exponent at a loaded "
              "obtuse end), to choose --direction from",
              io::scan_step_deg);
    add_material(s, &WholeBodyCheckSettings::youngs_modulus_pa, &WholeBodyCheckSettings::poisson_ratio);
    add_whole_body_options(s);
    add_reduced_model_options(s);
    s.real("body_end_layer", "--body-end-layer", &WholeBodyCheckSettings::body_end_layer, "",
           "Whole body: thickness of its end layers (and of its section's elements near the contact line at the "
           "ends), h / b",
           io::Bounds{1e-3, 1, false, true})
        .flag("end_layers_only", "--end-layers-only", &WholeBodyCheckSettings::end_layers_only,
              "Whole body: do not refine the section near the contact line to the end layers' size (by default the "
              "elements at the ends are as small across and in depth as along the ruling, as the end model's "
              "isotropic edge elements); only the end layers are then thin and the edge pressure is a number of "
              "the mesh")
        .real("end_zone_over_half_width", "--end-zone", &WholeBodyCheckSettings::end_zone_over_half_width, "",
              "Whole body: radius of that refinement about the contact line, in units of b", io::Bounds{0, 20, false, true})
        .real("tolerance", "--tolerance", &WholeBodyCheckSettings::tolerance, "",
              "Largest relative difference of the whole body's pressure from the reduced models' that passes "
              "(issue 14: 3 %)",
              io::Bounds{0, 1, true, true});
  });
}

nlohmann::json run_whole_body(const io::Parameters& p)
{
  namespace wing = study::whole_body;
  const wing::WholeBodyCheckSettings settings = whole_body_schema().bind(p);
  if (settings.scan_step_deg > 0)
  {
    const auto scan = wing::scan_whole_body_orientations(settings, settings.scan_step_deg);
    print_summary(wing::scan_report(settings, scan));
    return wing::scan_json(settings, scan);
  }
  const wing::WholeBodyCheck check = wing::run_whole_body_check(MPI_COMM_WORLD, settings);
  print_summary(wing::report(check));
  return to_json(check);
}
} // namespace

void add_whole_body_command(CLI::App& app)
{
  CLI::App* sub = add_scene_command(app, whole_body_schema(), run_whole_body);
  // The option's former name, refused as the case key's is (io::BoundSchema::former):
  // elsewhere --load-rule is the load each ruling carries, another quantity.
  sub->add_option_function<std::string>("--load-rule", [](const std::string&) {
       // A parse error: exit 2 with the message, as for any refused option.
       throw CLI::ValidationError("whole-body: --load-rule is now --share-rule (how the reduced models share F "
                                  "along the ruling; --load-rule of oracle and fem-sds is the load each ruling "
                                  "carries)");
     })->group("");
}
} // namespace rollcheck::cli
