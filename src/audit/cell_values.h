#pragma once
// How the rules compare a cell's numbers with the paper's and print them:
// the formats and the tolerance test every rules_*.cpp shares.
#include "audit/rules.h"
#include <string>
#include <string_view>
#include <vector>

namespace rollcheck::audit
{
/// Three significant digits; "∞" for infinity.
std::string sci(double v);
/// A ratio to one decimal, "58.1x"; "∞" for infinity, "∞/∞" for NaN (0/0, ∞/∞).
std::string times(double v);
/// "(theta, d, rho)", as the preprint prints a genome.
std::string genome_text(const Genome& g);

/// |value / paper - 1| <= tolerance.
bool within(double value, double paper, double tolerance);
/// `value` printed to `digits` significant digits, rounded or truncated, is
/// `paper`: |value - paper| below one unit of the last printed digit.
bool to_printed_digits(double value, double paper, int digits);

/// Appends `item` to the list `list`, after `separator` unless it is the first.
void append_listed(std::string& list, const std::string& item, std::string_view separator = ", ");

/// A number a rule checks against the paper's, printed as `shown`.
struct Checked
{
  std::string shown; ///< its label and value, as the cell prints them
  double value, paper;
  int digits; ///< significant digits the paper prints
};

/// Holds when each number is within `tolerance` of its paper value; the value
/// lists each `shown` (" (✗)" after those outside) and counts those equal to
/// the printed digits: "a 1.2, b 3.4 (✗) (1 of 2 to the printed digits)".
CellResult each_checked(const std::vector<Checked>& numbers, double tolerance);
} // namespace rollcheck::audit
