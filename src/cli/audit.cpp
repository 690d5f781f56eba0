// `rollcheck audit`: recomputes every quantitative claim of the preprint in
// each mode that applies (paper-compatible, matched mesh resolution, true
// oloid, corrected physics, real rolling, contact mechanics) and prints the
// claim table. The claims are data in the audit layer (audit/claims.h), each
// number the output of a `rollcheck` command run as a child process of this
// executable exactly as the table lists it (audit/runner.h).
#include "cli/cli.h"
#include "core/atomic_file.h"
#include "core/child_process.h"
#include "core/comma_list.h"
#include "core/data_folder.h"
#include "core/error.h"
#include "audit/runner.h"
#include "io/work_budget.h"
#include <filesystem>
#include <fmt/format.h>

namespace rollcheck::cli
{
namespace
{
namespace fs = std::filesystem;

/// The reference meshes the paper-compatible mode scores, checked before any
/// command runs.
fs::path reference_meshes(const std::string& folder)
{
  const fs::path meshes = fs::weakly_canonical(fs::path(folder));
  for (const char* name : {"oloid_reference.obj", "cylinder_reference.obj"})
    if (!fs::is_regular_file(meshes / name))
      throw InputError(fmt::format("option --reference-meshes: '{}' has no {} (the reference meshes of "
                                   "meshes/reference)",
                                   meshes.string(), name));
  return meshes;
}
} // namespace

void add_audit_command(CLI::App& app)
{
  CLI::App* sub = app.add_subcommand(
      "audit", "Recompute every quantitative claim of the preprint in each mode (paper-compatible, matched "
               "resolution, true oloid, corrected physics, real rolling) and print the claim table with verdicts "
               "and commands");
  static std::string json_path, markdown_path, outputs_folder, claims_list;
  static audit::AuditSettings settings;
  static std::string meshes = (data_folder() / "meshes" / "reference").string();
  add_json_option(sub, json_path);
  sub->add_option("--markdown", markdown_path,
                  "Also write the table as Markdown to PATH ('-' for stdout) (default: none)");
  sub->add_flag("--quick", settings.quick,
                "Fewer thresholds (0.01, 0.04, 0.16) and mesh sizes (100, 200, 400 points per circle) (default: off)");
  sub->add_option("--threads", settings.threads, "Commands run at once; 0 = one per core (default: 0)")
      ->check(CLI::Range(0, static_cast<int>(io::thread_count.upper)));
  sub->add_option("--reference-meshes", meshes, "Folder of the reference meshes (default: <source>/meshes/reference)");
  sub->add_option("--claims", claims_list,
                  "Decide only these claims (ids as in the JSON's claims[].id, comma-separated), running only their "
                  "commands (default: every claim)");
  sub->add_option("--outputs", outputs_folder,
                  "Also keep each command's JSON output as DIR/cN.json, N its number in the table, for a later step "
                  "that reads one (the main job's report reads the robustness command's) (default: none)");
  on_run(sub, [] {
    if (json_path == "-" && markdown_path == "-")
      throw InputError("options --json and --markdown: only one of them can be '-' (stdout)");
    settings.reference_meshes = reference_meshes(meshes);
    for (const std::string_view id : comma_list_items(claims_list))
      settings.claims.emplace_back(id);
    // Refused before the commands run, not after them.
    for (const auto& [path, option] : {std::pair{json_path, "option --json"}, std::pair{markdown_path, "option --markdown"}})
      if (!path.empty() && path != "-")
        check_output_file(path, option);
    if (!outputs_folder.empty())
      check_output_folder(outputs_folder, "audit --outputs");
    std::vector<audit::CommandOutput> outputs;
    const audit::AuditTable table = audit::run_audit(settings, process::own_executable(), &outputs);
    if (!outputs_folder.empty())
      write_folder_atomically(outputs_folder, "audit --outputs", [&](const fs::path& folder) {
        for (std::size_t i = 0; i < outputs.size(); ++i)
          write_file_atomically(folder / (audit::command_id(i) + ".json"), outputs[i].at("").dump(2) + "\n");
      });
    const std::string markdown = audit::to_markdown(table);
    if (!markdown_path.empty() && markdown_path != "-")
      write_file_atomically(markdown_path, markdown);
    if (markdown_path == "-" || json_path != "-")
      write_stdout(markdown, "the claim table");
    emit_json(json_path, to_json(table));
    return 0;
  });
}
} // namespace rollcheck::cli
