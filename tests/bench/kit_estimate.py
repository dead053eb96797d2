#!/usr/bin/env python3
"""The kit estimate before a run against the kit plan after it (issue 38), from the files
kit_estimate.sh writes: for each mesh, Z0's parts and the finished model's parts (`zomeify parts
--json`). Prints, per mesh, how much more of each strut colour and of balls the finished model needs
than Z0 has, the kits the page names before the run (Z0's parts with the margins of
core/parts/kit_fit.h's estimate_parts, planned as core/parts/kits.cpp plans) and the plan after it,
and whether the estimate holds every part. A copy of the kit data and planner keeps it standalone.
    python3 tests/bench/kit_estimate.py build/bench/kit_estimate [--margins B,Y,R,BALLS]
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
# core/parts/kit_fit.h kEstimateMargins: blue, yellow, red, balls (keep in step).
MARGINS = (0.25, 0.25, 0.25, 0.10)


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


# core/parts/kit_fit.cpp kStrutsPerBall: the bunny's annealed mix (the estimate before issue 38).
TYPICAL = (0.411, 0.534, 0.108, 0.489, 0.446, 0.129, 0.239, 0.313, 0.031)


def typical(z0):
    out = {k: math.ceil(TYPICAL[i] * z0['balls']) for i, k in enumerate(KINDS)}
    out['balls'] = z0['balls']
    return out


def estimate(z0, margins, source='z0'):
    """The parts named before the run: Z0's (or the typical mix for Z0's balls), each colour and the
    balls with its margin."""
    base = z0 if source == 'z0' else typical(z0)
    out = {k: math.ceil(base[k] * (1 + margins[KINDS.index(k) // 3]) - 1e-9) for k in KINDS}
    out["balls"] = math.ceil(base["balls"] * (1 + margins[3]) - 1e-9)
    return out


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else 'build/bench/kit_estimate'
    margins = MARGINS
    if '--margins' in sys.argv:
        margins = tuple(float(x) for x in sys.argv[sys.argv.index('--margins') + 1].split(','))
    source = sys.argv[sys.argv.index('--from') + 1] if '--from' in sys.argv else 'z0'
    base_of = (lambda z: z) if source == 'z0' else typical
    rows, covered, tight = [], 0, 0
    c3_parts = part_count(KITS[1])
    names = sorted(os.path.basename(p)[:-len('.z0.parts.json')] for p in glob.glob(f'{folder}/*.z0.parts.json'))
    print(f'margins blue {margins[0]:.2f}, yellow {margins[1]:.2f}, red {margins[2]:.2f}, balls {margins[3]:.2f}')
    print('| mesh | Z0 balls | final balls | final/Z0 need (blue, yellow, red, balls) | before: low (Z0) | before: high '
          '(named) | after: plan | holds all | extra parts |')
    print('|---|---|---|---|---|---|---|---|---|')
    for name in names:
        z0 = counts_of(json.load(open(f'{folder}/{name}.z0.parts.json')))
        final = counts_of(json.load(open(f'{folder}/{name}.parts.json')))
        low, _ = plan(base_of(z0))
        high, high_bought = plan(estimate(z0, margins, source))
        after, after_bought = plan(final)
        have = contents(high)
        holds = all(have[k] >= final[k] for k in KINDS + ['balls'])
        ratios = [f / z if z else float('inf') for f, z in zip(colour_needs(final), colour_needs(base_of(z0)))]
        extra = high_bought - after_bought
        covered += holds
        tight += holds and extra <= c3_parts
        print(f'| {name} | {z0["balls"]} | {final["balls"]} | {", ".join(f"{r:.2f}" for r in ratios)} | '
              f'{plan_text(low)} | {plan_text(high)} | {plan_text(after)} | {"yes" if holds else "NO"} | {extra} |')
    print(f'estimate holds the plan on {covered} of {len(names)}; within one Creator 3 ({c3_parts} parts) on {tight}')
    return 0 if covered == len(names) and tight >= 0.8 * len(names) else 1


if __name__ == '__main__':
    sys.exit(main())
