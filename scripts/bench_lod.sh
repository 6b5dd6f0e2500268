#!/usr/bin/env bash
# Layered-impostor LOD (Schauffler, ../shared/papers/layered-impostors.md section 4; issue 11):
# builtin:field:N (N instances of one 46080-triangle mesh over a ground) drawn with
# `strata bench --lod geometry` (the reference), `--lod impostors` for every
# views x slices x image size, and `--lod auto` (the cost model's per-object choice). Table:
# median GPU frame ms, speedup against geometry, PSNR of the first frame against geometry's,
# impostor objects and impostor memory (the bench JSON's impostor_objects, impostor_bytes).
# The issue's aim: >= 5x faster than geometry at PSNR >= 30 dB on field:1000 at 1080p.
# Then the crossover (Fig. 8): builtin:field:1 (one instance, its bounding sphere 0.592 x the
# image height across: tests/field_scene_test.cpp) in square images of --crossover-sizes, geometry
# against impostors (20 views, 128 px) per slice count; the measured on-screen size where the
# impostor stops being cheaper, next to the cost model's prediction (lod/lod_cost_model.hpp
# crossoverSizePx for 46080 triangles) when the bench JSON carries the calibrated model as
# "lod": {"model": {geometry_fixed_ms, geometry_ms_per_megatriangle, geometry_ms_per_megapixel,
# impostor_fixed_ms, impostor_instance_ms, impostor_ms_per_kiloquad, impostor_ms_per_kiloside_px,
# impostor_ms_per_megapixel}} (a quad a slice, a draw of its own).
# Each run's JSON and first frame stay in the output folder; the table goes to stdout (markdown).
#
# usage: scripts/bench_lod.sh [--out DIR] [--strata PATH] [--count N] [--size WxH] [--frames N]
#        [--views 12,20,32] [--slices 16,64,256] [--resolutions 64,128,256] [--mode ID]
#        [--transparent] [--crossover-sizes 64,128,256,512,1024] [--quick]
#        [--scale [--scale-counts 100,1000,10000]]
#   --quick: field:100 at 640x360, views 20, slices 16,64, resolutions 64,128, 2 frames,
#            crossover sizes 64,128,256.
#   --scale: instead of the above, the scene graph at scale (issue 23; scripts/lib/bench_scale.py):
#            builtin:orchard:N for each of --scale-counts, 64 copies of a 115-part CAD model
#            (assimp-testmodels' 2CylinderEngine.glb) and 10^4 copies of a 12-triangle box
#            (scripts/lib/instanced_boxes.py); render wall time and RSS, frame ms and PSNR per LOD
#            mode, impostor memory, the LOD step's CPU per object, GL draws per frame and the
#            render thread's CPU, beside the issue's aims.
#            Default size 640x400, 3 frames; output in docs/bench/scale.
# The impostor settings reach strata as --impostor-views, --impostor-slices and
# --impostor-resolution (change VIEWS_FLAG, SLICES_FLAG, RES_FLAG below if they are named otherwise).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/docs/bench/lod
strata=$root/build/viewer/strata
count=1000
size=1920x1080
frames=3
views=12,20,32
slices=16,64,256
resolutions=64,128,256
crossover_sizes=64,128,256,512,1024
scale=""
scale_counts=100,1000,10000
size_given=""
out_given=""
mode=blend-sorted  # the transparency technique: the opaque field does not depend on it
variant=""
VIEWS_FLAG=--impostor-views
SLICES_FLAG=--impostor-slices
RES_FLAG=--impostor-resolution
while [[ $# -gt 0 ]]; do
    case $1 in
        --out) out=$2; out_given=1; shift 2 ;;
        --strata) strata=$2; shift 2 ;;
        --count) count=$2; shift 2 ;;
        --size) size=$2; size_given=1; shift 2 ;;
        --frames) frames=$2; shift 2 ;;
        --views) views=$2; shift 2 ;;
        --slices) slices=$2; shift 2 ;;
        --resolutions) resolutions=$2; shift 2 ;;
        --mode) mode=$2; shift 2 ;;
        --transparent) variant=:transparent; shift ;;
        --crossover-sizes) crossover_sizes=$2; shift 2 ;;
        --scale) scale=1; shift ;;
        --scale-counts) scale_counts=$2; shift 2 ;;
        --quick) count=100; size=640x360; views=20; slices=16,64; resolutions=64,128; frames=2
                 crossover_sizes=64,128,256; shift ;;
        -h|--help) sed -n '2,32p' "$0"; exit 0 ;;
        *) echo "bench_lod.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done
[[ -x $strata ]] || { echo "bench_lod.sh: no strata executable at $strata (run scripts/build.sh build)" >&2; exit 1; }
help=$("$strata" bench --help 2>&1 || true)
for flag in --lod "$VIEWS_FLAG" "$SLICES_FLAG" "$RES_FLAG"; do
    grep -q -- "$flag" <<<"$help" || { echo "bench_lod.sh: 'strata bench' has no $flag option yet" >&2; exit 1; }
done
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless}
if [[ -n $scale ]]; then
    [[ -n $out_given ]] || out=$root/docs/bench/scale
    [[ -n $size_given ]] || size=640x400
    exec python3 "$root/scripts/lib/bench_scale.py" "$strata" "$out" "$size" "$frames" "$scale_counts"
fi
mkdir -p "$out"
scene=builtin:field:$count$variant
tag=$count${variant:+-transparent}-$size

bench() {  # name, then extra arguments: the field at --size
    bench_at "$scene" "$size" "$@"
}
bench_at() {  # scene, size, name, then extra arguments
    local at=$1 wh=$2 name=$3; shift 3
    echo "bench_lod.sh: $at at $wh: $name" >&2
    rm -rf "${out:?}/$name"
    "$strata" bench "$at" --modes "$mode" --size "$wh" --frames "$frames" --warmup 1 \
        --json "$out/$name.json" --images "$out/$name" "$@" >/dev/null
}

bench "geometry-$tag" --lod geometry
bench "auto-$tag" --lod auto
for v in ${views//,/ }; do
    for l in ${slices//,/ }; do
        for r in ${resolutions//,/ }; do
            bench "impostors-$tag-v$v-l$l-r$r" --lod impostors "$VIEWS_FLAG" "$v" "$SLICES_FLAG" "$l" "$RES_FLAG" "$r"
        done
    done
done

for c in ${crossover_sizes//,/ }; do
    bench_at "builtin:field:1$variant" "${c}x$c" "crossover-geometry-$c" --lod geometry
    for l in ${slices//,/ }; do
        bench_at "builtin:field:1$variant" "${c}x$c" "crossover-impostors-$c-l$l" --lod impostors \
            "$VIEWS_FLAG" 20 "$SLICES_FLAG" "$l" "$RES_FLAG" 128
    done
done

python3 - "$out" "$tag" "$mode" "$scene" "$size" "$views" "$slices" "$resolutions" "$crossover_sizes" <<'PY'
import json, math, os, struct, sys, zlib
out, tag, mode, scene, size = sys.argv[1:6]
views, slices, resolutions, crossover_sizes = (s.split(',') for s in sys.argv[6:10])

def png(path):
    """8-bit grey/RGB/RGBA, non-interlaced PNG -> (width, height, channels, rows of bytes)."""
    with open(path, 'rb') as f:
        data = f.read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise SystemExit(f'bench_lod.sh: {path}: not a PNG')
    pos, idat, header = 8, b'', None
    while pos < len(data):
        length, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b'IHDR':
            header = struct.unpack('>IIBBBBB', body)
        elif kind == b'IDAT':
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    channels = {0: 1, 2: 3, 6: 4, 4: 2}.get(colour)
    if depth != 8 or channels is None or interlace:
        raise SystemExit(f'bench_lod.sh: {path}: only 8-bit non-interlaced grey/RGB/RGBA PNGs are read')
    raw, stride, rows, prev = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b, c = prev[x], prev[x - channels] if x >= channels else 0
            if kind == 1: line[x] = (line[x] + a) & 255
            elif kind == 2: line[x] = (line[x] + b) & 255
            elif kind == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, channels, rows

def psnr(a_path, b_path):
    """PSNR in dB over the colour channels of two PNGs of one size (8-bit values, peak 255)."""
    wa, ha, ca, ra = png(a_path)
    wb, hb, cb, rb = png(b_path)
    if (wa, ha) != (wb, hb):
        raise SystemExit(f'bench_lod.sh: {a_path} and {b_path} differ in size')
    colour = min(ca, cb, 3)
    total, n = 0, 0
    for la, lb in zip(ra, rb):
        for x in range(wa):
            for k in range(colour):
                d = la[x * ca + k] - lb[x * cb + k]
                total += d * d
        n += wa * colour
    mse = total / n
    return math.inf if mse == 0 else 10 * math.log10(255 * 255 / mse)

def load(name):
    with open(os.path.join(out, name + '.json')) as f:
        report = json.load(f)
    row = report['modes'][0]
    ms = row.get('frame_ms_median', row.get('ms_median'))
    field = lambda k: row.get(k, report.get(k, 0))
    return ms, field('impostor_objects'), field('impostor_bytes'), row.get('psnr', 0.0)

def first_frame(name):
    return os.path.join(out, name, mode + '.png')

geo = f'geometry-{tag}'
geo_ms = load(geo)[0]
print(f'### Layered impostors on {scene} at {size} ({mode}; median GPU frame ms; PSNR against geometry: the bench\'s, '
      f'linear RGB over every frame, and of the first frame\'s 8-bit sRGB PNG)\n')
print(f'geometry: {geo_ms:.2f} ms\n')
print('| lod | views | slices | image | ms | speedup | PSNR dB linear | PSNR dB sRGB 8-bit | impostor objects | impostor MB |')
print('|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|')
def row(name, label, v='-', l='-', r='-'):
    ms, objects, nbytes, linear = load(name)
    p = psnr(first_frame(geo), first_frame(name))
    print(f'| {label} | {v} | {l} | {r} | {ms:.2f} | {geo_ms / ms:.2f}x | {linear:.2f} | {p:.2f} | {objects} | {nbytes / 1e6:.3f} |')
row(f'auto-{tag}', 'auto')
for v in views:
    for l in slices:
        for r in resolutions:
            row(f'impostors-{tag}-v{v}-l{l}-r{r}', 'impostors', v, l, f'{r}x{r}')

# Fig. 8: where the impostor stops being cheaper than the 46080-triangle model.
FRACTION, TRIANGLES = 0.592, 46080  # field:1's bounding diameter / image height; the mesh
print(f'\n### Crossover on builtin:field:1 (one {TRIANGLES}-triangle instance; impostors 20 views, 128 px; median GPU frame ms)\n')
print('| image | object px | geometry ms | ' + ' | '.join(f'L={l} ms' for l in slices) + ' |')
print('|---:|---:|---:|' + '---:|' * len(slices))
geometry = {c: load(f'crossover-geometry-{c}')[0] for c in crossover_sizes}
impostor = {(c, l): load(f'crossover-impostors-{c}-l{l}')[0] for c in crossover_sizes for l in slices}
for c in crossover_sizes:
    print(f'| {c}x{c} | {FRACTION * int(c):.0f} | {geometry[c]:.2f} | ' +
          ' | '.join(f'{impostor[(c, l)]:.2f}' for l in slices) + ' |')
model = None  # the cost model the auto run calibrated (geometry runs measure none)
for name in sorted(os.listdir(out)):
    if name.startswith('auto-') and name.endswith('.json'):
        with open(os.path.join(out, name)) as f:
            model = model or (json.load(f).get('lod') or {}).get('model')
def predicted(l):
    if not model:
        return 'n/a (no lod.model in the bench JSON: run with --lod auto)'
    # lod_cost_model.cpp's crossoverSizePx: a s^2 + b s < margin.
    a = (model['impostor_ms_per_megapixel'] * l - model['geometry_ms_per_megapixel']) * 1e-6
    b = model.get('impostor_ms_per_kiloside_px', 0.0) * l * 1e-3
    impostor_fixed = (model['impostor_fixed_ms'] + model.get('impostor_instance_ms', 0.0) +
                      model.get('impostor_ms_per_kiloquad', 0.0) * l * 1e-3)
    margin = model['geometry_fixed_ms'] + model['geometry_ms_per_megatriangle'] * TRIANGLES * 1e-6 - impostor_fixed
    if margin <= 0:
        return 'never'
    if a == 0:
        return f'{margin / b:.0f} px' if b > 0 else 'every size'
    discriminant = b * b + 4 * a * margin
    if discriminant < 0 or (a < 0 and b <= 0):
        return 'every size'
    return f'{(-b + math.sqrt(discriminant)) / (2 * a):.0f} px'
print('\n| slices | measured crossover (object px) | predicted (cost model) |')
print('|---:|---:|---:|')
for l in slices:
    points = [(FRACTION * int(c), impostor[(c, l)] - geometry[c]) for c in crossover_sizes]
    measured = 'impostor cheaper at every size' if all(d < 0 for _, d in points) else \
               'geometry cheaper at every size' if all(d >= 0 for _, d in points) else None
    if measured is None:  # the first sign change, interpolated linearly
        for (p0, d0), (p1, d1) in zip(points, points[1:]):
            if (d0 < 0) != (d1 < 0):
                measured = f'{p0 + (p1 - p0) * d0 / (d0 - d1):.0f} px'
                break
    print(f'| {l} | {measured} | {predicted(int(l))} |')
PY
