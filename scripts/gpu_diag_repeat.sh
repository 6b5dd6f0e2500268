#!/usr/bin/env bash
# The repeated-render diagnostic (tests/diagnostic_gl_test.cpp) on a lent GPU: once alone, then
# four copies side by side (the losses were more frequent under load), then four copies with a
# glFinish after every object's draw (STRATA_DEBUG_FINISH_DRAWS=1). Logs and the images of the
# renders that differed go to OUT (default gpu-diag-repeat).
# usage: scripts/gpu_diag_repeat.sh [--bundle DIR] [OUT]
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
source "$root/scripts/gpu_common.sh"
bundle=$root/.gpu
out=gpu-diag-repeat
[[ ${1-} == --bundle ]] && { bundle=$2; shift 2; }
[[ $# -gt 0 ]] && out=$1
[[ -x $bundle/strata_gl_tests ]] ||
    { echo "gpu_diag_repeat.sh: $bundle holds no strata_gl_tests (make it with scripts/gpu_pack.sh)" >&2; exit 1; }
bundle=$(realpath "$bundle")
out=$(fresh_report_folder gpu_diag_repeat.sh "$out" .strata-gpu-diag-repeat) || exit 1
use_gpu_bundle "$bundle"
export STRATA_SOURCE_DIR=$root
run() {  # name [VAR=value ...]
    local name=$1
    shift
    env "$@" XDG_CACHE_HOME=/tmp/xdg-$name STRATA_TEST_DUMP=$out/images-$name \
        timeout --kill-after=10 "${LIMIT:-100}" "$bundle/strata_gl_tests" --no-skip -tc='diagnostic*' >"$out/$name.txt" 2>&1
}
if [[ ${KNOBS-} == 1 ]]; then
    # KNOBS=1: the quick diagnostic (abuffer, fresh renderers) once per driver or debug setting.
    export STRATA_DIAG_QUICK=1
    run base
    run check-uniforms STRATA_DEBUG_CHECK_UNIFORMS=1
    run frame-uniforms-per-draw STRATA_DEBUG_FRAME_UNIFORMS_PER_DRAW=1
    run no-debug-context STRATA_DEBUG_NO_DEBUG_CONTEXT=1
    run finish-builds-and-draws STRATA_DEBUG_FINISH_BUILDS=1 STRATA_DEBUG_FINISH_DRAWS=1
    run no-program-cache STRATA_PROGRAM_CACHE=0
    run no-threads-no-debug __GL_THREADED_OPTIMIZATIONS=0 STRATA_DEBUG_NO_DEBUG_CONTEXT=1
    run base-again
else
run alone
for i in 1 2 3 4; do run "load$i" & done
wait
for i in 1 2 3 4; do run "finish$i" STRATA_DEBUG_FINISH_DRAWS=1 & done
wait
fi
for f in "$out"/*.txt; do
    echo "== $(basename "$f" .txt): $(grep -c '^diagnostic .*differs in [1-9]\|opaque colour in [1-9]\|opaque depth in [1-9]' "$f") variants with a differing render"
    grep '^diagnostic ' "$f" | grep -v 'differs in 0, opaque colour in 0, opaque depth in 0$' | cut -c1-400
    grep -E '^\[doctest\] test cases' "$f"
    grep -c '^\[strata debug\]' "$f" | sed 's/^/  debug lines: /'
    grep -m5 '^\[strata debug\]' "$f"
done
