#include "io/batch_report.h"
#include "core/error.h"
#include "io/batch_process.h"
#include "rollcheck_version.h"
#include <fmt/format.h>
#include <fstream>
#include <unistd.h>

namespace rollcheck::io
{
namespace fs = std::filesystem;

fs::path default_scripts_folder() { return fs::path(ROLLCHECK_SOURCE_DIR) / "postprocess"; }

void run_script(const fs::path& python, const fs::path& script, const std::vector<std::string>& args,
                const fs::path& cwd, const fs::path& log)
{
  if (!fs::is_regular_file(script))
    throw InputError(fmt::format("plotting script '{}': no such file", script.string()));
  if (access(python.c_str(), X_OK) != 0)
    throw InputError(fmt::format("--python '{}': not an executable (Debian's python3 with matplotlib and h5py is "
                                 "needed: apt-get install python3-matplotlib python3-h5py)",
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
  const fs::path target = fs::absolute(folder).lexically_normal();
  const fs::path parent = target.parent_path();
  fs::create_directories(parent);
  const std::string stem = target.filename().string();
  const fs::path drawing = parent / fmt::format(".{}.tmp{}", stem, getpid());
  const fs::path replaced = parent / fmt::format(".{}.old{}", stem, getpid());
  fs::remove_all(drawing);
  fs::create_directories(drawing);
  try
  {
    prepare(drawing);
    std::vector<std::string> script_args = args;
    script_args.insert(script_args.end(), {"--out", drawing.string()});
    run_script(python, script, script_args, drawing, drawing / log_name);
  }
  catch (...)
  {
    fs::remove_all(drawing);
    throw;
  }
  if (fs::exists(target))
    fs::rename(target, replaced);
  fs::rename(drawing, target);
  fs::remove_all(replaced);
}

ReportFiles write_report(const fs::path& store, const fs::path& folder, const fs::path& scripts,
                         const fs::path& python)
{
  if (!fs::is_regular_file(store))
    throw InputError(fmt::format("report --from '{}': no such results store", store.string()));
  if (!fs::is_regular_file(scripts / "make_report.py"))
    throw InputError(fmt::format("report --scripts '{}': has no make_report.py", scripts.string()));
  draw_folder(folder, python, scripts / "make_report.py",
              {"--store", fs::absolute(store).string(), "--rollcheck", own_executable().string()}, "report.log",
              [](const fs::path&) {});
  const fs::path target = fs::absolute(folder).lexically_normal();
  return {target / "report.md", target / "report.html"};
}
} // namespace rollcheck::io
