#!/usr/bin/env python3
"""The kits named before a run against the kit plan after it (issue 38), from the files
kit_estimate.sh writes: for each run, the kits named (its stats' `kit_estimate.kits`) and the
finished model's parts (`zomeify parts --json`). Prints per run the range named before the run, the
plan after it, whether the named kits hold every part, and by how many parts they exceed the plan;
exits 1 if a plan is not held. A copy of the kit data and the planner keeps it standalone.
    python3 tests/bench/kit_estimate.py build/bench/kit_estimate
"""
import glob
import json
import math
import os
import sys

KINDS = ['B0', 'B1', 'B2', 'Y0', 'Y1', 'Y2', 'R0', 'R1', 'R2']
# core/parts/kits.cpp: struts per length (blue, yellow, red) and balls, largest first.
KITS = [('Workshop', (720, 640, 560), 1000), ('Creator 3', (90, 60, 36), 180), ('Creator 1', (30, 20, 12), 60),
        ('Basic', (15, 10, 6), 30)]
def part_count(kit):
    return 3 * sum(kit[1]) + kit[2]


def colour_needs(counts):
    """Per colour the largest count of one length (a kit has as many of each), then the balls."""
    return [max(counts[k] for k in KINDS[3 * c:3 * c + 3]) for c in range(3)] + [counts['balls']]


def plan(counts):
    """core/parts/kits.cpp plan_kits: fewest parts bought, then fewest kits."""
    need = colour_needs(counts)
    def covers(kit):
        return max([math.ceil(need[c] / kit[1][c]) for c in range(3)] + [math.ceil(need[3] / kit[2])])
    best = None
    for w in range(covers(KITS[0]) + 1):
        for c3 in range(covers(KITS[1]) + 1):
            for c1 in range(min(2, covers(KITS[2])) + 1):
                n = (w, c3, c1)
                basic = 0
                for c in range(4):
                    have = sum(n[i] * (KITS[i][1][c] if c < 3 else KITS[i][2]) for i in range(3))
                    per = KITS[3][1][c] if c < 3 else KITS[3][2]
                    if have < need[c]:
                        basic = max(basic, math.ceil((need[c] - have) / per))
                kits = n + (basic,)
                bought = sum(kits[i] * part_count(KITS[i]) for i in range(4))
                key = (bought, sum(kits))
                if best is None or key < best[0]:
                    best = (key, kits)
    return best[1], best[0][0]


def plan_text(kits):
    return ' + '.join(f'{n} {KITS[i][0]}' for i, n in enumerate(kits) if n) or 'none'


def contents(kits):
    out = {}
    for k, kind in enumerate(KINDS):
        out[kind] = sum(kits[i] * KITS[i][1][k // 3] for i in range(4))
    out['balls'] = sum(kits[i] * KITS[i][2] for i in range(4))
    return out


def counts_of(report):
    struts = report['struts']
    counts = {k: int(struts.get(k, 0)) for k in KINDS} if isinstance(struts, dict) else dict(zip(KINDS, struts))
    counts['balls'] = int(report['balls'])
    return counts


def kits_of(text):
    """'4 Creator 3 + 1 Basic' (the core's text) as counts in KITS order."""
    counts = [0] * len(KITS)
    for item in filter(None, text.split(' + ')):
        n, name = item.split(' ', 1)
        counts[[k[0] for k in KITS].index(name)] = int(n)
    return tuple(counts)


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else 'build/bench/kit_estimate'
    runs = sorted(os.path.basename(p)[:-len('.parts.json')] for p in glob.glob(f'{folder}/*.parts.json'))
    c3_parts = part_count(KITS[1])
    covered = tight = 0
    print('| run | balls | before: range | after: plan | holds all | extra parts |')
    print('|---|---|---|---|---|---|')
    for run in runs:
        final = counts_of(json.load(open(f'{folder}/{run}.parts.json')))
        named = json.load(open(f'{folder}/{run}.json'))['kit_estimate']
        kits = kits_of(named['kits'])
        bought = sum(n * part_count(KITS[i]) for i, n in enumerate(kits))
        after, after_bought = plan(final)
        have = contents(kits)
        holds = all(have[k] >= final[k] for k in KINDS + ['balls'])
        extra = bought - after_bought
        covered += holds
        tight += holds and extra <= c3_parts
        print(f'| {run} | {final["balls"]} | {named["typically"]} … {named["kits"]} | {plan_text(after)} | '
              f'{"yes" if holds else "NO"} | {extra} |')
    print(f'the kits named hold the plan on {covered} of {len(runs)}; '
          f'exceed it by at most one Creator 3 ({c3_parts} parts) on {tight}')
    return 0 if covered == len(runs) else 1


if __name__ == '__main__':
    sys.exit(main())
