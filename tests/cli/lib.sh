# Shared helpers of the CLI tests (sourced). Each records a failure in $fail
# and prints what failed; the script ends with `exit $fail`.
fail=0

# check CONDITION DESCRIPTION: CONDITION (evaluated) must hold.
check() { if ! eval "$1"; then echo "FAIL: $2"; fail=1; fi; }

# check_json DESCRIPTION JQ-EXPRESSION FILE: the expression must print true.
check_json() {
  [[ $(jq -r "$2" "$3") == true ]] || { echo "FAIL: $1 ($2)"; jq -c . "$3" 2>/dev/null | head -c 2000; echo; fail=1; }
}

# expect CODE PATTERN -- COMMAND...: the command exits CODE, its output
# matches PATTERN (extended, case-insensitive), and it reports no internal error.
expect() {
  local code=$1 pattern=$2; shift 3
  local out; out=$(timeout 300 "$@" 2>&1); local rc=$?
  if [[ $rc -ne $code ]]; then echo "FAIL ($rc != $code): $*"; echo "$out" | head -c 2000; fail=1; return; fi
  if ! grep -qiE -- "$pattern" <<<"$out"; then echo "FAIL (output lacks '$pattern'): $*"; echo "$out" | head -c 2000; fail=1; return; fi
  if grep -q "internal error" <<<"$out"; then echo "FAIL (internal error): $*"; echo "$out" | head -c 2000; fail=1; fi
}

# refuses SUBCOMMAND 'ARGS:TEXT'...: each command line `$bin -q SUBCOMMAND ARGS`
# exits 2 with a message holding TEXT (the input named) and writes no result.
refuses() {
  local sub=$1 args rc; shift
  for args in "$@"; do
    "$bin" -q "$sub" ${args%%:*} --json "$tmp/bad.json" > "$tmp/bad.log" 2>&1; rc=$?
    if [[ $rc -ne 2 ]] || ! grep -q -- "${args#*:}" "$tmp/bad.log" || [[ -e "$tmp/bad.json" ]]; then
      echo "FAIL: $sub ${args%%:*} gave exit $rc without '${args#*:}' (or wrote a result):"; cat "$tmp/bad.log"; fail=1
    fi
  done
}

# batch_ok DESCRIPTION ARGS...: `$bin -q batch ARGS` exits 0; if not, the
# failure is recorded with the batch's own output (each failed case's
# message), so that a failure on another machine says why.
batch_ok() {
  local what=$1 out rc; shift
  out=$("$bin" -q batch "$@" 2>&1); rc=$?
  [[ $rc -eq 0 ]] && return 0
  echo "FAIL: $what (exit $rc):"; echo "$out" | tail -c 4000; fail=1; return 1
}
