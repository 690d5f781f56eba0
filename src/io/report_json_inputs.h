#pragma once
// The JSON files a report reads besides the results store (`--validation`,
// `--audit`, `--robustness`, `--life` of `rollcheck report` and `rollcheck
// validate`),
// checked before anything is computed: each must be a bounded regular file
// holding a JSON object with the top-level keys the report's scripts read
// (postprocess/make_report.py, findings.py), so a wrong file is refused by
// its option's name with exit 2, not found by Python after the work.
#include <filesystem>

namespace rollcheck::io
{
struct ReportJsonInputs
{
  std::filesystem::path validation; ///< `rollcheck validate`'s validation.json; empty: none
  std::filesystem::path audit;      ///< `rollcheck audit --json`; empty: none
  std::filesystem::path robustness; ///< `rollcheck robustness --json`; empty: none
  std::filesystem::path life;       ///< `rollcheck life --json`; empty: none
};

/// InputError naming the option (`command` --validation/--audit/--robustness/--life)
/// and the path for the first input that is not such a JSON object.
void require_report_json_inputs(const ReportJsonInputs& inputs, const char* command);
} // namespace rollcheck::io
