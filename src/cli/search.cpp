// `rollcheck search`: the preprint's two-layer parametric search over the
// paper family of rollers (README "rollcheck search"): approximate screening
// of a grid, rigid-body revalidation of the best K (or all), a ranked table,
// JSON and HDF5. Also the scene "search" of case files.
#include "cli/cli.h"
#include "cli/scenes.h"
#include "contact/face_curvature.h"
#include "contact/face_pressure.h"
#include "contact/trajectory_scores.h"
#include "core/error.h"
#include "io/search_store.h"
#include "oracle/parametric_search.h"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

namespace rollcheck::cli
{
namespace
{
const io::Schema& search_schema()
{
  static const io::Schema schema = [] {
    const oracle::SearchOptions d;
    io::Schema s{"search", {}};
    s.parameters = {
        {"grid", "--grid", std::string("quick"), "",
         "Grid of the reference code: quick (45 genomes, the preprint's), standard (616) or deep (1430)",
         {"quick", "standard", "deep"}},
        {"validate_top", "--validate-top", std::int64_t{5}, "",
         "Revalidate the best K genomes by approximate CDS with the rigid-body oracle (the preprint's 5)"},
        {"validate_all", "--validate-all", false, "", "Revalidate every valid genome"},
        {"matched_resolution", "--matched-resolution", false, "",
         "Mesh every body, the anchor oloid included, with --points samples per circle (else the anchor uses "
         "--anchor-points, as the preprint compares a 400-point oloid with 300-point candidates)"},
        {"points", "--points", std::int64_t{d.points}, "", "Samples per generating circle of the candidates (the reference's search)"},
        {"anchor_points", "--anchor-points", std::int64_t{d.anchor_points}, "",
         "Samples per circle of the anchor oloid without --matched-resolution (the reference's generate_oloid)"},
        {"steps", "--steps", std::int64_t{0}, "",
         "Approximate oracle steps; 0 = the reference's (200 for quick, 300 for standard and deep)"},
        {"radius_m", "--radius", d.radius_m, "m", "r1 of every roller (the preprint's)"},
        {"threads", "--threads", std::int64_t{0}, "", "Worker threads; 0 = one per core"},
        {"paper_compat", "--paper-compat", false, "",
         "Reproduce the reference code's quirks (see `rollcheck oracle --help`); without it every quirk is corrected"},
        {"quirks", "--quirks", std::string(), "", "Set single paper-compat switches: name=paper|corrected,..."},
        {"metrics", "--metrics", std::string("all"), "",
         "Scores of revalidated genomes besides CDS, from sds,tds,wds,fds, or all (contact parameters at the "
         "preprint's values)"},
        {"hdf5", "--hdf5", std::string(), "", "Also write the results to this HDF5 file (README: search store)"},
        {"table_rows", "--rows", std::int64_t{20}, "", "Rows of the ranked table printed"},
    };
    return s;
  }();
  return schema;
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
    std::fprintf(stderr, "\r%-11s [%s%s] %zu/%zu  %5.1f s  ETA %5.1f s", p.phase.c_str(), std::string(filled, '#').c_str(),
                 std::string(width - filled, '.').c_str(), p.done, p.total, elapsed, eta);
    if (p.done == p.total)
      std::fputc('\n', stderr), phase_.clear();
    std::fflush(stderr);
  }

private:
  bool enabled_;
  std::string phase_;
  std::chrono::steady_clock::time_point start_{}, last_{};
};

oracle::RevalidationMetrics contact_metrics(const contact::MetricSet& metrics, const oracle::PaperCompat& compat)
{
  return [metrics, compat](const geometry::SurfaceMesh& mesh, const oracle::RollingBody& body,
                           const oracle::Trajectory& trajectory) {
    const contact::ContactParameters parameters;
    const contact::FaceCurvature curvature = contact::face_curvature(mesh, parameters.hertz, compat);
    const contact::FacePressure pressure = contact::face_pressure(curvature.effective_radius_m, parameters.hertz, compat);
    const contact::ScoreVector v
        = contact::score_trajectory({body, curvature, pressure}, trajectory, metrics, parameters, compat, 0);
    oracle::NamedScores out;
    if (v.sds)
    {
      out.emplace_back("sds", *v.sds);
      out.emplace_back("mean_peak_pressure_pa", v.peak_pressure_pa.mean);
      out.emplace_back("stress_cv", v.peak_pressure_pa.cv);
    }
    if (v.tds)
      out.emplace_back("tds", *v.tds);
    if (v.wds_vol)
      out.emplace_back("wds_vol", *v.wds_vol), out.emplace_back("wds_depth", *v.wds_depth);
    if (v.fds)
      out.emplace_back("fds", *v.fds);
    return out;
  };
}

std::string score_text(double v) { return std::isinf(v) ? "inf" : fmt::format("{:.4g}", v); }

double metric(const oracle::GenomeResult& r, const std::string& name)
{
  for (const auto& [key, value] : r.metrics)
    if (key == name)
      return value;
  return std::numeric_limits<double>::quiet_NaN();
}

void print_table(const oracle::SearchResult& result, std::size_t rows)
{
  const oracle::GenomeResult& anchor = result.anchor;
  fmt::print("{} grid: {} genomes, {} valid, {} revalidated; {} threads, {:.2f} s (approximate {:.2f} s, rigid-body "
             "{:.2f} s)\n",
             oracle::name_of(result.options.grid), result.genomes.size(),
             std::count_if(result.genomes.begin(), result.genomes.end(), [](const auto& r) { return r.valid; }),
             std::count_if(result.genomes.begin(), result.genomes.end(), [](const auto& r) { return r.validated; }),
             result.threads, result.wall_s, result.approximate_wall_s, result.rigid_wall_s);
  fmt::print("{:>4} {:>6} {:>5} {:>5} {:>2} {:>5} {:>7} {:>11} {:>7} {:>11} {:>7} {:>5} {:>11} {:>11} {:>11}\n", "rank",
             "theta", "d", "rho", "n", "faces", "area", "approx CDS", "/anchor", "rigid CDS", "/anchor", "rank",
             "SDS", "TDS", "FDS");
  auto row = [&](const std::string& rank, const oracle::GenomeResult& r) {
    std::string rigid = r.validated ? fmt::format("{:>11} {:>7.3f} {:>5} {:>11} {:>11} {:>11}", score_text(r.rigid_cds),
                                                  r.rigid_cds / anchor.rigid_cds,
                                                  r.rigid_rank > 0 ? std::to_string(r.rigid_rank) : "-",
                                                  score_text(metric(r, "sds")), score_text(metric(r, "tds")),
                                                  score_text(metric(r, "fds")))
                                    : "";
    fmt::print("{:>4} {:>6.1f} {:>5.2f} {:>5.2f} {:>2} {:>5} {:>7.3f} {:>11} {:>7.3f} {}\n", rank, r.genome.theta_deg,
               r.genome.offset, r.genome.ratio, r.genome.n_circles, r.n_faces, r.area_m2, score_text(r.approximate_cds),
               r.approximate_cds / anchor.approximate_cds, rigid);
  };
  row(fmt::format("{}pt", result.anchor_points).substr(0, 4), anchor);
  std::vector<const oracle::GenomeResult*> ranked;
  for (const auto& r : result.genomes)
    if (r.valid)
      ranked.push_back(&r);
  std::sort(ranked.begin(), ranked.end(), [](auto a, auto b) { return a->approximate_rank < b->approximate_rank; });
  for (std::size_t k = 0; k < std::min(rows, ranked.size()); ++k)
    row(std::to_string(ranked[k]->approximate_rank) + (ranked[k]->is_anchor_genome ? "*" : ""), *ranked[k]);
  fmt::print("(first row: the anchor oloid at {} points per circle; * the grid's own (90, 1, 1) genome; ratios "
             "against the anchor)\n",
             result.anchor_points);
}

nlohmann::json run_search(const io::Parameters& p)
{
  oracle::SearchOptions o;
  o.grid = oracle::parse_search_grid(p.text("grid"), "option --grid");
  if (p.integer("validate_top") < 0)
    throw InputError(fmt::format("option --validate-top: must be >= 0, got {}", p.integer("validate_top")));
  o.validate_top = static_cast<std::size_t>(p.integer("validate_top"));
  o.validate_all = p.flag("validate_all");
  o.matched_resolution = p.flag("matched_resolution");
  o.points = static_cast<int>(p.integer("points"));
  o.anchor_points = static_cast<int>(p.integer("anchor_points"));
  if (p.integer("steps") < 0)
    throw InputError(fmt::format("option --steps: must be >= 0 (0: the reference's), got {}", p.integer("steps")));
  o.approximate_steps = p.integer("steps");
  o.radius_m = p.real("radius_m");
  if (p.integer("threads") < 0)
    throw InputError(fmt::format("option --threads: must be >= 0, got {}", p.integer("threads")));
  o.threads = static_cast<unsigned>(p.integer("threads"));
  o.compat = p.flag("paper_compat") ? oracle::PaperCompat::reference() : oracle::PaperCompat::corrected();
  oracle::apply_quirk_settings(o.compat, p.text("quirks"), "option --quirks");
  contact::MetricSet metrics = contact::MetricSet::parse(p.text("metrics"), "option --metrics");
  metrics.cds = false; // the search computes CDS itself
  o.revalidation_metrics = contact_metrics(metrics, o.compat);
  ProgressBar bar;
  o.progress = [&](const oracle::SearchProgress& progress) { bar(progress); };
  const oracle::SearchResult result = oracle::parametric_search(o);
  print_table(result, static_cast<std::size_t>(std::max<std::int64_t>(p.integer("table_rows"), 0)));
  if (const std::string& path = p.text("hdf5"); !path.empty())
  {
    io::write_search_hdf5(result, path);
    spdlog::info("search results written to {}", path);
  }
  return io::search_summary(result);
}
} // namespace

void add_search_command(CLI::App& app)
{
  CLI::App* sub = app.add_subcommand(
      "search", "Two-layer parametric search over the preprint's roller family: approximate screening, rigid-body "
                "revalidation");
  static std::string json_path;
  add_json_option(sub, json_path);
  static io::SchemaOptions* options = new io::SchemaOptions(sub, search_schema());
  register_scene({&search_schema(), run_search});
  on_run(sub, [] {
    emit_json(json_path, run_search(options->apply()));
    return 0;
  });
}
} // namespace rollcheck::cli
