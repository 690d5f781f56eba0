// The rules that read `rollcheck oracle` and `rollcheck mesh` outputs: the
// scores of one body or of the oloid against the cylinder, their convergence
// and scaling, the faces touched, the meshes' areas.
#include "audit/cell_values.h"
#include "audit/rules.h"
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::audit::rules
{
namespace
{
/// Least-squares slope and R^2 of log(y) against log(x).
std::pair<double, double> power_law_fit(const std::vector<double>& x, const std::vector<double>& y)
{
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly, syy += ly * ly;
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double r = (n * sxy - sx * sy) / std::sqrt((n * sxx - sx * sx) * (n * syy - sy * sy));
  return {slope, r * r};
}
} // namespace

Rule oloid_more_uniform()
{
  return [](const std::vector<CommandOutput*>& out) {
    const double u_oloid = out[0]->number("/uniformity_score_continuum");
    const double u_cylinder = out[1]->number("/uniformity_score_continuum");
    return CellResult{fmt::format("U_inf {:.3f} (cylinder {:.3f})", u_oloid, u_cylinder), u_oloid < u_cylinder};
  };
}

Rule uniformity_ratio_above_one()
{
  return [](const std::vector<CommandOutput*>& out) {
    const double r =
        out[1]->number("/uniformity_score_continuum") / out[0]->number("/uniformity_score_continuum");
    return CellResult{fmt::format("U_inf ratio {:.2f}x", r), r > 1};
  };
}

Rule convergence_ratio(double rate, double tolerance)
{
  return [=](const std::vector<CommandOutput*>& out) {
    CommandOutput& oracle = *out[0];
    const std::size_t last = oracle.at("/convergence/cds").size() - 1;
    const double first_n = oracle.number("/convergence/cds/0/0");
    const double last_n = oracle.number(fmt::format("/convergence/cds/{}/0", last));
    const double r =
        oracle.number("/convergence/cds/0/1") / oracle.number(fmt::format("/convergence/cds/{}/1", last));
    return CellResult{fmt::format("{} ({:g} → {:g} samples)", times(r), first_n, last_n), within(r, rate, tolerance)};
  };
}

Rule face_count_exponent(double exponent, double tolerance)
{
  return [=](const std::vector<CommandOutput*>& out) {
    std::vector<double> faces, cds;
    for (CommandOutput* o : out)
    {
      faces.push_back(o->number("/n_faces"));
      cds.push_back(o->number("/cds"));
    }
    const auto [slope, r2] = power_law_fit(faces, cds);
    return CellResult{fmt::format("{:.2f} (R² {:.3f})", slope, r2), within(slope, exponent, tolerance)};
  };
}

Rule threshold_spread(double tolerance)
{
  return [=](const std::vector<CommandOutput*>& out) {
    const double at_default = out[1]->number("/cds") / out[0]->number("/cds");
    double lo = at_default, hi = at_default;
    for (std::size_t i = 2; i + 1 < out.size(); i += 2)
    {
      const double r = out[i + 1]->number("/cds") / out[i]->number("/cds");
      lo = std::min(lo, r), hi = std::max(hi, r);
    }
    const double spread = std::max(hi / at_default - 1, 1 - lo / at_default);
    return CellResult{fmt::format("{} ... {} ({:.0f} %)", times(lo), times(hi), 100 * spread), spread <= tolerance};
  };
}

Rule cylinder_fds_infinite()
{
  return [](const std::vector<CommandOutput*>& out) {
    const double fo = out[0]->number("/fds"), fy = out[1]->number("/fds");
    CellResult cell{fmt::format("oloid {}, cylinder {}", sci(fo), sci(fy)), std::isinf(fy) && std::isfinite(fo)};
    if (out.size() == 4)
    {
      const double mo = out[2]->number("/fds"), my = out[3]->number("/fds");
      cell.holds = cell.holds && std::isinf(my) && std::isfinite(mo);
      cell.value = fmt::format("all corrected: {}; E* = E/(1-ν²) alone: oloid {}, cylinder {}", cell.value, sci(mo),
                               sci(my));
    }
    return cell;
  };
}

Rule areas_within(double area, double tolerance, std::vector<std::string> labels)
{
  return [=](const std::vector<CommandOutput*>& out) {
    CellResult cell{"", true};
    for (std::size_t i = 0; i < labels.size(); ++i)
    {
      const double a = out[i]->number("/area_m2");
      cell.holds = cell.holds && within(a, area, tolerance);
      append_listed(cell.value, fmt::format("{}{:.4f}", labels[i].empty() ? "" : labels[i] + " ", a));
    }
    return cell;
  };
}

Rule tds_lowest()
{
  return [](const std::vector<CommandOutput*>& out) {
    const double tds = out[0]->number("/tds"), cds = out[0]->number("/cds");
    std::string lower;
    for (const char* key : {"cds", "sds", "wds_vol", "wds_depth", "fds"})
      if (out[0]->number(std::string("/") + key) < tds * (1 - 1e-9))
        append_listed(lower, key);
    return CellResult{fmt::format("TDS {}, CDS {}; below TDS: {}", sci(tds), sci(cds), lower.empty() ? "none" : lower),
                      lower.empty() && tds < cds};
  };
}

Rule every_face_touched()
{
  return [](const std::vector<CommandOutput*>& out) {
    const double untouched = out[0]->number("/contact/faces_without_contact");
    const double faces = out[0]->number("/n_faces");
    CellResult cell{fmt::format("{:g} of {:g} faces untouched", untouched, faces), untouched == 0};
    if (out[0]->has("/per_face"))
    {
      const nlohmann::json& counts = out[0]->at("/per_face/contact_counts");
      const nlohmann::json& areas = out[0]->at("/per_face/face_areas_m2");
      double area = 0;
      for (std::size_t f = 0; f < counts.size(); ++f)
        area += counts[f].get<double>() == 0 ? areas[f].get<double>() : 0.0;
      cell.value += fmt::format(" (area {:.3f} m²)", area);
    }
    return cell;
  };
}

Rule coverage_at_least(double fraction)
{
  return [=](const std::vector<CommandOutput*>& out) {
    const double coverage = out[0]->number("/coverage");
    CellResult cell{fmt::format("coverage {:.4f}", coverage), coverage >= fraction};
    std::string hertz;
    for (std::size_t i = 1; i < out.size(); ++i)
      append_listed(hertz, fmt::format("{:.3f} ({:g}²)", out[i]->number("/coverage"),
                                       out[i]->number("/face_subdivisions")));
    if (!hertz.empty())
      cell.value += "; Hertz width, by face subdivisions: " + hertz;
    return cell;
  };
}
} // namespace rollcheck::audit::rules
