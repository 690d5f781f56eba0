#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang in build-fuzz/ (the whole
# build instrumented: -fsanitize=fuzzer-no-link,address,undefined), replays the
# saved crash inputs of fuzz/regressions/<target>/, then fuzzes each target for
# SECONDS seconds from its seeds fuzz/corpus/<target>/. New inputs go to
# build-fuzz/corpus/<target>/, never into the seeds. Crashes (and their
# reports) are printed at the end and make the exit status 1; save a crash
# input in fuzz/regressions/<target>/ once its bug is understood.
# Usage: scripts/setup/fuzz.sh [SECONDS (default 600)] [TARGET...]   (case options obj stl ply off)
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
build=$here/build-fuzz
seconds=${1:-600}
targets=("${@:2}")
((${#targets[@]})) || targets=(case options obj stl ply off)
jobs=${JOBS:-$(nproc)}

flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DROLLCHECK_FUZZ=ON \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" >/dev/null
cmake --build "$build" -j "$jobs" --target "${targets[@]/#/fuzz_}"

export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
failed=()
for target in "${targets[@]}"; do
  fuzzer=$build/fuzz/fuzz_$target
  crashes=$build/crashes/$target
  log=$build/logs/$target.log
  mkdir -p "$build/corpus/$target" "$crashes" "$(dirname "$log")"
  if compgen -G "$here/fuzz/regressions/$target/*" >/dev/null; then
    echo "fuzz: $target: replaying fuzz/regressions/$target/"
    "$fuzzer" "$here/fuzz/regressions/$target"/* >"$build/logs/$target.regressions.log" 2>&1 \
      || { echo "fuzz: $target: a saved regression fails again (see $build/logs/$target.regressions.log)"; failed+=("$target"); continue; }
  fi
  echo "fuzz: $target for $seconds s"
  # -timeout: an input taking 10 s is a hang; -rss_limit_mb also caps single allocations.
  if ! "$fuzzer" "$build/corpus/$target" "$here/fuzz/corpus/$target" -max_total_time="$seconds" -timeout=10 \
       -rss_limit_mb=2048 -artifact_prefix="$crashes/" -print_final_stats=1 >"$log" 2>&1; then
    failed+=("$target")
  fi
  grep -E "^(stat::number_of_executed_units|#[0-9]+ +DONE)" "$log" | sed "s/^/fuzz: $target: /" || true
done

for target in "${failed[@]}"; do
  echo "==== fuzz: $target found a crash: $build/logs/$target.log"
  grep -E "ERROR: |SUMMARY: |runtime error|terminate called|what\(\):|Test unit written" "$build/logs/$target.log" || true
  ls -l "$build/crashes/$target"
done
((${#failed[@]} == 0))
