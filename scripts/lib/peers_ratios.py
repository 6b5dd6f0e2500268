#!/usr/bin/env python3
"""Issue 25's table from runs of ../shared/tools/peers/peers.sh: Strata's time over each peer's
(and over Strata's own base technique), one cell per layer count with every run's ratio, and the
issue's aim beside it. Below 1 is faster.

usage: peers_ratios.py [--median] RUN.txt [RUN.txt ...]   (each the stdout of one peers.sh run)

--median: each cell is the median of the runs' ratios and their range, "0.62 (0.57-0.71)", for
a host that moves single runs by more than the differences looked for (a run's ratio is read
within that run; the median is taken over the ratios, not over the times).
"""
import re
import statistics
import sys

# (row label, numerator, denominator, aim)
ROWS = [
    ('f2b / probe F2B', 'strata f2b', 'probe F2B', 0.67),
    ('f2b2 / probe F2B', 'strata f2b2', 'probe F2B', 0.67),
    ('abuffer / probe lists', 'strata abuffer', 'probe PPLL', 0.67),
    ('dual / VTK dual', 'strata dual', 'vtk dual', 0.67),
    ('wboit / VTK wboit', 'strata wboit', 'vtk wboit', 0.67),
    ('blend-sorted / VTK blend', 'strata blend-sorted', 'vtk blend', 0.67),
    ('dual / f2b', 'strata dual', 'strata f2b', 0.6),
    ('f2b-2p / f2b', 'strata f2b-2p', 'strata f2b', 1.3),
    ('f2b-3p / f2b', 'strata f2b-3p', 'strata f2b', 2.0),
    ('dual-2p / dual', 'strata dual-2p', 'strata dual', 1.3),
    # The coplanarity-aware storage variants against their bases (the same 1.3x aim).
    ('f2b-ll / f2b', 'strata f2b-ll', 'strata f2b', 1.3),
    ('f2b-fab / f2b', 'strata f2b-fab', 'strata f2b', 1.3),
    ('f2b-kb / f2b', 'strata f2b-kb', 'strata f2b', 1.3),
    ('dual-ll / dual', 'strata dual-ll', 'strata dual', 1.3),
    ('dual-fab / dual', 'strata dual-fab', 'strata dual', 1.3),
    ('bun-ll / bun', 'strata bun-ll', 'strata bun', 1.3),
]


def parse(path):
    """{layers: {'strata f2b': ms, 'vtk dual': ms, 'probe F2B': ms, ...}} from one run."""
    times, layers = {}, None
    for line in open(path):
        m = re.match(r'== \d+x\d+, (\d+) layers', line)
        if m:
            layers = int(m.group(1))
            times[layers] = {}
            continue
        if layers is None:
            continue
        m = re.match(r'vtk (\w+) .*median ([\d.]+) ms', line)
        if m:
            times[layers]['vtk ' + m.group(1)] = float(m.group(2))
            continue
        m = re.match(r'probe (PPLL|F2B)[^:]*: ([\d.]+) ms', line)
        if m:
            times[layers]['probe ' + m.group(1)] = float(m.group(2))
            continue
        m = re.match(r'strata ([\w-]+): median ([\d.]+) ms', line)
        if m:
            times[layers]['strata ' + m.group(1)] = float(m.group(2))
    if not times:
        sys.exit('peers_ratios.py: %s has no "== WxH, L layers" section (not peers.sh output?)' % path)
    return times


def main(paths):
    if not paths or paths[0] in ('-h', '--help'):
        print(__doc__)
        return 0 if paths else 2
    median = paths[0] == '--median'
    if median:
        paths = paths[1:]
        if not paths:
            sys.exit('peers_ratios.py: --median needs at least one run')
    runs = [parse(p) for p in paths]
    layer_counts = sorted(runs[0])
    print('| Strata / peer | ' + ' | '.join('%d layers' % l for l in layer_counts) + ' | aim |')
    print('|---|' + '---|' * len(layer_counts) + '---:|')
    for label, num, den, aim in ROWS:
        cells = []
        for l in layer_counts:
            ratios = []
            for run in runs:
                t = run.get(l, {})
                ratios.append(t[num] / t[den] if num in t and den in t and t[den] > 0 else None)
            known = [r for r in ratios if r is not None]
            if median:
                cells.append('%.2f (%.2f-%.2f)' % (statistics.median(known), min(known), max(known)) if known else '-')
            else:
                cells.append(', '.join('-' if r is None else '%.2f' % r for r in ratios))
        print('| %s | %s | %s |' % (label, ' | '.join(cells), aim))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
