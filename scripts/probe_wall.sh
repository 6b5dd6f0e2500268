#!/usr/bin/env bash
# Strata beside the naive probe (../shared/tools/peers/oitprobe.c), wall clock against wall
# clock: the probe times each frame to a glFinish; `strata bench --wall` draws the same frames
# again without its pass timers and fragment count and times them the same way. On llvmpipe the
# pass timers drain the pipeline at every pass edge, so the summed pass times that peers.sh
# compares overstate Strata's frame (docs/results.md, "Two clocks"). VTK's peers are not here:
# peers.sh runs them (they need Debian's libvtk9-dev).
#
# Each run: per layer count, the probe (linked lists and F2B, 5 frames) then Strata's f2b, f2b2,
# dual and abuffer, and ll at capacity L (every fragment kept). Prints one markdown table of
# Strata wall / probe wall per run and layer count.
#
# usage: scripts/probe_wall.sh [--strata PATH] [--size WxH] [--layers "8 16 32"] [--runs N] [--out DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
strata=$root/build/viewer/strata
size=256x256
layers="8 16 32"
runs=3
out=/tmp/strata-probe-wall
while [[ $# -gt 0 ]]; do
    case $1 in
        --strata) strata=$2; shift 2 ;;
        --size) size=$2; shift 2 ;;
        --layers) layers=$2; shift 2 ;;
        --runs) runs=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
        *) echo "probe_wall.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done
[[ $size =~ ^[0-9]+x[0-9]+$ ]] || { echo "probe_wall.sh: --size takes WxH, not '$size'" >&2; exit 2; }
[[ -x $strata ]] || { echo "probe_wall.sh: no $strata (build first: bash scripts/build.sh build)" >&2; exit 1; }
probe_src=$root/../shared/tools/peers/oitprobe.c
[[ -e $probe_src ]] || { echo "probe_wall.sh: no $probe_src" >&2; exit 1; }
mkdir -p "$out"
probe=$out/oitprobe
[[ $probe -nt $probe_src ]] || gcc -O2 "$probe_src" -o "$probe" -lEGL -lGL -lm
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless} XDG_CACHE_HOME=$out/cache
w=${size%x*}
h=${size#*x}

echo "| run | layers | probe F2B ms | probe lists ms | f2b | f2b2 | dual | abuffer | ll (capacity L) |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for run in $(seq 1 "$runs"); do
    for L in $layers; do
        echo "probe_wall.sh: run $run, $L layers" >&2
        "$probe" "$w" "$h" "$L" 0 0 5 >"$out/probe-$run-$L.txt" 2>&1
        "$strata" bench "builtin:layers:$L" --lod geometry --size "$size" --frames 5 --wall \
            --modes f2b,f2b2,dual,abuffer,ll --set ll.capacity="$L" --json "$out/strata-$run-$L.json" \
            >"$out/strata-$run-$L.txt" 2>&1
        python3 - "$out/probe-$run-$L.txt" "$out/strata-$run-$L.json" "$run" "$L" <<'EOF'
import json, re, sys
probe = open(sys.argv[1]).read()
f2b = float(re.search(r"^F2B peel: ([0-9.]+)", probe, re.M).group(1))
lists = float(re.search(r"^PPLL: ([0-9.]+)", probe, re.M).group(1))
wall = {m["id"]: m["wall_ms_median"] for m in json.load(open(sys.argv[2]))["modes"]}
def r(mode, peer):
    return "%.2f (%.1f)" % (wall[mode] / peer, wall[mode])
print("| %s | %s | %.1f | %.1f | %s | %s | %s | %s | %s |" % (sys.argv[3], sys.argv[4], f2b, lists,
      r("f2b", f2b), r("f2b2", f2b), r("dual", f2b), r("abuffer", lists), r("ll", lists)))
EOF
    done
done
echo
echo "Each Strata cell: its wall ms over the probe's (F2B for f2b, f2b2 and dual; the linked lists for"
echo "abuffer and ll), and in brackets its wall ms. Raw output in $out."
