#include "io/batch_report.h"
#include "core/atomic_file.h"
#include "core/data_folder.h"
#include "core/error.h"
#include "io/batch_process.h"
#include "rollcheck_version.h"
#include <fmt/format.h>
#include <fstream>
#include <unistd.h>

namespace rollcheck::io
{
namespace fs = std::filesystem;

fs::path default_scripts_folder() { return data_folder() / "postprocess"; }

void run_script(const fs::path& python, const fs::path& script, const std::vector<std::string>& args,
                const fs::path& cwd, const fs::path& log)
{
  if (!fs::is_regular_file(script))
    throw InputError(fmt::format("plotting script '{}': no such file", script.string()));
  if (access(python.c_str(), X_OK) != 0)
    throw InputError(fmt::format("--python '{}': not an executable (Debian's python3 with matplotlib and h5py is "
                                 "needed: apt-get install python3-matplotlib python3-h5py python3-jinja2)",
                                 python.string()));
  std::vector<std::string> argv{python.string(), script.string()};
  argv.insert(argv.end(), args.begin(), args.end());
  ChildProcess process(argv, cwd, log);
  const ExitStatus status = process.wait();
  if (status.success())
    return;
  std::ifstream file(log);
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (text.size() > 2000)
    text = "..." + text.substr(text.size() - 2000);
  throw ComputationError(fmt::format("{} failed ({}):\n{}", script.string(), status.describe(), text));
}

void draw_folder(const fs::path& folder, const fs::path& python, const fs::path& script,
                 const std::vector<std::string>& args, const std::string& log_name,
                 const std::function<void(const fs::path&)>& prepare)
{
  write_folder_atomically(folder, "output folder", [&](const fs::path& drawing) {
    prepare(drawing);
    std::vector<std::string> script_args = args;
    script_args.insert(script_args.end(), {"--out", drawing.string()});
    run_script(python, script, script_args, drawing, drawing / log_name);
  });
}

ReportFiles write_report(const fs::path& store, const fs::path& folder, const fs::path& scripts,
                         const fs::path& python, const fs::path& validation, const fs::path& audit,
                         const fs::path& robustness, const fs::path& life)
{
  std::vector<std::string> args = {"--store", fs::absolute(store).string(), "--rollcheck", own_executable().string()};
  for (const auto& [option, path] :
       {std::pair{"--validation", validation}, std::pair{"--audit", audit}, std::pair{"--robustness", robustness},
        std::pair{"--life", life}})
    if (!path.empty())
    {
      if (!fs::is_regular_file(path))
        throw InputError(fmt::format("report {} '{}': no such file", option, path.string()));
      args.insert(args.end(), {option, fs::absolute(path).string()});
    }
  if (!fs::is_regular_file(store))
    throw InputError(fmt::format("report --from '{}': no such results store", store.string()));
  if (!fs::is_regular_file(scripts / "make_report.py"))
    throw InputError(fmt::format("report --scripts '{}': has no make_report.py", scripts.string()));
  draw_folder(folder, python, scripts / "make_report.py", args, "report.log", [](const fs::path&) {});
  const fs::path target = fs::absolute(folder).lexically_normal();
  return {target / "report.md", target / "report.html"};
}
} // namespace rollcheck::io
