#!/usr/bin/env bash
# Issue 42: the OBJ + MTL and the GLB of one model show the same colours in Blender (within 5% per channel).
#   bash tests/blender/blender_colours.sh ZOMEIFY [SHARED_DIR]
# Writes the paper's bunny (SHARED_DIR/data/vef/bunny.vef: balls and blue, yellow and red struts) as OBJ (mm)
# and GLB with the CLI, then runs compare_colours.py in Blender headless (BLENDER=path overrides `blender`).
# Without Blender it prints "skipped: Blender not installed" and exits 0; without the shared data it exits 77.
# ZOME_BLENDER_KEEP=DIR keeps the files and the renders there.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
zomeify=${1:?usage: blender_colours.sh ZOMEIFY [SHARED_DIR]}
shared=${2:-$here/../../../shared}
blender=${BLENDER:-blender}
if ! command -v "$blender" >/dev/null 2>&1; then
  echo "skipped: Blender not installed"
  exit 0
fi
vef="$shared/data/vef/bunny.vef"
if [ ! -f "$vef" ]; then
  echo "skipped: no $vef"
  exit 77
fi
if [ -n "${ZOME_BLENDER_KEEP:-}" ]; then
  dir=$ZOME_BLENDER_KEEP; mkdir -p "$dir"
else
  dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
fi
"$zomeify" convert "$vef" -o "$dir/bunny.obj" -o "$dir/bunny.glb" >/dev/null 2>&1 || {
  echo "blender colours: FAIL (zomeify convert $vef failed)"; exit 1; }
"$blender" -b --factory-startup --python-exit-code 1 -P "$here/compare_colours.py" -- \
  "$dir/bunny.obj" "$dir/bunny.glb" --keep "$dir/renders" >"$dir/blender.log" 2>&1
rc=$?
"$blender" --version 2>/dev/null | head -1
# The script's summary: from its JSON object to its verdict line.
sed -n '/^{$/,/^blender colours: /p' "$dir/blender.log"
if [ $rc -ne 0 ]; then
  grep -q '^blender colours: ' "$dir/blender.log" || { echo "blender colours: FAIL (Blender exited $rc)"; tail -30 "$dir/blender.log"; }
  exit 1
fi
