#!/usr/bin/env bash
# Regenerates the audit of the preprint's claims: `rollcheck audit` recomputes
# every quantitative claim (paper-compatible, matched resolution, true oloid,
# corrected physics, real rolling, contact mechanics; two verdicts per claim,
# reproduced and true), writes the Markdown table and its JSON;
# scripts/studies/readme_findings.py rewrites the README's findings block and
# scripts/studies/audit_page.py docs/results/audit.md from them.
# Pass --quick (or other audit options) after the output folder.
# Usage: scripts/studies/audit.sh [ROLLCHECK_BINARY] [OUT_DIR] [audit options...]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/audit}
mkdir -p "$out"
"$bin" audit --json "$out/audit.json" --markdown "$out/audit.md" "${@:3}"
/usr/bin/python3 "$here/scripts/studies/readme_findings.py" "$out/audit.json" "$here/README.md"
/usr/bin/python3 "$here/scripts/studies/audit_page.py" "$out/audit.json" "$out/audit.md" "$here" "$("$bin" --version | head -n 1 | cut -d " " -f 1-2)" \
  "$here/docs/results/audit.md"
