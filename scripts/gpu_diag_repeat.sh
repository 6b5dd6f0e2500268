#!/usr/bin/env bash
# The repeated-render diagnostic (tests/diagnostic_gl_test.cpp) on a lent GPU: once alone, then
# four copies side by side (the losses were more frequent under load), then four copies with a
# glFinish after every object's draw (STRATA_DEBUG_FINISH_DRAWS=1). Logs and the images of the
# renders that differed go to OUT (default gpu-diag-repeat).
# usage: scripts/gpu_diag_repeat.sh [--bundle DIR] [OUT]
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bundle=$root/.gpu
out=gpu-diag-repeat
[[ ${1-} == --bundle ]] && { bundle=$2; shift 2; }
[[ $# -gt 0 ]] && out=$1
bundle=$(realpath "$bundle")
rm -rf "$out" && mkdir -p "$out" && out=$(realpath "$out")
export LD_LIBRARY_PATH=$bundle/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH} STRATA_SHADER_DIR=$bundle/shaders
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless} STRATA_SOURCE_DIR=$root
for v in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json /usr/share/glvnd/egl_vendor.d/10_nvidia.json; do
    [[ -z ${__EGL_VENDOR_LIBRARY_FILENAMES-} && -e $v ]] && export __EGL_VENDOR_LIBRARY_FILENAMES=$v
done
run() {  # name [VAR=value ...]
    local name=$1
    shift
    env "$@" XDG_CACHE_HOME=/tmp/xdg-$name STRATA_TEST_DUMP=$out/images-$name \
        timeout --kill-after=10 100 "$bundle/strata_gl_tests" --no-skip -tc='diagnostic*' >"$out/$name.txt" 2>&1
}
run alone
for i in 1 2 3 4; do run "load$i" & done
wait
for i in 1 2 3 4; do run "finish$i" STRATA_DEBUG_FINISH_DRAWS=1 & done
wait
for f in "$out"/*.txt; do
    echo "== $(basename "$f" .txt): $(grep -c '^diagnostic .*differs in [1-9]\|opaque colour in [1-9]\|opaque depth in [1-9]' "$f") variants with a differing render"
    grep '^diagnostic ' "$f" | grep -v 'differs in 0, opaque colour in 0, opaque depth in 0$' | cut -c1-400
    grep -E '^\[doctest\] test cases' "$f"
done
