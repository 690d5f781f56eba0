#include "cli/cli.h"

namespace rollcheck::cli
{
void add_report_command(CLI::App& app)
{
  CLI::App* sub = app.add_subcommand("report", "Not built yet (issue 6)");
  sub->allow_extras();
  on_run(sub, [] { return not_built("report", "issue 6"); });
}
} // namespace rollcheck::cli
