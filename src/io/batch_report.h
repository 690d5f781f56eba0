#pragma once
// The report of a results store: Markdown and HTML with the plots and tables
// that postprocess/make_report.py draws from the store (Debian's
// /usr/bin/python3 with matplotlib and h5py; README "Report").
#include <filesystem>

namespace rollcheck::io
{
struct ReportFiles
{
  std::filesystem::path markdown; ///< report.md, images beside it
  std::filesystem::path html;     ///< report.html, images embedded
};

/// The postprocess/ folder of the source tree the binary was built from.
std::filesystem::path default_scripts_folder();

/// Writes the report of `store` into `folder`, replacing an earlier report
/// whole: it is drawn in a temporary folder that is renamed into place only
/// when the script succeeded. InputError for a missing store, scripts folder
/// or interpreter; ComputationError (with the script's last output) if the
/// script fails.
ReportFiles write_report(const std::filesystem::path& store, const std::filesystem::path& folder,
                         const std::filesystem::path& scripts, const std::filesystem::path& python);
} // namespace rollcheck::io
