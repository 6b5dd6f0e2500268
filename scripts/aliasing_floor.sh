#!/usr/bin/env bash
# How much of a LOD image's PSNR against geometry is the geometry's own aliasing (issue 23: the
# CAD field stays near 27 dB whatever the impostor settings). Renders SCENE with --lod geometry
# and with --lod auto at WxH and at 2Wx2H (one sample per pixel each), and compares:
#   - geometry against itself sampled half a pixel off (every other pixel of the 2x frame):
#     how far two equally right samplings of this scene lie apart;
#   - geometry, and auto, against the 2x geometry averaged 2x2 (an antialiased stand-in for truth);
#   - auto against geometry, at 1x and both averaged 2x2.
# PSNR over linear RGB clamped to [0, 1], as strata bench computes it.
#
# usage: scripts/aliasing_floor.sh STRATA SCENE WxH [strata render options...]
#   e.g. scripts/aliasing_floor.sh build/viewer/strata docs/bench/scale/kept-model/cad-64.json 640x400 \
#          --mode blend-sorted --impostor-cache /tmp/cad-cache
# Needs python3 with OpenImageIO and numpy (Debian: python3-openimageio python3-numpy).
set -euo pipefail
[[ $# -ge 3 ]] || { sed -n '2,16p' "$0"; exit 2; }
strata=$1 scene=$2 size=$3
shift 3
py=/usr/bin/python3
"$py" -c 'import OpenImageIO, numpy' 2>/dev/null ||
    { echo "aliasing_floor.sh: needs python3-openimageio and python3-numpy (apt-get install python3-openimageio python3-numpy)" >&2; exit 1; }
[[ $size =~ ^([0-9]+)x([0-9]+)$ ]] || { echo "aliasing_floor.sh: size '$size' is not WxH" >&2; exit 2; }
w=${BASH_REMATCH[1]} h=${BASH_REMATCH[2]}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless}
for lod in geometry auto; do
    for s in "${w}x${h}" "$((2 * w))x$((2 * h))"; do
        echo "aliasing_floor.sh: render --lod $lod --size $s" >&2
        "$strata" render "$scene" --size "$s" --lod "$lod" "$@" --out "$work/$lod-$s.exr" >"$work/log" 2>&1 ||
            { cat "$work/log" >&2; exit 1; }
    done
done
"$py" - "$work" "$w" "$h" <<'EOF'
import sys
import numpy as np
import OpenImageIO as oiio

work, w, h = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])

def read(name):
    i = oiio.ImageInput.open(f'{work}/{name}.exr')
    a = np.array(i.read_image(format='float'))[..., :3]
    i.close()
    return np.clip(a, 0.0, 1.0)

def psnr(a, b):
    mse = float(((a - b) ** 2).mean())
    return float('inf') if mse == 0.0 else 10.0 * np.log10(1.0 / mse)

def average2x2(a):
    return a.reshape(h, 2, w, 2, 3).mean(axis=(1, 3))

g1, g2 = read(f'geometry-{w}x{h}'), read(f'geometry-{2 * w}x{2 * h}')
a1, a2 = read(f'auto-{w}x{h}'), read(f'auto-{2 * w}x{2 * h}')
truth = average2x2(g2)
rows = [
    ('geometry against itself sampled half a pixel off', psnr(g1, g2[1::2, 1::2])),
    ('geometry against 2x2-averaged geometry', psnr(g1, truth)),
    ('auto against 2x2-averaged geometry', psnr(a1, truth)),
    ('auto against geometry (what strata bench reports)', psnr(a1, g1)),
    ('auto 2x2-averaged against geometry 2x2-averaged', psnr(average2x2(a2), truth)),
]
print(f'| {w}x{h} | PSNR dB |')
print('|---|---:|')
for name, value in rows:
    print(f'| {name} | {value:.2f} |')
EOF
