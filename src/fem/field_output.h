#pragma once
// A field output's settings, checked before any computation by the scenes
// that write one (fem/write_fields.h writes it): the NAME.xdmf path, and how
// long a rank whose write failed waits for the others (the write's
// patience, 30 s, or the whole seconds the environment variable
// ROLLCHECK_WRITE_PATIENCE names: a parallel file system's collective
// writes may take longer). Free of DOLFINx, so that a scene's settings
// check needs none of it.
#include <chrono>
#include <filesystem>
#include <string>

namespace rollcheck::fem
{
/// The environment variable of the write's patience, in whole seconds.
inline constexpr const char* write_patience_variable = "ROLLCHECK_WRITE_PATIENCE";

/// 30 s if ROLLCHECK_WRITE_PATIENCE is unset or empty, else the whole
/// seconds it names (digits, 1 to 86400); InputError naming the variable if
/// it names anything else.
std::chrono::seconds write_patience();

/// NAME.xdmf, a file that can be written there (core/atomic_file.h
/// check_output_file) and the write's patience; InputError otherwise.
/// `origin` names the setting ("hertz: the field output (--xdmf)").
void check_field_output(const std::filesystem::path& xdmf_path, const std::string& origin);
} // namespace rollcheck::fem
