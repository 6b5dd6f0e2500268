#!/usr/bin/env bash
# The command line's contract: bad input gives one line on stderr naming the input, a non-zero
# exit and no output file; good input writes what it says. Usage: cli_test.sh STRATA_BINARY
set -uo pipefail
strata=$1
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0
failed=0
models=/usr/share/assimp/models/glTF2
shared=$(cd "$(dirname "$0")/../.." && pwd)/shared/scenes-data

ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL: $*"; }

# expect_error "what stderr must contain" ARGS... (the output file $tmp/out.png must not appear)
expect_error() {
  local want=$1; shift
  rm -f "$tmp/out.png"
  "$strata" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local rc=$?
  local lines
  lines=$(wc -l <"$tmp/stderr")
  if [ $rc -eq 0 ]; then bad "exit 0 for: $*"; return; fi
  if [ $rc -ge 128 ]; then bad "crashed (status $rc) for: $*"; return; fi
  if [ "$lines" -ne 1 ]; then bad "$lines lines on stderr for: $* -> $(cat "$tmp/stderr")"; return; fi
  if ! grep -qF -- "$want" "$tmp/stderr"; then bad "stderr lacks '$want' for: $* -> $(cat "$tmp/stderr")"; return; fi
  if [ -e "$tmp/out.png" ] || ls "$tmp"/*.partial* >/dev/null 2>&1; then bad "output written for: $*"; return; fi
  ok
}

expect_error "no such file" render "$tmp/missing.glb" --out "$tmp/out.png"
expect_error "unknown builtin scene" render builtin:nothing --out "$tmp/out.png"
expect_error "must be an integer" render builtin:layers:x --out "$tmp/out.png"
expect_error "unknown technique 'nope'" render builtin:layers:2 --mode nope --out "$tmp/out.png"
# Settings: every rejection is one line before any frame (bench prints a progress line per mode,
# so one line on stderr also proves nothing was benched).
expect_error "technique abuffer has no setting 'foo' (has: " render builtin:layers:2 --set foo=1 --out "$tmp/out.png"
expect_error "capacity = 'abc': expected integer in [1, 1024]" bench builtin:layers:2 --modes abuffer,ll --set ll.capacity=abc --json "$tmp/out.png"
expect_error "capacity = '2.5': expected integer" render builtin:layers:2 --mode ll --set capacity=2.5 --out "$tmp/out.png"
expect_error "capacity = '0': expected integer in [1, 64]" render builtin:layers:2 --mode kbuffer --set capacity=0 --out "$tmp/out.png"
expect_error "precision = '24': expected 16 or 32" render builtin:layers:2 --mode wboit --set precision=24 --out "$tmp/out.png"
expect_error "tail = 'yes': expected flag (true or false" render builtin:layers:2 --mode fab --set tail=yes --out "$tmp/out.png"
expect_error "no technique run has a setting 'capacty'" bench builtin:layers:2 --modes abuffer,ll --set capacty=16 --json "$tmp/out.png"
expect_error "unknown technique 'llx'" bench builtin:layers:2 --modes ll --set llx.capacity=4 --json "$tmp/out.png"
expect_error "technique kbuffer is not among those run (abuffer, ll)" bench builtin:layers:2 --modes ll --set kbuffer.capacity=4 --json "$tmp/out.png"
expect_error "not of the form [technique.]name=value" render builtin:layers:2 --set capacity --out "$tmp/out.png"
expect_error "missing.json: not a readable regular file" render builtin:layers:2 --settings "$tmp/missing.json" --out "$tmp/out.png"
printf '{"capacity": 4,' >"$tmp/broken.json"
expect_error "broken.json: " render builtin:layers:2 --mode ll --settings "$tmp/broken.json" --out "$tmp/out.png"
printf '{"capacity": "four"}' >"$tmp/string.json"
expect_error "string.json: \"capacity\" is not a number or a boolean" render builtin:layers:2 --mode ll --settings "$tmp/string.json" --out "$tmp/out.png"
printf '{"ll.capacity": 4, "ll.capacty": 4}' >"$tmp/typo.json"
expect_error "typo.json ll.capacty=4: technique ll has no setting 'capacty'" render builtin:layers:2 --mode ll --settings "$tmp/typo.json" --out "$tmp/out.png"
printf '{"capacity": 2000}' >"$tmp/range.json"
expect_error "range.json capacity=2000: setting capacity = '2000': expected integer in [1, 1024]" render builtin:layers:2 --mode ll --settings "$tmp/range.json" --out "$tmp/out.png"
expect_error "is not WxH" render builtin:layers:2 --size 12 --out "$tmp/out.png"
expect_error "unsupported image type" render builtin:layers:2 --out "$tmp/out.jpg"
expect_error "does not exist" render builtin:layers:2 --out "$tmp/no/such/folder/out.png"
printf '0 0 0 0 0 0 0 1\n1 0 0\n' >"$tmp/path.txt"
expect_error "path.txt:2: expected 8 numbers" render builtin:layers:2 --camera-path "$tmp/path.txt" --out "$tmp/out.png"
expect_error "unknown technique" bench builtin:layers:2 --modes abuffer,nope --json "$tmp/out.png"
if [ -d "$models" ]; then
  expect_error "IndexOutOfRange.gltf: " render "$models/IndexOutOfRange/IndexOutOfRange.gltf" --out "$tmp/out.png"
  expect_error "RecursiveNodes.gltf: " render "$models/RecursiveNodes/RecursiveNodes.gltf" --out "$tmp/out.png"
  expect_error "MissingBin" render "$models/MissingBin/BoxTextured.gltf" --out "$tmp/out.png"
  expect_error "non-finite POSITION" render "$models/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb" --out "$tmp/out.png"
else
  echo "skipped: $models absent (apt-get install assimp-testmodels)"
fi

# Good input: a PNG from a real model, and bench JSON that parses.
if [ -f "$shared/fandisk.glb" ]; then
  if "$strata" render "$shared/fandisk.glb" --size 64x48 --out "$tmp/fandisk.png" >/dev/null 2>"$tmp/stderr" &&
     [ -s "$tmp/fandisk.png" ]; then ok; else bad "render of fandisk.glb: $(cat "$tmp/stderr")"; fi
else
  echo "skipped: $shared absent, no real model to render"
fi
if "$strata" bench builtin:layers:3 --size 32x32 --frames 2 --json "$tmp/bench.json" --csv "$tmp/bench.csv" \
     >"$tmp/table" 2>/dev/null && python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert d['modes'] and all(m['id'] for m in d['modes'])" "$tmp/bench.json" &&
   grep -q "abuffer" "$tmp/table" && [ "$(wc -l <"$tmp/bench.csv")" -ge 2 ]; then ok; else bad "bench JSON/CSV/table"; fi
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

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
