#pragma once
// A case file to start from: the [scene] table of a kind with every key of its
// schema at its default, each under a comment giving what it is, its unit, its
// valid range or choices and its option (`rollcheck run --template KIND`). The
// keys are commented out, so the template runs the defaults as it stands and
// an uncommented line overrides one.
#include "io/parameters.h"
#include <string>

namespace rollcheck::io
{
std::string case_template(const Schema& schema);
} // namespace rollcheck::io
