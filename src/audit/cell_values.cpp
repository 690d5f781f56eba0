#include "audit/cell_values.h"
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::audit
{
std::string sci(double v) { return std::isinf(v) ? "∞" : fmt::format("{:.3g}", v); }

std::string times(double v)
{
  return std::isnan(v) ? "∞/∞" : std::isinf(v) ? "∞" : fmt::format("{:.1f}x", v);
}

std::string genome_text(const Genome& g)
{
  return fmt::format("({:g}, {:.2f}, {:.2f})", g.theta_deg, g.offset, g.ratio);
}

bool within(double value, double paper, double tolerance) { return std::abs(value / paper - 1) <= tolerance; }

bool to_printed_digits(double value, double paper, int digits)
{
  if (paper == 0 || !std::isfinite(value))
    return false;
  const double unit = std::pow(10.0, std::floor(std::log10(std::abs(paper))) - digits + 1);
  return std::abs(value - paper) < unit * (1 - 1e-9);
}

void append_listed(std::string& list, const std::string& item, std::string_view separator)
{
  if (!list.empty())
    list += separator;
  list += item;
}

CellResult each_checked(const std::vector<Checked>& numbers, double tolerance)
{
  CellResult cell{"", true};
  int printed = 0;
  for (const Checked& n : numbers)
  {
    const bool ok = within(n.value, n.paper, tolerance);
    printed += to_printed_digits(n.value, n.paper, n.digits);
    cell.holds = cell.holds && ok;
    append_listed(cell.value, n.shown + (ok ? "" : " (✗)"));
  }
  cell.value += fmt::format(" ({} of {} to the printed digits)", printed, numbers.size());
  return cell;
}
} // namespace rollcheck::audit
