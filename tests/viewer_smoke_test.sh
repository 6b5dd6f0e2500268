#!/usr/bin/env bash
# Smoke test of `strata view` under Xvfb with Mesa's software rasteriser: five frames with the
# panel, then a screenshot of the whole window. Fails when the window cannot open, the PNG is
# missing, small or of the wrong size, the scene rendered flat (black), or the panel drew nothing.
# Then the heatmap, error and split views and the fragment inspector, each checked on the figures
# the viewer prints on its last frame.
set -euo pipefail
strata=${1:?usage: viewer_smoke_test.sh PATH/TO/strata}
command -v xvfb-run >/dev/null || { echo "viewer_smoke: xvfb-run not installed (scripts/install-deps.sh)"; exit 1; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
shot=$tmp/shot.png
cd "$tmp"   # nothing the viewer might write lands in the source tree

out=$(LIBGL_ALWAYS_SOFTWARE=1 timeout 300 xvfb-run -a -s "-screen 0 1024x768x24" \
      "$strata" view builtin:default --exit-after-frames 5 --screenshot "$shot" --size 800x600 2>&1) || {
    echo "$out"; echo "viewer_smoke: strata view failed"; exit 1; }
echo "$out"

fail() { echo "viewer_smoke: $*"; exit 1; }
[[ -f $shot ]] || fail "no screenshot written"
bytes=$(stat -c %s "$shot")
(( bytes > 10240 )) || fail "screenshot is only $bytes bytes"
# PNG IHDR: width and height as big-endian 32-bit integers at bytes 16..23.
read -r w h < <(od -An -tu1 -j16 -N8 "$shot" |
    awk '{ print $1*16777216 + $2*65536 + $3*256 + $4, $5*16777216 + $6*65536 + $7*256 + $8 }')
[[ "$w x $h" == "800 x 600" ]] || fail "screenshot is ${w}x${h}, expected 800x600"

line=$(grep '^screenshot: ' <<<"$out" | tail -n 1) || fail "no 'screenshot:' line in the output"
field() { sed -n "s/.* $1=\([0-9][0-9]*\).*/\1/p" <<<"$line"; }
size=$(awk '{ print $3 }' <<<"$line")
distinct=$(field distinct_colors)
scene=$(field scene_colors)
panel=$(field panel_pixels)
[[ $size == 800x600 ]] || fail "viewer reports a ${size} window"
(( distinct > 50 )) || fail "only $distinct distinct colours in the window"
# The scene alone (read before the panel is drawn): a black or flat frame has a handful.
(( scene > 50 )) || fail "only $scene distinct colours in the scene (black or flat render?)"
(( panel > 10000 )) || fail "the panel changed only $panel pixels"
echo "viewer_smoke: ok (${w}x${h}, $bytes bytes, $distinct colours, scene $scene, panel $panel px)"

# The coplanarity heatmap view: the same window showing the detector's colours. builtin:default
# has coincident surfaces (C_p > 0), so the scene holds grey and at least red; being Fig. 13's
# flat palette it holds at most its nine colours, which no shaded image would.
heat=$tmp/heat.png
out=$(LIBGL_ALWAYS_SOFTWARE=1 timeout 300 xvfb-run -a -s "-screen 0 1024x768x24" \
      "$strata" view builtin:default --view heatmap --exit-after-frames 5 --screenshot "$heat" --size 800x600 2>&1) || {
    echo "$out"; echo "viewer_smoke: strata view --view heatmap failed"; exit 1; }
[[ -f $heat ]] || fail "no heatmap screenshot written"
line=$(grep '^screenshot: ' <<<"$out" | tail -n 1) || fail "no 'screenshot:' line in the heatmap run"
scene=$(field scene_colors)
panel=$(field panel_pixels)
(( scene >= 2 && scene <= 9 )) || fail "heatmap view shows $scene distinct colours, expected 2 to 9 (Fig. 13's palette)"
(( panel > 10000 )) || fail "the panel changed only $panel pixels in the heatmap view"
echo "viewer_smoke: heatmap ok (scene $scene colours, panel $panel px)"

# The error view: blend-unsorted against abuffer on the same frame. builtin:default has
# transparent objects that overlap out of submission order, so the error is well above round-off.
view() {  # view ARGS...: five frames at 800x600 with a screenshot; prints the output
    LIBGL_ALWAYS_SOFTWARE=1 timeout 300 xvfb-run -a -s "-screen 0 1024x768x24" \
        "$strata" view builtin:default --exit-after-frames 5 --screenshot "$tmp/view.png" --size 800x600 "$@" 2>&1
}
num() { sed -n "s/.*[ |]$1=\([-+0-9.e]*\).*/\1/p" <<<"$2" | head -n 1; }
out=$(view --view error --mode blend-unsorted) || { echo "$out"; fail "strata view --view error failed"; }
line=$(grep '^error: ' <<<"$out") || fail "no 'error:' line in the error view's output"
echo "$line"
error_rmse=$(num rmse "$line")
awk -v r="$error_rmse" -v p="$(num psnr "$line")" -v m="$(num max "$line")" \
    'BEGIN { exit !(r > 1e-3 && r < 0.5 && p > 6 && p < 60 && m > 0.01 && m <= 1) }' ||
    fail "error view figures out of range: $line"
line=$(grep '^screenshot: ' <<<"$out" | tail -n 1)
scene=$(field scene_colors)
(( scene > 9 )) || fail "the error view shows only $scene colours"

# The same technique against the reference is exactly 0 (two renders of abuffer, one frame).
out=$(view --view error --mode abuffer) || { echo "$out"; fail "strata view --view error --mode abuffer failed"; }
line=$(grep '^error: ' <<<"$out") || fail "no 'error:' line for abuffer"
[[ $(num rmse "$line") == 0.000000e+00 && $(num max "$line") == 0.000000e+00 && $(num psnr "$line") == 100.0000 ]] ||
    fail "abuffer against itself is not exactly 0: $line"
echo "viewer_smoke: error view ok (blend-unsorted rmse $error_rmse; abuffer exactly 0)"

# Split A | B: abuffer left, blend-unsorted right, divider at 0.25 of 800 pixels. Each half's
# error is over the whole frame, so B's equals the error view's above (same frame, same camera).
out=$(view --view split --mode abuffer --split-with blend-unsorted --split-at 0.25) ||
    { echo "$out"; fail "strata view --view split failed"; }
line=$(grep '^split: ' <<<"$out") || fail "no 'split:' line in the split view's output"
echo "$line"
[[ $(num divider "$line") == 200 ]] || fail "divider at $(num divider "$line"), expected 200"
a=${line%%|*}
b=${line#*|}
[[ $a == *" A=abuffer "* && $b == *" B=blend-unsorted "* ]] || fail "split halves misnamed: $line"
[[ $(num rmse "$a") == 0.000000e+00 ]] || fail "split: A (abuffer) error is not 0: $line"
[[ $(num rmse "$b") == "$error_rmse" ]] || fail "split: B's rmse $(num rmse "$b") differs from the error view's $error_rmse"
awk -v t="$(num gpu_ms "$a")" -v u="$(num gpu_ms "$b")" 'BEGIN { exit !(t > 0 && u > 0) }' || fail "split: no GPU time: $line"
echo "viewer_smoke: split view ok"

# The fragment inspector at a pixel of the globe (wireframe and surface, and its back face):
# abuffer keeps all, a k-buffer of capacity 1 exactly the nearest.
inspect() {
    out=$(view --inspect 430,410 "$@") || { echo "$out"; fail "strata view --inspect $* failed"; }
    grep -E '^(inspect|fragment): ' <<<"$out"
}
out=$(inspect --mode abuffer)
echo "$out"
n=$(num fragments "$(grep '^inspect: ' <<<"$out")")
(( n >= 2 )) || fail "inspect: $n fragments at 430,410, expected the globe's (at least 2)"
(( $(grep -c '^fragment: .*kept=yes$' <<<"$out") == n )) || fail "inspect: abuffer did not keep all $n"
grep -q "verdict=\"all $n kept\"" <<<"$out" || fail "inspect: abuffer's verdict is not 'all $n kept'"
# Each fragment's alpha is its factor times the texel's; the globe has no texture: texel 1.
awk '/^fragment: / { for (i = 1; i <= NF; ++i) { split($i, kv, "="); v[kv[1]] = kv[2] }
                     d = v["alpha"] - v["alpha_factor"] * v["texel_alpha"]; if (d < -1e-3 || d > 1e-3 || v["texel_alpha"] != "1.0000") bad = 1 }
     END { exit bad }' <<<"$out" || fail "inspect: alpha is not factor x texel alpha (texel 1 on the untextured globe)"
out=$(inspect --mode kbuffer --set kbuffer.capacity=1)
echo "$out"
grep -q "verdict=\"the nearest 1 of $n kept\"" <<<"$out" || fail "inspect: kbuffer capacity=1 is not 'the nearest 1 of $n'"
grep -q '^fragment: 0 .*kept=yes$' <<<"$out" || fail "inspect: kbuffer capacity=1 did not keep the nearest"
(( $(grep -c '^fragment: .*kept=no$' <<<"$out") == n - 1 )) || fail "inspect: kbuffer capacity=1 kept more than one"
echo "viewer_smoke: inspector ok ($n fragments)"

# Zoom rendering: at zoom 3 the error view measures what the zoom loses against the reference at
# zoom 1 (abuffer against abuffer: only the zoom differs); under a frame budget the predictive
# policy calibrates first and then picks a zoom within --zoom-max and a LOD bound.
out=$(view --zoom 3 --view error --mode abuffer) || { echo "$out"; fail "strata view --zoom 3 failed"; }
grep -q '^zoom: 3 (fixed)' <<<"$out" || fail "no 'zoom: 3 (fixed)' line: $out"
line=$(grep '^error: ' <<<"$out") || fail "no 'error:' line at zoom 3"
awk -v r="$(num rmse "$line")" 'BEGIN { exit !(r > 1e-3 && r < 0.2) }' || fail "zoom 3 error out of range: $line"
out=$(view --frame-budget-ms 50 --zoom-controller predictive --zoom-max 4) ||
    { echo "$out"; fail "strata view --frame-budget-ms failed"; }
grep -q '^zoom calibrated: ' <<<"$out" || fail "the predictive controller did not calibrate: $out"
line=$(grep '^zoom: ' <<<"$out") || fail "no 'zoom:' line under a budget"
echo "$line"
# By default the budget steers the zoom and auto LOD's error bound (among 4, 8, 16 and 32 px).
[[ $line =~ ^zoom:\ [1-4]\ \(predictive,\ levers\ zoom,lod\),\ frame\ [0-9.]+\ ms\ GPU,\ predicted\ [0-9.]+\ ms,\ lod\ bound\ (4|8|16|32)\.00\ px,\ loss\ [0-9.]+\ px$ ]] ||
    fail "unexpected zoom line under a budget: $line"
echo "viewer_smoke: zoom ok"

# Ctrl-C in the terminal closes the window as its close button would: status 130 and one line.
# (Python sends the signal: a shell's background job starts with SIGINT ignored.)
out=$(LIBGL_ALWAYS_SOFTWARE=1 timeout 300 xvfb-run -a -s "-screen 0 1024x768x24" python3 -c '
import signal, subprocess, sys, time
p = subprocess.Popen([sys.argv[1], "view", "builtin:layers:4", "--size", "320x200", "--lod", "geometry"],
                     stderr=subprocess.PIPE, text=True)
time.sleep(5)
p.send_signal(signal.SIGINT)
err = p.communicate(timeout=120)[1].strip().splitlines()
print(p.returncode, err[-1] if err else "")
' "$strata" 2>&1) || fail "the interrupt check did not run: $out"
[[ $(tail -n 1 <<<"$out") == "130 strata: interrupted by SIGINT" ]] || fail "strata view after SIGINT: $out"
echo "viewer_smoke: SIGINT closes the window (status 130)"
