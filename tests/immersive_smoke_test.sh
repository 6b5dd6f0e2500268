#!/usr/bin/env bash
# Smoke test of `strata view --immersive` under Xvfb with Mesa's software rasteriser: a mono run
# and a side-by-side stereo run of five frames driven by the synthetic head trace, each saving a
# window screenshot; then the bad-input paths (no --trace, a malformed trace: file and line).
# Fails when a run fails, the PNG is missing or of the wrong size, the scene rendered flat,
# the panel drew nothing, or no frame was scored against the truth.
set -euo pipefail
strata=${1:?usage: immersive_smoke_test.sh PATH/TO/strata}
source_dir=$(cd "$(dirname "$0")/.." && pwd)
trace=$source_dir/scenes/traces/head-synthetic-measured.path
command -v xvfb-run >/dev/null || { echo "immersive_smoke: xvfb-run not installed (scripts/install-deps.sh)"; exit 1; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"   # nothing the viewer might write lands in the source tree
fail() { echo "immersive_smoke: $*"; exit 1; }

# The runs play the trace against the wall clock, so under load a fast head turn can leave
# the view on a bare wall by the screenshot. A gentle trace (yaw +-3 deg, pitch +-1.5 deg, 4 s at
# 120 Hz, truth = measured) keeps the scene in view however slow the frames are.
awk 'BEGIN { for (i = 0; i <= 480; ++i) { t = i / 120; y = 0.0523599 * sin(t * 1.5); p = 0.0261799 * sin(t * 2.1);
       sy = sin(y / 2); cy = cos(y / 2); sp = sin(p / 2); cp = cos(p / 2);
       printf "%.6f 0 0 0 %.9f %.9f %.9f %.9f\n", t, cy * sp, cp * sy, -sy * sp, cy * cp } }' >"$tmp/gentle-measured.path"
cp "$tmp/gentle-measured.path" "$tmp/gentle-truth.path"
trace=$tmp/gentle-measured.path

run_case() {  # name, extra arguments...
    local name=$1; shift
    local shot=$tmp/$name.png out
    out=$(LIBGL_ALWAYS_SOFTWARE=1 timeout 300 xvfb-run -a -s "-screen 0 1024x768x24" \
          "$strata" view builtin:default --immersive --trace "$trace" --exit-after-frames 5 \
          --screenshot "$shot" --size 800x600 "$@" 2>&1) || { echo "$out"; fail "$name: strata view failed"; }
    echo "$out"
    [[ -f $shot ]] || fail "$name: no screenshot written"
    read -r w h < <(od -An -tu1 -j16 -N8 "$shot" |
        awk '{ print $1*16777216 + $2*65536 + $3*256 + $4, $5*16777216 + $6*65536 + $7*256 + $8 }')
    [[ "$w x $h" == "800 x 600" ]] || fail "$name: screenshot is ${w}x${h}, expected 800x600"
    local line scene panel scored
    line=$(grep '^screenshot: ' <<<"$out" | tail -n 1) || fail "$name: no 'screenshot:' line"
    scene=$(sed -n 's/.* scene_colors=\([0-9]*\).*/\1/p' <<<"$line")
    panel=$(sed -n 's/.* panel_pixels=\([0-9]*\).*/\1/p' <<<"$line")
    (( scene > 50 )) || fail "$name: only $scene distinct colours in the scene (black or flat render?)"
    (( panel > 10000 )) || fail "$name: the panel changed only $panel pixels"
    grep -q 'truth gentle-truth.path' <<<"$out" || fail "$name: the truth trace beside the measured one was not used"
    scored=$(sed -n 's/^immersive: .*, \([0-9]*\) frames scored, mean error \([0-9.]*\) deg.*/\1/p' <<<"$out")
    (( ${scored:-0} >= 1 )) || fail "$name: no frame was scored"
    if [[ $name == zoomed ]]; then grep -q '^zoom: 2 (fixed)' <<<"$out" || fail "$name: no 'zoom: 2 (fixed)' line"; fi
    grep -q '^lod ' <<<"$out" || fail "$name: no 'lod' line (the immersive window has level of detail)"
    if [[ $name == budget ]]; then
        # The LOD lever alone: the zoom stays 1 and the bound is one of the ladder's.
        grep -Eq '^zoom: 1 \(reactive, levers lod\), frame [0-9.]+ ms GPU(, predicted [0-9.]+ ms)?, lod bound (4|8|16|32)\.00 px' <<<"$out" ||
            fail "$name: no 'zoom: 1 (reactive, levers lod) ... lod bound' line"
    fi
    if [[ $name == impostors ]]; then
        local impostors
        impostors=$(sed -n 's/^lod impostors: \([0-9]*\) of .*/\1/p' <<<"$out")
        (( ${impostors:-0} > 0 )) || fail "$name: no object drawn as an impostor"
    fi
    echo "immersive_smoke: $name ok (scene $scene colours, panel $panel px, $scored frames scored)"
}

run_case mono
run_case stereo --stereo --ipd 64 --predictor cv --deflect shift --extra-latency 20
# Zoom 2 folded into the homography deflection: the same checks, and the zoom reported.
run_case zoomed --zoom 2
# Level of detail as in the walkthrough window: forced impostors bake (within the frame budget)
# and draw in both eyes.
run_case impostors --lod impostors --stereo
# The frame budget steers the LOD error bound in this window too.
run_case budget --frame-budget-ms 5 --budget-levers lod

# Bad input fails before a window opens, with a message.
if out=$("$strata" view builtin:default --immersive 2>&1); then fail "--immersive without --trace succeeded"; fi
grep -q -- '--trace' <<<"$out" || fail "no mention of --trace in: $out"
printf '0 0 0 0 0 0 0 1\n0.1 0 0 0 0 0 0\n' > bad.path
if out=$("$strata" view builtin:default --immersive --trace bad.path 2>&1); then fail "a malformed trace was accepted"; fi
grep -q 'bad.path:2' <<<"$out" || fail "the malformed trace error does not name file:line: $out"
if out=$("$strata" view builtin:default --immersive --trace "$trace" --predictor nope 2>&1); then
    fail "an unknown predictor was accepted"; fi
grep -q 'kalman' <<<"$out" || fail "the unknown predictor error does not list the known ones: $out"
echo "immersive_smoke: ok"
