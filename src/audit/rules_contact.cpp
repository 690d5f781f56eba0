// The rules that read the contact mechanics' outputs: `rollcheck hertz` (FEM
// against Hertz), `rollcheck fem-sds` (FEM-SDS over a loop of real rolling,
// its slices against line-contact Hertz) and `rollcheck rim` (the loop's ends).
#include "audit/cell_values.h"
#include "audit/rules.h"
#include "core/error.h"
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <optional>

namespace rollcheck::audit::rules
{
Rule fem_agrees_with_hertz(double tolerance)
{
  return [=](const std::vector<CommandOutput*>& out) {
    const double a = out[0]->number("/a_error"), p_axi = out[0]->number("/p0_error");
    const double b = out[1]->number("/b_error"), p_line = out[1]->number("/p0_error");
    const bool holds = std::abs(a) <= tolerance && std::abs(p_axi) <= tolerance && std::abs(b) <= tolerance &&
                       std::abs(p_line) <= tolerance;
    return CellResult{fmt::format("sphere (axi): a {:+.2f} %, p0 {:+.2f} %; cylinder (plane strain): b {:+.2f} %, "
                                  "p0 {:+.2f} %",
                                  100 * a, 100 * p_axi, 100 * b, 100 * p_line),
                      holds};
  };
}

Rule point_hertz_is_contact_pressure(double tolerance)
{
  return [=](const std::vector<CommandOutput*>& out) {
    CommandOutput& fem = *out[0];
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (std::size_t i = 0; i < fem.at("/per_orientation").size(); ++i)
    {
      const std::string o = fmt::format("/per_orientation/{}", i);
      if (!fem.at(o + "/fem_solved").get<bool>())
        continue;
      const double r = fem.number(o + "/point_hertz_peak_pa") / fem.number(o + "/fem_peak_pa");
      lo = std::min(lo, r), hi = std::max(hi, r);
    }
    if (hi == 0)
      throw ComputationError(fmt::format("`{}` solved no orientation", fem.command()));
    const double line = fem.number("/fem_vs_line_hertz_worst");
    return CellResult{fmt::format("point Hertz / FEM peak {:.1f}x ... {:.1f}x; FEM vs line Hertz worst {:.2f} %", lo,
                                  hi, 100 * line),
                      within(lo, 1, tolerance) && within(hi, 1, tolerance)};
  };
}

Rule converged_sds_ratio(double paper, double tolerance)
{
  return [=](const std::vector<CommandOutput*>& out) {
    for (CommandOutput* o : out)
      if (!o->at("/converged").get<bool>())
        return CellResult{fmt::format("not converged: {}", o->at("/fem_sds_status").get<std::string>()), false};
    auto ratio = [&](const std::string& pointer) { return out[1]->number(pointer) / out[0]->number(pointer); };
    const double fem = ratio("/fem_sds");
    return CellResult{fmt::format("FEM-SDS {:.3g}x (line Hertz {:.3g}x, the preprint's point Hertz over the same "
                                  "loop {:.3g}x)",
                                  fem, ratio("/line_hertz_sds"), ratio("/analytic_sds")),
                      within(fem, paper, tolerance)};
  };
}

Rule line_contact_fatigue(double fatigue_load_n, double endurance_limit_pa)
{
  return [=](const std::vector<CommandOutput*>& out) {
    // Line contact: p0 grows as sqrt(F) (Johnson 1985, eq. 4.45); a zero-to-p0
    // cycle has the amplitude p0 / 2. No amplitude above the endurance limit:
    // no damage anywhere, an infinite FDS.
    auto amplitude = [&](CommandOutput& o) {
      return 0.5 * o.number("/loop/fem_peak_pa") * std::sqrt(fatigue_load_n / o.number("/normal_load_n"));
    };
    const double ao = amplitude(*out[0]), ay = amplitude(*out[1]);
    const bool oloid_finite = ao > endurance_limit_pa, cylinder_infinite = ay <= endurance_limit_pa;
    return CellResult{fmt::format("largest stress amplitude at {:g} N: body {:.3g} MPa, cylinder {:.3g} MPa, endurance "
                                  "limit {:.3g} MPa: FDS body {}, cylinder {}",
                                  fatigue_load_n, ao / 1e6, ay / 1e6, endurance_limit_pa / 1e6,
                                  oloid_finite ? "finite" : "∞", cylinder_infinite ? "∞" : "finite"),
                      oloid_finite && cylinder_infinite};
  };
}

Rule fem_agrees_with_line_hertz(double tolerance)
{
  return [=](const std::vector<CommandOutput*>& out) {
    CommandOutput& fem = *out[0];
    const double slices = fem.number("/fem_vs_line_hertz_worst");
    const double loop = fem.number("/fem_sds") / fem.number("/line_hertz_sds") - 1;
    const double point = fem.number("/analytic_sds") / fem.number("/fem_sds");
    return CellResult{fmt::format("FEM vs line-contact Hertz: slices {:.2f} %, FEM-SDS / line-Hertz SDS over the loop "
                                  "{:+.2f} %; the preprint's point-Hertz SDS {:.3g}x FEM-SDS",
                                  100 * slices, 100 * loop, point),
                      slices <= tolerance && std::abs(loop) <= tolerance};
  };
}

Rule rims_free_of_concentration()
{
  return [](const std::vector<CommandOutput*>& out) {
    struct Rims
    {
      double loaded = 0, samples = 0, singular = 0;
      std::optional<double> end_to_interior; ///< none: singular
    };
    auto read = [](CommandOutput& o) {
      Rims r;
      r.loaded = o.number("/loop_scores/loaded_ends");
      r.samples = o.number("/loop_scores/loaded_end_samples");
      r.singular = r.loaded > 0 ? o.number("/loop_scores/end_aware/0/singular_ends") : 0;
      if (!o.at("/loop_end_to_interior").is_null())
        r.end_to_interior = o.number("/loop_end_to_interior");
      return r;
    };
    auto describe = [](const Rims& r) {
      return fmt::format("{:.0f} of {:.0f} loaded rim ends singular ({:.0f} samples load a rim){}", r.singular,
                         r.loaded, r.samples,
                         r.end_to_interior ? fmt::format(", largest end pressure {:.2f}x the interior's",
                                                         *r.end_to_interior)
                                           : std::string());
    };
    const Rims oloid = read(*out[0]), cylinder = read(*out[1]);
    return CellResult{fmt::format("sharp edges on the rigid plane: oloid {}; cylinder {}", describe(oloid),
                                  describe(cylinder)),
                      oloid.singular == 0 && oloid.end_to_interior.value_or(0) <= 1};
  };
}
} // namespace rollcheck::audit::rules
