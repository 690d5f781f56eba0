#include "cli/cli.h"

namespace rollcheck::cli
{
void add_audit_command(CLI::App& app)
{
  CLI::App* sub = app.add_subcommand("audit", "Not built yet (issue 7)");
  sub->allow_extras();
  on_run(sub, [] { return not_built("audit", "issue 7"); });
}
} // namespace rollcheck::cli
