#!/usr/bin/env bash
# Packs what a lent GPU machine needs into one ignored folder (default .gpu/, about 33 MB): the
# built `strata` and GL test executables with their libraries and shaders
# (../shared/tools/gpu-bundle/make-bundle.py), the naive probe (../shared/tools/peers/oitprobe.c)
# and the shared models. On the GPU machine, from the repository root:
#   bash scripts/gpu_check.sh --bundle .gpu --tar $OUT/report.tgz [--sizes ...] [--modes ...]
# (docs/gpu-h100.md: what a 15-minute run held).
#
# usage: scripts/gpu_pack.sh [BUILD_DIR] [BUNDLE_DIR]   (defaults build and .gpu)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
bundle=${2:-.gpu}
shared=$root/../shared
cd "$root"
for f in "$build/viewer/strata" "$build/tests/strata_gl_tests"; do
    [[ -x $f ]] || { echo "gpu_pack.sh: no $f (build first: bash scripts/build.sh $build)" >&2; exit 1; }
done
[[ -e $shared/tools/gpu-bundle/make-bundle.py ]] || { echo "gpu_pack.sh: no $shared/tools/gpu-bundle/make-bundle.py" >&2; exit 1; }
rm -rf "$bundle"
python3 "$shared/tools/gpu-bundle/make-bundle.py" "$bundle" shaders "$build/viewer/strata" "$build/tests/strata_gl_tests"
gcc -O2 "$shared/tools/peers/oitprobe.c" -o "$bundle/oitprobe" -lEGL -lGL -lm
if [[ -d $shared/scenes-data ]]; then cp -r "$shared/scenes-data" "$bundle/scenes-data"; fi
# Keep it out of git: it travels as an ignored folder the device tool carries.
mkdir -p .git/info
grep -qx "/$bundle/" .git/info/exclude 2>/dev/null || echo "/$bundle/" >>.git/info/exclude
echo "gpu_pack.sh: $(du -sh "$bundle" | cut -f1) in $bundle"
