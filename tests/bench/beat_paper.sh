#!/usr/bin/env bash
# Does the bunny at the paper's size beat the paper's model? One line of JSON per seed, then the
# medians. The paper's Zome bunny (data/vef/, design.md §7): symmetric RMS 0.150 b0, Hausdorff 0.646 b0.
# Usage: beat_paper.sh SEEDS "RUN OPTIONS" [ZOMEIFY] [SHARED]
#   e.g. beat_paper.sh "1 2 3 4 5" "--threads 1 --seconds 8"
#        beat_paper.sh "1 2 3" "--threads 1 --proposals 20000000"
# Runs one seed at a time (timed runs need the machine to themselves); --samples 400000 for the score.
set -euo pipefail
seeds=${1:?seeds}
opts=${2:?run options}
z=${3:-build/native/core/cli/zomeify}
shared=${4:-../shared}
mesh=$shared/data/meshes/bunny.obj
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for k in $seeds; do
  # shellcheck disable=SC2086
  "$z" run "$mesh" --b1 0.1907 --target-nodes 392 $opts --seed "$k" -o "$out/m$k.zome.json" \
    --stats "$out/s$k.json" >/dev/null
  "$z" score "$out/m$k.zome.json" --mesh "$mesh" --samples 400000 --json >"$out/f$k.json"
done
python3 - "$out" "$seeds" "$opts" <<'PY'
import json, statistics, sys
out, seeds, opts = sys.argv[1], sys.argv[2].split(), sys.argv[3]
rows = []
for k in seeds:
    f = json.load(open(f"{out}/f{k}.json"))
    s = json.load(open(f"{out}/s{k}.json"))
    fid = f["fidelity"]
    r = {"seed": int(k), "proposals": s["proposals"], "seconds": round(s["wall_seconds"], 2),
         "rms_sym_b0": round(fid["rms_symmetric_b0"], 4), "hausdorff_b0": round(fid["hausdorff_b0"], 3),
         "clashes": f["clearance"]["clashes"], "fold_overs": f["fold_overs"], "balls": f["nodes"]}
    r["beats_paper"] = r["rms_sym_b0"] <= 0.150 and r["hausdorff_b0"] <= 0.646 and r["clashes"] == 0 and r["fold_overs"] == 0
    rows.append(r)
    print(json.dumps(r))
med = lambda key: statistics.median(r[key] for r in rows)
print(json.dumps({"options": opts, "median_rms_sym_b0": med("rms_sym_b0"), "median_hausdorff_b0": med("hausdorff_b0"),
                  "median_proposals": med("proposals"), "beat_paper": sum(r["beats_paper"] for r in rows), "of": len(rows)}))
PY
