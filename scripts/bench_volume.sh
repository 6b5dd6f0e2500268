#!/usr/bin/env bash
# The volumetric paper's Tables 1-2 setup: builtin:slabs:N (N full-view closed slabs, exactly 2N
# fragments per pixel) for N = 2..16 at 800x600 and 1024x768, ll-volume against ll and abuffer
# (and abuffer-volume) in one bench run per point, ll's pools sized to hold every fragment.
# Prints one markdown table (ms per frame, the volume resolve against the surface resolve) and
# keeps each run's JSON in the output folder.
#
# usage: scripts/bench_volume.sh [--out DIR] [--strata PATH] [--frames N] [--layers "2 4 8 16"] [--sizes "800x600 1024x768"]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/docs/bench/volume
strata=$root/build/viewer/strata
frames=3
layers="2 4 8 16"
sizes="800x600 1024x768"
while [[ $# -gt 0 ]]; do
    case $1 in
        --out) out=$2; shift 2 ;;
        --strata) strata=$2; shift 2 ;;
        --frames) frames=$2; shift 2 ;;
        --layers) layers=$2; shift 2 ;;
        --sizes) sizes=$2; shift 2 ;;
        -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
        *) echo "bench_volume.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done
[[ -x $strata ]] || { echo "bench_volume.sh: no strata executable at $strata (run scripts/build.sh build)" >&2; exit 1; }
mkdir -p "$out"
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless}
for size in $sizes; do
    for n in $layers; do
        echo "bench_volume.sh: slabs:$n at $size" >&2
        "$strata" bench "builtin:slabs:$n" --lod geometry --modes abuffer,abuffer-volume,ll,ll-volume --size "$size" \
            --frames "$frames" --warmup 1 --set "capacity=$((2 * n))" --json "$out/slabs-$n-$size.json" >/dev/null
    done
done
python3 - "$out" $sizes -- $layers <<'PY'
import json, sys
out = sys.argv[1]
split = sys.argv.index('--')
sizes, layers = sys.argv[2:split], sys.argv[split + 1:]
print("| size | slabs (fragments/pixel) | abuffer | abuffer-volume | ll | ll-volume | ll-volume / ll resolve | ll-volume / ll total | max err (vs abuffer-volume) |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
for size in sizes:
    for n in layers:
        d = json.load(open(f"{out}/slabs-{n}-{size}.json"))
        m = {x["id"]: x for x in d["modes"]}
        def resolve(id):
            return sum(v for k, v in m[id]["pass_ms_median"].items() if "resolve" in k)
        ratio_resolve = resolve("ll-volume") / resolve("ll")
        ratio_total = m["ll-volume"]["ms_median"] / m["ll"]["ms_median"]
        print(f"| {size} | {n} ({2 * int(n)}) | {m['abuffer']['ms_median']:.1f} | {m['abuffer-volume']['ms_median']:.1f} | "
              f"{m['ll']['ms_median']:.1f} | {m['ll-volume']['ms_median']:.1f} | {ratio_resolve:.2f} | {ratio_total:.2f} | "
              f"{m['ll-volume']['max_abs_error']:.1e} |")
PY
