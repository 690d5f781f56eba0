#pragma once
// Layer: audit. The preprint's claims as data (claims.h), the runner that
// starts the `rollcheck` commands they cite and reads their JSON (runner.h),
// and the table of cells and verdicts (table.h). A client of the executables,
// not of the libraries: it links no study or FEM code.
#include "audit/claims.h"
#include "audit/runner.h"
#include "audit/table.h"
