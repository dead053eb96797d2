#!/usr/bin/env bash
# Formats every tracked .h/.cpp under core/ wasm/ tests/ in place with the repo's .clang-format, then turns the
# format lane of `npm test` on (creates tests/format/enforced). Run once on main, build and test, and commit the
# result as one commit (see tests/format/README.md). Prints how many files it changed.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
cd "$root"
source tests/format/files.sh
tool=$(format_tool)
mapfile -t files < <(format_files "$root")
printf '%s\0' "${files[@]}" | xargs -0 -n 50 "$tool" -i --style=file
changed=$(git diff --name-only -- "${files[@]}" | wc -l)
echo "apply: formatted ${#files[@]} files, $changed changed"
echo "clang-format $("$tool" --version | grep -oE 'version [0-9.]+') over core/ wasm/ tests/; the lane of npm test checks it" > tests/format/enforced
bash tests/format/check.sh >/dev/null && echo "apply: tests/format/check.sh passes; tests/format/enforced written (commit it with the reformat)"
