#pragma once
// `search --score fem-sds` (search_family.cpp), in rollcheck-fem only.
#include "study/fem_sds_family.h"
#include <nlohmann/json.hpp>
#include <string>

namespace rollcheck::cli
{
/// The family table; its JSON summary returned, and with `out` the folder of
/// its files and plot.
nlohmann::json run_family_scores(const study::FamilySettings& settings, const std::string& out,
                                 const std::string& python);
} // namespace rollcheck::cli
