#pragma once
// The modes of the audit's table, its columns: the ways each claim is
// recomputed, their names and what each means.
#include "audit/table.h"
#include <string>
#include <utility>
#include <vector>

namespace rollcheck::audit
{
/// The modes' names, in column order.
namespace mode
{
inline const std::string& paper = paper_compatible_mode;
inline const std::string matched = "matched resolution";
inline const std::string true_oloid = "true oloid";
inline const std::string corrected = "corrected physics";
inline const std::string rolling = "real rolling";
inline const std::string contact = "contact mechanics";
inline const std::string life = "fatigue life";
} // namespace mode

/// The modes of the table, in column order, with what each means.
std::vector<std::pair<std::string, std::string>> audit_modes();
} // namespace rollcheck::audit
