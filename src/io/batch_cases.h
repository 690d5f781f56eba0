#pragma once
// What a batch runs: the case files named on its command line (files,
// folders, globs), each resolved against its scene's schema and keyed by the
// hash of its resolved parameters.
#include "io/parameters.h"
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rollcheck::io
{
/// The scene registry lives in the cli layer; the batch asks it for schemas
/// through this (InputError naming `origin` for an unknown kind).
using FindSchema = std::function<const Schema&(const std::string& kind, const std::string& origin)>;

struct BatchCase
{
  std::filesystem::path file;         ///< absolute path of the case file
  std::string name;                   ///< its stem; folder_stem if another case has that stem
  std::string kind;                   ///< the scene
  nlohmann::json parameters;          ///< resolved: every default filled in
  std::vector<std::string> overrides; ///< `--set key=value` for the case's process
  nlohmann::json inputs;              ///< {key: {file, sha256}} of each parameter naming an existing file
  std::string hash;                   ///< case_hash of the parameters and the inputs' content
  int mpi_ranks = 1;                  ///< processes the case asks for (its `mpi_ranks` key, if the scene has one)
  std::string error;                  ///< why the case cannot run; empty if it can
};

/// Case files named by `arguments`, in order, each once: a file as is, a
/// folder as its *.toml files (sorted), a glob (quoted, so that the shell
/// left it) as what it matches. InputError for an argument that names
/// nothing, so that a typo does not silently shrink a batch.
std::vector<std::filesystem::path> expand_case_arguments(const std::vector<std::string>& arguments);

/// Reads and resolves each case file. A file that cannot be read or resolved
/// is kept with its message in `error`: the batch reports it as failed and
/// runs the others. A string parameter (without fixed choices) that names an
/// existing file is an input: its content is hashed with the parameters (a
/// changed mesh file is a new case), and a path relative to the current
/// folder is made absolute, since the case runs in a folder of its own; an
/// output path that does not exist yet stays relative and so lands in the
/// case's folder.
std::vector<BatchCase> resolve_batch_cases(const std::vector<std::filesystem::path>& files,
                                           const FindSchema& find_schema);
} // namespace rollcheck::io
