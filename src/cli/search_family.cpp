// `rollcheck search --score fem-sds`: the family table of FEM-SDS over whole
// rolling loops (study/loop_scores/fem_sds_family.h): JSON with a row per genome, the
// report with its Markdown table on the log, and with --out the folder of family.json,
// table.md and family.png (postprocess/plot_fem_family.py).
#include "cli/search_family.h"
#include "cli/cli.h"
#include "core/atomic_file.h"
#include "io/batch_report.h"
#include "study/loop_scores/fem_sds_family.h"
#include <mpi.h>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
nlohmann::json run_family_scores(oracle::SearchGrid grid, int points, double radius_m, const std::string& out,
                                 const std::string& python)
{
  study::loop_scores::FamilySettings settings;
  settings.grid = grid;
  settings.points = points;
  settings.scoring.body.radius_m = radius_m;
  const study::loop_scores::FamilyResult result = study::loop_scores::fem_sds_family(MPI_COMM_WORLD, settings);
  const nlohmann::json j = to_json(result);
  if (process_rank() != 0)
    return j;
  print_summary(study::loop_scores::report(result, settings));
  if (!out.empty())
    io::draw_folder(out, python, io::default_scripts_folder() / "plot_fem_family.py", {}, "plot.log",
                    [&](const std::filesystem::path& folder) {
                      write_file_atomically(folder / "family.json", j.dump(1) + "\n");
                      write_file_atomically(folder / "table.md", study::loop_scores::markdown_table(result));
                    });
  return j;
}
} // namespace rollcheck::cli
