#!/usr/bin/env bash
# The depth-fighting paper's measurements (../shared/papers/depth-fighting-aware-multi-fragment-rendering.md):
#  1. coplanarity sweep: builtin:coplanar:K (K coincident full-view quads: overlap grows with K)
#     and depth-complexity sweep: builtin:layers:N (nothing coplanar), every coplanarity-aware
#     variant against its base method in one bench run per scene: time ratio variant / base
#     (whole technique, median GPU ms) and each one's R_h (robustness_ratio);
#  2. near-coplanar tolerance (the paper's case iii): C_p and the one-fragment-per-layer R_h of
#     the GPU detector at depth-tie tolerances 0..2^20 ulps on the builtin scenes with coincident
#     or round-off surfaces and the shipped transparent models.
# JSON of each run stays in the output folder; markdown tables go to stdout.
#
# usage: scripts/bench_coplanarity.sh [--out DIR] [--strata PATH] [--size WxH] [--frames N]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/docs/bench/coplanarity
strata=$root/build/viewer/strata
size=256x256
frames=3
while [[ $# -gt 0 ]]; do
    case $1 in
        --out) out=$2; shift 2 ;;
        --strata) strata=$2; shift 2 ;;
        --size) size=$2; shift 2 ;;
        --frames) frames=$2; shift 2 ;;
        -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
        *) echo "bench_coplanarity.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done
[[ -x $strata ]] || { echo "bench_coplanarity.sh: no strata executable at $strata (run scripts/build.sh build)" >&2; exit 1; }
mkdir -p "$out"
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless}
# Each variant and its base; only those `strata modes` lists are run.
pairs="f2b:f2b-2p f2b:f2b-3p f2b:f2b-ll f2b:f2b-fab f2b:f2b-kb dual:dual-2p dual:dual-ll dual:dual-fab bun:bun-ll"
known=$("$strata" modes | awk 'NR > 1 { print $1 }')
modes=""
for p in $pairs; do
    for id in ${p%%:*} ${p##*:}; do
        grep -qx -- "$id" <<<"$known" && [[ ",$modes," != *",$id,"* ]] && modes=${modes:+$modes,}$id
    done
done
scenes="coplanar:1 coplanar:2 coplanar:4 coplanar:8 coplanar:16 layers:2 layers:4 layers:8 layers:16"
for s in $scenes; do
    echo "bench_coplanarity.sh: builtin:$s at $size" >&2
    "$strata" bench "builtin:$s" --lod geometry --modes "$modes" --size "$size" --frames "$frames" --warmup 1 \
        --json "$out/sweep-${s/:/-}.json" >/dev/null
done
models=""
for f in "$root"/scenes/*-glass.json "$root"/scenes/models-volume.json; do [[ -f $f ]] && models="$models $f"; done
tolerances="0 4 64 1024 16384 1048576"
for s in builtin:shells:3:roundoff builtin:cubes builtin:default $models; do
    for u in $tolerances; do
        name=$(basename "${s//:/-}" .json)
        "$strata" render "$s" --size 320x240 --out "$out/tol-$name-$u.png" --heatmap "$out/tol-$name-$u-heat.png" \
            --depth-tie-ulps "$u" >"$out/tol-$name-$u.txt"
        rm -f "$out/tol-$name-$u.png"
    done
done
python3 - "$out" "$pairs" "$scenes" "$tolerances" $models <<'PY'
import glob, json, os, re, sys
out, pairs, scenes, tolerances = sys.argv[1], sys.argv[2].split(), sys.argv[3].split(), sys.argv[4].split()
models = [os.path.basename(m)[:-5] for m in sys.argv[5:]]
runs = {s: {m['id']: m for m in json.load(open(os.path.join(out, f"sweep-{s.replace(':', '-')}.json")))['modes']} for s in scenes}
present = [p.split(':') for p in pairs if all(i in runs[scenes[0]] for i in p.split(':'))]
print('### Variant against its base: time ratio (R_h of the variant; of the base)\n')
print('| scene | ' + ' | '.join(f'{v} / {b}' for b, v in present) + ' |')
print('|---|' + '---:|' * len(present))
for s in scenes:
    cells = []
    for b, v in present:
        mb, mv = runs[s][b], runs[s][v]
        ratio = mv['ms_median'] / mb['ms_median'] if mb['ms_median'] > 0 else float('nan')
        cells.append(f"{ratio:.2f} ({mv['robustness_ratio']:.3f}; {mb['robustness_ratio']:.3f})")
    print(f'| `{s}` | ' + ' | '.join(cells) + ' |')
print('\n### Near-coplanar tolerance: C_p / one-fragment-per-layer R_h at 320x240\n')
print('| scene | ' + ' | '.join(f'{u} ulps' for u in tolerances) + ' |')
print('|---|' + '---:|' * len(tolerances))
for s in ['builtin-shells-3-roundoff', 'builtin-cubes', 'builtin-default'] + models:
    cells = []
    for u in tolerances:
        text = open(os.path.join(out, f'tol-{s}-{u}.txt')).read()
        cp = re.search(r'C_p ([0-9.]+)', text)
        rh = re.search(r'one fragment per layer \(f2b\) ([0-9.]+)', text)
        cells.append(f"{cp.group(1)} / {rh.group(1)}" if cp and rh else 'n/a')
    print(f'| `{s}` | ' + ' | '.join(cells) + ' |')
PY
