#pragma once
// The rim command's text reports (`rollcheck rim`, printed to the log):
// one end's levels as a table with its verdict (fem/scenes/rim_end_contact.h),
// or the rim loop's loaded ends as a table with its end tables and its
// scores with and without the ends (study/rims/rim_loop.h).
#include "fem/scenes/rim_end_contact.h"
#include "study/rims/rim_loop.h"
#include <string>

namespace rollcheck::study::rims
{
/// One end's verdict in words: singular with its measured exponent, or its
/// end/interior ratio converged, not converged, not resolved, or of one
/// level.
std::string rim_end_verdict(const fem::RimEndStudy& study);

/// One end: its setting, its levels' table, its verdict and how far the far
/// side is in plane strain.
std::string report(const fem::RimEndStudy& study);

/// The loop: its loaded ends' table, the loop's range of loaded ends, the
/// end tables against the direct ends, and its scores with the ends.
std::string report(const RimLoopResult& result);
} // namespace rollcheck::study::rims
