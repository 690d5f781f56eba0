#pragma once
// The work budget: every parameter that multiplies a run's memory or time is
// capped so that no single value can ask for more than about 2 GB of memory,
// or hours of work where the default takes seconds. The caps are ranges like
// any other (checked in Parameters::set, listed in --help and in
// docs/guide/case-files.md#limits), so a case file and an option are refused
// alike, by name, with exit 2, before anything is computed. Each states what
// it bounds and how it was chosen (measured with /usr/bin/time -v on the
// values just beyond the old limits, docs/guide/case-files.md#limits).
#include "io/parameters.h"

namespace rollcheck::io
{
/// Worker threads (0: one per core): each holds its own meshes and oracle
/// state; 256 is far beyond any core count rollcheck runs on, while 100,000
/// threads exhausted the process's thread limit (SIGABRT).
inline constexpr Bounds thread_count{1, 256, false, false, true};

/// Cylinder sides and UV-sphere sectors: a UV sphere of n sectors has about
/// n^2 triangles, so 1024 gives about a million faces (~0.5 GB with the
/// checks' edge maps); 100,000 asked for 10^10 (12.6 GB, then bad_alloc).
inline constexpr Bounds body_sections{4, 1024};

/// Samples of one rolling loop, every one scored: 2^18 = 16 x the default of
/// FEM-SDS (each sample keeps its orientation, contact locus and scores; 10^7
/// took 2.2 GB in 30 s and kept growing).
inline constexpr Bounds loop_samples{2, 262144};

/// Loops of the rolling oracle: undamped, every loop is the same, so more than
/// a few only repeat the work (1000 took 3.1 GB in 60 s); 100 is kept for studies of drift.
inline constexpr Bounds rolling_loops{1, 100};

/// Rigid-body oracle steps per run, duration / dt: 200 x the preprint's
/// 10 s / 2 ms (a 10^6 / 10^-3 run asked for 10^9 steps).
inline constexpr double max_rigid_steps = 1e6;

/// The rigid-body oracle's duration where dt is not an option (optimize):
/// max_rigid_steps at the default dt of 2 ms.
inline constexpr Bounds rigid_duration_s{0, 2000, true, false};

/// A scan of orientations every `step` degrees (0: no scan): at least
/// 0.01 deg, 36,000 directions of a cheap geometric listing; 10^-9 deg never ended.
inline constexpr Bounds scan_step_deg{0.01, 360, false, false, true};
} // namespace rollcheck::io
