#pragma once
// The report of a results store: Markdown and HTML with the plots and tables
// that postprocess/make_report.py draws from the store (Debian's
// /usr/bin/python3 with matplotlib and h5py; docs/guide/report.md).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace rollcheck::io
{
struct ReportFiles
{
  std::filesystem::path markdown; ///< report.md, images beside it
  std::filesystem::path html;     ///< report.html, images embedded
};

/// The postprocess/ folder of the source tree the binary was built from.
std::filesystem::path default_scripts_folder();

/// Runs `python script args...` in folder `cwd`, its output in `log`: the one
/// way a plotting script is run. InputError for a missing script or
/// interpreter; ComputationError (with the script's last output) if it fails.
void run_script(const std::filesystem::path& python, const std::filesystem::path& script,
                const std::vector<std::string>& args, const std::filesystem::path& cwd,
                const std::filesystem::path& log);

/// Fills `folder` whole or not at all: `prepare` writes into a temporary
/// folder beside it, then `python script args... --out TMP` runs there (its
/// output in TMP/<log_name>), and the temporary folder replaces `folder` only
/// when both succeeded (core write_folder_atomically: a folder holding files
/// rollcheck did not write is refused, never replaced). Errors as run_script's.
void draw_folder(const std::filesystem::path& folder, const std::filesystem::path& python,
                 const std::filesystem::path& script, const std::vector<std::string>& args,
                 const std::string& log_name, const std::function<void(const std::filesystem::path&)>& prepare);

/// Writes the report of `store` into `folder`, replacing an earlier report
/// whole: it is drawn in a temporary folder that is renamed into place only
/// when the script succeeded. InputError for a missing store, scripts folder
/// or interpreter; ComputationError (with the script's last output) if the
/// script fails.
/// `validation` (the checks JSON of `rollcheck validate`) and `audit` (the JSON
/// of `rollcheck audit`) are shown first when given; `robustness` (the JSON of
/// `rollcheck robustness`) gives the headline's ranges over the modelling choices;
/// `life` (the JSON of `rollcheck life`) the fatigue-life section.
ReportFiles write_report(const std::filesystem::path& store, const std::filesystem::path& folder,
                         const std::filesystem::path& scripts, const std::filesystem::path& python,
                         const std::filesystem::path& validation = {}, const std::filesystem::path& audit = {},
                         const std::filesystem::path& robustness = {}, const std::filesystem::path& life = {});
} // namespace rollcheck::io
