#pragma once
// The verdicts of a batch: every case's [[check]] tables (io/case_checks.h)
// applied to its stored summary. A case that failed, or states no check, is
// a failed row: `rollcheck validate` passes only when every case was checked
// and every check holds.
#include "io/batch_run.h"
#include "io/case_checks.h"
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rollcheck::io
{
struct CaseVerdict
{
  std::string case_name;
  std::string kind;
  CheckOutcome outcome;
};

std::vector<CaseVerdict> check_batch(const BatchResult& batch, const std::filesystem::path& out);

/// {"checks": [{case, kind, pointer, criterion, measured, reference, passed}], "passed": n, "failed": m}
nlohmann::json to_json(const std::vector<CaseVerdict>& verdicts);

/// The verdict table, Markdown.
std::string verdict_table(const std::vector<CaseVerdict>& verdicts);
} // namespace rollcheck::io
