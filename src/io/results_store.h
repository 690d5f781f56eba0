#pragma once
// The results store of a batch: one HDF5 file holding every case's record,
// written whole or not at all (a temporary file renamed over the target).
// The scene summaries are stored generically, so a new scene needs no change
// here. Layout (docs/guide/fields.md#hdf5-stores):
//
//   /                      attrs: layout = "rollcheck-results-1", rollcheck_version,
//                                 and the batch attributes given (n_cases, ...)
//   /cases/<name>/         one group per case, <name> the case file's stem;
//                          attrs: the record's scalar fields (status, message,
//                                 case_file, case_text (the case file as run),
//                                 hash, kind, wall_s, ...)
//   /cases/<name>/parameters   attrs: the resolved parameters, one per key, typed;
//                              an input file's SHA-256 as KEY_sha256 (mesh_file_sha256),
//                              and body = the mesh file's path when a mesh file was read
//   /cases/<name>/summary/     the scene's JSON summary, mapped by
//   /cases/<name>/files        the output files of the case (paths relative to
//                              the store's folder), a string dataset
//
// JSON -> HDF5 mapping of a summary (write_json_tree):
//   object                     -> group
//   number                     -> scalar dataset, int64 or float64; every numeric
//                                 dataset has an attribute "units", the unit the
//                                 record's schema declares for its field
//                                 (io/result_fields.h; "1" for a pure number),
//                                 and a table (convergence/*) "columns"
//   "inf" / "-inf"             -> float64 +-infinity (numbers stay numbers)
//   true/false                 -> scalar dataset of the enum {FALSE, TRUE} (numpy bool)
//   string                     -> scalar dataset, variable-length UTF-8
//   null                       -> dataset with an empty (H5S_NULL) dataspace
//   rectangular numeric array  -> n-d dataset (int64 if every entry is an
//                                 integer or a boolean, else float64;
//                                 booleans alone give the enum)
//   array of strings           -> 1-d variable-length string dataset (also an
//                                 empty list the schema declares text: flags)
//   any other array            -> group with attribute json_array = 1 and
//                                 members "0", "1", ... mapped the same way
// A '/' in a key (illegal in HDF5 names) becomes '_'.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rollcheck::io
{
struct StoreEntry
{
  std::string name;     ///< group name under /cases
  nlohmann::json record; ///< object: scalar fields, "parameters", "summary", "files"
};

/// Writes `entries` to `path` atomically; `attributes` (an object of
/// scalars) go on the root group. InputError if the folder does not exist,
/// ComputationError if HDF5 fails.
void write_results_store(const std::filesystem::path& path, const std::vector<StoreEntry>& entries,
                         const nlohmann::json& attributes);

/// Whether `path` is an HDF5 file whose root attribute `layout` names this
/// store ("rollcheck-results-..."): a store written by rollcheck, also one
/// from before output folders had a manifest (core/output_manifest.h).
bool is_results_store(const std::filesystem::path& path);
} // namespace rollcheck::io
