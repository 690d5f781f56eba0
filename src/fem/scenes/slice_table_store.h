#pragma once
// The slice table's nodes (fem/scenes/slice_scaling.h) kept on disk, so
// that the processes of one job solve each node once: the audit's FEM
// commands build the same nondimensional table g(lambda) from the same
// slice settings, each in a process of its own.
//
// A node is a file named by the SHA-256 of the executable's build-id
// (core/build_id.h), the slice settings and the node's load (its bits): a
// different build, material, penalty, mesh level or PETSc option never reads
// it. Files are written whole (core/atomic_file.h); two processes that solve
// the same node write the same numbers, the last rename wins. A file that
// does not parse as a node is solved again.
//
// The folder: core/slice_table_folder.h (ROLLCHECK_SLICE_TABLE_DIR, which
// the audit sets for its commands); unset, nothing is kept.
#include "core/slice_table_folder.h"
#include "fem/scenes/slice_contact.h"
#include <filesystem>
#include <optional>

namespace rollcheck::fem
{
/// The node solved for `load` under `settings`, if the folder holds it.
std::optional<SliceFem> read_stored_slice(const std::filesystem::path& folder, const SliceSettings& settings,
                                          const SliceLoad& load);

/// Keeps `fem` (solved under `settings`) in the folder, creating it if
/// needed. The folder is a convenience, not an output: one that cannot be
/// written is named in a warning and the run goes on (false).
bool store_slice(const std::filesystem::path& folder, const SliceSettings& settings, const SliceFem& fem);
} // namespace rollcheck::fem
