#!/usr/bin/python3
"""Benchmark (not a test): the longest silence of each long-running command.

Runs each command at the default log level, stamps every line it writes
(stdout and stderr, merged) with the time since the command started, and
prints per command its wall time, its longest gap between two lines (the
start and the exit count as lines) and the phase that gap ended in. Issue 61
asks that no phase of a default case, the rim loop or a batch stays silent
for more than 10 s.

    /usr/bin/python3 scripts/bench/bench_silence.py [path/to/rollcheck] [--quick]

--quick leaves out flat-rim's defaults (50 s), the 2-rank rim loop (25 s) and the
audit (70 s).
"""
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parents[2]
LIMIT_S = 10.0


def commands(rollcheck: str, scratch: Path, quick: bool):
    mpirun = ["mpirun", "-n", "2"]
    yield "batch cases/default (2 workers)", [rollcheck, "batch", str(HERE / "cases/default"), "--out",
                                               str(scratch / "batch")]
    for case in sorted((HERE / "cases/default").glob("*.toml")):
        yield f"run {case.name}", [rollcheck, "run", str(case), "--json", str(scratch / f"{case.stem}.json")]
    yield "fem-sds --body oloid (2 ranks)", mpirun + [rollcheck, "fem-sds", "--body", "oloid", "--json",
                                                       str(scratch / "fem_sds.json")]
    yield "hertz --model 3d (2 ranks)", mpirun + [rollcheck, "hertz", "--model", "3d", "--json",
                                               str(scratch / "hertz.json")]
    if not quick:
        yield "flat-rim (its defaults)", [rollcheck, "flat-rim", "--json", str(scratch / "flat_rim.json")]
        yield "rim --body oloid --orientations 1 --levels 1 (2 ranks)", mpirun + [
            rollcheck, "rim", "--body", "oloid", "--orientations", "1", "--levels", "1", "--json",
            str(scratch / "rim.json")]
        yield "audit --quick", [rollcheck, "audit", "--quick", "--json", str(scratch / "audit.json")]


def longest_silence(argv):
    """(wall s, longest gap s, the line that ended it, exit code)."""
    start = time.monotonic()
    process = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, bufsize=1)
    last, gap, ended_by = start, 0.0, ""
    for line in process.stdout:
        now = time.monotonic()
        if now - last > gap:
            gap, ended_by = now - last, line.strip()
        last = now
    code = process.wait()
    now = time.monotonic()
    if now - last > gap:
        gap, ended_by = now - last, "(exit)"
    return now - start, gap, ended_by, code


def main():
    args = [a for a in sys.argv[1:] if a != "--quick"]
    rollcheck = args[0] if args else str(HERE / "build/src/cli/rollcheck")
    os.environ.update(OPENBLAS_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    print(f"cores: {os.cpu_count()}; limit {LIMIT_S:g} s of silence at the default log level")
    print("| command | wall s | longest silence s | within limit | the silence ended with |")
    print("|---|---|---|---|---|")
    failed = 0
    with tempfile.TemporaryDirectory() as scratch:
        for name, argv in commands(rollcheck, Path(scratch), "--quick" in sys.argv):
            wall, gap, ended_by, code = longest_silence(argv)
            if code != 0:
                failed += 1
                ended_by = f"EXIT {code}: {ended_by}"
            print(f"| {name} | {wall:.1f} | {gap:.1f} | {'yes' if gap <= LIMIT_S else 'NO'} | {ended_by[:90]} |",
                  flush=True)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
