#!/usr/bin/env bash
# The command line's contract: bad input, of any kind (a bad file, a rejected option value, a
# missing or unknown option, an output that cannot be written), gives exactly one line on stderr
# naming the input, exit status 1, and leaves the output folder as it was: no output file and no
# temporary of any kind. Good input writes what it says; a glTF file drawn with something ignored
# says so on stderr. Usage: cli_test.sh STRATA_BINARY
set -uo pipefail
strata=$1
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless}
tmp=$(mktemp -d)
trap 'chmod -R u+w "$tmp" 2>/dev/null; rm -rf "$tmp"' EXIT
work=$tmp/work      # every output of every command goes here
# Impostors baked by one case are not loaded by another: the cache lives and dies with this run.
export XDG_CACHE_HOME=$tmp/cache
mkdir -p "$work/a-folder"
passed=0
failed=0
models=/usr/share/assimp/models/glTF2
root=$(cd "$(dirname "$0")/.." && pwd)
shared=$(cd "$(dirname "$0")/../.." && pwd)/shared/scenes-data

ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL: $*"; }

snapshot() { (cd "$work" && find . | sort); }

# expect_error "what stderr must contain" ARGS...
expect_error() {
  local want=$1; shift
  local before
  before=$(snapshot)
  "$strata" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local rc=$?
  local lines
  lines=$(wc -l <"$tmp/stderr")
  if [ $rc -ge 128 ]; then bad "crashed (status $rc) for: $*"; return; fi
  if [ $rc -ne 1 ]; then bad "status $rc, not 1, for: $* -> $(cat "$tmp/stderr")"; return; fi
  if [ "$lines" -ne 1 ]; then bad "$lines lines on stderr for: $* -> $(cat "$tmp/stderr")"; return; fi
  if ! grep -qF -- "$want" "$tmp/stderr"; then bad "stderr lacks '$want' for: $* -> $(cat "$tmp/stderr")"; return; fi
  if [ "$(snapshot)" != "$before" ]; then
    bad "files left behind for: $* -> $(diff <(echo "$before") <(snapshot) | grep '^>' | tr '\n' ' ')"; return
  fi
  ok
}

# Bad input files and values.
expect_error "no such file" render "$tmp/missing.glb" --out "$work/out.png"
expect_error "unknown builtin scene" render builtin:nothing --out "$work/out.png"
expect_error "must be an integer" render builtin:layers:x --out "$work/out.png"
expect_error "unknown technique 'nope'" render builtin:layers:2 --mode nope --out "$work/out.png"
# Settings: every rejection is one line before any frame (bench prints a progress line per mode,
expect_error "technique abuffer has no setting 'foo' (has: " render builtin:layers:2 --set foo=1 --out "$work/out.png"
expect_error "capacity = 'abc': expected integer in [1, 1024]" bench builtin:layers:2 --modes abuffer,ll --set ll.capacity=abc --json "$work/out.png"
expect_error "capacity = '2.5': expected integer" render builtin:layers:2 --mode ll --set capacity=2.5 --out "$work/out.png"
expect_error "capacity = '0': expected integer in [1, 64]" render builtin:layers:2 --mode kbuffer --set capacity=0 --out "$work/out.png"
expect_error "precision = '24': expected 16 or 32" render builtin:layers:2 --mode wboit --set precision=24 --out "$work/out.png"
expect_error "tail = 'yes': expected flag (true or false" render builtin:layers:2 --mode fab --set tail=yes --out "$work/out.png"
expect_error "no technique run has a setting 'capacty'" bench builtin:layers:2 --modes abuffer,ll --set capacty=16 --json "$work/out.png"
expect_error "unknown technique 'llx'" bench builtin:layers:2 --modes ll --set llx.capacity=4 --json "$work/out.png"
expect_error "technique kbuffer is not among those run (abuffer, ll)" bench builtin:layers:2 --modes ll --set kbuffer.capacity=4 --json "$work/out.png"
expect_error "not of the form [technique.]name=value" render builtin:layers:2 --set capacity --out "$work/out.png"
expect_error "missing.json: no such file" render builtin:layers:2 --settings "$tmp/missing.json" --out "$work/out.png"
# Zoom rendering's options.
expect_error "zoom '0' is not an integer in 1..16" render builtin:layers:2 --zoom 0 --out "$work/out.png"
expect_error "zoom '2.5' is not an integer in 1..16" bench builtin:layers:2 --zoom 2.5 --json "$work/out.json"
expect_error "--zoom-controller requires --frame-budget-ms" bench builtin:layers:2 --zoom-controller predictive
expect_error "--zoom excludes --frame-budget-ms" bench builtin:layers:2 --zoom 2 --frame-budget-ms 10
expect_error "--zoom excludes --frame-budget-ms" view --zoom 3 --frame-budget-ms 5
expect_error "--frame-budget-ms: Value -1 not in range" bench builtin:layers:2 --frame-budget-ms -1
expect_error "--zoom-controller: pid not in {reactive,predictive}" bench builtin:layers:2 --frame-budget-ms 10 --zoom-controller pid
expect_error "--budget-levers requires --frame-budget-ms" bench builtin:layers:2 --budget-levers lod
expect_error "budget levers 'fps' are not one of zoom|lod|zoom,lod" bench builtin:layers:2 --frame-budget-ms 10 --budget-levers fps
expect_error "--budget-levers lod needs --lod auto (the bound steers auto's choice; --lod is geometry)" bench builtin:layers:2 --frame-budget-ms 10 --budget-levers lod --lod geometry
expect_error "--budget-pin requires --frame-budget-ms" bench builtin:layers:2 --budget-pin 2,0
expect_error "budget pin '2,4': expected ZOOM,LEVEL with a zoom of 1..16 and a LOD ladder level of 0..3" bench builtin:layers:2 --frame-budget-ms 10 --budget-pin 2,4
expect_error "a pinned LOD level above 0 needs the LOD lever" bench builtin:layers:2 --frame-budget-ms 10 --budget-pin 2,1 --lod geometry
expect_error "a pinned zoom above 1 needs the zoom lever" bench builtin:layers:2 --frame-budget-ms 10 --budget-pin 2,0 --budget-levers lod
expect_error "the pinned zoom 9 is above --zoom-max 8" bench builtin:layers:2 --frame-budget-ms 10 --budget-pin 9,0
expect_error "--budget-levers lod needs --lod auto" view --frame-budget-ms 10 --budget-levers lod --lod impostors
expect_error "--depth-tie-ulps: Value -1 not in range" render builtin:layers:2 --depth-tie-ulps -1 --out "$work/out.png"
expect_error "--lod: fast not in {geometry,impostors,auto}" render builtin:layers:2 --lod fast --out "$work/out.png"
expect_error "--impostor-views: 7 not in {12,20,32}" bench builtin:layers:2 --impostor-views 7
expect_error "--impostor-slices: Value 0 not in range 1 to 256" view --impostor-slices 0
expect_error "builtin:field:0: argument '0' must be an integer in [1, 1000]" render builtin:field:0 --out "$work/out.png"
expect_error "--highlight-coplanar needs the frame at its size" render builtin:layers:2 --zoom 2 --highlight-coplanar "$work/h.png" --out "$work/out.png"
printf '{"capacity": 4,' >"$tmp/broken.json"
expect_error "broken.json: " render builtin:layers:2 --mode ll --settings "$tmp/broken.json" --out "$work/out.png"
printf '{"capacity": "four"}' >"$tmp/string.json"
expect_error "string.json: \"capacity\" is not a number or a boolean" render builtin:layers:2 --mode ll --settings "$tmp/string.json" --out "$work/out.png"
printf '{"ll.capacity": 4, "ll.capacty": 4}' >"$tmp/typo.json"
expect_error "typo.json ll.capacty=4: technique ll has no setting 'capacty'" render builtin:layers:2 --mode ll --settings "$tmp/typo.json" --out "$work/out.png"
printf '{"capacity": 2000}' >"$tmp/range.json"
expect_error "range.json capacity=2000: setting capacity = '2000': expected integer in [1, 1024]" render builtin:layers:2 --mode ll --settings "$tmp/range.json" --out "$work/out.png"
expect_error "is not WxH" render builtin:layers:2 --size 12 --out "$work/out.png"
expect_error "unsupported image type" render builtin:layers:2 --out "$work/out.jpg"
printf '0 0 0 0 0 0 0 1\n1 0 0\n' >"$tmp/path.txt"
expect_error "path.txt:2: expected 8 numbers" render builtin:layers:2 --camera-path "$tmp/path.txt" --out "$work/out.png"
expect_error "unknown technique" bench builtin:layers:2 --modes abuffer,nope --json "$work/out.json"

# Rejected by the argument parser: the same one line and status 1 as any other bad input (CLI11
# on its own prints two lines and exits 105, 106, 109...), named by the command.
expect_error "strata bench: --frames: Value 0 not in range" bench builtin:layers:4 --frames 0
# The advisor and `bench --modes auto` (bench/advisor.hpp).
expect_error "unknown technique 'nope'" advise builtin:layers:2 --modes ll,nope --json "$work/advise.json"
expect_error "no such file" advise "$tmp/missing.glb"
expect_error "strata advise: --max-error: Value 2 not in range" advise builtin:layers:2 --max-error 2
expect_error "--modes auto chooses the settings itself" bench builtin:layers:2 --modes auto --set precision=16
expect_error "strata bench: --warmup: Value -1 not in range" bench builtin:layers:4 --warmup -1
expect_error "strata render: --out is required" render builtin:layers:2
expect_error "strata render: scene is required" render --out "$work/out.png"
expect_error "--bogus" render builtin:layers:2 --out "$work/out.png" --bogus
expect_error "strata render: Could not convert: --time = abc" render builtin:layers:2 --out "$work/out.png" --time abc
expect_error "strata: A subcommand is required" 
expect_error "strata: unknown command 'nosuch'" nosuch
if "$strata" track --help >/dev/null 2>&1; then
  expect_error "strata track: --trace excludes --synthetic" track --trace "$tmp/path.txt" --synthetic 1
  expect_error "strata track: --display-hz" track --synthetic 1 --display-hz -5
  expect_error "--motion \`run\`: expected seated, walk or scan" track --synthetic 1 --motion run
  # Numbers that would ask for unbounded work or memory, or that are not numbers: refused while
  # parsing, naming the option, before anything is generated.
  expect_error "strata track: --synthetic: must be a number in (0, 600] s, got inf" track --synthetic inf
  expect_error "strata track: --synthetic: must be a number in (0, 600] s, got 1e7" track --synthetic 1e7
  expect_error "strata track: --synthetic: must be a number in (0, 600] s, got nan" track --synthetic nan
  expect_error "strata track: --display-hz: must be a number in (0, 1000] Hz, got 1e300" track --synthetic 1 --display-hz 1e300
  expect_error "strata track: --display-hz: must be a number in (0, 1000] Hz, got nan" track --synthetic 1 --display-hz nan
  expect_error "strata track: --latency-ms: must be a number in [0, 1000] ms, got nan" track --synthetic 1 --latency-ms nan
  expect_error "strata track: --reread-ms: must be a number in [0, 1000] ms, got nan" track --synthetic 1 --reread-ms nan
  expect_error "strata track: --seed: must be a non-negative integer, got -1" track --synthetic 1 --seed -1
  # Options that do nothing without another are refused, not ignored.
  expect_error "strata track: --seed requires --synthetic" track --trace "$tmp/path.txt" --seed 3
  expect_error "strata track: --write-traces requires --synthetic" track --trace "$tmp/path.txt" --write-traces "$work/t"
  # A trace whose samples lie far apart would be scored frame by frame: bounded before scoring.
  printf '0 0 0 0 0 0 0 1\n1000000 0 0 0 0 0 0 1\n' >"$tmp/far.path"
  expect_error "far.path: spans 1e+06 s, 9e+07 frames at 90 Hz; at most 1e+06 frames are scored" track --trace "$tmp/far.path"
  # The truth trace is named when it is the one without motion to score.
  printf '0 0 0 0 0 0 0 1\n' >"$tmp/one.path"
  printf '1 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n' >"$tmp/still.path"
  printf '0 0 0 0 0 0 0 1\n2 0 0 0 0 0 0 1\n' >"$tmp/two.path"
  expect_error "one.path: needs at least 2 samples, has 1" track --trace "$tmp/two.path" --truth "$tmp/one.path"
  expect_error "still.path: all 2 samples are at time 1; a trace must span some time" track --trace "$tmp/two.path" --truth "$tmp/still.path"
  expect_error "one.path: needs at least 2 samples, has 1" track --trace "$tmp/one.path"
  expect_error "/dev/zero: is a character device, not a regular file" track --trace /dev/zero
fi
# Help is not a rejection: it prints and exits 0.
if "$strata" bench --help >"$tmp/stdout" 2>"$tmp/stderr" && grep -q -- "--frames" "$tmp/stdout" && [ ! -s "$tmp/stderr" ]
then ok; else bad "strata bench --help: status or output"; fi
if "$strata" --help >"$tmp/stdout" 2>&1 && grep -q "render" "$tmp/stdout"; then ok; else bad "strata --help"; fi

# Outputs that cannot be written: refused before the work, nothing left behind.
expect_error "a-folder: is a folder" render builtin:layers:2 --size 8x8 --out "$work/a-folder"
expect_error "a-folder: is a folder" render builtin:layers:2 --size 8x8 --out "$work/ok.png" --heatmap "$work/a-folder"
expect_error "does not exist" render builtin:layers:2 --out "$work/no/such/folder/out.png"
expect_error "a-folder: is a folder" bench builtin:layers:2 --size 8x8 --frames 1 --json "$work/a-folder"
expect_error "does not exist" bench builtin:layers:2 --size 8x8 --frames 1 --csv "$work/missing/b.csv"
expect_error "h.jpg: unsupported image type" render builtin:layers:2 --size 8x8 --out "$work/ok.png" --heatmap "$work/h.jpg"
# Folders are made after every input was checked, and removed again when the command fails.
expect_error "argument '0' must be an integer" bench builtin:layers:0 --images "$work/imgs"
expect_error "size '0x0' is not WxH" demo --headless --size 0x0 --out "$work/rep"
expect_error "unknown technique" bench builtin:layers:2 --modes nope --images "$work/imgs"
printf 'x' >"$work/plain-file"
expect_error "plain-file: is not a folder" demo --headless --out "$work/plain-file"
expect_error "plain-file: is not a folder" bench builtin:layers:2 --size 8x8 --frames 1 --report "$work/plain-file"
rm -f "$work/plain-file"
expect_error "camera.path: no such file" bench builtin:layers:2 --size 8x8 --frames 1 --images "$work/imgs" --camera-path "$tmp/camera.path"
# Options that would be ignored are refused.
expect_error "strata render: --time requires --camera-path" render builtin:layers:2 --time 3 --out "$work/out.png"
expect_error "strata view: --stereo requires --immersive" view --stereo
expect_error "strata view: --predictor requires --immersive" view --predictor cv
expect_error "strata view: --screenshot requires --exit-after-frames" view --screenshot "$work/shot.png"
if [ "$(id -u)" -ne 0 ]; then  # root writes into read-only folders
  mkdir -p "$work/locked" && chmod a-w "$work/locked"
  expect_error "cannot write in" render builtin:layers:2 --size 8x8 --out "$work/locked/out.png"
  chmod u+w "$work/locked" && rmdir "$work/locked"
fi
# A write that fails half-way (the file-size limit makes the write itself fail, after the
# temporary was created): the temporary is removed and nothing else appears.
expect_file_too_large() {
  (trap '' XFSZ; ulimit -f 1; expect_error "$@"; echo "$passed $failed" >"$tmp/counts")
  read -r passed failed <"$tmp/counts"
}
expect_file_too_large "big.exr: cannot write image" render builtin:shells:3 --size 96x96 --out "$work/big.exr"
# The image is written (a 520-byte PNG), then its heatmap fails (a 1.7 kB EXR): neither appears.
expect_file_too_large "h.exr: cannot write image" render builtin:layers:2 --size 128x128 --out "$work/o.png" --heatmap "$work/h.exr"
if "$strata" track --help >/dev/null 2>&1; then
  expect_error "a-folder: is a folder" track --synthetic 1 --json "$work/a-folder"
  expect_file_too_large "t.json: write failed: File too large" track --synthetic 2 --json "$work/t.json"
fi

if [ -d "$models" ]; then
  expect_error "IndexOutOfRange.gltf: " render "$models/IndexOutOfRange/IndexOutOfRange.gltf" --out "$work/out.png"
  expect_error "RecursiveNodes.gltf: " render "$models/RecursiveNodes/RecursiveNodes.gltf" --out "$work/out.png"
  expect_error "MissingBin" render "$models/MissingBin/BoxTextured.gltf" --out "$work/out.png"
  expect_error "non-finite POSITION" render "$models/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb" --out "$work/out.png"
  # The Khronos validator rejects this file (TEXCOORD_1 without TEXCOORD_0); Strata draws it
  # and says what it ignored, one line per kind, each naming the file.
  crash=$models/issue_3269/texcoord_crash.gltf
  if "$strata" render "$crash" --size 16x16 --out "$work/crash.png" >/dev/null 2>"$tmp/stderr" && [ -s "$work/crash.png" ] &&
     [ "$(wc -l <"$tmp/stderr")" -eq 1 ] &&
     grep -qxF "strata: warning: $crash: TEXCOORD_1 without TEXCOORD_0: attribute set is not contiguous, ignored (mesh 0 primitive 0)" "$tmp/stderr"
  then ok; else bad "texcoord_crash.gltf: warnings -> $(cat "$tmp/stderr")"; fi
  rm -f "$work/crash.png"
else
  echo "skipped: $models absent (apt-get install assimp-testmodels)"
fi

# Good input: a PNG from a real model, and bench JSON that parses.
if [ -f "$shared/fandisk.glb" ]; then
  if "$strata" render "$shared/fandisk.glb" --size 64x48 --out "$work/fandisk.png" >/dev/null 2>"$tmp/stderr" &&
     [ -s "$work/fandisk.png" ] && [ ! -s "$tmp/stderr" ]; then ok; else bad "render of fandisk.glb: $(cat "$tmp/stderr")"; fi
else
  echo "skipped: $shared absent, no real model to render"
fi
if "$strata" bench builtin:layers:3 --size 32x32 --frames 2 --json "$work/bench.json" --csv "$work/bench.csv" \
     >"$tmp/table" 2>/dev/null && python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert d['modes'] and all(m['id'] for m in d['modes'])" "$work/bench.json" &&
   grep -q "abuffer" "$tmp/table" && [ "$(wc -l <"$work/bench.csv")" -ge 2 ]; then ok; else bad "bench JSON/CSV/table"; fi
# The advisor's JSON: every configuration measured, the front marked, a recommendation with its reason.
if "$strata" advise builtin:layers:3 --size 16x16 --frames 1 --warmup 0 --modes abuffer,wboit,ll --budget-ms 1000 \
     --json "$work/advise.json" >"$tmp/advise" 2>/dev/null &&
   python3 -c "import json,sys; d=json.load(open(sys.argv[1])); c=d['configurations']; assert len(c) == 8, len(c); assert any(x['pareto'] for x in c); assert d['recommended']['reason']" "$work/advise.json" &&
   grep -q "^recommended: " "$tmp/advise"; then ok; else bad "advise JSON/table: $(cat "$tmp/advise")"; fi
# A report folder (bench/report_page.hpp's layout): the page, its chart and every image it shows,
# the volumetric row against its own reference. Without gnuplot the page says so, and so does
# stderr, and there is no chart file.
if "$strata" bench builtin:layers:3 --size 32x24 --frames 1 --warmup 0 --modes floor,wboit,ll-volume \
     --report "$tmp/rep" >"$tmp/stdout" 2>/dev/null && grep -q "report written to .*/rep/index.html" "$tmp/stdout" &&
   (cd "$tmp/rep" && ls index.html README.md bench.json bench.csv chart.svg exact.png heatmap.png images/wboit.png \
      errors/ll-volume.png thumbs/wboit.png thumbs/floor-error.png >/dev/null) &&
   grep -q "error against <code>abuffer-volume</code>" "$tmp/rep/index.html" && grep -q "<svg" "$tmp/rep/chart.svg"
then ok; else bad "bench --report: $(cat "$tmp/stdout")"; fi
if env PATH=/nonexistent "$strata" bench builtin:layers:3 --size 32x24 --frames 1 --warmup 0 --modes wboit \
     --report "$tmp/rep2" >/dev/null 2>"$tmp/stderr" && grep -q "chart was not drawn: gnuplot was not found" "$tmp/stderr" &&
   grep -q "chart was not drawn" "$tmp/rep2/index.html" && [ ! -e "$tmp/rep2/chart.svg" ]
then ok; else bad "bench --report without gnuplot: $(cat "$tmp/stderr")"; fi
# Under a frame budget along a camera path: one zoom, time and prediction per frame, each zoom in range.
if "$strata" bench builtin:layers:4 --size 48x32 --frames 6 --warmup 0 --modes ll \
     --camera-path "$root/scenes/paths/zoom-load-jumps.path" --frame-budget-ms 5 --zoom-controller predictive \
     --zoom-max 3 --json "$tmp/budget.json" >/dev/null 2>&1 &&
   python3 - "$tmp/budget.json" <<'PY'; then ok; else bad "bench --frame-budget-ms JSON"; fi
import json, sys
d = json.load(open(sys.argv[1]))
assert d['zoom_controller'] == 'predictive' and d['frame_budget_ms'] == 5
(m,) = d['modes']
b = m['budget']
assert len(b['frame_zoom']) == len(b['frame_ms']) == len(b['frame_predicted_ms']) == 6
assert all(1 <= z <= 3 for z in b['frame_zoom'])
assert 0.0 <= b['within_band'] <= b['not_over_band'] <= 1.0
assert b['model']['ms_per_megafragment'] >= 0.0
# By default the budget also steers auto LOD's bound: one of 4, 8, 16, 32 px every frame.
assert d['budget_levers'] == 'zoom,lod'
assert len(b['frame_lod_bound_px']) == len(b['frame_loss_px']) == 6
assert all(x in (4, 8, 16, 32) for x in b['frame_lod_bound_px']), b['frame_lod_bound_px']
assert all(x >= 0 for x in b['frame_loss_px'])
PY
# A pinned state (the oracle's runs, scripts/bench_budget.sh --oracle): every frame at zoom 2 and
# the ladder's level 1 (8 px), no governor, the same per-frame figures.
if "$strata" bench builtin:layers:4 --size 48x32 --frames 3 --warmup 0 --modes ll --frame-budget-ms 5 \
     --budget-pin 2,1 --json "$tmp/pinned.json" >/dev/null 2>&1 &&
   python3 - "$tmp/pinned.json" <<'PY'; then ok; else bad "bench --budget-pin JSON"; fi
import json, sys
d = json.load(open(sys.argv[1]))
assert d['zoom_controller'] == 'pinned' and d['budget_pin'] == {'zoom': 2, 'lod_level': 1}, d['budget_pin']
(m,) = d['modes']
b = m['budget']
assert b['frame_zoom'] == [2, 2, 2], b['frame_zoom']
assert b['frame_lod_bound_px'] == [8, 8, 8], b['frame_lod_bound_px']
assert len(b['frame_psnr']) == len(b['frame_ms']) == 3
PY
# Level of detail: forced impostors on a field of 4 (the ground stays geometry: the eye is within
# 2 of its radii), in the render summary and the bench JSON; geometry bakes nothing.
if "$strata" render builtin:field:4 --lod impostors --size 64x48 --out "$tmp/field.png" >"$tmp/stdout" 2>"$tmp/stderr" &&
   grep -q "lod impostors: 4 of 5 objects as impostors (1 distinct)" "$tmp/stdout" && [ ! -s "$tmp/stderr" ]
then ok; else bad "render --lod impostors: $(cat "$tmp/stdout" "$tmp/stderr")"; fi
# The impostor cache: a second identical render loads what the first baked; `none` keeps nothing.
ic=$tmp/impostor-cache
if "$strata" render builtin:field:4 --lod impostors --impostor-cache "$ic" --size 64x48 --out "$tmp/f1.png" >"$tmp/stdout" 2>/dev/null &&
   grep -q "1 impostors baked (0 from the cache)" "$tmp/stdout" && [ "$(ls "$ic" | grep -c '\.strata-impostor$')" -eq 1 ] &&
   "$strata" render builtin:field:4 --lod impostors --impostor-cache "$ic" --size 64x48 --out "$tmp/f2.png" >"$tmp/stdout" 2>/dev/null &&
   grep -q "1 impostors baked (1 from the cache)" "$tmp/stdout" && cmp -s "$tmp/f1.png" "$tmp/f2.png"
then ok; else bad "render --impostor-cache: $(cat "$tmp/stdout")"; fi
if env XDG_CACHE_HOME="$tmp/none-cache" "$strata" render builtin:field:4 --lod impostors --impostor-cache none --size 64x48 \
     --out "$tmp/f3.png" >/dev/null 2>&1 && [ ! -e "$tmp/none-cache/strata" ] &&
   env XDG_CACHE_HOME="$tmp/default-cache" "$strata" render builtin:field:4 --lod impostors --size 64x48 \
     --out "$tmp/f4.png" >/dev/null 2>&1 && ls "$tmp/default-cache/strata/impostors/"*.strata-impostor >/dev/null
then ok; else bad "render --impostor-cache none wrote a cache, or the default folder got none"; fi
# A memory cap below one impostor's images: nothing is baked, every object draws geometry, and the
# JSON says the cap.
if "$strata" bench builtin:field:4 --lod impostors --impostor-memory-mb 0.5 --impostor-cache none --size 48x32 --frames 1 \
     --warmup 0 --modes blend-sorted --json "$tmp/cap.json" >/dev/null 2>&1 &&
   python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert d['lod']['memory_cap_bytes']==524288 and d['modes'][0]['impostor_objects']==0, d['lod']" "$tmp/cap.json"
then ok; else bad "bench --impostor-memory-mb"; fi
if "$strata" bench builtin:field:4 --lod impostors --size 48x32 --frames 1 --warmup 0 --modes blend-sorted \
     --impostor-resolution 32 --impostor-slices 8 --json "$tmp/lod.json" >/dev/null 2>&1 &&
   python3 - "$tmp/lod.json" <<'PY'; then ok; else bad "bench --lod impostors JSON"; fi
import json, sys
d = json.load(open(sys.argv[1]))
assert d['lod']['mode'] == 'impostors' and d['lod']['slices'] == 8 and d['lod']['resolution'] == 32
(m,) = d['modes']
assert m['impostor_objects'] == 4, m['impostor_objects']
# One shared impostor: 20 views of 32x32 RGBz (Table 2) + 4 bytes per (view, slice) rectangle.
assert m['impostor_bytes'] >= 4 * 32 * 32 * 20 + 4 * 20 * 8, m['impostor_bytes']
PY
if "$strata" bench builtin:field:4 --lod geometry --size 48x32 --frames 1 --warmup 0 --modes blend-sorted \
     --json "$tmp/geom.json" >/dev/null 2>"$tmp/stderr" &&
   python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert d['lod']=={'mode':'geometry'} and d['modes'][0]['impostor_objects']==0" "$tmp/geom.json" &&
   ! grep -q "baking" "$tmp/stderr"
then ok; else bad "bench --lod geometry bakes nothing"; fi
# A successful run leaves its outputs and nothing else.
leftover=$(cd "$work" && find . -mindepth 1 | sort | grep -vxF -e ./a-folder -e ./fandisk.png -e ./bench.json -e ./bench.csv -e ./advise.json)
if [ -z "$leftover" ]; then ok; else bad "left in the output folder: $leftover"; fi
"$strata" modes --settings >"$tmp/modes" 2>&1
if grep -q "^abuffer " "$tmp/modes"; then ok; else bad "modes lists abuffer"; fi
if grep -q "^    capacity  *integer in \[1, 64\]  *default 8 .*change: reallocate" "$tmp/modes"; then ok
else bad "modes --settings lists kbuffer's capacity"; fi

# A preset, then --set over it: the bench row records what it ran with (integers as integers).
printf '{"capacity": 3, "ll.tail": true, "precision": 16}' >"$tmp/preset.json"
if "$strata" bench builtin:layers:3 --size 16x16 --frames 1 --modes ll,kbuffer --settings "$tmp/preset.json" \
     --set kbuffer.capacity=5 --json "$tmp/set.json" >/dev/null 2>&1 &&
   python3 - "$tmp/set.json" <<'PY'; then ok; else bad "bench --settings/--set values in the JSON"; fi
import json, sys
rows = {m["id"]: m["settings"] for m in json.load(open(sys.argv[1]))["modes"]}
assert rows["ll"] == {"capacity": 3, "tail": True, "precision": 16}, rows["ll"]
assert rows["kbuffer"] == {"capacity": 5, "tail": False, "precision": 16}, rows["kbuffer"]
assert isinstance(rows["ll"]["capacity"], int)
PY

# Interrupts (io/interrupt.hpp). A bench sent SIGINT, then one sent SIGTERM, while a later
# technique runs: status 128 + the signal, one line naming it, JSON and CSV with exactly the
# techniques that completed (a prefix of those asked for, "interrupted": true) and no temporary.
# A demo sent SIGINT leaves no report folder at all. (Python sends the signals: a shell's
# background job starts with SIGINT ignored, and Strata leaves an ignored signal ignored.)
for signal in INT TERM; do
  mkdir -p "$tmp/int-$signal"
  if python3 - "$strata" "$tmp/int-$signal" "$signal" <<'PY'; then ok; else bad "bench interrupted by SIG$signal"; fi
import json, os, signal, subprocess, sys, time
strata, folder, name = sys.argv[1], sys.argv[2], sys.argv[3]
modes = ["abuffer", "wboit", "ll", "kbuffer", "fab"]
err = open(os.path.join(folder, "stderr"), "w+")
p = subprocess.Popen([strata, "bench", "builtin:layers:8", "--size", "96x96", "--frames", "400", "--warmup", "0",
                      "--modes", ",".join(modes), "--json", os.path.join(folder, "b.json"),
                      "--csv", os.path.join(folder, "b.csv")], stdout=subprocess.DEVNULL, stderr=err)
deadline = time.time() + 240
while time.time() < deadline and "[3/5]" not in open(err.name).read():
    time.sleep(0.05)
p.send_signal(getattr(signal, "SIG" + name))
rc = p.wait(timeout=240)
text = open(err.name).read()
assert rc == 128 + getattr(signal, "SIG" + name), (rc, text)
assert text.strip().splitlines()[-1] == "strata: interrupted by SIG" + name, text
started = max(int(line.split("[")[1].split("/")[0]) for line in text.splitlines() if line.startswith("bench: ["))
d = json.load(open(os.path.join(folder, "b.json")))
ids = [m["id"] for m in d["modes"]]
assert d["interrupted"] is True
# The technique running when the signal came is dropped; one that had just finished is kept.
assert ids == modes[:len(ids)] and started - 1 <= len(ids) <= started and 2 <= len(ids) < 5, (ids, started)
csv_rows = open(os.path.join(folder, "b.csv")).read().strip().splitlines()[1:]
assert [r.split(",")[4] for r in csv_rows] == ids
assert sorted(os.listdir(folder)) == ["b.csv", "b.json", "stderr"], os.listdir(folder)
PY
done
mkdir -p "$tmp/int-demo"
if python3 - "$strata" "$tmp/int-demo" <<'PY'; then ok; else bad "demo interrupted by SIGINT"; fi
import os, signal, subprocess, sys, time
strata, folder = sys.argv[1], sys.argv[2]
p = subprocess.Popen([strata, "demo", "--headless", "--size", "96x64", "--frames", "200", "--out",
                      os.path.join(folder, "report")], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
seen = ""
while "[3/" not in seen:
    line = p.stderr.readline()
    assert line, seen
    seen += line
p.send_signal(signal.SIGINT)
rest = p.communicate(timeout=240)[1]
assert p.returncode == 130, (p.returncode, rest)
assert os.listdir(folder) == [], os.listdir(folder)  # the report folder and its temporaries are gone
PY

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
