#pragma once
// The genomes of a `rollcheck search` output (its "/genomes" array), as the
// search rules (rules_search.cpp) find and rank them.
#include "audit/rules.h"
#include <string>
#include <utility>
#include <vector>

namespace rollcheck::audit
{
/// The pointer to genome `g` ("/genomes/i"); ComputationError when the grid has none.
std::string genome_pointer(const CommandOutput& search, const Genome& g);

/// The genome at `pointer` ("/genomes/i").
Genome genome_at(const CommandOutput& search, const std::string& pointer);

/// The revalidated genomes other than the anchor, as (rigid-body CDS, pointer), best first.
std::vector<std::pair<double, std::string>> revalidated_by_cds(CommandOutput& search);
} // namespace rollcheck::audit
