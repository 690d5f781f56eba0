// FEM-SDS (study/loop_scores/fem_sds.h): the orientation sources, the per-orientation
// FEM against line Hertz, and the scores over the orientations.
#include "study/loop_scores/fem_sds.h"
#include "contact/face_curvature.h"
#include "contact/face_pressure.h"
#include "contact/hertz.h"
#include "contact/load_ratio.h"
#include "contact/rim_overhang.h"
#include "core/error.h"
#include "fem/all_gather.h"
#include "fem/petsc_session.h"
#include "oracle/distribution_score.h"
#include "oracle/rigid_body_oracle.h"
#include "oracle/rolling_body.h"
#include "oracle/rolling_study.h"
#include "oracle/stratified_samples.h"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <numbers>
#include <spdlog/spdlog.h>

namespace rollcheck::study::loop_scores
{
namespace
{
/// The library settings the method's settings stand for.
struct Models
{
  contact::HertzParameters hertz;
  oracle::PaperCompat compat;
  contact::LocusSettings locus;
  fem::SliceSettings slice;
  fem::SlabSettings slab;
  double effective_modulus_pa = 0; ///< of the FEM and the line-Hertz slices
};

Models models_of(const FemSdsSettings& s)
{
  Models m;
  m.hertz.youngs_modulus_pa = s.youngs_modulus_pa;
  m.hertz.poisson_ratio = s.poisson_ratio;
  m.hertz.normal_load_n = s.normal_load_n;
  m.compat = s.paper_compat ? oracle::PaperCompat::reference() : oracle::PaperCompat::corrected();
  m.locus.contact_threshold_m = s.contact_threshold_m;
  m.locus.ground_at_lowest_centroid = m.compat.ground_at_lowest_centroid;
  m.slice.youngs_modulus_pa = s.youngs_modulus_pa;
  m.slice.poisson_ratio = s.poisson_ratio;
  m.slice.refine = s.refine;
  m.slice.penalty_c = s.penalty_c;
  m.slice.elastic_plane = s.elastic_plane;
  m.slab.youngs_modulus_pa = s.youngs_modulus_pa;
  m.slab.poisson_ratio = s.poisson_ratio;
  m.slab.penalty_c = s.penalty_c;
  m.slab.elastic_plane = s.elastic_plane;
  m.slab.refine = s.slab_refine;
  m.effective_modulus_pa = contact::effective_modulus(s.youngs_modulus_pa, s.poisson_ratio, s.elastic_plane);
  return m;
}

/// One loop of real rolling; `uniformity`, if given, gets U of its contact
/// density on `mesh` (oracle/uniformity_score.h).
LoopSource rolling_source(const FemSdsSettings& s, const geometry::SurfaceMesh& mesh, bool& contact_held,
                          std::optional<double>* uniformity, std::optional<oracle::RealRolling>& kept_run)
{
  oracle::RollingStudyParameters rp;
  rp.rolling_energy = s.rolling_energy;
  rp.samples_per_loop = s.samples_per_loop;
  const oracle::RealRolling& run = kept_run.emplace(oracle::real_rolling(s.body, rp));
  LoopSource source{run.circles, run.mass.centre_of_mass_m, {}, {}, {}, ""};
  for (const oracle::RollingSample& sample : run.trajectory.samples)
    if (sample.time_s <= run.scored_end_s)
    {
      source.rotations.push_back(sample.rotation);
      source.times_s.push_back(sample.time_s);
    }
  contact_held = run.trajectory.contact_held;
  source.description
      = contact_held ? fmt::format("real rolling, one loop of {:.4g} s, {} samples", run.scored_end_s,
                                   source.rotations.size())
                     : fmt::format("real rolling: a rim lifts at t = {:.4g} s, after {:.3f} of the loop (the "
                                   "line-contact model stops there); {} samples",
                                   run.scored_end_s, run.loops_completed, source.rotations.size());
  if (uniformity)
    *uniformity = oracle::score_real_rolling(run, mesh, rp).uniformity;
  return source;
}

LoopSource rigid_source(const FemSdsSettings& s, const Models& m, const oracle::RollingBody& body)
{
  oracle::RigidBodySettings options;
  options.contact_threshold_m = m.locus.contact_threshold_m;
  const auto runs = static_cast<std::size_t>(s.runs);
  const auto& spins = oracle::reference_initial_spins();
  options.initial_spins.assign(spins.begin(), spins.begin() + static_cast<long>(runs));
  const oracle::Trajectory t = oracle::rigid_body_oracle(body, options, m.compat);
  LoopSource source{oracle::line_contact_circles(s.body), body.mass.centre_of_mass, {}, {}, {}, ""};
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

/// A body ready to be scored: its mesh, the preprint's per-face pressures, the face cones and the loop.
struct Scene
{
  Models models;
  geometry::SurfaceMesh mesh;
  oracle::RollingBody body;
  contact::FacePressure pressure;
  oracle::FaceCones cones;
  LoopSource source;
  bool contact_held = true;
  std::optional<double> uniformity;
  std::optional<oracle::RealRolling> run; ///< the rolling oracle's
};

/// Without the template or U (`mesh_parts` false) the scene has no mesh,
/// faces or pressures: the loop's samples and its run alone.
Scene make_scene(const FemSdsSettings& s, bool with_uniformity, bool mesh_parts = true)
{
  oracle::require_line_contact(s.body);
  if (s.time_law == contact::TimeLaw::uniform_rate && s.load_rule == contact::LoadRule::dynamic)
    throw InputError("--time-law uniform_rate needs --load-rule static or uniform: the dynamic load is the free motion's, and no "
                     "free motion rolls at a uniform rate");
  Scene scene;
  scene.models = models_of(s);
  const Models& m = scene.models;
  if (mesh_parts || s.oracle != OrientationOracle::rolling)
  {
    scene.mesh = geometry::make_body(s.body);
    scene.body = oracle::make_rolling_body(scene.mesh, m.compat);
    const contact::FaceCurvature curvature = contact::face_curvature(scene.mesh, m.hertz, m.compat);
    scene.pressure = contact::face_pressure(curvature.effective_radius_m, m.hertz, m.compat);
    scene.cones = oracle::face_cones(scene.mesh);
  }
  scene.source = s.oracle == OrientationOracle::rolling
                     ? rolling_source(s, scene.mesh, scene.contact_held, with_uniformity ? &scene.uniformity : nullptr,
                                      scene.run)
                     : rigid_source(s, m, scene.body);
  return scene;
}

/// The continuum value of a whole rolling loop; none otherwise.
std::optional<ContinuumSds> scene_continuum(MPI_Comm comm, const Scene& scene, const FemSdsSettings& s,
                                            fem::SliceScaling& table)
{
  if (!scene.run || !scene.contact_held || !std::isfinite(scene.run->first_loop_end_s))
    return std::nullopt;
  return continuum_sds(comm, *scene.run, continuum_settings(s), table, {s.tolerance, loop_settings(s).max_nodes_per_decade});
}

/// The slices' FEM along the loaded ruling and their peaks, and the line
/// Hertz at its loaded ends.
void solve_slices_along(MPI_Comm comm, FemSdsOrientation& r, const FemSdsSettings& s, const Models& m,
                        std::span<const double> fractions)
{
  const oracle::Ruling& ruling = *r.locus.ruling;
  const double c = r.locus.centre_of_pressure, L = ruling.length_m;
  std::vector<fem::SliceLoad> loads;
  for (const double f : fractions)
    loads.push_back({f * L, (1 - f) * ruling.start_radius_m + f * ruling.end_radius_m,
                     oracle::line_load(s.normal_load_n, c, L, f)});
  const auto start = std::chrono::steady_clock::now();
  r.slices = fem::solve_slices(comm, loads, m.slice);
  r.wall_s = fem::wall_seconds_since(comm, start);
  for (const fem::SliceFem& slice : r.slices)
  {
    r.fem_peak_pa = std::max(r.fem_peak_pa, slice.peak_pressure_pa);
    r.fem_peak_refined_pa = std::max(r.fem_peak_refined_pa, slice.refined_peak_pressure_pa);
    r.line_hertz_peak_pa = std::max(r.line_hertz_peak_pa, slice.hertz_peak_pressure_pa);
    r.contact_width_m = std::max(r.contact_width_m, 2 * slice.half_width_m);
    r.dofs += slice.dofs;
    r.newton_iterations += slice.newton_iterations;
    r.krylov_iterations += slice.krylov_iterations;
  }
  for (const double end : {r.locus.loaded_from, r.locus.loaded_to})
    r.line_hertz_end_peak_pa
        = std::max(r.line_hertz_end_peak_pa, line_hertz_peak(s.normal_load_n, c, ruling, m.effective_modulus_pa, end));
  r.contact_length_m = (r.locus.loaded_to - r.locus.loaded_from) * L;
}

FemSdsOrientation evaluate_orientation(MPI_Comm comm, const LoopSource& source, std::size_t pick,
                                       const FemSdsSettings& s, const Models& m, const oracle::RollingBody& body,
                                       const contact::FacePressure& pressure)
{
  FemSdsOrientation r;
  const std::vector<int>* counted = source.oracle_faces.empty() ? nullptr : &source.oracle_faces[pick];
  r.locus = contact::contact_locus(source.circles, source.centre_of_mass_m, body, source.rotations[pick], m.locus,
                                   counted);
  r.locus.sample = pick;
  r.locus.time_s = source.times_s[pick];
  for (const int f : r.locus.oracle_faces)
    r.point_hertz_peak_pa = std::max(r.point_hertz_peak_pa, pressure.peak_pressure_pa[f]);
  if (!r.locus.ruling || !r.locus.in_equilibrium)
    return r;
  r.solved = true;
  r.rim_overhang_rad = contact::rim_overhang(source.circles, r.locus.support.circles[0], r.locus.support.circles[1],
                                             *r.locus.ruling);
  const std::vector<double> fractions
      = slice_fractions(r.locus.loaded_from, r.locus.loaded_to, s.end_margin, s.fem_slices);
  solve_slices_along(comm, r, s, m, fractions);
  return r;
}

/// Largest |table / direct - 1| of the FEM peaks of a solved orientation's slices.
double table_against_direct(MPI_Comm comm, const FemSdsOrientation& r, fem::SliceScaling& table)
{
  std::vector<double> lambdas;
  for (const fem::SliceFem& slice : r.slices)
    if (slice.peak_pressure_pa > 0)
      lambdas.push_back(contact::load_ratio(slice.load.load_n_per_m, slice.load.radius_m, table.effective_modulus_pa()));
  if (lambdas.empty())
    return 0;
  table.cover(comm, *std::min_element(lambdas.begin(), lambdas.end()),
              *std::max_element(lambdas.begin(), lambdas.end()));
  double worst = 0;
  std::size_t k = 0;
  for (const fem::SliceFem& slice : r.slices)
    if (slice.peak_pressure_pa > 0)
      worst = std::max(worst, std::abs(slice.hertz_peak_pressure_pa * table.ratio(lambdas[k++]) /
                                           slice.peak_pressure_pa - 1));
  return worst;
}

/// The fuller model of a solved orientation: its whole ruling as one 3D slab
/// under the slices' approaches, at the slab level and one finer. Its end
/// faces are square: leaning them as the rims do (SlabBody::end_overhang_rad)
/// shears the whole slab, and that moved the oloid's peak by +3.7 % against
/// the slices (docs/methods/fem-sds.md#creases), so the rims' lean is reported, not modelled.
void check_with_slab(MPI_Comm comm, FemSdsOrientation& r, const FemSdsSettings& s, const Models& m)
{
  const oracle::Ruling& ruling = *r.locus.ruling;
  for (const int level : {m.slab.refine, m.slab.refine + 1})
  {
    fem::SlabSettings settings = m.slab;
    settings.refine = level;
    r.slab.push_back(fem::solve_slab(
        comm, {ruling.length_m, ruling.start_radius_m, ruling.end_radius_m, s.normal_load_n, {0.0, 0.0}}, r.slices,
        settings));
  }
}

/// Rank 0's lines for the loop's scores.
void log_loop(const LoopSds& loop, const std::optional<ContinuumSds>& continuum, const fem::SliceScaling& table)
{
  if (continuum)
    spdlog::info("continuum (exact surface): line-Hertz SDS {:.4g}, FEM-SDS {:.4g} ({:+.3f} % from half the "
                 "resolution, {:+.3f} % from every other node of the FEM table, {} per decade){}",
                 continuum->line_hertz, continuum->fem, 100 * continuum->change(), 100 * continuum->table_change(),
                 continuum->nodes_per_decade, continuum->converged() ? "" : " - NOT CONVERGED");
  auto text = [](const std::optional<double>& v) { return v ? fmt::format("{:.4g}", *v) : std::string("singular"); };
  spdlog::info("loop of {} samples ({} singular): point-Hertz SDS {}, line-Hertz SDS {}, FEM-SDS {}; FEM table {} "
               "solves ({} per decade, {:.1f} s{}), K-to-2K change {:+.3f} %, half-samples change {:+.3f} %{}",
               loop.samples, loop.singular_samples, text(loop.point_hertz.value), text(loop.line_hertz.value),
               text(loop.fem.value), loop.fem_solves, loop.nodes_per_decade, table.wall_s(),
               table.nodes_read() ? fmt::format("; {} of its nodes read from the job's table", table.nodes_read()) : "",
               100 * loop.table_change(), 100 * loop.fem_rulings.sample_change(),
               loop.converged() ? "" : " - NOT CONVERGED");
}

/// Rank 0's line for an orientation just evaluated, the `count`-th solved directly.
void log_orientation(const FemSdsOrientation& r, std::size_t count)
{
  if (!r.solved)
  {
    spdlog::warn("orientation {} of {} (t = {:.4g} s): {} - no FEM (a point of an edge or no equilibrium has no "
                 "finite converged peak pressure)",
                 r.index + 1, count, r.locus.time_s,
                 r.locus.creases.empty() ? std::string("ruling out of equilibrium") : r.locus.creases.front());
    return;
  }
  spdlog::info("orientation {} of {} (t = {:.4g} s, c = {:.3f}): FEM p0 {:.4g} MPa (finer {:+.2f} %), line-Hertz "
               "{:.4g} MPa, point-Hertz {:.4g} MPa; {} DOFs, {:.1f} s",
               r.index + 1, count, r.locus.time_s, r.locus.centre_of_pressure, r.fem_peak_pa / 1e6,
               100 * (r.fem_peak_refined_pa / r.fem_peak_pa - 1), r.line_hertz_peak_pa / 1e6,
               r.point_hertz_peak_pa / 1e6, r.dofs, r.wall_s);
}

/// The slab check of a solved orientation while fewer than
/// slab_orientations were checked, if one slab can resolve its slices.
void slab_check_if_due(MPI_Comm comm, FemSdsResult& result, FemSdsOrientation& r, const FemSdsSettings& s,
                       const Models& m, bool log)
{
  if (result.slab_checked >= s.slab_orientations)
    return;
  if (!fem::slab_feasible(r.slices))
  {
    ++result.slab_skipped;
    if (log)
      spdlog::info("orientation {}: no slab check (b / R varies more than 2-fold along the ruling)", r.index);
    return;
  }
  check_with_slab(comm, r, s, m);
  for (const fem::SlabFem& slab : r.slab)
    result.slab_worst_peak_difference
        = std::max(result.slab_worst_peak_difference, std::abs(r.slab_peak_difference(slab)));
  ++result.slab_checked;
}
} // namespace

int FemSdsOrientation::obtuse_loaded_rims() const
{
  return (locus.loaded_from == 0 && rim_overhang_rad[0] > 0) + (locus.loaded_to == 1 && rim_overhang_rad[1] > 0);
}

double FemSdsOrientation::slab_peak_difference(const fem::SlabFem& level) const
{
  const auto& p = level.slice_peak_pressure_pa;
  return *std::max_element(p.begin(), p.end()) / fem_peak_pa - 1;
}

double FemSdsOrientation::slab_slice_difference(const fem::SlabFem& level) const
{
  double worst = 0;
  for (std::size_t i = 0; i < slices.size(); ++i)
    if (slices[i].peak_pressure_pa > 0)
      worst = std::max(worst, std::abs(level.slice_peak_pressure_pa[i] / slices[i].peak_pressure_pa - 1));
  return worst;
}

const char* oracle_name(OrientationOracle oracle)
{
  return oracle == OrientationOracle::rolling ? "rolling" : "rigid";
}

const char* support_name(oracle::CircleSupportKind kind)
{
  static const char* names[] = {"point", "segment", "polygon", "disc"};
  return names[static_cast<int>(kind)];
}

std::vector<double> slice_fractions(double loaded_from, double loaded_to, double end_margin, int slices)
{
  const double lo = loaded_from + end_margin, hi = loaded_to - end_margin;
  std::vector<double> fractions;
  for (int k = 0; k < slices; ++k)
    fractions.push_back(lo + (hi - lo) * k / (slices - 1));
  return fractions;
}

FemSdsResult run_fem_sds(MPI_Comm comm, const FemSdsSettings& s)
{
  oracle::require_line_contact(s.body);
  fem::SliceScaling table(models_of(s).slice, s.table_nodes_per_decade);
  return run_fem_sds(comm, s, table);
}

FemSdsResult run_fem_sds(MPI_Comm comm, const FemSdsSettings& s, fem::SliceScaling& table)
{
  const auto start = std::chrono::steady_clock::now();
  oracle::require_line_contact(s.body);
  fem::ensure_petsc();
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const Scene scene = make_scene(s, false);
  const Models& m = scene.models;
  const LoopSource& source = scene.source;
  const oracle::RollingBody& body = scene.body;
  const contact::FacePressure& pressure = scene.pressure;
  FemSdsResult result;
  result.body = geometry::body_label(s.body);
  result.oracle = s.oracle;
  result.source = source.description;
  result.contact_held = scene.contact_held;
  result.circles = source.circles;
  result.centre_of_mass_m = source.centre_of_mass_m;
  if (rank == 0)
    spdlog::info("fem-sds {}: {}; every sample scored, {} orientations solved directly (seed {})", result.body,
                 source.description, s.orientations, s.seed);

  const LoopSdsSettings loop = loop_settings(s);
  result.loop_samples = map_loop_samples(comm, source, body, pressure.peak_pressure_pa, scene.cones,
                                         table.effective_modulus_pa(), loop);
  result.loop = loop_sds(comm, result.loop_samples, table, loop);
  result.continuum = scene_continuum(comm, scene, s, table);
  if (rank == 0)
    log_loop(result.loop, result.continuum, table);

  const std::vector<std::size_t> picks = oracle::stratified_samples(source.rotations.size(), s.orientations, s.seed);
  for (const std::size_t pick : picks)
  {
    FemSdsOrientation& r
        = result.orientations.emplace_back(evaluate_orientation(comm, source, pick, s, m, body, pressure));
    r.index = result.orientations.size() - 1;
    result.reaching_crease += !r.locus.creases.empty();
    result.standing_on_crease += !r.solved && !r.locus.ruling;
    if (r.solved)
    {
      ++result.fem_solved;
      result.reaching_obtuse_rim += r.obtuse_loaded_rims() > 0;
      r.table_vs_direct = table_against_direct(comm, r, table);
      result.table_vs_direct_worst = std::max(result.table_vs_direct_worst, r.table_vs_direct);
      slab_check_if_due(comm, result, r, s, m, rank == 0);
      result.worst_refinement_change
          = std::max(result.worst_refinement_change, std::abs(r.fem_peak_refined_pa / r.fem_peak_pa - 1));
      result.max_orientation_wall_s = std::max(result.max_orientation_wall_s, r.wall_s);
    }
    if (rank == 0)
      log_orientation(r, picks.size());
  }
  for (const auto& [k, node] : table.nodes())
    result.table.push_back(node);
  result.table_wall_s = table.wall_s();
  result.table_nodes_read = table.nodes_read();
  result.normal_load_n = s.normal_load_n;
  result.effective_modulus_pa = m.effective_modulus_pa;
  result.analytic_effective_modulus_pa = pressure.effective_modulus_pa;
  result.n_faces = static_cast<std::int64_t>(scene.mesh.faces.rows());
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

BodyLoop score_body_loop(MPI_Comm comm, const FemSdsSettings& s, fem::SliceScaling& table, const BodyLoopParts& parts)
{
  fem::ensure_petsc(); // MPI too
  const Scene scene = make_scene(s, parts.uniformity, parts.face_template || parts.uniformity);
  BodyLoop r;
  r.body = geometry::body_label(s.body);
  r.source = scene.source.description;
  r.contact_held = scene.contact_held;
  r.n_faces = static_cast<std::int64_t>(scene.mesh.faces.rows());
  r.uniformity = scene.uniformity;
  r.parts = parts;
  const LoopSdsSettings loop = loop_settings(s);
  if (parts.face_template)
    r.loop = loop_sds(comm,
                      map_loop_samples(comm, scene.source, scene.body, scene.pressure.peak_pressure_pa, scene.cones,
                                       table.effective_modulus_pa(), loop),
                      table, loop);
  if (parts.continuum)
    r.continuum = scene_continuum(comm, scene, s, table);
  return r;
}

std::string BodyLoop::status() const
{
  if (parts.face_template)
    return loop.status();
  return continuum ? continuum->status() : "no continuum value: the loop did not close";
}

fem::SliceSettings slice_settings(const FemSdsSettings& s) { return models_of(s).slice; }

LoopSdsSettings loop_settings(const FemSdsSettings& s)
{
  LoopSdsSettings loop;
  loop.normal_load_n = s.normal_load_n;
  loop.end_margin = s.end_margin;
  loop.map_points = s.map_points;
  loop.locus = models_of(s).locus;
  loop.tolerance = s.tolerance;
  return loop;
}

contact::ContinuumLoopSettings continuum_settings(const FemSdsSettings& s)
{
  return {.load_rule = s.load_rule,
          .time_law = s.time_law,
          .width = s.contact_width,
          .end_margin = s.end_margin, // the template's points are held there too
          .normal_load_n = s.normal_load_n,
          .effective_modulus_pa = models_of(s).effective_modulus_pa,
          .pieces = s.continuum_pieces};
}
} // namespace rollcheck::study::loop_scores
