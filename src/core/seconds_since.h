#pragma once
// Wall seconds on this process since a steady-clock instant: the phase
// times in logs and JSON (`wall_s`, `mesh_wall_s`, ...).
#include <chrono>

namespace rollcheck
{
inline double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
} // namespace rollcheck
