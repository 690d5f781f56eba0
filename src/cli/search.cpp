#include "cli/cli.h"

namespace rollcheck::cli
{
void add_search_command(CLI::App& app)
{
  CLI::App* sub = app.add_subcommand("search", "Not built yet (issue 3)");
  sub->allow_extras();
  on_run(sub, [] { return not_built("search", "issue 3"); });
}
} // namespace rollcheck::cli
