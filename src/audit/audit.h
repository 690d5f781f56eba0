#pragma once
// Layer: audit. The preprint's claims as data (claims.h: the records in
// claims_*.cpp, the commands they cite in claim_commands.h), the modes they
// are recomputed in (modes.h), the rules that decide each cell from the
// commands' JSON (rules.h), the runner that starts the `rollcheck` commands
// and reads their JSON (runner.h), and the table of cells and verdicts
// (table.h). A client of the executables, not of the libraries: it links no
// study or FEM code.
#include "audit/claims.h"
#include "audit/runner.h"
#include "audit/table.h"
