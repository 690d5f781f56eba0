#pragma once
// The preprint's two-layer parametric search over the paper family of rollers:
// layer 1 meshes every genome of a grid (search_grid.h) and scores it with the
// approximate oracle; layer 2 revalidates the best K by approximate CDS (or
// every genome) with the rigid-body oracle. An anchor oloid, the paper
// family's (90, 1, 1) member, is scored by both layers for comparison: with
// anchor_points samples per circle (the reference's generate_oloid, 400) unless
// matched_resolution, which meshes every body, the anchor included, with the
// same `points` (the reference's search uses 300 for its candidates). Genomes
// whose hull is flat or degenerate are reported invalid, not scored (the
// reference scores the flat three-circle hulls). Work runs on all cores;
// results do not depend on the thread count.
#include "geometry/surface_mesh.h"
#include "geometry/two_circle_roller.h"
#include "oracle/approximate_oracle.h"
#include "oracle/paper_compat.h"
#include "oracle/rigid_body_oracle.h"
#include "oracle/rolling_body.h"
#include "oracle/search_grid.h"
#include "oracle/trajectory.h"
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace rollcheck::oracle
{
/// Named extra scores of a revalidated body (the contact layer's SDS, TDS, ...).
using NamedScores = std::vector<std::pair<std::string, double>>;
using RevalidationMetrics
    = std::function<NamedScores(const geometry::SurfaceMesh&, const RollingBody&, const Trajectory&)>;

struct SearchProgress
{
  std::string phase;   ///< "approximate" or "rigid-body"
  std::size_t done = 0, total = 0;
};

struct SearchSettings
{
  SearchGrid grid = SearchGrid::quick;
  long approximate_steps = 0;     ///< 0: the reference's (200 quick, 300 standard and deep)
  std::size_t validate_top = 5;   ///< K best by approximate CDS revalidated (the preprint's 5)
  bool validate_all = false;      ///< revalidate every valid genome
  bool matched_resolution = false;
  int points = 300;               ///< samples per generating circle (the reference's search)
  int anchor_points = 400;        ///< the anchor oloid's (the reference's generate_oloid)
  double radius_m = 1.0;          ///< r1 (the preprint's)
  unsigned threads = 0;           ///< 0: one per core
  ApproximateSettings approximate; ///< its steps are replaced by approximate_steps
  RigidBodySettings rigid;
  PaperCompat compat;
  RevalidationMetrics revalidation_metrics;           ///< optional
  std::function<void(const SearchProgress&)> progress; ///< optional, called from worker threads under a lock
};

struct GenomeResult
{
  geometry::RollerGenome genome;
  bool valid = false;
  std::string error;                  ///< why the genome is invalid
  long n_faces = 0;
  double area_m2 = 0;
  double approximate_cds = 0, approximate_contact_cv = 0, approximate_max_contact_ratio = 0;
  long approximate_rank = 0;          ///< 1 = lowest CDS among valid genomes
  bool validated = false;
  double rigid_cds = 0, rigid_contact_cv = 0, rigid_max_contact_ratio = 0;
  long rigid_rank = 0;                ///< among validated genomes (the anchor not counted)
  NamedScores metrics;                ///< from revalidation_metrics
  bool is_anchor_genome = false;      ///< (90, 1, 1, 2)
};

struct SearchResult
{
  SearchSettings options;              ///< as run (approximate_steps resolved)
  std::vector<GenomeResult> genomes;  ///< in grid order
  GenomeResult anchor;                ///< the anchor oloid, scored by both layers
  int anchor_points = 0;
  double approximate_wall_s = 0, rigid_wall_s = 0, wall_s = 0;
  unsigned threads = 0;
};

/// InputError for invalid options (points < 3, radius, oracle options).
SearchResult parametric_search(const SearchSettings& options);
} // namespace rollcheck::oracle
