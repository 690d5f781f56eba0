#pragma once
// The key under which a batch stores a case's result: a hash of what the case
// computes (its resolved parameters, every default filled in) and of the code
// that computes it (the rollcheck version). Two case files that resolve to the
// same parameters share one result; any change of a value or of the version
// makes a new key, so a stale result is never reused.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace rollcheck::io
{
/// SHA-256 (FIPS 180-4) of `bytes`, as 64 lowercase hexadecimal digits.
std::string sha256_hex(std::string_view bytes);

/// First 16 hex digits (64 bits) of SHA-256 over "rollcheck <version>\n" and
/// the compact JSON of `resolved_parameters` (nlohmann::json objects keep
/// their keys sorted, and numbers print in shortest round-trip form, so equal
/// parameters always give equal text). 64 bits make an accidental collision
/// among even a million cases a 3e-8 chance.
std::string case_hash(const nlohmann::json& resolved_parameters);
} // namespace rollcheck::io
