#!/usr/bin/env bash
# What `npm start` shows until the web page lands: the CLI on the bundled sample model.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/native/core/cli/zomeify ] || bash tests/build.sh native
sample=tests/data/samples/icosahedron.zome.json
echo "\$ zomeify parts $sample"
build/native/core/cli/zomeify parts "$sample"
if [ -f ../shared/data/vef/bunny.vef ]; then
  echo; echo "\$ zomeify parts ../shared/data/vef/bunny.vef   # the paper's Zome bunny"
  build/native/core/cli/zomeify parts ../shared/data/vef/bunny.vef
fi
if [ -f ../shared/data/meshes/torus.obj ]; then
  echo; echo "\$ zomeify run ../shared/data/meshes/torus.obj --initial-only --resolution 12 -o build/torus-z0.zome.json"
  build/native/core/cli/zomeify run ../shared/data/meshes/torus.obj --initial-only --resolution 12 -o build/torus-z0.zome.json
fi
echo; echo "The CLI is build/native/core/cli/zomeify (zomeify --help lists its commands)."
