#!/usr/bin/env bash
# Silhouette opacity, measured (Sen, Chemudugunta, Gopi, sections 3-5): opacity against the
# viewing angle for abuffer, crow and the three screen-door techniques, on the builtin sphere
# (alpha 0.3) and on scenes/spot-glass.json (a closed model, alpha 0.3), each rendered over white
# and over black by build/tools/strata-silhouette. Writes docs/silhouette/{sphere,spot-glass}.{csv,md}
# and docs/silhouette-opacity.png.
#
# usage: scripts/silhouette_opacity.sh [--size N] [--supersampling N] [--out DIR]
# Defaults: 256x256 at 16x16 supersampling (the paper's), about a minute on llvmpipe.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
size=256
supersampling=16
out=$root/docs
while [[ $# -gt 0 ]]; do
    case $1 in
        --size) size=$2; shift 2 ;;
        --supersampling) supersampling=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
        *) echo "silhouette_opacity.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done
tool=$root/build/tools/strata-silhouette
[[ -x $tool ]] || { echo "silhouette_opacity.sh: build $tool first (scripts/build.sh build)" >&2; exit 1; }
command -v gnuplot >/dev/null || { echo "silhouette_opacity.sh: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless}
mkdir -p "$out/silhouette"
out=$(realpath "$out")
cd "$root"  # scene names in the CSVs stay relative to the repository
for scene in sphere scenes/spot-glass.json; do
    name=$(basename "$scene" .json)
    echo "== $name" >&2
    "$tool" "$scene" --alpha 0.3 --size "$size" --supersampling "$supersampling" \
        --csv "$out/silhouette/$name.csv" --markdown "$out/silhouette/$name.md" > /dev/null
    cat "$out/silhouette/$name.md"
done
gnuplot -e "csvs='$out/silhouette/sphere.csv $out/silhouette/spot-glass.csv'; out='$out/silhouette-opacity.png'" \
    "$root/scripts/plots/silhouette-opacity.gp"
echo "wrote $out/silhouette/{sphere,spot-glass}.{csv,md} and $out/silhouette-opacity.png" >&2
