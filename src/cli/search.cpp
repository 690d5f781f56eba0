// `rollcheck search`: the preprint's two-layer parametric search over the
// paper family of rollers (docs/methods/oracles.md#rollcheck-search): approximate screening
// of a grid, rigid-body revalidation of the best K (or all) scored by
// study::body_scores::revalidation_scores, the ranked table
// (study/body_scores/search_table.h), JSON and HDF5. Also the scene "search"
// of case files.
#include "cli/cli.h"
#include "cli/scenes.h"
#include "cli/search_family.h"
#include "core/error.h"
#include "io/search_store.h"
#include "oracle/parametric_search.h"
#include "study/body_scores/score_body.h"
#include "study/body_scores/search_table.h"
#include <chrono>
#include <cstdio>
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

namespace rollcheck::cli
{
namespace
{
/// The search's options and the options that resolve into them (run_search).
enum class SearchScore
{
  cds,    ///< the preprint's two-layer search
  fem_sds ///< the family's FEM-SDS over whole rolling loops
};

struct SearchScene : oracle::SearchSettings
{
  SearchScore score = SearchScore::cds;
  std::string metric_list = "all", quirks, hdf5, out, python = "/usr/bin/python3";
  bool paper_compat = false;
  long table_rows = 20;
};

const SceneSchema<SearchScene>& search_schema()
{
  using S = SearchScene;
  return kept_schema<S>("search",
                        "Two-layer parametric search over the preprint's roller family: approximate screening, "
                        "rigid-body revalidation",
                        [](auto& s) {
    s.choice("grid", "--grid", &S::grid,
             "Grid of the reference code: quick (45 genomes, the preprint's), standard (616) or deep (1430)",
             {{"quick", oracle::SearchGrid::quick}, {"standard", oracle::SearchGrid::standard},
              {"deep", oracle::SearchGrid::deep}})
        .choice("score", "--score", &S::score,
                "cds: the preprint's two-layer search by contact-time score (approximate screening, rigid-body "
                "revalidation); fem-sds: every genome of the grid and the references (the preprint's body, the true "
                "oloid, the cylinder at the oloid's face count) over one loop of real rolling each, scored by "
                "point-Hertz SDS, line-Hertz SDS, FEM-SDS and U (docs/methods/fem-sds.md)",
                {{"cds", SearchScore::cds}, {"fem-sds", SearchScore::fem_sds}})
        .text("out", "--out", &S::out,
              "--score fem-sds: folder for family.json, table.md and family.png (written whole or not at all)")
        .text("python", "--python", &S::python, "Python with matplotlib for the plot (Debian's)")
        .integer("validate_top", "--validate-top", &S::validate_top, "",
                 "Revalidate the best K genomes by approximate CDS with the rigid-body oracle (the preprint's 5)",
                 io::Bounds{0, 100000})
        .flag("validate_all", "--validate-all", &S::validate_all, "Revalidate every valid genome")
        .flag("matched_resolution", "--matched-resolution", &S::matched_resolution,
              "Mesh every body, the anchor oloid included, with --points samples per circle (else the anchor uses "
              "--anchor-points, as the preprint compares a 400-point oloid with 300-point candidates)")
        .integer("points", "--points", &S::points, "",
                 "Samples per generating circle of the candidates (the reference's search)", body_points_range)
        .integer("anchor_points", "--anchor-points", &S::anchor_points, "",
                 "Samples per circle of the anchor oloid without --matched-resolution (the reference's generate_oloid)",
                 body_points_range)
        .integer("steps", "--steps", &S::approximate_steps, "",
                 fmt::format("Approximate oracle steps; 0 = the reference's (200 quick, 300 standard and deep); at "
                             "most {}, a resource guard", study::body_scores::max_oracle_samples),
                 io::Bounds{0, static_cast<double>(study::body_scores::max_oracle_samples)})
        .real("radius_m", "--radius", &S::radius_m, "m", "r1 of every roller (the preprint's)", io::positive)
        .integer("threads", "--threads", &S::threads, "", "Worker threads; 0 = one per core", io::thread_count)
        .flag("paper_compat", "--paper-compat", &S::paper_compat,
              "Reproduce the reference code's quirks (see `rollcheck oracle --help`); without it every quirk is "
              "corrected")
        .text("quirks", "--quirks", &S::quirks, "Set single paper-compat switches: name=paper|corrected,...")
        .text("metrics", "--metrics", &S::metric_list,
              "Scores of revalidated genomes besides CDS, from sds,tds,wds,fds, or all (contact parameters at the "
              "preprint's values)")
        .text("hdf5", "--hdf5", &S::hdf5, "Also write the results to this HDF5 file (docs/guide/fields.md#hdf5-stores)")
        .integer("table_rows", "--rows", &S::table_rows, "", "Rows of the ranked table printed",
                 io::Bounds{0, 100000});
  });
}

/// A one-line progress bar with ETA on stderr, only when stderr is a terminal.
class ProgressBar
{
public:
  ProgressBar() : enabled_(isatty(fileno(stderr)) != 0) {}
  void operator()(const oracle::SearchProgress& p)
  {
    if (!enabled_)
      return;
    const auto now = std::chrono::steady_clock::now();
    if (p.phase != phase_)
    {
      if (!phase_.empty())
        std::fputc('\n', stderr);
      phase_ = p.phase;
      start_ = now;
    }
    if (p.done != p.total && now - last_ < std::chrono::milliseconds(100))
      return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double eta = p.done > 0 ? elapsed / static_cast<double>(p.done) * static_cast<double>(p.total - p.done) : 0.0;
    constexpr int width = 30;
    const int filled = p.total > 0 ? static_cast<int>(width * p.done / p.total) : width;
    std::fprintf(stderr, "\r%-11s [%s%s] %zu/%zu  %5.1f s  ETA %5.1f s", p.phase.c_str(),
                 std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(), p.done, p.total, elapsed,
                 eta);
    if (p.done == p.total)
      std::fputc('\n', stderr), phase_.clear();
    std::fflush(stderr);
  }

private:
  bool enabled_;
  std::string phase_;
  std::chrono::steady_clock::time_point start_{}, last_{};
};

nlohmann::json run_search(const io::Parameters& params)
{
  const SearchScene scene = search_schema().bind(params);
  if (scene.score != SearchScore::fem_sds && !scene.out.empty())
    throw InputError("option --out (out) is written only with --score fem-sds; the CDS search writes --hdf5 and "
                     "--json");
  if (scene.score == SearchScore::fem_sds)
    return run_family_scores(scene.grid, scene.points, scene.radius_m, scene.out, scene.python);
  oracle::SearchSettings o = scene;
  o.compat = scene.paper_compat ? oracle::PaperCompat::reference() : oracle::PaperCompat::corrected();
  oracle::apply_quirk_settings(o.compat, scene.quirks, "option --quirks");
  study::body_scores::ScoreBodySettings scoring; // the preprint's contact parameters
  scoring.compat = o.compat;
  scoring.metrics = contact::MetricSet::parse(scene.metric_list, "option --metrics");
  scoring.metrics.cds = false; // the search computes CDS itself
  scoring.convergence_every = 0;
  o.revalidation_metrics = study::body_scores::revalidation_scores(scoring);
  ProgressBar bar;
  o.progress = [&](const oracle::SearchProgress& progress) { bar(progress); };
  const oracle::SearchResult result = oracle::parametric_search(o);
  print_summary(study::body_scores::ranked_table(result, static_cast<std::size_t>(scene.table_rows)));
  if (!scene.hdf5.empty())
  {
    io::write_search_hdf5(result, scene.hdf5);
    spdlog::info("search results written to {}", scene.hdf5);
  }
  return io::search_summary(result);
}
} // namespace

void add_search_command(CLI::App& app)
{
  add_scene_command(app, search_schema(), run_search);
  declare_outputs(search_schema().schema(), {{"hdf5", OutputKind::file}, {"out", OutputKind::folder}});
}
} // namespace rollcheck::cli
