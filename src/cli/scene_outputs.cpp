// The output layer of the scenes: each scene declares which of its
// parameters are output paths, and every path is checked before the scene
// computes anything (from its options, `rollcheck run` and a batch's cases).
#include "cli/cli.h"
#include "core/atomic_file.h"
#include <fmt/format.h>
#include <map>

namespace rollcheck::cli
{
namespace
{
std::map<std::string, std::vector<SceneOutput>>& declared()
{
  static std::map<std::string, std::vector<SceneOutput>> outputs;
  return outputs;
}
} // namespace

void declare_outputs(const io::Schema& schema, std::vector<SceneOutput> outputs)
{
  declared()[schema.kind] = std::move(outputs);
}

void check_scene_outputs(const io::Schema& schema, const io::Parameters& params)
{
  const auto found = declared().find(schema.kind);
  if (found == declared().end())
    return;
  for (const SceneOutput& output : found->second)
  {
    const std::string& path = params.text(output.key);
    if (path.empty())
      continue;
    const std::string origin = fmt::format("{} (case key {})", schema.find(output.key, schema.kind).flag, output.key);
    if (output.kind == OutputKind::file)
      check_output_file(path, origin);
    else
      check_output_folder(path, origin);
  }
}
} // namespace rollcheck::cli
