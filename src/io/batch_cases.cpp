#include "io/batch_cases.h"
#include "core/error.h"
#include "io/case_hash.h"
#include <algorithm>
#include <fmt/format.h>
#include <fstream>
#include <glob.h>
#include <set>

namespace rollcheck::io
{
namespace
{
namespace fs = std::filesystem;

std::vector<fs::path> toml_files_in(const fs::path& folder)
{
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder))
    if (entry.is_regular_file() && entry.path().extension() == ".toml")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<fs::path> glob_matches(const std::string& pattern)
{
  glob_t matches{};
  std::vector<fs::path> paths;
  if (glob(pattern.c_str(), 0, nullptr, &matches) == 0)
    for (std::size_t i = 0; i < matches.gl_pathc; ++i)
      paths.emplace_back(matches.gl_pathv[i]);
  globfree(&matches);
  return paths;
}

/// Relative paths that name existing files, made absolute (see
/// resolve_batch_cases); each such file with the SHA-256 of its content.
nlohmann::json anchor_input_paths(const Schema& schema, nlohmann::json& parameters, std::vector<std::string>& overrides)
{
  nlohmann::json inputs = nlohmann::json::object();
  for (const Parameter& p : schema.parameters)
  {
    if (!std::holds_alternative<std::string>(p.default_value) || !p.choices.empty())
      continue;
    const std::string value = parameters.at(p.key).get<std::string>();
    std::error_code ec;
    if (value.empty() || !fs::is_regular_file(value, ec))
      continue;
    std::ifstream in(value, std::ios::binary);
    const std::string content{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad())
      throw InputError(fmt::format("{} '{}': cannot be read", p.key, value));
    const std::string absolute = fs::absolute(value).lexically_normal().string();
    inputs[p.key] = {{"file", absolute}, {"sha256", sha256_hex(content)}};
    if (fs::path(value).is_absolute())
      continue;
    parameters[p.key] = absolute;
    overrides.push_back(fmt::format("{}={}", p.key, absolute));
  }
  return inputs;
}

BatchCase resolve_one(const fs::path& file, const FindSchema& find_schema)
{
  BatchCase c;
  c.file = fs::absolute(file).lexically_normal();
  c.name = file.stem().string();
  try
  {
    const CaseFile case_file = read_case_file(file);
    const std::string origin = fmt::format("case file '{}'", file.string());
    const Schema& schema = find_schema(case_file.kind, origin);
    c.kind = case_file.kind;
    c.parameters = resolve_case(case_file, schema, {}, origin).to_json();
    c.inputs = anchor_input_paths(schema, c.parameters, c.overrides);
    if (const auto ranks = c.parameters.find("mpi_ranks"); ranks != c.parameters.end() && ranks->is_number_integer())
    {
      c.mpi_ranks = ranks->get<int>();
      if (c.mpi_ranks < 1)
        throw InputError(fmt::format("{}: 'mpi_ranks' must be at least 1, got {}", origin, c.mpi_ranks));
    }
    c.hash = case_hash({{"parameters", c.parameters}, {"inputs", c.inputs}});
  }
  catch (const std::exception& e)
  {
    c.error = e.what();
  }
  return c;
}
} // namespace

std::vector<fs::path> expand_case_arguments(const std::vector<std::string>& arguments)
{
  std::vector<fs::path> files;
  std::set<fs::path> seen;
  auto add = [&](const fs::path& file) {
    if (seen.insert(fs::weakly_canonical(file)).second)
      files.push_back(file);
  };
  for (const std::string& argument : arguments)
  {
    std::vector<fs::path> named;
    if (fs::exists(argument))
      named.emplace_back(argument);
    else if (argument.find_first_of("*?[") != std::string::npos)
      named = glob_matches(argument);
    if (named.empty())
      throw InputError(fmt::format("batch: '{}' is neither a case file, nor a folder, nor a glob that matches one",
                                   argument));
    for (const fs::path& path : named)
    {
      if (fs::is_directory(path))
      {
        const std::vector<fs::path> inside = toml_files_in(path);
        if (inside.empty() && named.size() == 1)
          throw InputError(fmt::format("batch: folder '{}' holds no .toml case file", path.string()));
        std::for_each(inside.begin(), inside.end(), add);
      }
      else
        add(path);
    }
  }
  return files;
}

std::vector<BatchCase> resolve_batch_cases(const std::vector<fs::path>& files, const FindSchema& find_schema)
{
  std::vector<BatchCase> cases;
  for (const fs::path& file : files)
    cases.push_back(resolve_one(file, find_schema));
  // Case files of one name in different folders are told apart by their
  // folder's name, and if that is not enough, by their position.
  auto count = [&](const std::string& name) {
    return std::count_if(cases.begin(), cases.end(), [&](const BatchCase& c) { return c.name == name; });
  };
  std::vector<std::string> names;
  for (const BatchCase& c : cases)
    names.push_back(count(c.name) > 1 ? fmt::format("{}_{}", c.file.parent_path().filename().string(), c.name)
                                      : c.name);
  for (std::size_t i = 0; i < cases.size(); ++i)
    cases[i].name = std::count(names.begin(), names.end(), names[i]) > 1 ? fmt::format("{}_{}", names[i], i)
                                                                          : names[i];
  return cases;
}
} // namespace rollcheck::io
