#!/usr/bin/env bash
# Smoke test of `strata view` under Xvfb with Mesa's software rasteriser: five frames with the
# panel, then a screenshot of the whole window. Fails when the window cannot open, the PNG is
# missing, small or of the wrong size, the scene rendered flat (black), or the panel drew nothing.
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
