// `rollcheck fem-sds`: FEM contact stress at orientations sampled from an
// oracle run, against the preprint's analytic SDS (README "FEM contact stress
// at sampled orientations"). Also the scene "fem-sds" of case files.
//
// Per orientation: the contact locus (contact/contact_locus.h), the
// preprint's point-Hertz peak over the faces its oracle counts, the
// line-contact Hertz slices, and the plane-strain FEM of the slices at two
// refinement levels (fem/slice_contact.h), away from the creases the contact
// reaches. Over the orientations: the SDS template (oracle/distribution_score.h)
// applied to the preprint's face pressures, to the line-Hertz and to the FEM
// peak pressures mapped back onto the faces along each ruling.
#include "cli/body_from_parameters.h"
#include "cli/cli.h"
#include "cli/scenes.h"
#include "contact/contact_locus.h"
#include "contact/rim_overhang.h"
#include "contact/face_curvature.h"
#include "contact/face_pressure.h"
#include "contact/hertz.h"
#include "fem/all_gather.h"
#include "fem/slab_contact.h"
#include "fem/slice_contact.h"
#include "core/atomic_file.h"
#include "geometry/body.h"
#include "core/error.h"
#include "io/batch_report.h"
#include "io/search_store.h"
#include "oracle/distribution_score.h"
#include "oracle/rigid_body_oracle.h"
#include "oracle/rolling_body.h"
#include "oracle/rolling_study.h"
#include "oracle/stratified_samples.h"
#include <algorithm>
#include <chrono>
#include <map>
#include <fmt/format.h>
#include <fstream>
#include <mpi.h>
#include <numbers>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
namespace
{
const io::Schema& fem_sds_schema()
{
  static const io::Schema schema = [] {
    const contact::HertzParameters hertz;
    const fem::SliceSettings slice;
    const contact::LocusOptions locus;
    io::Schema s{"fem-sds", body_parameters()};
    const std::vector<io::Parameter> own = {
        {"oracle", "--oracle", std::string("rolling"), "",
         "Where the orientations come from: rolling (real rolling without slipping, the body on a ruling at every "
         "instant) or rigid (the preprint's rigid-body oracle, whose orientations mostly stand on a rim point)",
         {"rolling", "rigid"}},
        {"orientations", "--orientations", std::int64_t{12}, "",
         "Orientations K sampled from the oracle run, one per equal stratum of it"},
        {"seed", "--seed", std::int64_t{1}, "", "Seed of the stratified sampling (the same seed, the same picks)"},
        {"barrier_energy_excess", "--energy-excess", 0.1, "",
         "Rolling oracle: initial kinetic energy / potential barrier - 1 (README real-rolling table)"},
        {"runs", "--runs", std::int64_t{3}, "", "Rigid oracle: runs with the reference's initial spins (the preprint: 3)"},
        {"threshold_m", "--threshold", locus.contact_threshold_m, "m",
         "The preprint's contact threshold eps: the faces its SDS counts at an orientation"},
        {"paper_compat", "--paper-compat", false, "",
         "The preprint's face pressures (doubled mean curvature, E / (2 (1 - nu^2)), ground at the lowest centroid) "
         "for the analytic SDS; otherwise every quirk corrected"},
        {"youngs_modulus_pa", "--youngs-modulus", hertz.youngs_modulus_pa, "Pa", "E of the body, steel (the preprint's)"},
        {"poisson_ratio", "--poisson", hertz.poisson_ratio, "", "nu of the body (the preprint's)"},
        {"normal_load_n", "--load", hertz.normal_load_n, "N",
         "Force F pressing the body onto the rigid plane through its centre of mass (the preprint's)"},
        {"fem_slices", "--fem-slices", std::int64_t{9}, "",
         "Plane-strain FEM slices per orientation, evenly spread over the loaded ruling away from its ends"},
        {"crease_margin", "--crease-margin", 0.05, "",
         "Fraction of the ruling kept clear of each end of the loaded contact: the FEM peaks are taken inside, away "
         "from the creases (end effects decay within a few contact widths b, and b / L < 1e-3 here)"},
        {"map_points", "--map-points", std::int64_t{64}, "",
         "Points along each ruling at which the peak pressures are mapped onto the faces (FEM-SDS)"},
        {"refine", "--refine", std::int64_t{slice.refine}, "",
         "Plane-strain mesh level of the slices (hertz --refine); the error estimate runs one level finer"},
        {"penalty_c", "--penalty-c", slice.penalty_c, "", "Penalty kappa = c E / h_c (README: penalty study)"},
        {"slab_orientations", "--slab-check", std::int64_t{0}, "",
         "The first N solved orientations whose b / R varies at most 2-fold along the ruling are also solved as one "
         "3D slab of the whole ruling (fem/slab_contact.h, square end faces) at two section levels: the fuller model the slices must agree with (peak within 2 %), and the pressure at the ruling's "
         "ends; 0: none"},
        {"slab_refine", "--slab-refine", std::int64_t{0}, "",
         "Section level of the 3D slab (elements across the narrowest half-width: 10 * 2^(level / 2)); the second "
         "solve is one level finer"},
        {"elastic_plane", "--elastic-plane", false, "",
         "FEM against the E* of two identical steel bodies (the preprint's) instead of a rigid plane"},
        {"out", "--out", std::string(), "",
         "Folder for fem_sds.json, table.md and the plots (written whole or not at all); empty: none"},
        {"python", "--python", std::string("/usr/bin/python3"), "",
         "Python with matplotlib for the plots (Debian's)"},
    };
    s.parameters.insert(s.parameters.end(), own.begin(), own.end());
    return s;
  }();
  return schema;
}

struct Settings
{
  std::size_t orientations = 12;
  std::uint64_t seed = 1;
  int fem_slices = 9;
  int map_points = 64;
  double crease_margin = 0.05;
  double force_n = 100;
  double effective_modulus_pa = 0; ///< of the FEM and the line-Hertz slices
  contact::HertzParameters hertz;
  oracle::PaperCompat compat;
  contact::LocusOptions locus;
  fem::SliceSettings slice;
  std::size_t slab_orientations = 1;
  fem::SlabSettings slab;
};

std::int64_t bounded(const io::Parameters& p, const std::string& key, std::int64_t lo, std::int64_t hi)
{
  const std::int64_t v = p.integer(key);
  if (v < lo || v > hi)
    throw InputError(fmt::format("{}: must be {} to {}, got {}", key, lo, hi, v));
  return v;
}

double positive(const io::Parameters& p, const std::string& key)
{
  const double v = p.real(key);
  if (!(v > 0) || !std::isfinite(v))
    throw InputError(fmt::format("{}: must be a positive finite number, got {}", key, v));
  return v;
}

Settings settings_from(const io::Parameters& p)
{
  Settings s;
  s.orientations = static_cast<std::size_t>(bounded(p, "orientations", 1, 10000));
  s.seed = static_cast<std::uint64_t>(bounded(p, "seed", 0, std::numeric_limits<std::int64_t>::max()));
  s.fem_slices = static_cast<int>(bounded(p, "fem_slices", 2, 1000));
  s.map_points = static_cast<int>(bounded(p, "map_points", 2, 100000));
  s.crease_margin = p.real("crease_margin");
  if (!(s.crease_margin > 0 && s.crease_margin < 0.25))
    throw InputError(fmt::format("crease_margin: must lie in (0, 0.25), got {}", s.crease_margin));
  s.force_n = positive(p, "normal_load_n");
  s.hertz.youngs_modulus_pa = positive(p, "youngs_modulus_pa");
  s.hertz.poisson_ratio = p.real("poisson_ratio");
  if (!(s.hertz.poisson_ratio >= 0 && s.hertz.poisson_ratio < 0.5))
    throw InputError(fmt::format("poisson_ratio: must lie in [0, 0.5), got {}", s.hertz.poisson_ratio));
  s.hertz.normal_load_n = s.force_n;
  s.compat = p.flag("paper_compat") ? oracle::PaperCompat::reference() : oracle::PaperCompat::corrected();
  s.locus.contact_threshold_m = p.real("threshold_m");
  if (!(s.locus.contact_threshold_m >= 0) || !std::isfinite(s.locus.contact_threshold_m))
    throw InputError(fmt::format("threshold_m: must be >= 0, got {}", s.locus.contact_threshold_m));
  s.locus.ground_at_lowest_centroid = s.compat.ground_at_lowest_centroid;
  s.slice.youngs_modulus_pa = s.hertz.youngs_modulus_pa;
  s.slice.poisson_ratio = s.hertz.poisson_ratio;
  s.slice.refine = static_cast<int>(bounded(p, "refine", -1, 12));
  s.slice.penalty_c = positive(p, "penalty_c");
  s.slice.elastic_plane = p.flag("elastic_plane");
  s.slab_orientations = static_cast<std::size_t>(bounded(p, "slab_orientations", 0, 10000));
  s.slab.youngs_modulus_pa = s.slice.youngs_modulus_pa;
  s.slab.poisson_ratio = s.slice.poisson_ratio;
  s.slab.penalty_c = s.slice.penalty_c;
  s.slab.elastic_plane = s.slice.elastic_plane;
  s.slab.refine = static_cast<int>(bounded(p, "slab_refine", 0, 8));
  s.effective_modulus_pa
      = contact::effective_modulus(s.hertz.youngs_modulus_pa, s.hertz.poisson_ratio, s.slice.elastic_plane);
  return s;
}

/// The sampled orientations of an oracle run, with the body's circles and centre of mass.
struct OrientationSource
{
  std::vector<oracle::Circle> circles;
  Eigen::Vector3d centre_of_mass_m;
  std::vector<Eigen::Matrix3d> rotations;
  std::vector<double> times_s;
  std::vector<std::vector<int>> oracle_faces; ///< rigid oracle: its own counts; rolling: empty
  std::string description;
};

OrientationSource rolling_source(const geometry::BodySpec& spec, const io::Parameters& p)
{
  oracle::RollingStudyParameters rp;
  rp.barrier_energy_excess = p.real("barrier_energy_excess");
  const oracle::RealRolling run = oracle::real_rolling(spec, rp);
  OrientationSource source{run.circles, run.mass.centre_of_mass_m, {}, {}, {}, ""};
  for (const oracle::RollingSample& s : run.trajectory.samples)
    if (s.time_s <= run.scored_end_s)
    {
      source.rotations.push_back(s.rotation);
      source.times_s.push_back(s.time_s);
    }
  source.description = fmt::format("real rolling, one loop of {:.4g} s, {} samples{}", run.scored_end_s,
                                   source.rotations.size(), run.trajectory.contact_held ? "" : " (a rim lifted)");
  return source;
}

OrientationSource rigid_source(const geometry::BodySpec& spec, const oracle::RollingBody& body, const Settings& s,
                               const io::Parameters& p)
{
  oracle::RigidBodyOptions options;
  options.contact_threshold_m = s.locus.contact_threshold_m;
  const auto runs = static_cast<std::size_t>(bounded(p, "runs", 1, 5));
  const auto& spins = oracle::reference_initial_spins();
  options.initial_spins.assign(spins.begin(), spins.begin() + static_cast<long>(runs));
  const oracle::Trajectory t = oracle::rigid_body_oracle(body, options, s.compat);
  OrientationSource source{oracle::line_contact_circles(spec), body.mass.centre_of_mass, {}, {}, {}, ""};
  const double sample_dt = options.time_step_s * static_cast<double>(options.sample_every);
  std::vector<int> per_run(runs, 0);
  for (std::size_t k = 0; k < t.size(); ++k)
  {
    source.rotations.push_back(t.samples[k].rotation);
    source.times_s.push_back(sample_dt * per_run[static_cast<std::size_t>(t.samples[k].run)]++);
    source.oracle_faces.emplace_back(t.contacts_begin(k), t.contacts_end(k));
  }
  source.description = fmt::format("the preprint's rigid-body oracle, {} runs, {} samples", runs, t.size());
  return source;
}

/// Linear interpolation of `values` given at increasing `at`, held constant
/// beyond the first and last.
double interpolate(std::span<const double> at, std::span<const double> values, double x)
{
  if (x <= at.front())
    return values.front();
  if (x >= at.back())
    return values.back();
  const auto upper = std::upper_bound(at.begin(), at.end(), x) - at.begin();
  const double t = (x - at[upper - 1]) / (at[upper] - at[upper - 1]);
  return (1 - t) * values[upper - 1] + t * values[upper];
}

struct OrientationResult
{
  contact::ContactLocus locus;
  double point_hertz_peak_pa = 0;          ///< the preprint's: largest p_f over its faces
  bool solved = false;                     ///< a ruling in equilibrium: slices solved
  std::vector<fem::SliceFem> slices;
  double fem_peak_pa = 0, fem_peak_refined_pa = 0, line_hertz_peak_pa = 0;
  double line_hertz_end_peak_pa = 0;       ///< slice formula at the loaded ends (the crease's nominal value)
  double contact_length_m = 0, contact_width_m = 0;
  std::int64_t dofs = 0;
  int newton_iterations = 0, krylov_iterations = 0;
  double wall_s = 0;
  std::vector<std::pair<int, double>> fem_faces, line_faces; ///< (face, peak) along the ruling
  std::vector<fem::SlabFem> slab;          ///< the 3D check at two section levels, if run
  /// Lean of the body's rims at the ruling's start and end (contact/rim_overhang.h):
  /// > 0 an obtuse edge, singular against the rigid plane where loaded.
  std::array<double, 2> rim_overhang_rad{};
  int obtuse_loaded_rims() const
  {
    return (locus.loaded_from == 0 && rim_overhang_rad[0] > 0) + (locus.loaded_to == 1 && rim_overhang_rad[1] > 0);
  }
  /// The slab's peak over the slices' positions against the slices' peak,
  /// minus 1: the orientation's peak under the fuller model.
  double slab_peak_difference(const fem::SlabFem& level) const
  {
    const auto& p = level.slice_peak_pressure_pa;
    return *std::max_element(p.begin(), p.end()) / fem_peak_pa - 1;
  }
  /// Largest |slab / slice - 1| over the loaded slices: the outermost show
  /// the free end's compliance that plane strain leaves out.
  double slab_slice_difference(const fem::SlabFem& level) const
  {
    double worst = 0;
    for (std::size_t i = 0; i < slices.size(); ++i)
      if (slices[i].peak_pressure_pa > 0)
        worst = std::max(worst, std::abs(level.slice_peak_pressure_pa[i] / slices[i].peak_pressure_pa - 1));
    return worst;
  }
};

/// The fuller model of a solved orientation: its whole ruling as one 3D slab
/// under the slices' approaches, at the slab level and one finer. Its end
/// faces are square: leaning them as the rims do (SlabBody::end_overhang_rad)
/// shears the whole slab, and that moved the oloid's peak by +3.7 % against
/// the slices (README "Creases"), so the rims' lean is reported, not modelled.
void check_with_slab(OrientationResult& r, const Settings& s)
{
  const oracle::Ruling& ruling = *r.locus.ruling;
  for (const int level : {s.slab.refine, s.slab.refine + 1})
  {
    fem::SlabSettings settings = s.slab;
    settings.refine = level;
    r.slab.push_back(fem::solve_slab(
        MPI_COMM_WORLD, {ruling.length_m, ruling.start_radius_m, ruling.end_radius_m, s.force_n, {0.0, 0.0}}, r.slices,
        settings));
  }
}

OrientationResult evaluate_orientation(const OrientationSource& source, std::size_t pick, const Settings& s,
                                       const oracle::RollingBody& body, const contact::FacePressure& pressure,
                                       const oracle::FaceCones& cones)
{
  OrientationResult r;
  const std::vector<int>* counted = source.oracle_faces.empty() ? nullptr : &source.oracle_faces[pick];
  r.locus = contact::contact_locus(source.circles, source.centre_of_mass_m, body, source.rotations[pick], s.locus,
                                   counted);
  r.locus.sample = pick;
  r.locus.time_s = source.times_s[pick];
  for (const int f : r.locus.oracle_faces)
    r.point_hertz_peak_pa = std::max(r.point_hertz_peak_pa, pressure.peak_pressure_pa[f]);
  if (!r.locus.ruling || !r.locus.in_equilibrium)
    return r;
  r.solved = true;
  const oracle::Ruling& ruling = *r.locus.ruling;
  r.rim_overhang_rad = contact::rim_overhang(source.circles, r.locus.support.circles[0], r.locus.support.circles[1], ruling);
  const double c = r.locus.centre_of_pressure, L = ruling.length_m;
  auto radius_at = [&](double f) { return (1 - f) * ruling.start_radius_m + f * ruling.end_radius_m; };
  auto hertz_at = [&](double f) {
    const double q = oracle::line_load(s.force_n, c, L, f);
    return q > 0 ? std::sqrt(q * s.effective_modulus_pa / (std::numbers::pi * radius_at(f))) : 0.0;
  };
  const double lo = r.locus.loaded_from + s.crease_margin, hi = r.locus.loaded_to - s.crease_margin;
  std::vector<double> fractions(static_cast<std::size_t>(s.fem_slices));
  std::vector<fem::SliceLoad> loads;
  for (int k = 0; k < s.fem_slices; ++k)
  {
    const double f = lo + (hi - lo) * k / (s.fem_slices - 1);
    fractions[static_cast<std::size_t>(k)] = f;
    loads.push_back({f * L, radius_at(f), oracle::line_load(s.force_n, c, L, f)});
  }
  const auto start = std::chrono::steady_clock::now();
  r.slices = fem::solve_slices(MPI_COMM_WORLD, loads, s.slice);
  r.wall_s = fem::wall_seconds_since(MPI_COMM_WORLD, start);
  std::vector<double> fem_values, line_values;
  for (const fem::SliceFem& slice : r.slices)
  {
    r.fem_peak_pa = std::max(r.fem_peak_pa, slice.peak_pressure_pa);
    r.fem_peak_refined_pa = std::max(r.fem_peak_refined_pa, slice.refined_peak_pressure_pa);
    r.line_hertz_peak_pa = std::max(r.line_hertz_peak_pa, slice.hertz_peak_pressure_pa);
    r.contact_width_m = std::max(r.contact_width_m, 2 * slice.half_width_m);
    r.dofs += slice.dofs;
    r.newton_iterations += slice.newton_iterations;
    r.krylov_iterations += slice.krylov_iterations;
    fem_values.push_back(slice.peak_pressure_pa);
    line_values.push_back(slice.hertz_peak_pressure_pa);
  }
  for (const double end : {r.locus.loaded_from, r.locus.loaded_to})
    r.line_hertz_end_peak_pa = std::max(r.line_hertz_end_peak_pa, hertz_at(end));
  r.contact_length_m = (r.locus.loaded_to - r.locus.loaded_from) * L;

  // Onto the faces: the peak pressure at points along the loaded ruling, held
  // at the outermost slices' values over the crease margins.
  std::vector<double> along;
  for (int k = 0; k < s.map_points; ++k)
    along.push_back(r.locus.loaded_from + (r.locus.loaded_to - r.locus.loaded_from) * (k + 0.5) / s.map_points);
  const std::vector<int> faces = contact::faces_along_ruling(cones, r.locus, along);
  auto collect = [&](const std::vector<double>& values, std::vector<std::pair<int, double>>& out) {
    std::map<int, double> peak;
    for (std::size_t k = 0; k < along.size(); ++k)
      peak[faces[k]] = std::max(peak[faces[k]], interpolate(fractions, values, along[k]));
    out.assign(peak.begin(), peak.end());
  };
  collect(fem_values, r.fem_faces);
  collect(line_values, r.line_faces);
  return r;
}

nlohmann::json number(double v) { return io::json_number(v); }

const char* support_name(oracle::CircleSupportKind kind)
{
  static const char* names[] = {"point", "segment", "polygon", "disc"};
  return names[static_cast<int>(kind)];
}

nlohmann::json orientation_json(const OrientationResult& r, std::size_t index)
{
  const contact::ContactLocus& l = r.locus;
  nlohmann::json j = {{"index", index},
                      {"sample", l.sample},
                      {"time_s", number(l.time_s)},
                      {"support", support_name(l.support.kind)},
                      {"creases", l.creases},
                      {"reaches_crease", !l.creases.empty()},
                      {"oracle_faces", l.oracle_faces.size()},
                      {"point_hertz_peak_pa", number(r.point_hertz_peak_pa)},
                      {"fem_solved", r.solved}};
  if (l.ruling)
  {
    j["ruling_length_m"] = number(l.ruling->length_m);
    j["start_radius_m"] = number(l.ruling->start_radius_m);
    j["end_radius_m"] = number(l.ruling->end_radius_m);
    j["centre_of_pressure"] = number(l.centre_of_pressure);
    j["in_equilibrium"] = l.in_equilibrium;
  }
  if (!r.solved)
    return j;
  j["loaded_from"] = number(l.loaded_from);
  j["loaded_to"] = number(l.loaded_to);
  j["rim_overhang_deg"] = {number(r.rim_overhang_rad[0] * 180 / std::numbers::pi),
                           number(r.rim_overhang_rad[1] * 180 / std::numbers::pi)};
  j["obtuse_loaded_rims"] = r.obtuse_loaded_rims();
  j["fem_peak_pa"] = number(r.fem_peak_pa);
  j["fem_peak_refined_pa"] = number(r.fem_peak_refined_pa);
  j["fem_peak_refinement_change"] = number(r.fem_peak_refined_pa / r.fem_peak_pa - 1);
  j["line_hertz_peak_pa"] = number(r.line_hertz_peak_pa);
  j["fem_vs_line_hertz"] = number(r.fem_peak_pa / r.line_hertz_peak_pa - 1);
  j["line_hertz_end_peak_pa"] = number(r.line_hertz_end_peak_pa);
  j["contact_length_m"] = number(r.contact_length_m);
  j["contact_width_m"] = number(r.contact_width_m);
  j["dofs"] = r.dofs;
  j["newton_iterations"] = r.newton_iterations;
  j["krylov_iterations"] = r.krylov_iterations;
  j["wall_s"] = number(r.wall_s);
  nlohmann::json slices = nlohmann::json::array();
  for (const fem::SliceFem& s : r.slices)
    slices.push_back({{"position_m", number(s.load.position_m)},
                      {"radius_m", number(s.load.radius_m)},
                      {"load_n_per_m", number(s.load.load_n_per_m)},
                      {"fem_peak_pa", number(s.peak_pressure_pa)},
                      {"fem_peak_refined_pa", number(s.refined_peak_pressure_pa)},
                      {"fem_half_width_m", number(s.half_width_m)},
                      {"line_hertz_peak_pa", number(s.hertz_peak_pressure_pa)},
                      {"line_hertz_half_width_m", number(s.hertz_half_width_m)},
                      {"dofs", s.dofs},
                      {"refined_dofs", s.refined_dofs}});
  j["slices"] = slices;
  auto faces_json = [](const std::vector<std::pair<int, double>>& faces) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& [f, p] : faces)
      a.push_back({f, number(p)});
    return a;
  };
  j["fem_faces"] = faces_json(r.fem_faces);
  if (!r.slab.empty())
  {
    nlohmann::json levels = nlohmann::json::array();
    for (const fem::SlabFem& slab : r.slab)
    {
      nlohmann::json peaks = nlohmann::json::array(), planes = nlohmann::json::array();
      for (double p : slab.slice_peak_pressure_pa)
        peaks.push_back(number(p));
      for (std::size_t k = 0; k < slab.plane_position_m.size(); ++k)
        planes.push_back({number(slab.plane_position_m[k]), number(slab.plane_peak_pressure_pa[k])});
      levels.push_back({{"refine", slab.refine},
                        {"dofs", slab.dofs},
                        {"layers", slab.layers},
                        {"end_layer_m", number(slab.end_layer_m)},
                        {"newton_iterations", slab.newton_iterations},
                        {"krylov_iterations", slab.krylov_iterations},
                        {"wall_s", number(slab.wall_s)},
                        {"approach_factor", number(slab.approach_factor)},
                        {"force_n", number(slab.force_n)},
                        {"centre_of_pressure", number(slab.centre_of_pressure)},
                        {"slice_peak_pa", peaks},
                        {"peak_difference_vs_slices", number(r.slab_peak_difference(slab))},
                        {"max_slice_difference", number(r.slab_slice_difference(slab))},
                        {"end_peak_pa", {number(slab.end_peak_pressure_pa[0]), number(slab.end_peak_pressure_pa[1])}},
                        {"plane_peaks", planes}});
    }
    j["slab"] = levels;
    j["slab_end_faces"] = "square";
  }
  return j;
}

std::string markdown_table(const std::vector<OrientationResult>& results)
{
  std::string t = "| # | t (s) | support | c | creases | point-Hertz p0 (MPa) | line-Hertz p0 (MPa) | FEM p0 (MPa) | "
                  "FEM finer (MPa) | change | FEM / line - 1 | length (m) | width (um) | DOFs | Newton | s |\n"
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < results.size(); ++i)
  {
    const OrientationResult& r = results[i];
      t += fmt::format("| {} | {:.4g} | {} | {} | {} | {:.4g} |", i, r.locus.time_s,
                     support_name(r.locus.support.kind),
                     r.locus.ruling ? fmt::format("{:.3f}", r.locus.centre_of_pressure) : std::string("-"),
                     r.locus.creases.size(), r.point_hertz_peak_pa / 1e6);
    if (r.solved)
      t += fmt::format(" {:.4g} | {:.4g} | {:.4g} | {:+.2f} % | {:+.2f} % | {:.4g} | {:.3g} | {} | {} | {:.1f} |\n",
                       r.line_hertz_peak_pa / 1e6, r.fem_peak_pa / 1e6, r.fem_peak_refined_pa / 1e6,
                       100 * (r.fem_peak_refined_pa / r.fem_peak_pa - 1), 100 * (r.fem_peak_pa / r.line_hertz_peak_pa - 1),
                       r.contact_length_m, 1e6 * r.contact_width_m, r.dofs, r.newton_iterations, r.wall_s);
    else
      t += " - | - | - | - | - | - | - | - | - | - |\n";
  }
  return t;
}

std::string slab_table(const std::vector<OrientationResult>& results)
{
  std::string t = "| # | level | DOFs | layers | Newton | s | approach factor | c (slab / locus) | slab peak / slices' - 1 "
                  "| max over slices of abs(slab / slice - 1) | end p at s = 0, L (MPa) |\n"
                  "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < results.size(); ++i)
    for (const fem::SlabFem& slab : results[i].slab)
    {
      t += fmt::format("| {} | {} | {} | {} | {} | {:.1f} | {:.4f} | {:.4f} / {:.4f} | {:+.2f} % | {:.2f} % | {:.4g}, {:.4g} |\n",
                       i, slab.refine, slab.dofs, slab.layers, slab.newton_iterations, slab.wall_s,
                       slab.approach_factor, slab.centre_of_pressure, results[i].locus.centre_of_pressure,
                       100 * results[i].slab_peak_difference(slab), 100 * results[i].slab_slice_difference(slab),
                       slab.end_peak_pressure_pa[0] / 1e6, slab.end_peak_pressure_pa[1] / 1e6);
    }
  return t;
}

nlohmann::json run_fem_sds(const io::Parameters& params)
{
  const auto start = std::chrono::steady_clock::now();
  if (!params.text("mesh_file").empty())
    throw InputError(fmt::format("mesh_file '{}': fem-sds needs the exact body (its circles), give --body "
                                 "oloid|paper-oloid|roller|cylinder",
                                 params.text("mesh_file")));
  const geometry::BodySpec spec = body_spec_from_parameters(params);
  if (spec.body != "oloid" && spec.body != "paper-oloid" && spec.body != "roller" && spec.body != "cylinder")
    throw InputError(fmt::format("body '{}': fem-sds covers the hulls of circles (oloid, paper-oloid, roller, "
                                 "cylinder), whose contact is a ruling; a sphere's point contact is `rollcheck hertz`",
                                 spec.body));
  std::string label;
  const geometry::SurfaceMesh mesh = body_from_parameters(params, &label);
  const Settings s = settings_from(params);
  const oracle::RollingBody body = oracle::make_rolling_body(mesh, s.compat);
  const contact::FaceCurvature curvature = contact::face_curvature(mesh, s.hertz, s.compat);
  const contact::FacePressure pressure = contact::face_pressure(curvature.effective_radius_m, s.hertz, s.compat);
  const oracle::FaceCones cones = oracle::face_cones(mesh);
  const bool rolling = params.text("oracle") == "rolling";
  const OrientationSource source = rolling ? rolling_source(spec, params) : rigid_source(spec, body, s, params);
  const std::vector<std::size_t> picks = oracle::stratified_samples(source.rotations.size(), s.orientations, s.seed);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    spdlog::info("fem-sds {}: {}; {} orientations (seed {})", label, source.description, picks.size(), s.seed);

  const auto faces = static_cast<Eigen::Index>(mesh.faces.rows());
  Eigen::VectorXd analytic_all = Eigen::VectorXd::Zero(faces), analytic = analytic_all, line = analytic_all,
                  fem = analytic_all;
  std::vector<OrientationResult> results;
  nlohmann::json per_orientation = nlohmann::json::array();
  std::size_t solved = 0, with_crease = 0, standing_on_crease = 0;
  double worst_change = 0, max_wall = 0, worst_slab = 0;
  std::size_t slab_checked = 0, slab_skipped = 0, with_obtuse_rim = 0;
  for (const std::size_t pick : picks)
  {
    results.push_back(evaluate_orientation(source, pick, s, body, pressure, cones));
    const OrientationResult& r = results.back();
    for (const int f : r.locus.oracle_faces)
    {
      analytic_all[f] += pressure.peak_pressure_pa[f];
      if (r.solved)
        analytic[f] += pressure.peak_pressure_pa[f];
    }
    with_crease += !r.locus.creases.empty();
    if (!r.solved)
    {
      standing_on_crease += !r.locus.ruling;
      if (rank == 0)
        spdlog::warn("orientation {} (t = {:.4g} s): {} - no FEM (a point of an edge or no equilibrium has no "
                     "finite converged peak pressure)",
                     results.size() - 1, r.locus.time_s,
                     r.locus.creases.empty() ? std::string("ruling out of equilibrium") : r.locus.creases.front());
      per_orientation.push_back(orientation_json(r, results.size() - 1));
      continue;
    }
    ++solved;
    with_obtuse_rim += r.obtuse_loaded_rims() > 0;
    if (slab_checked < s.slab_orientations)
    {
      if (fem::slab_feasible(r.slices))
      {
        check_with_slab(results.back(), s);
        for (const fem::SlabFem& slab : r.slab)
          worst_slab = std::max(worst_slab, std::abs(r.slab_peak_difference(slab)));
        ++slab_checked;
      }
      else
      {
        ++slab_skipped;
        if (rank == 0)
          spdlog::info("orientation {}: no slab check (b / R varies more than 2-fold along the ruling)",
                       results.size() - 1);
      }
    }
    for (const auto& [f, p] : r.fem_faces)
      fem[f] += p;
    for (const auto& [f, p] : r.line_faces)
      line[f] += p;
    worst_change = std::max(worst_change, std::abs(r.fem_peak_refined_pa / r.fem_peak_pa - 1));
    max_wall = std::max(max_wall, r.wall_s);
    if (rank == 0)
      spdlog::info("orientation {} (t = {:.4g} s, c = {:.3f}): FEM p0 {:.4g} MPa (finer {:+.2f} %), line-Hertz "
                   "{:.4g} MPa, point-Hertz {:.4g} MPa; {} DOFs, {:.1f} s",
                   results.size() - 1, r.locus.time_s, r.locus.centre_of_pressure, r.fem_peak_pa / 1e6,
                   100 * (r.fem_peak_refined_pa / r.fem_peak_pa - 1), r.line_hertz_peak_pa / 1e6,
                   r.point_hertz_peak_pa / 1e6, r.dofs, r.wall_s);
    per_orientation.push_back(orientation_json(r, results.size() - 1));
  }
  auto score = [&](const Eigen::VectorXd& accumulator) {
    return solved > 0 || accumulator.sum() > 0 ? number(oracle::distribution_score(accumulator, body.face_areas))
                                                : nlohmann::json(nullptr);
  };
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::json j = {
      {"body", label},
      {"oracle", params.text("oracle")},
      {"source", source.description},
      {"orientations", picks.size()},
      {"fem_solved_orientations", solved},
      {"orientations_reaching_crease", with_crease},
      {"orientations_standing_on_crease", standing_on_crease},
      {"orientations_reaching_obtuse_rim", with_obtuse_rim},
      {"analytic_sds", score(analytic)},
      {"analytic_sds_all_orientations", score(analytic_all)},
      {"line_hertz_sds", score(line)},
      {"fem_sds", score(fem)},
      {"fem_peak_worst_refinement_change", number(worst_change)},
      {"max_orientation_wall_s", number(max_wall)},
      {"slab_checked_orientations", slab_checked},
      {"slab_skipped_orientations", slab_skipped},
      {"slab_worst_peak_difference", number(worst_slab)},
      {"effective_modulus_pa", s.effective_modulus_pa},
      {"analytic_effective_modulus_pa", pressure.effective_modulus_pa},
      {"n_faces", faces},
      {"wall_s", number(wall_s)},
      {"per_orientation", per_orientation},
      {"contact_model",
       "developable bodies touch the plane along a ruling: the preprint's point-contact Hertz with R = 1/sqrt(k1 k2) "
       "does not apply there (k1 k2 = 0 on the exact surface); the FEM and line-Hertz columns treat the ruling as "
       "plane-strain slices; peaks are taken away from the ruling's ends, where it meets the body's rims (creases: "
       "singular between two elastic bodies, not plane strain in any case; the 3D slab check shows the end)"}};
  std::string table = markdown_table(results);
  if (slab_checked > 0)
    table += "\n3D slab of the whole ruling against the slices (fem/slab_contact.h; square end faces; README "
             "\"Creases\"):\n\n"
             + slab_table(results);
  // Tables go to the log (stderr), so that `--json -` stays JSON alone.
  if (rank == 0)
    spdlog::info("\nfem-sds {} ({}):\n\n{}\nanalytic SDS {}, line-Hertz SDS {}, FEM-SDS {} over {} solved of {} "
               "orientations; {} reach a crease\n\n",
               label, source.description, table, j["analytic_sds"].dump(), j["line_hertz_sds"].dump(),
               j["fem_sds"].dump(), solved, picks.size(), with_crease);
  if (const std::string& out = params.text("out"); !out.empty() && rank == 0)
    io::draw_folder(out, params.text("python"), io::default_scripts_folder() / "plot_fem_orientations.py",
                    {}, "plot.log", [&](const std::filesystem::path& folder) {
                      std::ofstream(folder / "fem_sds.json") << j.dump(1) << "\n";
                      std::ofstream(folder / "table.md") << table;
                    });
  return j;
}
} // namespace

void add_fem_sds_command(CLI::App& app)
{
  CLI::App* sub = app.add_subcommand(
      "fem-sds", "FEM contact stress at orientations sampled from an oracle run (plane-strain slices along the "
                 "contact ruling, two mesh levels) against the preprint's analytic SDS and line-contact Hertz");
  static std::string json_path;
  add_json_option(sub, json_path);
  static io::SchemaOptions* options = new io::SchemaOptions(sub, fem_sds_schema());
  register_scene({&fem_sds_schema(), run_fem_sds});
  on_run(sub, [] {
    emit_json(json_path, run_fem_sds(options->apply()));
    return 0;
  });
}
} // namespace rollcheck::cli
