#!/usr/bin/env bash
# The format lane: fails when a C++ file under core/ wasm/ tests/ differs from what clang-format (the repo's
# .clang-format, clang-format 14 from Debian) would write. Lists each such file and ends with one line
#   format: N files checked, M unformatted
# Usage: bash tests/format/check.sh [FILE...]   (no argument: every tracked .h/.cpp under core/ wasm/ tests/)
# `npm test` runs it only once the tree has been formatted (tests/format/enforced exists; see tests/format/README.md).
set -uo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
cd "$root"
source tests/format/files.sh
tool=$(format_tool) || exit 1
if [ $# -gt 0 ]; then files=("$@"); else mapfile -t files < <(format_files "$root"); fi
[ ${#files[@]} -gt 0 ] || { echo "format: no files to check" >&2; exit 1; }
# One clang-format process per 64 files; each unformatted file reports "FILE:LINE:COL: error: code should be
# clang-formatted" on stderr.
log=$(mktemp)
printf '%s\0' "${files[@]}" | xargs -0 -n 64 "$tool" --dry-run -Werror --style=file >/dev/null 2>"$log"
rc=$?
mapfile -t unformatted < <(grep -oE '^[^:]+:[0-9]+:[0-9]+: error' "$log" | cut -d: -f1 | sort -u)
bad=${#unformatted[@]}
for f in "${unformatted[@]}"; do echo "format: needs clang-format: ${f#"$root"/}"; done
if [ "$rc" -ne 0 ] && [ "$bad" -eq 0 ]; then cat "$log"; bad=1; fi   # clang-format itself failed
rm -f "$log"
echo "format: ${#files[@]} files checked, $bad unformatted ($("$tool" --version | grep -oE 'version [0-9.]+'))"
[ "$bad" -eq 0 ] || echo "format: fix with: clang-format -i FILE (or bash tests/format/apply.sh for the whole tree)"
[ "$bad" -eq 0 ]
