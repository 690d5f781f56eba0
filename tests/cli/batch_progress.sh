#!/usr/bin/env bash
# Issue 61: a batch is never silent for more than 10 s while a case runs.
# Its stderr goes to a file (no terminal): between the start of a case that
# runs longer than 10 s and its status line there must be a progress line
# naming the running case and its elapsed time.
#   batch_progress.sh ROLLCHECK SOURCE_DIR TMP_DIR
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
cd "$tmp" || exit 1
# The deep grid's search with every genome revalidated on one thread: about
# 12 s of CPU (its own wall time is checked below, so a machine fast enough
# to finish it within 10 s shows up as a skipped check, not as a pass).
printf '[scene]\nkind = "search"\ngrid = "deep"\nvalidate_all = true\nthreads = 1\n' > slow.toml
"$bin" batch slow.toml -j 1 --out out > batch.out 2> batch.err
rc=$?
check '[[ $rc -eq 0 ]]' "batch exit code $rc: $(cat batch.err)"
wall=$(jq -r '.wall_s' out/cases/*/result.json 2>/dev/null | head -1)
if awk -v w="${wall:-0}" 'BEGIN { exit !(w > 10) }'; then
  # Every line of stderr until the case's status line, with the progress
  # lines among them naming the case and an elapsed time.
  check 'grep -qE "running +slow \([0-9]+:[0-9]{2}\)" batch.err' "no progress line while the case ran ${wall} s: $(cat batch.err)"
  lines=$(grep -cE "running +slow" batch.err)
  # At most one line per 5 s interval, at least one per 10 s of the case.
  check '[[ $lines -ge $(awk -v w="$wall" "BEGIN { print int(w / 10) }") ]]' "$lines progress lines in ${wall} s"
else
  echo "SKIP: the slow case took ${wall:-?} s, not over 10 s: nothing to check"
fi
exit $fail
