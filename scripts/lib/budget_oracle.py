#!/usr/bin/env python3
"""The best any frame-budget policy could have done on a path (scripts/bench_budget.sh --oracle).

Reads one bench JSON per pinned state (strata bench --budget-pin Z,L: every frame drawn at zoom Z
and LOD ladder level L, with each frame's time and PSNR against the unconstrained frame) and,
frame by frame, picks the state an oracle would: among the states whose measured time is within
the budget's band (target x 1.1), the one with the highest PSNR; where none is, the fastest (as
the governor's rule does). It knows every frame's cost before drawing it, so it draws the most
frames within the band, and on those frames no causal policy scores a higher PSNR, up to the
noise of one draw per state and frame. (On a frame nothing fits, a policy drawing a slower,
better state over the band can score more there.) Done for each lever set (the zoom alone at
the least bound, LOD alone at zoom 1, both), it says how much a joint policy can gain over each
lever alone on this path and budget.

usage: budget_oracle.py BUDGET_MS PINNED.json... [--policy LABEL=RUN.json ...]
Prints a markdown table on stdout.
"""
import argparse
import json
import statistics
import sys


def load_pinned(paths):
    states = {}
    for path in paths:
        d = json.load(open(path))
        pin = d.get('budget_pin')
        if not pin:
            sys.exit('budget_oracle.py: %s is not a pinned run (no budget_pin)' % path)
        b = d['modes'][0]['budget']
        states[(pin['zoom'], pin['lod_level'])] = (b['frame_ms'], b['frame_psnr'])
    frames = {len(ms) for ms, _ in states.values()}
    if len(frames) != 1:
        sys.exit('budget_oracle.py: the pinned runs have different frame counts %s' % sorted(frames))
    return states, frames.pop()


def oracle(states, allowed, frames, edge):
    """Per frame, the best allowed state within the band edge; the fastest where none is."""
    within, psnr, picks = 0, [], []
    for f in range(frames):
        fits = [s for s in allowed if states[s][0][f] <= edge]
        if fits:
            within += 1
            best = max(fits, key=lambda s: (states[s][1][f], -states[s][0][f]))
        else:
            best = min(allowed, key=lambda s: states[s][0][f])
        psnr.append(states[best][1][f])
        picks.append(best)
    return within / frames, statistics.mean(psnr), picks


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('budget', type=float, help='the frame budget in ms')
    parser.add_argument('pinned', nargs='+', help='one bench JSON per pinned state')
    parser.add_argument('--policy', action='append', default=[], metavar='LABEL=RUN.json',
                        help='a budget run to show beside the oracle')
    args = parser.parse_args(argv[1:])
    budget, pinned = args.budget, args.pinned
    policies = []
    for p in args.policy:
        if '=' not in p:
            parser.error("--policy '%s': expected LABEL=RUN.json" % p)
        policies.append(tuple(p.split('=', 1)))
    states, frames = load_pinned(pinned)
    edge = budget * 1.1
    zooms = sorted({z for z, _ in states})
    levels = sorted({l for _, l in states})
    sets = [('zoom alone (oracle)', [(z, levels[0]) for z in zooms if (z, levels[0]) in states]),
            ('LOD alone (oracle)', [(zooms[0], l) for l in levels if (zooms[0], l) in states]),
            ('both (oracle)', sorted(states))]
    print('| levers | frames not over (+10 %) | mean PSNR dB | states picked (zoom, level): frames |')
    print('|---|---:|---:|---|')
    for label, allowed in sets:
        share, mean, picks = oracle(states, allowed, frames, edge)
        counts = {}
        for p in picks:
            counts[p] = counts.get(p, 0) + 1
        text = ', '.join('(%d, %d): %d' % (s[0], s[1], n) for s, n in sorted(counts.items(), key=lambda kv: -kv[1]))
        print('| %s | %.0f %% | %.2f | %s |' % (label, 100 * share, mean, text))
    for label, path in policies:
        b = json.load(open(path))['modes'][0]['budget']
        ms, psnr = b['frame_ms'], b['frame_psnr']
        if len(ms) != frames:
            sys.exit('budget_oracle.py: %s has %d frames, the pinned runs %d' % (path, len(ms), frames))
        share = sum(t <= edge for t in ms) / frames
        print('| %s | %.0f %% | %.2f | - |' % (label, 100 * share, statistics.mean(psnr)))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
