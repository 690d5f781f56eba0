# Shared set-up of the benchmark scripts (sourced): MPI as root, one BLAS
# thread, a scratch folder removed on exit, and run().
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
run() { # NAME COMMAND...: the command's --json in $tmp/NAME.json, its wall seconds in $tmp/NAME.s
  local name=$1 start end i; shift
  # --json goes before a `--`: what follows it are PETSc's options.
  local args=("$@") json=(--json "$tmp/$name.json")
  for i in "${!args[@]}"; do
    if [[ ${args[$i]} == -- ]]; then
      args=("${args[@]:0:$i}" "${json[@]}" "${args[@]:$i}")
      json=()
      break
    fi
  done
  start=$(date +%s.%N); "${args[@]}" "${json[@]}" > /dev/null 2> "$tmp/log" || { cat "$tmp/log"; exit 1; }
  end=$(date +%s.%N); echo "$end - $start" | bc -l > "$tmp/$name.s"
}
