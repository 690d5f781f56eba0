#pragma once
// The key under which a batch stores a case's result: a hash of what the case
// computes (its resolved parameters, every default filled in, and the content
// of every input file they name, io/batch_cases.h) and of the code that
// computes it (the rollcheck version and the executable's build-id,
// core/build_id.h). Two case files that resolve to the same parameters share
// one result; any change of a value, an input file or the build makes a new
// key, so a stale result is never reused.
#include "core/sha256.h"
#include <nlohmann/json.hpp>
#include <string>

namespace rollcheck::io
{
using rollcheck::sha256_hex;

/// First 16 hex digits (64 bits) of SHA-256 over "rollcheck <version> build
/// <build-id>\n" and the compact JSON of `resolved_parameters` (nlohmann::json
/// objects keep their keys sorted, and numbers print in shortest round-trip
/// form, so equal parameters always give equal text). 64 bits make an
/// accidental collision among even a million cases a 3e-8 chance.
std::string case_hash(const nlohmann::json& resolved_parameters);
} // namespace rollcheck::io
