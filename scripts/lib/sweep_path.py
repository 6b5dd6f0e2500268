#!/usr/bin/env python3
"""Writes a camera path for the joint frame budget (issue 24; scripts/bench_budget.sh) over a
builtin instance grid (field, orchard): from an empty view (the scene's default camera place,
looking 60 degrees up at the sky) it turns down onto the grid (0-2 s), then flies into it, down
to eye height in front of the first row (2-6 s). The default camera is the grid's own
(core/scene/builtin_scenes.cpp InstanceGrid::addGroundAndCamera): eye (0, 2 + 0.3 e, 3 + 0.45 e)
for the grid's extent e = max(columns x spacing + 4, rows x spacing).

usage: sweep_path.py COUNT SPACING OUT   (field: spacing 3; orchard: 2.5)
"""
import math
import sys


def main():
    count, spacing, out = int(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
    columns = math.ceil(math.sqrt(count))
    rows = (count + columns - 1) // columns
    extent = max(columns * spacing + 4.0, rows * spacing)
    start = (0.0, 2.0 + 0.3 * extent, 3.0 + 0.45 * extent)
    end = (0.0, 2.0, 0.5 * spacing + 1.0)
    keys = []
    for i in range(11):  # the turn: pitch +60 -> -30 degrees
        t = 0.2 * i
        keys.append((t, start, 60.0 - 90.0 * t / 2.0))
    for i in range(1, 21):  # the flight, eased at both ends: pitch -30 -> -8
        t = 2.0 + 0.2 * i
        s = (t - 2.0) / 4.0
        s = s * s * (3.0 - 2.0 * s)
        pos = tuple(a + (b - a) * s for a, b in zip(start, end))
        keys.append((t, pos, -30.0 + 22.0 * s))
    with open(out, "w") as f:
        f.write("# Camera path for the joint frame budget (issue 24), written by scripts/lib/sweep_path.py\n")
        f.write("# %d %g %s: the sky (0 s), turning onto the grid (2 s), into it (6 s).\n" % (count, spacing, out.split("/")[-1]))
        f.write("# time px py pz qx qy qz qw\n")
        for t, pos, pitch in keys:
            half = math.radians(pitch) / 2.0
            f.write("%.3f %.4f %.4f %.4f %.9f 0 0 %.9f\n" % (t, *pos, math.sin(half), math.cos(half)))


if __name__ == "__main__":
    main()
