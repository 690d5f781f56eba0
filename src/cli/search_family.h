#pragma once
// `search --score fem-sds` (search_family.cpp in rollcheck-fem; rollcheck's
// definition in light_session.cpp refuses, since it hands such command lines
// over): the declaration names no FEM type, so search.cpp is built once.
#include "oracle/search_grid.h"
#include <nlohmann/json.hpp>
#include <string>

namespace rollcheck::cli
{
/// The family table of `grid`'s genomes at `points` per generating circle,
/// radius `radius_m` (study::loop_scores::fem_sds_family); its JSON summary returned, and
/// with `out` the folder of its files and plot.
nlohmann::json run_family_scores(oracle::SearchGrid grid, int points, double radius_m, const std::string& out,
                                 const std::string& python);
} // namespace rollcheck::cli
