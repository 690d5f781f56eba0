// `rollcheck run CASE.toml [--set key=value ...]`: runs one case file through
// the scene its [scene] kind names.
#include "cli/cli.h"
#include "cli/scenes.h"
#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
void add_run_command(CLI::App& app)
{
  CLI::App* sub = app.add_subcommand("run", "Run a case file (TOML, see README 'Case files')");
  static std::string case_path, json_path;
  static std::vector<std::string> overrides;
  sub->add_option("case", case_path, "Case file (.toml) with a [scene] table")->required();
  sub->add_option("--set", overrides, "Override a case key: key=value (repeatable)");
  add_json_option(sub, json_path);
  on_run(sub, [] {
    const io::CaseFile file = io::read_case_file(case_path);
    const std::string origin = fmt::format("case file '{}'", case_path);
    const Scene& scene = find_scene(file.kind, origin);
    const io::Parameters params = io::resolve_case(file, *scene.schema, overrides, origin);
    nlohmann::json summary = scene.run(params);
    summary["case"] = {{"file", case_path}, {"parameters", params.to_json()}};
    emit_json(json_path, summary);
    return 0;
  });
}
} // namespace rollcheck::cli
