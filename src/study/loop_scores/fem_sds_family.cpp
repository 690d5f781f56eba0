// FEM-SDS of a whole family (study/loop_scores/fem_sds_family.h).
#include "study/loop_scores/fem_sds_family.h"
#include "core/error.h"
#include "core/json_number.h"
#include "fem/petsc_session.h"
#include "geometry/body.h"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace rollcheck::study::loop_scores
{
namespace
{
/// `body`'s whole loop of real rolling scored with `base`'s settings, and
/// `why_not` empty; or why it has none: a rim lifts before the loop closes,
/// or it cannot roll over its potential barrier (the same on every rank).
BodyLoop whole_loop(MPI_Comm comm, const geometry::BodySpec& body, const FemSdsSettings& base,
                    fem::SliceScaling& table, std::string& why_not, const BodyLoopParts& parts = {})
{
  FemSdsSettings settings = base;
  settings.body = body;
  settings.oracle = OrientationOracle::rolling;
  BodyLoop loop;
  try
  {
    loop = score_body_loop(comm, settings, table, parts);
    why_not = loop.contact_held ? "" : loop.source;
  }
  catch (const InputError& e)
  {
    loop.body = geometry::body_label(body);
    why_not = e.what();
  }
  return loop;
}

FamilyRow score_row(MPI_Comm comm, std::string kind, const geometry::BodySpec& body, const FamilySettings& s,
                    fem::SliceScaling& table)
{
  const auto start = std::chrono::steady_clock::now();
  FamilyRow row;
  row.kind = std::move(kind);
  if (body.body == "roller")
    row.genome = body.genome;
  row.loop = whole_loop(comm, body, s.scoring, table, row.why_not);
  row.scored = row.why_not.empty();
  row.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return row;
}

std::optional<double> ratio(const std::optional<double>& value, const std::optional<double>& cylinder)
{
  if (value && cylinder && *cylinder > 0)
    return *value / *cylinder;
  return std::nullopt;
}


std::optional<double> continuum_of(const FamilyRow& row)
{
  return row.scored && row.loop.continuum ? std::optional(row.loop.continuum->fem) : std::nullopt;
}

nlohmann::json row_json(const FamilyRow& row, const FamilyRow& cylinder)
{
  nlohmann::json j = {{"kind", row.kind}, {"body", row.loop.body}, {"faces", row.loop.n_faces},
                      {"scored", row.scored}, {"wall_s", json_number(row.wall_s)}};
  if (row.genome)
  {
    j["theta_deg"] = row.genome->theta_deg;
    j["offset"] = row.genome->offset;
    j["ratio"] = row.genome->ratio;
  }
  if (!row.scored)
  {
    j["why_not"] = row.why_not;
    return j;
  }
  const LoopSds& l = row.loop.loop;
  const LoopSds& c = cylinder.loop.loop;
  j.update(headline_json(l));
  j.update(continuum_json(row.loop.continuum));
  j["point_hertz_sds"] = json_number(l.point_hertz.value);
  j["uniformity"] = json_number(row.loop.uniformity);
  if (cylinder.scored)
    j["over_cylinder"] = {{"point_hertz_sds", json_number(ratio(l.point_hertz.value, c.point_hertz.value))},
                          {"line_hertz_sds", json_number(ratio(l.line_hertz.value, c.line_hertz.value))},
                          {"fem_sds", json_number(ratio(l.fem.value, c.fem.value))},
                          {"uniformity", json_number(ratio(row.loop.uniformity, cylinder.loop.uniformity))},
                          {"fem_sds_continuum", json_number(ratio(continuum_of(row), continuum_of(cylinder)))}};
  return j;
}

std::string label(const FamilyRow& row)
{
  if (row.genome)
    return fmt::format("({:g}, {:g}, {:g})", row.genome->theta_deg, row.genome->offset, row.genome->ratio);
  return row.kind;
}

std::string number(const std::optional<double>& v) { return v ? fmt::format("{:.4g}", *v) : std::string("-"); }

/// A scored row's convergence: the template's (LoopSds::status) and the
/// continuum value's (ContinuumSds::status), the ranking's, each named
/// where they differ.
std::string note(const FamilyRow& row)
{
  const std::string face_template = row.loop.loop.status();
  const std::string continuum = row.loop.continuum ? row.loop.continuum->status() : "no continuum value";
  if (face_template == continuum)
    return face_template;
  return fmt::format("template: {}; continuum: {}", face_template, continuum);
}
} // namespace

std::function<double(const geometry::BodySpec&)> fem_sds_scorer(MPI_Comm comm, const FemSdsSettings& base,
                                                                FemSdsValue value,
                                                                std::shared_ptr<std::vector<std::string>> statuses)
{
  fem::ensure_petsc();
  auto table = std::make_shared<fem::SliceScaling>(slice_settings(base), base.table_nodes_per_decade);
  return [comm, base, value, table, statuses](const geometry::BodySpec& body) {
    std::string why_not;
    // The search reads the value it scores alone, and its status.
    const bool continuum = value == FemSdsValue::continuum;
    const BodyLoop loop = whole_loop(comm, body, base, *table, why_not,
                                     {.uniformity = false, .face_template = !continuum, .continuum = continuum});
    if (statuses)
      statuses->push_back(why_not.empty() ? loop.status() : why_not);
    if (!why_not.empty())
      return std::numeric_limits<double>::infinity();
    if (value == FemSdsValue::continuum)
      return loop.continuum ? loop.continuum->fem : std::numeric_limits<double>::infinity();
    return loop.loop.fem.value ? *loop.loop.fem.value : std::numeric_limits<double>::infinity();
  };
}

FamilyResult fem_sds_family(MPI_Comm comm, const FamilySettings& s)
{
  const auto start = std::chrono::steady_clock::now();
  if (s.points < 16)
    throw InputError(fmt::format("points: at least 16 per generating circle, got {}", s.points));
  fem::ensure_petsc();
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  fem::SliceScaling table(slice_settings(s.scoring), s.scoring.table_nodes_per_decade);
  geometry::BodySpec body;
  body.radius_m = s.scoring.body.radius_m;
  body.points = s.points;
  FamilyResult result;
  const std::vector<geometry::RollerGenome> grid = oracle::search_grid(s.grid);
  const std::size_t total = grid.size() + 3; // and the references: the preprint's body, the oloid, the cylinder
  auto add = [&](std::string kind, const geometry::BodySpec& spec) {
    result.rows.push_back(score_row(comm, std::move(kind), spec, s, table));
    const FamilyRow& row = result.rows.back();
    if (rank == 0)
      spdlog::info("{} of {} {}: {} ({:.1f} s)", result.rows.size(), total, label(row),
                   row.scored ? fmt::format("point-Hertz SDS {}, FEM-SDS {}, U {}, continuum {} ({})",
                                            number(row.loop.loop.point_hertz.value), number(row.loop.loop.fem.value),
                                            number(row.loop.uniformity), number(continuum_of(row)), note(row))
                              : row.why_not,
                   row.wall_s);
  };
  body.body = "roller";
  body.family = geometry::RollerFamily::paper;
  for (const geometry::RollerGenome& genome : grid)
  {
    body.genome = genome;
    add("genome", body);
  }
  body.body = "paper-oloid";
  add("paper (90, 1, 1)", body);
  body.body = "oloid";
  add("oloid", body);
  body.body = "cylinder";
  body.height_m = 2 * body.radius_m;
  body.sections = static_cast<int>(std::lround(static_cast<double>(result.rows.back().loop.n_faces) / 4));
  add("cylinder", body);
  result.cylinder = result.rows.size() - 1;
  result.nodes_per_decade = table.nodes_per_decade();
  result.fem_solves = table.nodes().size();
  result.table_wall_s = table.wall_s();
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

nlohmann::json to_json(const FamilyResult& result)
{
  const FamilyRow& cylinder = result.rows[result.cylinder];
  nlohmann::json genomes = nlohmann::json::array(), references = nlohmann::json::array();
  for (const FamilyRow& row : result.rows)
    (row.kind == "genome" ? genomes : references).push_back(row_json(row, cylinder));
  return {{"genomes", genomes},
          {"references", references},
          {"fem_solves", result.fem_solves},
          {"table_nodes_per_decade", result.nodes_per_decade},
          {"fem_table_wall_s", json_number(result.table_wall_s)},
          {"wall_s", json_number(result.wall_s)}};
}

std::string markdown_table(const FamilyResult& result)
{
  std::vector<const FamilyRow*> ranked;
  for (const FamilyRow& row : result.rows)
    ranked.push_back(&row);
  auto key = [](const FamilyRow* r) {
    return r->scored && r->loop.continuum ? r->loop.continuum->fem : std::numeric_limits<double>::infinity();
  };
  std::stable_sort(ranked.begin(), ranked.end(), [&](auto a, auto b) { return key(a) < key(b); });
  const FamilyRow& cylinder = result.rows[result.cylinder];
  const LoopSds& c = cylinder.loop.loop;
  std::string t = "| rank | body (theta, d, rho) | faces | FEM-SDS continuum | continuum / cylinder | continuum half "
                  "resolution | point-Hertz SDS | line-Hertz SDS | FEM-SDS | U | point-Hertz / "
                  "cylinder | FEM / cylinder | U / cylinder | FEM K-to-2K | FEM half samples | note |\n"
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  int rank = 0;
  for (const FamilyRow* row : ranked)
  {
    const LoopSds& l = row->loop.loop;
    if (!row->scored)
    {
      t += fmt::format("| - | {} | {} | - | - | - | - | - | - | - | - | - | - | - | - | {} |\n", label(*row), row->loop.n_faces,
                       row->why_not);
      continue;
    }
    const std::optional<double> continuum = continuum_of(*row);
    t += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {:+.3f} % | {:+.3f} % | {} |\n",
                     ++rank, label(*row), row->loop.n_faces, number(continuum), number(ratio(continuum, continuum_of(cylinder))),
                     row->loop.continuum ? fmt::format("{:+.3f} %", 100 * row->loop.continuum->change()) : "-",
                     number(l.point_hertz.value), number(l.line_hertz.value),
                     number(l.fem.value), number(row->loop.uniformity),
                     number(ratio(l.point_hertz.value, c.point_hertz.value)), number(ratio(l.fem.value, c.fem.value)),
                     number(ratio(row->loop.uniformity, cylinder.loop.uniformity)), 100 * l.table_change(),
                     100 * l.fem_rulings.sample_change(), note(*row));
  }
  return t;
}

std::string report(const FamilyResult& result, const FamilySettings& settings)
{
  return fmt::format("\nFEM-SDS of the {} grid over one loop of real rolling each, ranked by FEM-SDS's continuum value ({} FEM solves "
                     "shared, {:.1f} s of FEM, {:.1f} s in all):\n\n{}",
                     oracle::name_of(settings.grid), result.fem_solves, result.table_wall_s, result.wall_s,
                     markdown_table(result));
}
} // namespace rollcheck::study::loop_scores
