#pragma once
// The parametric search's results as JSON and as an HDF5 file, and the JSON
// convention for scores shared by `rollcheck oracle` and `rollcheck search`:
// a finite number as is, an infinite one (an empty accumulator: nothing
// touched, or no stress above the endurance limit) as the string "inf", a
// score not asked for as null. NaN never appears: it raises ComputationError.
//
// HDF5 layout (docs/methods/oracles.md#rollcheck-search):
//   /          attrs: layout = "rollcheck-search-1", grid, approximate_steps,
//              points, anchor_points, matched_resolution, validate_top,
//              validate_all, compat (the paper-compat switches), threads,
//              approximate_wall_s, rigid_wall_s, wall_s
//   /genomes/  one 1-d dataset per column, one entry per genome in grid order:
//              theta_deg, offset, ratio, n_circles, valid, n_faces, area_m2,
//              approximate_cds, approximate_contact_cv,
//              approximate_max_contact_ratio, approximate_rank, validated,
//              rigid_cds, rigid_contact_cv, rigid_max_contact_ratio,
//              rigid_rank, one dataset per revalidation metric (sds, tds, ...),
//              and error (string). Values not computed (invalid genome, not
//              revalidated) are NaN, ranks 0; +inf is an infinite score.
//   /anchor/   the anchor oloid: the same columns, one entry each.
#include "core/json_number.h"
#include "oracle/parametric_search.h"
#include <filesystem>
#include <nlohmann/json.hpp>

namespace rollcheck::io
{

/// The search as JSON: settings, timings, the anchor, genomes in grid order.
nlohmann::json search_summary(const oracle::SearchResult& result);

/// Writes the HDF5 file atomically (whole or not at all).
void write_search_hdf5(const oracle::SearchResult& result, const std::filesystem::path& path);
} // namespace rollcheck::io
