#!/usr/bin/env python3
"""Sorts the LP-consistency exceptions into the assumptions that break (DESIGN.md decision 8, "Every
exception, case by case"), from the output of Consistency.java:

  java -cp "build/install/handsim/lib/*" -Dj3d.rend=noop -Djava.awt.headless=true -Xss16m \\
      tools/hold-lp-consistency/Consistency.java PLAN_DIR/best/01.json ... > LOG
  tools/hold-lp-consistency/classify.py LOG [LOG ...]

The scenarios must be named sSEED/best/NN.json (their file name then reads sSEED_NN.json in the
log). Prints the counts (directions with L below the cap: agree, fail both, hold both, reversed),
the ramps within 20 % of L, and one table row per exception, in DESIGN.md's columns:

  sudden load                      failed at 0.9 L and 1.1 L, while the ramp, loading slowly, reached 0.8 L or more
  squeeze spends the clutch        failed both, and the ramp gave way below 0.8 L too
  thresholds: only 1.1 L moved it  held both; under 0.5 mm and 0.5 deg at 0.9 L, more at 1.1 L
  thresholds: shifted alike        held both, moved alike at both loads
  L not the limit                  held both with no motion at 1.1 L (under 0.1 mm and 0.1 deg): look at the contacts
  reversed                         held 1.1 L but not 0.9 L
"""
import collections
import re
import sys

HEAD = re.compile(r's(\d+)_(\d+)\.json mu \S+ engaged (\w+) (\w+) (\w+)')
ROW = re.compile(r'\s+(\S+) L ([\d.]+) ramp (>=)?([\d.]+) \| 0.9L (\w+) \(([\d.e-]+) m ([\d.e-]+) deg\) '
                 r'1.1L (\w+) \(([\d.e-]+) m ([\d.e-]+) deg\) (\w+)')
NAMES = {'A': 'sudden load', 'B': 'squeeze spends the clutch', 'C1': 'thresholds: only 1.1 L moved it',
         'C2': 'thresholds: shifted alike', 'D': 'L not the limit', 'X': 'reversed'}


def rows_of(paths):
    rows = []
    for path in paths:
        grasp = None
        for line in open(path, encoding='utf-8'):
            m = HEAD.match(line)
            if m:
                grasp = (m.group(1), m.group(2), [m.group(k) == 'true' for k in (3, 4, 5)])
                continue
            m = ROW.match(line)
            if m and grasp:
                d, big_l, capped, ramp, lo, lod, lor, hi, hid, hir, verdict = m.groups()
                rows.append(dict(seed=grasp[0], best=grasp[1], engaged=grasp[2], d=d, L=float(big_l), ramp=float(ramp),
                                 capped=bool(capped), lo=lo.lower(), lod=float(lod), lor=float(lor), hi=hi.lower(),
                                 hid=float(hid), hir=float(hir), agree=verdict == 'AGREE'))
    return rows


def category(r):
    if r['lo'] == 'failed' and r['hi'] == 'failed':
        return 'A' if r['ramp'] >= 0.8 * r['L'] else 'B'
    if r['lo'] == 'held' and r['hi'] == 'held':
        if r['hid'] < 1e-4 and r['hir'] < 0.1:
            return 'D'
        return 'C1' if r['lod'] < 5e-4 and r['lor'] < 0.5 else 'C2'
    return 'X'


def main():
    if len(sys.argv) < 2 or sys.argv[1] in ('-h', '--help'):
        print(__doc__)
        sys.exit(0 if len(sys.argv) > 1 else 2)
    rows = rows_of(sys.argv[1:])
    if not rows:
        sys.exit('classify.py: no Consistency.java rows with L below the cap in ' + ' '.join(sys.argv[1:]))
    out = [(category(r), r) for r in rows if not r['agree']]
    count = collections.Counter(c for c, _ in out)
    fail_both, hold_both = count['A'] + count['B'], count['C1'] + count['C2'] + count['D']
    print(f"{len(rows)} directions: {len(rows) - len(out)} agree, {fail_both} fail both, {hold_both} hold both, "
          f"{count['X']} reversed")
    print('exceptions: ' + ', '.join(f'{NAMES[c]} {count[c]}' for c in NAMES if count[c]))
    within = sum(abs(r['ramp'] - r['L']) <= 0.2 * r['L'] for r in rows)
    print(f'ramps within 20 % of L: {within} of {len(rows)}')
    order = list(NAMES)
    for c, r in sorted(out, key=lambda x: (order.index(x[0]), x[1]['seed'], x[1]['best'])):
        engaged = ''.join('123'[i] for i in range(3) if r['engaged'][i]) or '-'
        d = r['d'].replace('-', '\u2212')
        print(f"| {NAMES[c]} | seed {r['seed']}, best {r['best']} {d} | {engaged} | {r['L']:.2f} | "
              f"{'≥' if r['capped'] else ''}{r['ramp']:.2f} | {r['lo']} {r['lod'] * 1e3:.2g} mm {r['lor']:.2g}° | "
              f"{r['hi']} {r['hid'] * 1e3:.2g} mm {r['hir']:.2g}° |")


if __name__ == '__main__':
    main()
