#include "cli/cli.h"

namespace rollcheck::cli
{
void add_hertz_command(CLI::App& app)
{
  CLI::App* sub = app.add_subcommand("hertz", "Not built yet (issue 4)");
  sub->allow_extras();
  on_run(sub, [] { return not_built("hertz", "issue 4"); });
}
} // namespace rollcheck::cli
