// `rollcheck run CASE.toml [--set key=value ...]`: runs one case file through
// the scene its [scene] kind names; `rollcheck run --template KIND` prints a
// commented case file of that kind instead.
#include "cli/cli.h"
#include "cli/scenes.h"
#include "core/error.h"
#include "io/case_template.h"
#include <fmt/format.h>

namespace rollcheck::cli
{
void add_run_command(CLI::App& app)
{
  static std::string case_path, template_kind;
  static std::vector<std::string> overrides;
  CLI::App* sub = add_command(app, "run", "Run a case file (TOML, see docs/guide/case-files.md)", [] {
    if (!template_kind.empty())
    {
      const Scene& scene = find_scene(template_kind, "option --template");
      fmt::print("{}", io::case_template(*scene.schema));
      return CommandResult{};
    }
    if (case_path.empty())
      throw InputError("run: give a case file (CASE.toml) or --template KIND");
    const io::CaseFile file = io::read_case_file(case_path);
    const std::string origin = fmt::format("case file '{}'", case_path);
    const Scene& scene = find_scene(file.kind, origin);
    const io::Parameters params = io::resolve_case(file, *scene.schema, overrides, origin);
    check_scene_outputs(*scene.schema, params);
    start_mpi();
    nlohmann::json summary = scene.run(params);
    summary["case"] = {{"file", case_path}, {"parameters", params.to_json()}};
    return CommandResult{summary};
  });
  CLI::Option* case_option = sub->add_option("case", case_path, "Case file (.toml) with a [scene] table");
  sub->add_option("--set", overrides, "Override a case key: key=value (repeatable)");
  sub->add_option("--template", template_kind,
                  "Print a case file of this kind (a scene: mesh, oracle, hertz, ...), every key at its default under "
                  "a comment, and run nothing")
      ->excludes(case_option);
}
} // namespace rollcheck::cli
