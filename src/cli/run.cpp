// `rollcheck run CASE.toml [--set key=value ...]`: runs one case file through
// the scene its [scene] kind names.
#include "cli/cli.h"
#include "cli/scenes.h"
#include <fmt/format.h>

namespace rollcheck::cli
{
void add_run_command(CLI::App& app)
{
  static std::string case_path;
  static std::vector<std::string> overrides;
  CLI::App* sub = add_command(app, "run", "Run a case file (TOML, see docs/guide/case-files.md)", [] {
    const io::CaseFile file = io::read_case_file(case_path);
    const std::string origin = fmt::format("case file '{}'", case_path);
    const Scene& scene = find_scene(file.kind, origin);
    const io::Parameters params = io::resolve_case(file, *scene.schema, overrides, origin);
    check_scene_outputs(*scene.schema, params);
    nlohmann::json summary = scene.run(params);
    summary["case"] = {{"file", case_path}, {"parameters", params.to_json()}};
    return CommandResult{summary};
  });
  sub->add_option("case", case_path, "Case file (.toml) with a [scene] table")->required();
  sub->add_option("--set", overrides, "Override a case key: key=value (repeatable)");
}
} // namespace rollcheck::cli
