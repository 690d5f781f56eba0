#pragma once
// Layer: study. Owns the scenes that join the layers below into one method:
// FEM-SDS over the rolling loop (fem_sds.h), the quirk table and the spin-nudge
// band of the paper-compatible oracles, score_body() (every score of one body
// under one oracle, used by oracle, search, tests and the benchmark), and the
// audit's claims as data with their runner, and the continuous search of the
// two-circle family (optimize.h: NLopt, noise, finite differences, sweeps), and
// the nearly flat rounded rim end by half-space theory (flat_rim_contact.h) at
// the loop's orientations found by an end's interior angle
// (flattest_loop_ends.h).
// Each is a library function with a
// result struct and its to_json; the CLI only declares options, calls and prints.
// Depends on geometry, oracle, contact, fem and core; never on io or cli.
