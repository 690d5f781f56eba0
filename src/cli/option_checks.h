#pragma once
// Checks of plain CLI11 options (those outside a scene's schema, whose values
// Parameters::set checks): CLI11's Range lets NaN through and takes "" for a
// path, so these refuse them by the option's name, with exit 2.
#include <CLI/CLI.hpp>

namespace rollcheck::cli
{
/// A finite number: "nan", "inf" and text are refused.
CLI::Validator finite_number();

/// A value that is not empty (a path given as "").
CLI::Validator non_empty();
} // namespace rollcheck::cli
