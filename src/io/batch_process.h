#pragma once
// A case of a batch runs in its own process (the rollcheck binary itself,
// `rollcheck run CASE --json FILE`), so that a crash, an abort or a hang of
// one case cannot take the batch down, and the batch needs no thread safety
// from the layers below. The process runner is core's (core/child_process.h:
// environment, process group, termination); the batch sends both streams of
// a case to its log.
#include "core/child_process.h"
#include <filesystem>
#include <string>
#include <vector>

namespace rollcheck::io
{
using process::ExitStatus;
using process::own_executable;

/// A case's process, started in folder `cwd` with stdout and stderr appended
/// to `log`.
class ChildProcess : public process::ChildProcess
{
public:
  ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
               const std::filesystem::path& log)
      : process::ChildProcess(argv, {cwd, log, process::Sink::log, process::Sink::log})
  {
  }
};
} // namespace rollcheck::io
