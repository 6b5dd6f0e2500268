#!/usr/bin/env bash
# Zoom rendering's tables (Mazuryk, Schmalstieg, Gervautz 1996):
#  1. speedup against z: builtin:layers:N (full-view quads: fill-bound) at a 1280x720 base,
#     z = 1..8, fill-bound techniques; the whole frame's GPU time (opaque pass, technique,
#     enlargement) at z against z = 1, next to the aim 0.8 z^2; PSNR against the reference at
#     z = 1 with replication and with the blur on builtin:default (edges: full-view quads lose
#     nothing to a zoom); frames per second with single buffering (1/t)
#     and with double buffering at 60 Hz (a frame waits for the next retrace: 1/(ceil(t/16.7) 16.7)),
#     both from the same measured t (the paper's Fig. 4);
#  2. a frame budget over a camera path with load jumps (scenes/paths/zoom-load-jumps.path: cuts
#     between facing the stack, facing away and a half turn): reactive against predictive, the
#     share of frames within +-10 % of the target and at most 10 % over it, and each excursion
#     over the band (its first frame, length and peak).
# Each run's JSON stays in the output folder; the tables go to stdout as markdown.
#
# usage: scripts/bench_zoom.sh [--out DIR] [--strata PATH] [--frames N] [--layers N] [--size WxH]
#        [--modes a,b] [--budget-size WxH] [--budget-ms T] [--budget-frames N] [--budget-mode ID]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/docs/bench/zoom
strata=$root/build/viewer/strata
frames=3
layers=8
size=1280x720
modes=abuffer,ll,wboit,blend-sorted
budget_size=640x360
budget_ms=70
budget_frames=60
budget_mode=abuffer
while [[ $# -gt 0 ]]; do
    case $1 in
        --out) out=$2; shift 2 ;;
        --strata) strata=$2; shift 2 ;;
        --frames) frames=$2; shift 2 ;;
        --layers) layers=$2; shift 2 ;;
        --size) size=$2; shift 2 ;;
        --modes) modes=$2; shift 2 ;;
        --budget-size) budget_size=$2; shift 2 ;;
        --budget-ms) budget_ms=$2; shift 2 ;;
        --budget-frames) budget_frames=$2; shift 2 ;;
        --budget-mode) budget_mode=$2; shift 2 ;;
        -h|--help) sed -n '2,18p' "$0"; exit 0 ;;
        *) echo "bench_zoom.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done
[[ -x $strata ]] || { echo "bench_zoom.sh: no strata executable at $strata (run scripts/build.sh build)" >&2; exit 1; }
mkdir -p "$out"
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless}
scene=builtin:layers:$layers
for z in 1 2 3 4 5 6 7 8; do
    echo "bench_zoom.sh: $scene at $size, zoom $z" >&2
    "$strata" bench "$scene" --lod geometry --modes "$modes" --size "$size" --frames "$frames" --warmup 1 --zoom "$z" \
        --json "$out/speed-z$z.json" >/dev/null
    if (( z > 1 )); then  # image error where there are edges: the demo room, replicated and blurred
        "$strata" bench builtin:default --lod geometry --modes abuffer --size "$size" --frames 1 --warmup 0 --zoom "$z" \
            --json "$out/error-z$z.json" >/dev/null
        "$strata" bench builtin:default --lod geometry --modes abuffer --size "$size" --frames 1 --warmup 0 --zoom "$z" --zoom-blur \
            --json "$out/blur-z$z.json" >/dev/null
    fi
done
for controller in reactive predictive; do
    echo "bench_zoom.sh: $budget_mode under a $budget_ms ms budget, $controller, at $budget_size" >&2
    "$strata" bench "builtin:layers:16" --lod geometry --modes "$budget_mode" --size "$budget_size" --frames "$budget_frames" \
        --warmup 1 --camera-path "$root/scenes/paths/zoom-load-jumps.path" --frame-budget-ms "$budget_ms" \
        --zoom-controller "$controller" --zoom-max 8 --json "$out/budget-$controller.json" >/dev/null
done
python3 - "$out" "$modes" "$size" "$scene" "$budget_ms" <<'PY'
import json, math, os, sys
out, modes, size, scene, budget = sys.argv[1], sys.argv[2].split(','), sys.argv[3], sys.argv[4], float(sys.argv[5])
def load(name):
    with open(os.path.join(out, name)) as f:
        return json.load(f)
def rows(report):
    return {m['id']: m for m in report['modes']}
speed = {z: rows(load(f'speed-z{z}.json')) for z in range(1, 9)}
blur = {z: rows(load(f'blur-z{z}.json')) for z in range(2, 9)}
error = {z: rows(load(f'error-z{z}.json')) for z in range(2, 9)}
print(f'### Speedup against z ({scene}, {size}; whole-frame GPU ms, median)\n')
print('| z | ' + ' | '.join(f'{m} ms | {m} speedup' for m in modes) + ' | 0.8 z^2 |')
print('|---|' + '---:|---:|' * len(modes) + '---:|')
for z in range(1, 9):
    cells = []
    for m in modes:
        t, t1 = speed[z][m]['frame_ms_median'], speed[1][m]['frame_ms_median']
        cells += [f'{t:.1f}', f'{t1 / t:.2f}']
    print(f'| {z} | ' + ' | '.join(cells) + f' | {0.8 * z * z:.1f} |')
print(f'\n### Image error against the reference at z = 1 (abuffer on builtin:default, PSNR dB) and buffering ({scene}, abuffer, {size})\n')
print('| z | replicated | blurred | enlarge ms | fps single | fps double (60 Hz) |')
print('|---|---:|---:|---:|---:|---:|')
for z in range(1, 9):
    m = speed[z]['abuffer']
    t = m['frame_ms_median']
    double = 1000.0 / (math.ceil(t / (1000.0 / 60.0)) * (1000.0 / 60.0))
    b = f"{blur[z]['abuffer']['psnr']:.2f}" if z > 1 else '-'
    e = f"{error[z]['abuffer']['psnr']:.2f}" if z > 1 else '100.00'
    print(f"| {z} | {e} | {b} | {m['enlarge_ms_median']:.2f} | {1000.0 / t:.2f} | {double:.2f} |")
print(f'\n### Frame budget {budget:g} ms over scenes/paths/zoom-load-jumps.path (builtin:layers:16)\n')
print('| controller | frames in +-10 % | frames <= +10 % | mean z | excursions over +10 % (first frame: frames, peak/target) |')
print('|---|---:|---:|---:|---|')
for c in ('reactive', 'predictive'):
    m = load(f'budget-{c}.json')['modes'][0]
    b = m['budget']
    z = sum(b['frame_zoom']) / len(b['frame_zoom'])
    runs = ', '.join(f"{e['first_frame']}: {e['frames']}, {e['peak_over_target']:.2f}" for e in b['excursions']) or 'none'
    print(f"| {c} | {b['within_band']:.2f} | {b['not_over_band']:.2f} | {z:.2f} | {runs} |")
m = load('budget-predictive.json')['modes'][0]['budget']['model']
print(f"\npredictive model (calibrated on this device): {m['fixed_ms']:.2f} ms + {m['ms_per_megapixel']:.2f} ms/Mpx"
      f" + {m['ms_per_megafragment']:.2f} ms/Mfragment")
PY
