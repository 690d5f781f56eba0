// `rollcheck validate`: the main job. Runs every case in cases/default/ and
// the geometry checks, and says plainly which parts are not built yet.
#include "cli/cli.h"
#include "cli/scenes.h"
#include "geometry/error.h"
#include "geometry/body.h"
#include "geometry/mass_properties.h"
#include "rollcheck_version.h"
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <numbers>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
void add_validate_command(CLI::App& app)
{
  CLI::App* sub = app.add_subcommand("validate", "The main job: run the default cases (cases/default) and report");
  static std::string cases_dir = std::string(ROLLCHECK_SOURCE_DIR) + "/cases/default";
  static std::string json_path;
  sub->add_option("--cases", cases_dir, "Folder of case files to run (default: the embedded cases/default)");
  add_json_option(sub, json_path);
  on_run(sub, [] {
    nlohmann::json summary = {{"rollcheck_version", ROLLCHECK_VERSION}, {"cases", nlohmann::json::array()}};
    if (!std::filesystem::is_directory(cases_dir))
      throw InputError(fmt::format("--cases '{}': not a folder", cases_dir));
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(cases_dir))
      if (entry.path().extension() == ".toml")
        files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    int failed = 0;
    for (const auto& file : files)
    {
      nlohmann::json record = {{"file", file.string()}};
      try
      {
        const io::CaseFile cf = io::read_case_file(file);
        const std::string origin = fmt::format("case file '{}'", file.string());
        const Scene& scene = find_scene(cf.kind, origin);
        record["result"] = scene.run(io::resolve_case(cf, *scene.schema, {}, origin));
        record["status"] = "ok";
        spdlog::info("{}: ok", file.filename().string());
      }
      catch (const std::exception& e)
      {
        record["status"] = "failed";
        record["message"] = e.what();
        spdlog::error("{}: {}", file.filename().string(), e.what());
        ++failed;
      }
      summary["cases"].push_back(record);
    }
    summary["not_built_yet"] = nlohmann::json::array();
    for (const char* part : {"batch runs and the report (issue 6)", "corrected physics and the audit (issue 7)"})
    {
      summary["not_built_yet"].push_back(part);
      spdlog::warn("not built yet: {}", part);
    }
    emit_json(json_path, summary);
    fmt::print("validate: {} case(s) run from {}, {} failed\n", files.size(), cases_dir, failed);
    return failed == 0 ? 0 : 1;
  });
}
} // namespace rollcheck::cli
