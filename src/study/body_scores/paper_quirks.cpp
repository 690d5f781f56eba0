#include "study/body_scores/paper_quirks.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::study::body_scores
{
namespace
{
/// Largest f(nudged, nominal) of `column` over the nudges where both are finite.
template <class Change>
double largest_change(const SpinNudgeBand& band, const ScoreColumn& column, Change change)
{
  double largest = 0;
  const std::optional<double> b = column.value(band.nominal);
  for (const contact::ScoreVector& v : band.nudged)
    if (const std::optional<double> a = column.value(v); a && b && std::isfinite(*a) && std::isfinite(*b))
      largest = std::max(largest, change(*a, *b));
  return largest;
}

nlohmann::json scores_json(const contact::ScoreVector& v)
{
  nlohmann::json j = nlohmann::json::object();
  for (const ScoreColumn& c : score_columns())
  {
    j[std::string(c.key)] = json_number(c.value(v));
  }
  return j;
}

std::string percent_change(const std::optional<double>& value, const std::optional<double>& base)
{
  if (!value || !base)
    return "-";
  if (std::isinf(*value) || std::isinf(*base))
    return std::isinf(*value) && std::isinf(*base) ? "inf = inf" : fmt::format("{:.3g} vs {:.3g}", *value, *base);
  return fmt::format("{:+.2f} %", 100 * (*value / *base - 1));
}

/// A '|' would end the Markdown cell.
std::string cell(std::string text)
{
  for (std::size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2))
    text.replace(at, 1, "\\|");
  return text;
}
} // namespace

const std::vector<ScoreColumn>& score_columns()
{
  using V = contact::ScoreVector;
  static const std::vector<ScoreColumn> columns = {
      {"CDS", "CDS", 1.0, "", [](const V& v) { return v.cds; }},
      {"SDS", "SDS", 1.0, "", [](const V& v) { return v.sds; }},
      {"TDS", "TDS", 1.0, "", [](const V& v) { return v.tds; }},
      {"WDS_vol", "WDS_vol", 1.0, "", [](const V& v) { return v.wds_vol; }},
      {"WDS_depth", "WDS_depth", 1.0, "", [](const V& v) { return v.wds_depth; }},
      {"FDS", "FDS", 1.0, "", [](const V& v) { return v.fds; }},
      {"mean_peak_pressure_pa", "mean p0", 1e6, " MPa",
       [](const V& v) { return std::optional<double>(v.peak_pressure_pa.mean); }},
  };
  return columns;
}

SpinNudgeBand spin_nudge_band(const ScoreBodySettings& settings)
{
  ScoreBodySettings nominal = settings;
  nominal.oracle = Oracle::rigid;
  SpinNudgeBand band{score_body(nominal).scores, {}};
  for (int axis = 0; axis < 3; ++axis)
    for (const double sign : {1.0, -1.0})
    {
      ScoreBodySettings nudged = nominal;
      for (Eigen::Vector3d& w : nudged.rigid.initial_spins)
        w[axis] += sign * spin_nudge_rad_s;
      band.nudged.push_back(score_body(nudged).scores);
    }
  return band;
}

double half_width(const SpinNudgeBand& band, const ScoreColumn& column)
{
  return largest_change(band, column, [](double a, double b) { return std::abs(a - b); });
}

double relative_half_width(const SpinNudgeBand& band, const ScoreColumn& column)
{
  return largest_change(band, column, [](double a, double b) { return std::abs(a / b - 1); });
}

QuirkTable quirk_table(const ScoreBodySettings& settings)
{
  ScoreBodySettings paper = settings;
  paper.oracle = Oracle::rigid;
  paper.compat = oracle::PaperCompat::reference();
  paper.metrics = {};
  QuirkTable table{geometry::body_label(settings.body), spin_nudge_band(paper), {}};
  for (const oracle::Quirk& q : oracle::quirks())
  {
    ScoreBodySettings alone = paper;
    alone.compat.*q.flag = false;
    table.rows.push_back({q, score_body(alone).scores});
  }
  return table;
}

nlohmann::json to_json(const QuirkTable& table)
{
  nlohmann::json rows = nlohmann::json::array();
  for (const QuirkRow& row : table.rows)
    rows.push_back({{"quirk", row.quirk.name},
                    {"layer", row.quirk.layer},
                    {"reference_does", row.quirk.reference_does},
                    {"physically_right", row.quirk.physically_right},
                    {"scores", scores_json(row.scores)}});
  nlohmann::json band = nlohmann::json::object();
  for (const ScoreColumn& c : score_columns())
    band[std::string(c.key)] = relative_half_width(table.band, c);
  return {{"body", table.body},
          {"paper_compatible", scores_json(table.band.nominal)},
          {"nudge_band_relative", band},
          {"quirks", rows}};
}

std::string to_markdown(const QuirkTable& table)
{
  const contact::ScoreVector& paper = table.band.nominal;
  std::string header = "| quirk | layer | reference does | physically right |", rule = "|---|---|---|---|";
  std::string values = "| (paper-compatible values) | | | |", band = "| (band: 1e-12 rad/s spin nudges) | | | |";
  for (const ScoreColumn& c : score_columns())
  {
    header += fmt::format(" {} |", c.header);
    rule += "---|";
    const std::optional<double> v = c.value(paper);
    values += v ? fmt::format(" {:.4g}{} |", *v / c.display_scale, c.unit) : " - |";
    band += fmt::format(" +-{:.2f} % |", 100 * relative_half_width(table.band, c));
  }
  std::string out = fmt::format("Paper-compat quirks on {} (rigid-body oracle, {} samples): change of each score "
                                "when the quirk alone is corrected\n\n{}\n{}\n{}\n{}\n",
                                table.body, paper.n_samples, header, rule, values, band);
  for (const QuirkRow& row : table.rows)
  {
    std::string line = fmt::format("| {} | {} | {} | {} |", row.quirk.name, row.quirk.layer,
                                   cell(std::string(row.quirk.reference_does)),
                                   cell(std::string(row.quirk.physically_right)));
    for (const ScoreColumn& c : score_columns())
      line += fmt::format(" {} |", percent_change(c.value(row.scores), c.value(paper)));
    out += line + "\n";
  }
  return out + "\n";
}
} // namespace rollcheck::study::body_scores
