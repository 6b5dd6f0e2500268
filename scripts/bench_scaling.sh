#!/usr/bin/env bash
# How cost grows with depth complexity and resolution, and the speed/accuracy trade, in one
# command: runs `strata bench` over builtin:layers:{2,4,8,16,32} at 256x256, builtin:layers:8 at
# 128/256/512, and scenes/fandisk-glass.json at 256x256 (every technique, floor included), keeps
# each run's CSV and JSON, merges them, writes a text table and three gnuplot plots:
#   error-vs-time.png       RMSE against GPU ms, one labelled point per technique (log-log)
#   time-vs-layers.png      GPU ms against layers, one line per technique
#   time-vs-resolution.png  GPU ms against pixels, one line per technique
#
# usage: scripts/bench_scaling.sh [--out DIR] [--strata PATH] [--modes all|ID,ID] [--frames N] [--warmup N]
# Defaults keep llvmpipe runs to a few minutes: --frames 3 --warmup 1, out docs/bench.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/docs/bench
strata=""
modes=all
frames=3
warmup=1
while [[ $# -gt 0 ]]; do
    case $1 in
        --out) out=$2; shift 2 ;;
        --strata) strata=$2; shift 2 ;;
        --modes) modes=$2; shift 2 ;;
        --frames) frames=$2; shift 2 ;;
        --warmup) warmup=$2; shift 2 ;;
        -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
        *) echo "bench_scaling.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done
if [[ -z $strata ]]; then
    strata=$root/build/viewer/strata
    [[ -x $strata ]] || bash "$root/scripts/build.sh" "$root/build"
fi
[[ -x $strata ]] || { echo "bench_scaling.sh: no strata executable at $strata" >&2; exit 1; }
strata=$(realpath "$strata")
mkdir -p "$out"
out=$(realpath "$out")
cd "$root"  # scene names in the reports stay relative to the repository
command -v gnuplot >/dev/null || { echo "bench_scaling.sh: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless}
mkdir -p "$out/runs"

# bench NAME SCENE SIZE: one run, kept as runs/NAME.{csv,json,txt}.
bench() {
    local name=$1 scene=$2 size=$3
    echo "== $name: $scene at $size" >&2
    "$strata" bench "$scene" --lod geometry --size "$size" --modes "$modes" --frames "$frames" --warmup "$warmup" \
        --csv "$out/runs/$name.csv" --json "$out/runs/$name.json" > "$out/runs/$name.txt"
    cat "$out/runs/$name.txt"
}

# merge KEY FILE VALUE...: prefixes each run's rows with KEY=VALUE; one header.
merge() {
    local key=$1 file=$2; shift 2
    local first=1
    : > "$file.partial"
    for v in "$@"; do
        local csv=$out/runs/$key-$v.csv
        if [[ $first == 1 ]]; then echo "$key,$(head -n1 "$csv")" >> "$file.partial"; first=0; fi
        tail -n +2 "$csv" | sed "s/^/$v,/" >> "$file.partial"
    done
    mv "$file.partial" "$file"
}

layers=(2 4 8 16 32)
resolutions=(128 256 512)
for n in "${layers[@]}"; do bench "layers-$n" "builtin:layers:$n" 256x256; done
for r in "${resolutions[@]}"; do bench "resolution-$r" "builtin:layers:8" "${r}x${r}"; done
bench fandisk-glass scenes/fandisk-glass.json 256x256
merge layers "$out/layers.csv" "${layers[@]}"
merge resolution "$out/resolution.csv" "${resolutions[@]}"
cp "$out/runs/layers-16.csv" "$out/layers-16.csv"
cp "$out/runs/fandisk-glass.csv" "$out/fandisk-glass.csv"

# The table: GPU ms per technique against layers and resolution, and x floor at 16 layers.
table() {
    local file=$1 key=$2; shift 2
    awk -F, -v key="$key" -v cols="$*" '
        NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
        { m = $c["mode"]; if (!(m in seen)) { seen[m] = 1; order[++n] = m } ms[m, $1] = $c["ms_median"] }
        END {
            k = split(cols, v, " ")
            printf "| mode |"; for (i = 1; i <= k; ++i) printf " %s %s |", key, v[i]; printf "\n"
            printf "|---|"; for (i = 1; i <= k; ++i) printf "---:|"; printf "\n"
            for (j = 1; j <= n; ++j) {
                printf "| %s |", order[j]
                for (i = 1; i <= k; ++i) printf " %.3f |", ms[order[j], v[i]]
                printf "\n"
            }
        }' "$file"
}
{
    echo "# Scaling (GPU ms, median of $frames frames; $(sed -n 's/.*"renderer": "\(.*\)",*/\1/p' "$out/runs/layers-16.json" | head -n1))"
    echo
    echo "Produced by \`scripts/bench_scaling.sh --modes $modes --frames $frames --warmup $warmup\`;"
    echo "ms_over_floor (\"x floor\") divides by the floor row of the same run."
    echo
    echo "## Depth complexity (builtin:layers:N, 256x256)"
    echo
    table "$out/layers.csv" layers "${layers[@]}"
    echo
    echo "## Resolution (builtin:layers:8)"
    echo
    table "$out/resolution.csv" px "${resolutions[@]}"
    echo
    echo "## builtin:layers:16 at 256x256"
    echo
    echo '```'
    cat "$out/runs/layers-16.txt"
    echo '```'
    echo
    echo "## scenes/fandisk-glass.json at 256x256"
    echo
    echo '```'
    cat "$out/runs/fandisk-glass.txt"
    echo '```'
} > "$out/scaling.md"

terminal="pngcairo font 'DejaVu Sans,10'"
gnuplot -e "set terminal pngcairo" >/dev/null 2>&1 || terminal="png"
for plot in error-vs-time time-vs-layers time-vs-resolution; do
    gnuplot -e "dir='$out'; plots='$root/scripts/plots'; term=\"$terminal\"" "$root/scripts/plots/$plot.gp"
done
echo "wrote $out/{layers,resolution,layers-16,fandisk-glass}.csv, scaling.md and" \
     "error-vs-time.png, time-vs-layers.png, time-vs-resolution.png" >&2
