#pragma once
// Every `rollcheck` command the audit's claims cite, in one place: a cell
// names its commands here and its rule reads their outputs in the order
// listed. Commands by mode are keyed by the mode's name (modes.h).
#include "audit/command_output.h"
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rollcheck::audit
{
/// A cell's commands in each mode that has them, keyed by mode.
using PerMode = std::map<std::string, std::vector<CommandArgs>>;

struct ClaimCommands
{
  /// The scans' thresholds and mesh sizes (points per circle).
  std::vector<std::string> thresholds, points;

  // The rigid-body oracle, per oracle mode (paper-compatible, matched
  // resolution, true oloid, corrected physics).
  PerMode oloid;                  ///< the mode's oloid
  PerMode pair;                   ///< the oloid, then the cylinder it is compared with
  PerMode face_scan;              ///< not matched: CDS of the (90,1,1) roller (true oloid: the oloid) at each mesh size
  PerMode threshold_scan;         ///< the pair, then the pair's CDS at each threshold
  PerMode approximate_then_rigid; ///< the pair's approximate CDS, then the pair
  PerMode fatigue;                ///< the pair; corrected also the reference meshes with the right E* alone
  PerMode mesh;                   ///< paper-compatible, true oloid: the scored oloid's meshes

  // The preprint's tables, paper-compatible.
  std::vector<CommandArgs> hertz_table;         ///< the oloid, the Hertz table's four candidates, the cylinder
  std::vector<CommandArgs> neighbour_pressures; ///< the oloid, the cylinder, the nearest neighbour
  std::vector<CommandArgs> neighbour_fatigue;   ///< the oloid, the nearest neighbour
  std::vector<CommandArgs> speed;               ///< the oloid's approximate CDS, then its rigid-body scores

  // The searches.
  PerMode search;                        ///< paper-compatible, matched, corrected: the quick grid
  std::vector<CommandArgs> revalidation; ///< the paper-compatible quick grid, the reference oloid
  PerMode optimize;                      ///< from the family's (90, 1, 1), in every mode but matched

  // Real rolling.
  std::vector<CommandArgs> rolling_pair;     ///< U of the oloid, the cylinder
  std::vector<CommandArgs> rolling_coverage; ///< the oloid with the geometric contact width, then the Hertz width at 1, 8, 16 face subdivisions
  std::vector<CommandArgs> paper_coverage;   ///< the paper-compatible oloid with its per-face arrays

  // The modelling choices.
  std::vector<CommandArgs> robustness; ///< every comparison of bodies over the grid of choices

  // Contact mechanics.
  std::vector<CommandArgs> hertz;            ///< FEM against Hertz: axisymmetric sphere, plane-strain cylinder
  std::vector<CommandArgs> fem_sds_pair;     ///< FEM-SDS over one loop: the preprint's body, the cylinder
  std::vector<CommandArgs> fem_sds_body;     ///< the preprint's body alone
  std::vector<CommandArgs> fem_orientations; ///< the preprint's body, three orientations solved directly
  std::vector<CommandArgs> rims;             ///< the loop's ends: the oloid, the cylinder

  // Rolling-contact fatigue life.
  std::vector<CommandArgs> life; ///< the bodies' L10 life ratios over the grid, the rim ends
};

/// The commands on the reference meshes in `reference_meshes`
/// (oloid_reference.obj, cylinder_reference.obj); `quick`: fewer thresholds,
/// mesh sizes and optimiser evaluations.
ClaimCommands claim_commands(const std::filesystem::path& reference_meshes, bool quick);
} // namespace rollcheck::audit
