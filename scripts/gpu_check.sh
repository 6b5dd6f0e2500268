#!/usr/bin/env bash
# Strata on whatever GPU EGL finds: the GL tests, then a fixed bench set, into one report folder.
#   builtin:layers:N for N in 4 8 16 32 64 at 1280x720, 1920x1080 and 3840x2160 (every technique),
#   and the shipped scenes/*.json at 1920x1080 when their models (../shared/scenes-data) are present.
# Each bench keeps its JSON, CSV, table and stderr under runs/; README.md holds the device, the test
# result and summary tables, and is rewritten after every step, so a run cut short still reports
# what it did. A failing or timed-out bench is recorded and the run goes on; the exit status is 1
# if anything failed.
#
# usage: scripts/gpu_check.sh [--quick] [--bundle DIR] [--strata PATH] [--tests PATH] [--probe PATH]
#                             [--frames N] [--warmup N] [--sizes WxH,..] [--layers N,..] [--modes LIST]
#                             [--timeout S] [--skip-tests] [--scenes-data DIR] [--tar FILE] [OUT_DIR]
#   OUT_DIR        report folder (default gpu-check-report); an old report there is replaced
#   --quick        a tiny subset to try the script anywhere (llvmpipe): 256x256, layers 4 and 8 and
#                  the scenes, 2 frames, 1 warm-up
#   --strata PATH  the strata executable ($STRATA, default build/viewer/strata)
#   --tests PATH   the GL test executable ($STRATA_GL_TESTS, default build/tests/strata_gl_tests)
#   --bundle DIR   a bundle made by scripts/gpu_pack.sh: its strata, tests, probe, libraries,
#                  shaders and models (sets LD_LIBRARY_PATH and STRATA_SHADER_DIR, and NVIDIA's EGL
#                  vendor file where the driver has one)
#   --probe PATH   the naive peer (../shared/tools/peers/oitprobe.c, built): run beside every
#                  layers bench, with a "Strata over the probe" table in README.md
#   --modes LIST   the techniques of the layers benches (default all; a GPU's 15 minutes do not
#                  hold every technique at every size)
#   --tar FILE     pack the report folder into FILE (.tgz) at the end (a tool that returns files)
#   --frames N --warmup N   recorded and warm-up frames per technique (default 10 and 2)
#   --sizes, --layers       replace the default sizes or layer counts (to split a run in parts)
#   --timeout S    limit per bench and for the tests, seconds (default 900)
#   --scenes-data DIR       the scene models (default ../shared/scenes-data beside the repository,
#                  else scenes-data beside the strata executable); without them the scenes are skipped
# For a lent GPU machine: pack here with scripts/gpu_pack.sh (.gpu/), then there, from the
# repository root:
#   bash scripts/gpu_check.sh --bundle .gpu --tar $OUT/report.tgz
# The whole set does not fit a 15-minute lease: the GL tests took 220 s on an H100, and one bench
# of every technique ~30 s at 720p (docs/gpu-h100.md). Choose with --sizes, --layers and --modes,
# e.g. --sizes 1280x720 --layers 8,16,32 --modes floor,blend-sorted,wboit,f2b,f2b2,dual,abuffer,ll,sbuffer.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
source "$root/scripts/gpu_common.sh"
strata=${STRATA:-$root/build/viewer/strata}
tests=${STRATA_GL_TESTS:-$root/build/tests/strata_gl_tests}
out=gpu-check-report
quick=0
frames=""
warmup=""
limit=900
skip_tests=0
scenes_data=""
bundle=""
probe=""
modes=all
tarball=""
sizes_arg=""
layers_arg=""
while [[ $# -gt 0 ]]; do
    case $1 in
        --quick) quick=1; shift ;;
        --strata) strata=$2; shift 2 ;;
        --tests) tests=$2; shift 2 ;;
        --frames) frames=$2; shift 2 ;;
        --warmup) warmup=$2; shift 2 ;;
        --timeout) limit=$2; shift 2 ;;
        --sizes) sizes_arg=$2; shift 2 ;;
        --layers) layers_arg=$2; shift 2 ;;
        --skip-tests) skip_tests=1; shift ;;
        --scenes-data) scenes_data=$2; shift 2 ;;
        --bundle) bundle=$2; shift 2 ;;
        --probe) probe=$2; shift 2 ;;
        --modes) modes=$2; shift 2 ;;
        --tar) tarball=$2; shift 2 ;;
        -h|--help) sed -n '2,37p' "$0"; exit 0 ;;
        -*) echo "gpu_check.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
        *) out=$1; shift ;;
    esac
done
if [[ -n $bundle ]]; then
    [[ -x $bundle/strata ]] || { echo "gpu_check.sh: $bundle holds no strata (make it with scripts/gpu_pack.sh)" >&2; exit 1; }
    bundle=$(realpath "$bundle")
    strata=$bundle/strata
    tests=$bundle/strata_gl_tests
    [[ -z $probe && -x $bundle/oitprobe ]] && probe=$bundle/oitprobe
    [[ -z $scenes_data && -d $bundle/scenes-data ]] && scenes_data=$bundle/scenes-data
    use_gpu_bundle "$bundle"
fi
if ((quick)); then
    sizes=(256x256); layers=(4 8); scene_size=256x256; frames=${frames:-2}; warmup=${warmup:-1}
else
    sizes=(1280x720 1920x1080 3840x2160); layers=(4 8 16 32 64); scene_size=1920x1080
    frames=${frames:-10}; warmup=${warmup:-2}
fi
for v in "$frames" "$warmup" "$limit"; do
    [[ $v =~ ^[0-9]+$ ]] || { echo "gpu_check.sh: '$v' is not a whole number" >&2; exit 2; }
done
[[ -n $sizes_arg ]] && IFS=, read -r -a sizes <<<"$sizes_arg"
[[ -n $layers_arg ]] && IFS=, read -r -a layers <<<"$layers_arg"
[[ -x $strata ]] || { echo "gpu_check.sh: no strata executable at $strata (build it, or give --strata)" >&2; exit 1; }
strata=$(realpath "$strata")
[[ -x $tests ]] && tests=$(realpath "$tests")
if [[ -z $scenes_data ]]; then
    scenes_data=$root/../shared/scenes-data
    [[ -d $scenes_data ]] || scenes_data=$(dirname "$strata")/scenes-data
fi
[[ -d $scenes_data ]] && scenes_data=$(realpath "$scenes_data")

# The report folder: made fresh; an old report (it has our marker) is replaced, anything else kept.
out=$(fresh_report_folder gpu_check.sh "$out" .strata-gpu-check) || exit 1
mkdir -p "$out/runs" || exit 1
cd "$root" || exit 1  # scene names in the reports stay relative to the repository
# Mesa needs surfaceless without a display; strata asks NVIDIA's EGL for its device platform itself.
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless}

started=$(date -u +%Y-%m-%dT%H:%M:%SZ)
tests_status="not run"
tests_summary=""
device="unknown (no bench finished)"
scenes_note=""
benches=()   # name|scene|size|status|seconds, in run order
failures=0

note() { echo "gpu_check: $*"; }

# The device from a bench's JSON: the three strings of its "device" object.
device_of() {
    awk '/"device": *\{/ {on=1; next} on && /\}/ {exit} on {
           sub(/^ *"/, ""); key=$0; sub(/".*/, "", key); val=$0; sub(/^[^:]*: *"/, "", val); sub(/",? *$/, "", val); d[key]=val }
         END { if (d["renderer"] != "") printf "%s (%s; %s)", d["renderer"], d["vendor"], d["version"] }' "$1"
}

# One markdown table from every finished bench's CSV: a row per bench, a column per technique.
wide_table() {  # column-name printf-format
    local files=() b name
    for b in "${benches[@]}"; do
        IFS='|' read -r name _ _ status _ <<<"$b"
        [[ $status == ok ]] && files+=("runs/$name.csv")
    done
    ((${#files[@]})) || { echo "(no bench finished)"; return; }
    (cd "$out" && awk -F, -v want="$1" -v fmt="$2" '
        FNR == 1 { name = FILENAME; sub(/^runs\//, "", name); sub(/\.csv$/, "", name); rows[++nrows] = name
                   for (i = 1; i <= NF; ++i) col[$i] = i; next }
        { m = $col["mode"]; if (!(m in seen)) { seen[m] = 1; modes[++nmodes] = m }
          v[name, m] = sprintf(fmt, $col[want]) ($col["overflowed"] == 1 ? " ovf" : "") }
        END { printf "| bench |"; for (j = 1; j <= nmodes; ++j) printf " %s |", modes[j]; printf "\n|---|"
              for (j = 1; j <= nmodes; ++j) printf "---:|"; printf "\n"
              for (r = 1; r <= nrows; ++r) { printf "| %s |", rows[r]
                  for (j = 1; j <= nmodes; ++j) printf " %s |", ((rows[r], modes[j]) in v) ? v[rows[r], modes[j]] : "-"
                  printf "\n" } }' "${files[@]}")
}

# Strata over the naive probe per layers bench that has a probe run: its linked lists against
# abuffer and ll, its F2B against f2b (GPU ms over wall ms).
probe_table() {
    local b name rows=()
    for b in "${benches[@]}"; do
        IFS='|' read -r name _ _ _ _ <<<"$b"
        [[ -s $out/runs/$name.probe && -s $out/runs/$name.csv ]] && rows+=("$name")
    done
    ((${#rows[@]})) || return 0
    echo
    echo "## Strata over the naive probe"
    echo
    echo "The probe (\`../shared/tools/peers/oitprobe.c\`) on the same W*H*L fragments, wall ms with"
    echo "\`glFinish\`; Strata's GPU ms. ll runs at capacity L."
    echo
    echo "| bench | probe lists ms | probe F2B ms | abuffer / lists | ll / lists | f2b / F2B |"
    echo "|---|---:|---:|---:|---:|---:|"
    for name in "${rows[@]}"; do
        awk -F, -v name="$name" '
            FNR == NR { if ($1 ~ /^PPLL:/) { sub(/^PPLL: */, "", $1); split($1, a, " "); lists = a[1] }
                        if ($0 ~ /^F2B peel:/) { sub(/^F2B peel: */, "", $0); split($0, a, " "); f2b = a[1] }
                        next }
            FNR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
            { ms[$col["mode"]] = $col["ms_median"] }
            END {
                  printf "| %s | %s | %s | %s | %s | %s |\n", name, lists == "" ? "-" : lists, f2b == "" ? "-" : f2b,
                         ("abuffer" in ms && lists > 0) ? sprintf("%.2f", ms["abuffer"] / lists) : "-",
                         ("ll" in ms && lists > 0) ? sprintf("%.2f", ms["ll"] / lists) : "-",
                         ("f2b" in ms && f2b > 0) ? sprintf("%.2f", ms["f2b"] / f2b) : "-" }' \
            "$out/runs/$name.probe" "$out/runs/$name.csv"
    done
}

write_readme() {
    local b name scene size status secs ok=0
    for b in "${benches[@]}"; do [[ $b == *"|ok|"* ]] && ok=$((ok + 1)); done
    {
        echo "# Strata GPU check"
        echo
        echo "- device: $device"
        echo "- started $started, this summary written $(date -u +%Y-%m-%dT%H:%M:%SZ) on $(uname -n)"
        echo "- strata: \`$strata\`$( ((quick)) && echo " (--quick)")"
        echo "- frames $frames, warm-up $warmup per technique; limit ${limit} s per bench"
        echo "- GL tests: $tests_status (output in \`gl-tests.txt\`; failing checks' images in \`test-images/\`)"
        [[ -n $tests_summary ]] && echo "  - $tests_summary"
        echo "- benches: $ok of ${#benches[@]} finished${scenes_note:+; $scenes_note}"
        echo
        echo "Each bench's JSON, CSV, table and stderr are in \`runs/\`; \`all.csv\` has every row with"
        echo "its bench's name in front. Times are GPU ms from timer queries (median over the frames);"
        echo "\`ovf\` marks a technique that overflowed its buffers; errors are against \`abuffer\`."
        echo
        echo "## Benches"
        echo
        echo "| bench | scene | size | status | seconds |"
        echo "|---|---|---|---|---:|"
        for b in "${benches[@]}"; do
            IFS='|' read -r name scene size status secs <<<"$b"
            echo "| $name | \`$scene\` | $size | $status | $secs |"
        done
        echo
        echo "## GPU ms (median) per technique"
        echo
        wide_table ms_median %.4g
        echo
        echo "## RMSE against the reference per technique"
        echo
        wide_table rmse %.2e
        probe_table
    } >"$out/README.md.partial" && mv "$out/README.md.partial" "$out/README.md"
}

# bench NAME SCENE SIZE N TOTAL [ARGS]: one `strata bench` (ARGS, default every technique at
# its defaults), recorded whatever happens.
bench() {
    local name=$1 scene=$2 size=$3 n=$4 total=$5 extra=${6:---modes all} rc t0 secs status
    note "[$n/$total] $name: $scene at $size $extra ..."
    t0=$(date +%s.%N)
    # shellcheck disable=SC2086  # extra is a list of arguments
    timeout --kill-after=30 "$limit" "$strata" bench "$scene" --lod geometry $extra --size "$size" \
        --frames "$frames" --warmup "$warmup" --json "$out/runs/$name.json" --csv "$out/runs/$name.csv" \
        >"$out/runs/$name.txt" 2>"$out/runs/$name.err"
    rc=$?
    secs=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
    if ((rc == 0)) && [[ -s $out/runs/$name.json && -s $out/runs/$name.csv ]]; then
        status=ok
        [[ $device == unknown* ]] && device=$(device_of "$out/runs/$name.json")
        [[ -e $out/all.csv ]] || sed -n '1s/^/bench,/p' "$out/runs/$name.csv" >"$out/all.csv"
        awk -v b="$name" 'NR > 1 { print b "," $0 }' "$out/runs/$name.csv" >>"$out/all.csv"
    else
        failures=$((failures + 1))
        if ((rc == 124 || rc == 137)); then status="FAILED: timed out after ${limit} s"
        else status="FAILED (exit $rc): $(tail -n 1 "$out/runs/$name.err" | tr '|' '/' | cut -c1-160)"; fi
    fi
    benches+=("$name|$scene|$size|$status|$secs")
    note "[$n/$total] $name: $status (${secs} s)"
    write_readme
}

note "report in $out"
{
    echo "strata: $strata"
    echo "tests: $tests"
    echo "uname: $(uname -a)"
    for v in EGL_PLATFORM LD_LIBRARY_PATH STRATA_SHADER_DIR __EGL_VENDOR_LIBRARY_FILENAMES; do echo "$v=${!v-}"; done
    if command -v nvidia-smi >/dev/null; then
        nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv 2>&1
    fi
} >"$out/environment.txt"
write_readme

# The GL tests first: a driver that fails them makes the numbers below suspect.
if ((skip_tests)); then
    tests_status="skipped (--skip-tests)"
elif [[ ! -x $tests ]]; then
    tests_status="FAILED: no test executable at $tests"
    echo "$tests_status" >"$out/gl-tests.txt"
    failures=$((failures + 1))
else
    note "GL tests: $tests ..."
    # Each test's duration, how the programs were built (a GPU compiles to machine code), and the
    # images of failing checks in test-images/ (tests/gl_test_support.hpp dumpImage).
    # The tests look for scenes/ and the shared models where they were built unless told; the
    # shipped scene descriptions name their models as ../../shared/scenes-data, so only models
    # there count (elsewhere the tests that need them skip).
    STRATA_SOURCE_DIR="$root" STRATA_SHARED_SCENES_DIR="$root/../shared/scenes-data" \
    STRATA_GL_STATS=1 STRATA_TEST_DUMP="$out/test-images" \
        timeout --kill-after=30 "$limit" "$tests" --duration=true >"$out/gl-tests.txt" 2>&1
    rc=$?
    tests_summary=$(grep -E '^\[doctest\] (test cases|assertions):' "$out/gl-tests.txt" | sed 's/^\[doctest\] //; s/  */ /g' | sed 's/ *|* *$//' | paste -sd ';' - | sed 's/;/; /')
    if ((rc == 0)); then tests_status="passed"
    elif ((rc == 124 || rc == 137)); then tests_status="FAILED: timed out after ${limit} s"; failures=$((failures + 1))
    else tests_status="FAILED (exit $rc)"; failures=$((failures + 1)); fi
    note "GL tests: $tests_status${tests_summary:+ ($tests_summary)}"
fi
write_readme

# The bench set.
todo=()
for size in "${sizes[@]}"; do
    # ll at a capacity that keeps every fragment, as the probe's linked lists do.
    for n in "${layers[@]}"; do todo+=("layers-$n-$size|builtin:layers:$n|$size|--modes $modes --set ll.capacity=$n"); done
    # The settings whose defaults were chosen on llvmpipe, at their other value: the compute
    # resolve and fp16 accumulation (compare with the layers-16 run of the same size).
    todo+=("layers-16-$size-compute-fp16|builtin:layers:16|$size|--modes abuffer,blend-sorted,f2b,dual,wboit,floor --set abuffer.compute_resolve=1 --set precision=16")
done
scene_files=("$root"/scenes/*.json)
if [[ -d $scenes_data ]]; then
    for f in "${scene_files[@]}"; do
        [[ -e $f ]] || continue
        s=scenes/$(basename "$f")
        # The shipped descriptions name their models relative to themselves (../../shared/scenes-data);
        # models elsewhere get a copy of the description that names them by absolute path.
        if [[ $scenes_data != $(realpath -m "$root/../shared/scenes-data") ]]; then
            mkdir -p "$out/scenes"
            sed "s#\\.\\./\\.\\./shared/scenes-data/#$scenes_data/#g" "$f" >"$out/scenes/$(basename "$f")"
            s=$out/scenes/$(basename "$f")
        fi
        todo+=("$(basename "$f" .json)-$scene_size|$s|$scene_size")
    done
else
    scenes_note="scenes/*.json skipped: no models at $scenes_data"
    note "$scenes_note"
fi
i=0
for t in "${todo[@]}"; do
    i=$((i + 1))
    IFS='|' read -r name scene size extra <<<"$t"
    bench "$name" "$scene" "$size" "$i" "${#todo[@]}" "${extra:-}"
    # The probe on the same stack (a plain layers bench only), wall clock with glFinish.
    if [[ -n $probe && $name =~ ^layers-([0-9]+)-([0-9]+)x([0-9]+)$ ]]; then
        timeout --kill-after=10 "$limit" "$probe" "${BASH_REMATCH[2]}" "${BASH_REMATCH[3]}" "${BASH_REMATCH[1]}" 0 0 \
            "$frames" >"$out/runs/$name.probe" 2>&1 || note "probe for $name failed (exit $?)"
        write_readme
    fi
done

write_readme
if [[ -n $tarball ]]; then
    tar czf "$tarball" -C "$(dirname "$out")" "$(basename "$out")" && note "packed into $tarball"
fi
note "done: $failures failure(s); summary in $out/README.md"
((failures == 0))
