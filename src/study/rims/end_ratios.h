#pragma once
// The loop's end/interior ratio of a loaded end, from the rim loop's two
// tables (study/rims/rim_loop.h): from the section angle flat_from_rad on
// the flat-rim table's at the end's section angle (study/rims/flat_rim_table.h:
// its peak over the end's line Hertz peak where the table's ends carry the
// loop's own load, the static rule; under another load rule its peak over
// its own line Hertz, a ratio at the table's load), below it the FEM end
// table's ratio at its
// dihedral angle (held to [60 deg, largest_modelled_rad]) and R
// (study/rims/end_table.h). The loop's end-aware scores
// (study/loop_scores/loop_sds.h loop_scores::end_aware_scores) take an end's
// pressure as that ratio times the FEM pressure at the end.
#include "study/loop_scores/loop_sds.h"
#include "study/rims/end_table.h"
#include "study/rims/flat_rim_table.h"
#include <numbers>
#include <optional>
#include <vector>

namespace rollcheck::study::rims
{
/// Each table is read by every stride-th node when it has 3 or more (the
/// check of its spacing), else by all.
struct EndRatios
{
  std::vector<EndTableNode> table;
  std::vector<FlatRimNode> flat_table;
  double flat_from_rad = std::numbers::pi;
  double singular_from_rad = std::numbers::pi;
  double largest_modelled_rad = std::numbers::pi;
  /// Whether the flat-rim table's ends carry the loop's ends' own load (the
  /// static rule: F through the centre of mass, the body's balance).
  bool flat_rim_own_load = true;
  /// The ratio of a loaded end (as loop_scores::finished_end has it); none
  /// where its dihedral angle lies above singular_from_rad.
  std::optional<double> operator()(int stride, const loop_scores::LoadedEnd& end) const;
  /// The end-aware scores' factors: by every node, then by every other when
  /// either table has 3 or more nodes.
  std::vector<loop_scores::EndFactor> factors() const;
};
} // namespace rollcheck::study::rims
