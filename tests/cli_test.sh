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
expect_error "has no parameter 'foo'" render builtin:layers:2 --set foo=1 --out "$tmp/out.png"
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
if "$strata" modes | grep -q "^abuffer "; then ok; else bad "modes lists abuffer"; fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
