#!/usr/bin/env bash
# The screen-door family's cost and error against the exact reference at 1x1, 4x4 and 16x16
# supersampling: one `strata bench` run per scene and level (`--set supersampling=N`, which every
# screen-door technique has and crow and abuffer lack), over builtin:default, scenes/spot-glass.json
# and the two scenes of the speed/accuracy chart (builtin:layers:16, scenes/fandisk-glass.json).
# Writes runs/screendoor-SCENE-nN.{csv,json,txt}, screendoor-SCENE.csv (merged, a supersampling
# column first), screendoor.md (ms and RMSE per technique and level), and redraws
# error-vs-time.png, which places these rows beside the other families of scripts/bench_scaling.sh.
#
# usage: scripts/bench_screendoor.sh [--out DIR] [--strata PATH] [--size WxH] [--frames N] [--warmup N]
# Defaults: 256x256, --frames 3 --warmup 1, out docs/bench; about 10 minutes on 2-core llvmpipe.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/docs/bench
strata=$root/build/viewer/strata
size=256x256
frames=3
warmup=1
while [[ $# -gt 0 ]]; do
    case $1 in
        --out) out=$2; shift 2 ;;
        --strata) strata=$2; shift 2 ;;
        --size) size=$2; shift 2 ;;
        --frames) frames=$2; shift 2 ;;
        --warmup) warmup=$2; shift 2 ;;
        -h|--help) sed -n '2,11p' "$0"; exit 0 ;;
        *) echo "bench_screendoor.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done
[[ -x $strata ]] || { echo "bench_screendoor.sh: no strata executable at $strata (scripts/build.sh build)" >&2; exit 1; }
strata=$(realpath "$strata")
mkdir -p "$out/runs"
out=$(realpath "$out")
cd "$root"  # scene names in the reports stay relative to the repository
command -v gnuplot >/dev/null || { echo "bench_screendoor.sh: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless}
modes=abuffer,crow,screendoor,screendoor-object,screendoor-object-sw
levels=(1 4 16)
declare -A scenes=([default]=builtin:default [spot-glass]=scenes/spot-glass.json
                   [layers-16]=builtin:layers:16 [fandisk-glass]=scenes/fandisk-glass.json)
names=(default spot-glass layers-16 fandisk-glass)

for name in "${names[@]}"; do
    : > "$out/screendoor-$name.csv.partial"
    for n in "${levels[@]}"; do
        run=$out/runs/screendoor-$name-n$n
        echo "== ${scenes[$name]} at $size, supersampling $n" >&2
        "$strata" bench "${scenes[$name]}" --lod geometry --size "$size" --modes "$modes" --frames "$frames" --warmup "$warmup" \
            --set "supersampling=$n" --csv "$run.csv" --json "$run.json" > "$run.txt"
        [[ -s $out/screendoor-$name.csv.partial ]] || echo "supersampling,$(head -n1 "$run.csv")" >> "$out/screendoor-$name.csv.partial"
        tail -n +2 "$run.csv" | sed "s/^/$n,/" >> "$out/screendoor-$name.csv.partial"
    done
    mv "$out/screendoor-$name.csv.partial" "$out/screendoor-$name.csv"
done

# The table: GPU ms and RMSE per technique at each level, one block per scene.
{
    echo "# Screen-door family: cost and error against abuffer ($size, median of $frames frames; $(sed -n 's/.*"renderer": "\(.*\)",*/\1/p' "$out/runs/screendoor-default-n1.json" | head -n1))"
    echo
    echo "Produced by \`scripts/bench_screendoor.sh --size $size --frames $frames --warmup $warmup\`: one"
    echo "\`strata bench SCENE --modes $modes --set supersampling=N\` per scene and N."
    echo "crow and abuffer have no supersampling: their rows repeat across levels (three measurements)."
    for name in "${names[@]}"; do
        echo
        echo "## ${scenes[$name]}"
        echo
        awk -F, '
            NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
            { m = $c["mode"]; if (!(m in seen)) { seen[m] = 1; order[++k] = m }
              ms[m, $1] = $c["ms_median"]; e[m, $1] = $c["rmse"]; o[m, $1] = $c["overflowed"] }
            END {
                printf "| mode | ms n=1 | ms n=4 | ms n=16 | RMSE n=1 | RMSE n=4 | RMSE n=16 |\n|---|---:|---:|---:|---:|---:|---:|\n"
                for (j = 1; j <= k; ++j) {
                    m = order[j]; printf "| %s |", m
                    split("1 4 16", v, " ")
                    for (i = 1; i <= 3; ++i) printf " %.2f |", ms[m, v[i]]
                    for (i = 1; i <= 3; ++i) printf " %.2e%s |", e[m, v[i]], o[m, v[i]] == 1 ? " (overflow)" : ""
                    printf "\n"
                }
            }' "$out/screendoor-$name.csv"
    done
} > "$out/screendoor.md"

terminal="pngcairo font 'DejaVu Sans,10'"
gnuplot -e "set terminal pngcairo" >/dev/null 2>&1 || terminal="png"
gnuplot -e "dir='$out'; plots='$root/scripts/plots'; term=\"$terminal\"" "$root/scripts/plots/error-vs-time.gp"
cat "$out/screendoor.md"
echo "wrote $out/screendoor-*.csv, screendoor.md and error-vs-time.png" >&2
