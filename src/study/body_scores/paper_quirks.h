#pragma once
// What each paper-compat switch (oracle/paper_compat.h) does to a body's
// scores, and how far chaos alone moves them.
//
// The spin-nudge band: the rigid-body runs are chaotic (tests/data/reference/
// README.md), so every run's initial spin is nudged by +-1e-12 rad/s along x,
// y and z in turn (6 nudged evaluations besides the nominal one); a score's
// band half-width is its largest change under a nudge.
//
// The quirk table: the rigid-body oracle's scores in paper-compatible mode,
// the band, and the scores with each switch alone corrected (`rollcheck oracle
// --quirk-table`, docs/results/oracles.md#paper-compat-quirk-table).
#include "contact/trajectory_scores.h"
#include "oracle/paper_compat.h"
#include "study/body_scores/score_body.h"
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rollcheck::study::body_scores
{
inline constexpr double spin_nudge_rad_s = 1e-12;

/// A score of a trajectory, a column of the quirk table.
struct ScoreColumn
{
  std::string_view key;    ///< JSON key (and Markdown header with `unit`)
  std::string_view header; ///< Markdown column
  double display_scale;    ///< the paper-compatible value is shown divided by this ...
  std::string_view unit;   ///< ... followed by this
  std::optional<double> (*value)(const contact::ScoreVector&);
};

/// CDS, SDS, TDS, WDS_vol, WDS_depth, FDS and the mean Hertz peak pressure.
const std::vector<ScoreColumn>& score_columns();

struct SpinNudgeBand
{
  contact::ScoreVector nominal;
  std::vector<contact::ScoreVector> nudged; ///< spins + and - 1e-12 rad/s along x, then y, then z
};

/// The rigid-body oracle's scores under `settings` (its oracle set to rigid)
/// and under each of the 6 nudges.
SpinNudgeBand spin_nudge_band(const ScoreBodySettings& settings);

/// Largest |nudged - nominal| of `column` over the nudges where both are finite.
double half_width(const SpinNudgeBand& band, const ScoreColumn& column);

/// Largest |nudged / nominal - 1| of `column` over the nudges where both are finite.
double relative_half_width(const SpinNudgeBand& band, const ScoreColumn& column);

struct QuirkRow
{
  oracle::Quirk quirk;
  contact::ScoreVector scores; ///< paper-compatible but this switch corrected
};

struct QuirkTable
{
  std::string body;     ///< geometry::body_label
  SpinNudgeBand band;   ///< its nominal: the paper-compatible scores
  std::vector<QuirkRow> rows;
};

/// The table on settings' body, rigid-body options and contact parameters;
/// oracle, metrics and switches are set here (rigid, every score, paper-compatible).
QuirkTable quirk_table(const ScoreBodySettings& settings);

/// Keys body, paper_compatible, nudge_band_relative and quirks (rows with
/// quirk, layer, reference_does, physically_right and their scores).
nlohmann::json to_json(const QuirkTable& table);

/// The README's Markdown table: a title, the paper-compatible values, the
/// band and each switch's relative change of every score.
std::string to_markdown(const QuirkTable& table);
} // namespace rollcheck::study::body_scores
