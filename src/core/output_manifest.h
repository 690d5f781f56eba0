#pragma once
// The one rule for what an output folder may lose: rollcheck removes or
// replaces only what the folder's manifest lists. Every folder rollcheck
// writes into (batch --out, validate --out, report --out, fem-sds --out, a
// study's --out, ...) holds the manifest `.rollcheck-output`, a JSON object
// {"written_by": "rollcheck", "entries": [relative paths]}; an entry names a
// file or a whole folder rollcheck wrote (or is about to write: an entry is
// added before its file is made, so a run killed half-way leaves nothing
// unlisted). Everything else in the folder is the user's and is never
// touched; a name rollcheck would write that holds an unlisted file is
// refused by name, before any computation.
//
// Work left by a killed run is recognised from the manifest too
// (is_stale_work): NAME.part and NAME.old of a listed NAME, and the
// temporaries `.STEM.tmpPID[.EXT]` of a listed STEM[.EXT] whose process is
// no longer running.
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rollcheck
{
/// The manifest's file name in every folder rollcheck writes.
inline constexpr const char* output_marker = ".rollcheck-output";

struct OutputManifest
{
  std::set<std::string> entries; ///< paths relative to the folder, '/'-separated

  /// Whether `relative` is an entry or lies inside a listed folder.
  bool lists(const std::filesystem::path& relative) const;
};

/// The manifest of `folder`, nullopt if it holds none. A marker of rollcheck
/// before manifests (plain text) lists nothing: its files cannot be told
/// from the user's, so none is removed or replaced. ComputationError if it
/// cannot be read.
std::optional<OutputManifest> read_output_manifest(const std::filesystem::path& folder);

/// Writes the manifest of `folder` (atomically).
void write_output_manifest(const std::filesystem::path& folder, const OutputManifest& manifest);

/// Adds `entries` to the manifest of `folder` (creating it), before they are
/// written. Single writer: the caller holds the folder (a batch's lock, rank 0).
void claim_outputs(const std::filesystem::path& folder, const std::vector<std::string>& entries);

/// InputError naming `origin` and the path if one of `entries` exists in
/// `folder` but its manifest does not list it: a file of the user's that the
/// output would replace. Checked before any computation.
void check_output_entries(const std::filesystem::path& folder, const std::vector<std::string>& entries,
                          const std::string& origin);

/// Whether `relative` (inside the manifest's folder) is work a killed run of
/// rollcheck left (see the header comment).
bool is_stale_work(const OutputManifest& manifest, const std::filesystem::path& relative);

/// Whether a process of this id is running (kill(pid, 0)).
bool process_running(long pid);
} // namespace rollcheck
