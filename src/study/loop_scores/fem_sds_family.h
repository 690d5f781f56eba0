#pragma once
// FEM-SDS of a whole family: every genome of a search grid (the preprint's
// quick grid: 45 two-circle rollers at its 300 points per circle), the
// preprint's (90, 1, 1) body, the true oloid and the cylinder, each over one
// loop of real rolling (study/loop_scores/fem_sds.h score_body_loop), with one FEM table
// shared by all: the nondimensional slice does not depend on the body
// (fem/scenes/slice_scaling.h), so each body adds only the load ratios no body
// before it reached.
//
// The SDS template weighs each face by its area share, so scores fall with
// the face count (the preprint's "CDS ~ N^-2"): the references are meshed at
// the genomes' resolution, and the cylinder gets as many faces as the true
// oloid (sections = faces / 4). Each body's ratio to the cylinder is given
// under every score, with U (oracle/uniformity_score.h), the
// resolution-free uniformity of the contact density.
//
// A body the line-contact rolling model cannot follow over a whole loop (a
// rim lifts: the centre of pressure leaves the ruling; or it cannot roll
// over its potential barrier) gets a row that says why, without scores.
#include "oracle/search_grid.h"
#include "study/loop_scores/fem_sds.h"
#include <functional>
#include <memory>
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rollcheck::study::loop_scores
{
struct FamilySettings
{
  oracle::SearchGrid grid = oracle::SearchGrid::quick;
  int points = 300; ///< per generating circle, every body (the preprint's search)
  /// Everything else of the loop scores (material, load, samples, FEM);
  /// its body and oracle are set per row (real rolling).
  FemSdsSettings scoring;
};

struct FamilyRow
{
  std::string kind;                          ///< "genome", "paper (90, 1, 1)", "oloid", "cylinder"
  std::optional<geometry::RollerGenome> genome;
  bool scored = false;                       ///< a whole loop rolled and scored
  std::string why_not;                       ///< when not scored
  BodyLoop loop;
  double wall_s = 0;
};

struct FamilyResult
{
  std::vector<FamilyRow> rows;               ///< the genomes in grid order, then the references
  std::size_t cylinder = 0;                  ///< index of the cylinder's row
  std::size_t fem_solves = 0;                ///< the shared table's nodes
  int nodes_per_decade = 0;
  double table_wall_s = 0;
  double wall_s = 0;
};

/// Which FEM-SDS a scorer returns: the continuum value on the exact surface
/// (fem_sds_continuum.h: resolution-free, `fem_sds_continuum` in JSON), or
/// the preprint's per-face template, which falls about as the face count^-2
/// and so moves with a genome's face count at fixed points per circle.
enum class FemSdsValue
{
  continuum,
  face_template
};

/// FEM-SDS of a body over one loop of real rolling, for a search that scores
/// many bodies (study/optimize/optimize_family.h BodyScore): `base`'s settings with
/// the body replaced, one FEM table shared by every call (a body only adds
/// the load ratios no body before it reached). +infinity for a body the
/// line-contact model cannot follow over a whole loop (a rim lifts) or that
/// cannot roll over its potential barrier: it has no whole loop to score
/// (and, for the continuum value, a loop without one).
/// Only the value scored is computed. Collective on `comm` at every call.
/// Each call's status, that of the value scored (LoopSds::status for the
/// template, ContinuumSds::status for the continuum value: "converged",
/// "not converged: ...", "singular: ...", or why there is no loop), is
/// appended to `statuses`, if given, so that the search can report how many
/// of the bodies it scored were converged.
std::function<double(const geometry::BodySpec&)> fem_sds_scorer(
    MPI_Comm comm, const FemSdsSettings& base, FemSdsValue value,
    std::shared_ptr<std::vector<std::string>> statuses = {});

/// Collective on `comm`; every rank gets the result. InputError for bad
/// settings; a body that cannot roll a loop is a row, not an error.
FamilyResult fem_sds_family(MPI_Comm comm, const FamilySettings& settings);

/// {"genomes": [one row per genome], "references": [...], ...}, with each
/// row's ratios to the cylinder.
nlohmann::json to_json(const FamilyResult& result);

/// The table of every row ranked by FEM-SDS, rows without scores last.
std::string markdown_table(const FamilyResult& result);
/// The table under a line naming the grid and the FEM table's cost: the log's report.
std::string report(const FamilyResult& result, const FamilySettings& settings);
} // namespace rollcheck::study::loop_scores
