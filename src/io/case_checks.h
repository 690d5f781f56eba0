#pragma once
// What a case's result must satisfy: the [[check]] tables of a case file.
// Each names a value of the scene's JSON summary by JSON pointer, the
// reference it is compared with (an analytic solution, the published code's
// output, a closed form) and the tolerance:
//
//   [[check]]
//   pointer = "/p0_error"          # relative error against Hertz
//   max_abs = 0.003                # |value| <= 0.003
//   reference = "Hertz: p0 = 3F / (2 pi a^2) (Johnson 1985, eq. 4.23)"
//
// Criteria (exactly one per check): max_abs = x; value = v with rel_tol = t
// (|measured / v - 1| <= t); expect = true|false (a flag of the summary).
// `rollcheck validate` evaluates them and fails when one does not hold.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rollcheck::io
{
struct CaseCheck
{
  std::string pointer;   ///< JSON pointer into the scene's summary
  std::string reference; ///< what the value is compared with, and where it comes from
  std::optional<double> max_abs;
  std::optional<double> value;
  double rel_tol = 0;
  std::optional<bool> expect;
  /// The criterion as text: "abs(x) <= 0.003", "within 1 % of 12.566", "is true".
  std::string criterion() const;
};

struct CheckOutcome
{
  CaseCheck check;
  std::string measured; ///< the value found, as text ("missing" if absent)
  bool passed = false;
};

/// Each check applied to `summary`. A missing key or a value of the wrong type
/// fails its check, with the reason in `measured`.
std::vector<CheckOutcome> evaluate_checks(const std::vector<CaseCheck>& checks, const nlohmann::json& summary);
} // namespace rollcheck::io
