// FEM-SDS results as text (study/loop_scores/fem_sds.h): the tables of the
// directly solved orientations and the report the CLI logs.
#include "core/json_number.h"
#include "study/loop_scores/fem_sds.h"
#include <fmt/format.h>

namespace rollcheck::study::loop_scores
{
namespace
{
std::string orientation_table(const std::vector<FemSdsOrientation>& results)
{
  std::string t = "| # | t (s) | support | c | creases | point-Hertz p0 (MPa) | line-Hertz p0 (MPa) | FEM p0 (MPa) | "
                  "FEM finer (MPa) | change | FEM / line - 1 | length (m) | width (um) | DOFs | Newton | s |\n"
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const FemSdsOrientation& r : results)
  {
    t += fmt::format("| {} | {:.4g} | {} | {} | {} | {:.4g} |", r.index, r.locus.time_s,
                     support_name(r.locus.support.kind),
                     r.locus.ruling ? fmt::format("{:.3f}", r.locus.centre_of_pressure) : std::string("-"),
                     r.locus.creases.size(), r.point_hertz_peak_pa / 1e6);
    if (r.solved)
      t += fmt::format(" {:.4g} | {:.4g} | {:.4g} | {:+.2f} % | {:+.2f} % | {:.4g} | {:.3g} | {} | {} | {:.1f} |\n",
                       r.line_hertz_peak_pa / 1e6, r.fem_peak_pa / 1e6, r.fem_peak_refined_pa / 1e6,
                       100 * (r.fem_peak_refined_pa / r.fem_peak_pa - 1),
                       100 * (r.fem_peak_pa / r.line_hertz_peak_pa - 1), r.contact_length_m, 1e6 * r.contact_width_m,
                       r.dofs, r.newton_iterations, r.wall_s);
    else
      t += " - | - | - | - | - | - | - | - | - | - |\n";
  }
  return t;
}

std::string slab_table(const std::vector<FemSdsOrientation>& results)
{
  std::string t = "| # | level | DOFs | layers | Newton | s | approach factor | c (slab / locus) | slab peak / slices' - 1 "
                  "| max over slices of abs(slab / slice - 1) | end p at s = 0, L (MPa) |\n"
                  "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const FemSdsOrientation& r : results)
    for (const fem::SlabFem& slab : r.slab)
      t += fmt::format("| {} | {} | {} | {} | {} | {:.1f} | {:.4f} | {:.4f} / {:.4f} | {:+.2f} % | {:.2f} % | {:.4g}, "
                       "{:.4g} |\n",
                       r.index, slab.refine, slab.dofs, slab.layers, slab.newton_iterations, slab.wall_s,
                       slab.approach_factor, slab.centre_of_pressure, r.locus.centre_of_pressure,
                       100 * r.slab_peak_difference(slab), 100 * r.slab_slice_difference(slab),
                       slab.end_peak_pressure_pa[0] / 1e6, slab.end_peak_pressure_pa[1] / 1e6);
  return t;
}
} // namespace

std::string markdown_table(const FemSdsResult& result)
{
  std::string table = orientation_table(result.orientations);
  if (result.slab_checked > 0)
    table += "\n3D slab of the whole ruling against the slices (fem/scenes/slab_contact.h; square end faces; "
             "docs/methods/fem-sds.md#creases):\n\n"
             + slab_table(result.orientations);
  return table;
}

std::string report(const FemSdsResult& result)
{
  const LoopSds& loop = result.loop;
  return fmt::format("\nfem-sds {} ({}):\n\n{}\nover the {} samples of the loop: point-Hertz SDS (the preprint's) {}, "
                     "line-Hertz SDS {}, FEM-SDS {} ({}; {} FEM solves, K-to-2K change {}); table against direct FEM "
                     "at the orientations above: {:.3f} %\n\n",
                     result.body, result.source, markdown_table(result), loop.samples,
                     json_number(loop.point_hertz.value).dump(), json_number(loop.line_hertz.value).dump(),
                     json_number(loop.fem.value).dump(), loop.status(), loop.fem_solves,
                     json_number_or_null(loop.table_change()).dump(), 100 * result.table_vs_direct_worst);
}
} // namespace rollcheck::study::loop_scores
