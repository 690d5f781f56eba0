#pragma once
// The ranked table of the preprint's two-layer parametric search
// (oracle/parametric_search.h), whose revalidated genomes are scored by
// revalidation_scores (score_body.h): the anchor oloid first, then the valid
// genomes by approximate rank, each with its approximate CDS and, when
// revalidated, its rigid-body CDS, rank, SDS, TDS and FDS; every CDS also
// as a ratio to the anchor's.
#include "oracle/parametric_search.h"
#include <cstddef>
#include <string>

namespace rollcheck::study::body_scores
{
/// A header line (grid, genomes, valid, revalidated, threads, times), the
/// column heads, the anchor's row, the first `rows` ranked genomes and a
/// closing note, each line ending in a newline: fixed-width text for the log.
std::string ranked_table(const oracle::SearchResult& result, std::size_t rows);
} // namespace rollcheck::study::body_scores
