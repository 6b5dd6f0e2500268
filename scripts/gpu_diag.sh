#!/usr/bin/env bash
# A lent GPU machine's diagnostic run, sized for one call of a 15-minute lease (docs/gpu-h100.md):
#  1. the whole GL suite in four shards run side by side (each its own process: NVIDIA compiles
#     programs on the CPU, and one process did not finish the suite in 220 s on an H100), and
#     beside them the repeated-render diagnostic with the program pool and without (and with
#     --ties, the coplanarity tests at another default tie tolerance);
#  2. (--group2) the tests that lost an object in one render of many (docs/gpu-h100.md, group 2),
#     repeated under driver and build settings that each remove one suspect: NVIDIA's threaded
#     dispatch (__GL_THREADED_OPTIMIZATIONS=0), an asynchronous link (STRATA_DEBUG_FINISH_BUILDS=1)
#     and the program binary cache (STRATA_PROGRAM_CACHE=0);
#  3. f2b, f2b2, dual, blend-sorted and abuffer at 1280x720 at both precisions, the naive probe
#     beside them (issue 25);
#  3b. dual on two single meshes (bunny-glass, fandisk-glass) with back_depth_test and
#     atomic_range off and on, f2b beside them (with the bundle's scenes-data);
#  4. builtin:orchard:10000 with --lod geometry and auto, twice (does the calibration choose
#     right; is the model kept).
# Everything lands in OUT (default gpu-diag); the summary is OUT/README.md, rewritten after each
# step so a run cut short keeps what it did.
#
# usage: scripts/gpu_diag.sh [--bundle DIR] [--tar FILE] [--quick] [OUT]
#   --bundle DIR  made by scripts/gpu_pack.sh (default .gpu)
#   --tar FILE    pack OUT into FILE (.tgz) at the end
#   --quick       small sizes and short limits, to try the script here on llvmpipe
#   --group2      run step 2 too (its suspects were ruled out on the H200; the cause, reused
#                 program names, was found in docs/gpu-h200-session3.md)
#   --no-repeat   leave out the repeated-render diagnostic (tests/diagnostic_gl_test.cpp) that runs
#                 beside the shards of step 1 with the program pool and without
#                 (STRATA_PROGRAM_POOL=0): the A/B of the fix for group 2
#   --ties ULPS   also run the coplanarity tests beside the shards with the default tie tolerance
#                 at ULPS (STRATA_DEBUG_DEPTH_TIE_ULPS; group 1; default 0, left out: the default
#                 tolerance is 1024 since docs/gpu-h100-session4.md)
#   --layers LIST the layer counts of step 3 (default 8,16,32)
#   --settings S  step 3's settings, ';'-separated (default: precision 32 and 16, 16 with
#                 read_ahead=0: what reading each layer's count before the next costs, and 16
#                 with atomic_range=1: dual's range by atomics, docs/gpu-h200-session5.md)
#   --tests-only  step 1 (and 2 with --group2) alone: no timings
#   --bench-only  steps 3, 3b and 4 alone: no tests
#   --no-orchard  leave out step 4
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
source "$root/scripts/gpu_common.sh"
bundle=$root/.gpu
out=gpu-diag
tarball=""
quick=0
skip_group2=1
repeat=1
ties=0
peel_layers=8,16,32
peel_settings="precision=32;precision=16;precision=16 read_ahead=0;precision=16 atomic_range=1"
run_tests=1
run_bench=1
run_orchard=1
while [[ $# -gt 0 ]]; do
    case $1 in
        --bundle) bundle=$2; shift 2 ;;
        --tar) tarball=$2; shift 2 ;;
        --quick) quick=1; shift ;;
        --group2) skip_group2=0; shift ;;
        --skip-group2) skip_group2=1; shift ;;
        --no-repeat) repeat=0; shift ;;
        --repeat) repeat=1; shift ;;
        --ties) ties=$2; shift 2 ;;
        --layers) peel_layers=$2; shift 2 ;;
        --settings) peel_settings=$2; shift 2 ;;
        --tests-only) run_bench=0; shift ;;
        --bench-only) run_tests=0; skip_group2=1; shift ;;
        --no-orchard) run_orchard=0; shift ;;
        -h|--help) sed -n '2,38p' "$0"; exit 0 ;;
        -*) echo "gpu_diag.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
        *) out=$1; shift ;;
    esac
done
[[ $ties =~ ^[0-9]+$ ]] || { echo "gpu_diag.sh: --ties takes a whole number of ulps, not '$ties'" >&2; exit 2; }
[[ -n $tarball && $tarball != /* ]] && tarball=$PWD/$tarball  # before the cd below
[[ -x $bundle/strata && -x $bundle/strata_gl_tests ]] ||
    { echo "gpu_diag.sh: $bundle holds no strata or strata_gl_tests (make it with scripts/gpu_pack.sh)" >&2; exit 1; }
bundle=$(realpath "$bundle")
out=$(fresh_report_folder gpu_diag.sh "$out" .strata-gpu-diag) || exit 1
mkdir -p "$out/images" || exit 1
cd "$root" || exit 1

use_gpu_bundle "$bundle"
export STRATA_SOURCE_DIR=$root STRATA_GL_STATS=1
[[ -d $bundle/scenes-data ]] && export STRATA_SHARED_SCENES_DIR=$bundle/scenes-data
tests=$bundle/strata_gl_tests
strata=$bundle/strata
if ((quick)); then
    shard_limit=300; repeat_limit=200; size=256x256; orchard=builtin:orchard:100
else
    shard_limit=200; repeat_limit=120; size=1280x720; orchard=builtin:orchard:10000
fi
summary=()
readme() {
    {
        echo "# Strata GPU diagnostic run"
        echo
        echo "- $(date -u +%FT%TZ) on $(uname -n); bundle \`$bundle\`"
        nvidia-smi --query-gpu=name,driver_version --format=csv,noheader 2>/dev/null | sed 's/^/- GPU: /'
        echo
        printf '%s\n' "${summary[@]}"
    } >"$out/README.md"
}
# The doctest totals line of a test log, or what ended it.
tally() {  # log status
    local line
    line=$(grep -E '^\[doctest\] test cases:' "$1" | tail -1)
    [[ $2 == 124 || $2 == 137 ]] && line="TIMED OUT; ${line:-no totals}"
    echo "${line:-exit $2, no totals}"
}

# "N x test case" for every test case of a log with failed checks.
failing() {
    awk '/^TEST CASE:/ { sub(/^TEST CASE: */, ""); tc = $0 } /ERROR: / { n[tc]++ }
         END { for (t in n) printf "%s%d x %s", (k++ ? "; " : ""), n[t], t; if (!k) printf "none" }' "$1"
}

# 1. The GL suite, four shards side by side (source-file patterns; every *_gl_test.cpp is in one).
shards=(
    '*exact_techniques*,*zoom_gl*,*frame_size*,*gpu_interface*,*shader_program*,*screendoor*'
    '*coplanar_buffers*,*coplanar_peeling*,*coplanarity_gl*,*volume_gl*,*deflection*,*error_map*'
    '*/material_gl*,*material_pbr*,*material_texture*,*transmission*,*gltf_sample*,*precision*,*approximate*'
    '*lod_*,*/buffers_gl*,*abuffer_gl*,*/peeling_gl*,*bench_gl*,*frustum*,*diagnostic*,*instanced*'
)
missing=$(cd "$root/tests" && for f in *_gl_test.cpp; do
    hit=0
    for s in "${shards[@]}"; do
        IFS=, read -r -a pats <<<"$s"
        for p in "${pats[@]}"; do [[ /$f == $p ]] && hit=1; done
    done
    ((hit)) || echo "$f"
done)
[[ -n $missing ]] && summary+=("- WARNING: test files in no shard: $missing")
if ((run_tests)); then
summary+=("## 1. The GL suite, four shards side by side" "")
start=$SECONDS
for i in "${!shards[@]}"; do
    (XDG_CACHE_HOME=/tmp/gpu-diag-xdg-$i STRATA_TEST_DUMP=$out/images/shard$i \
        timeout --kill-after=10 "$shard_limit" "$tests" -sf="${shards[$i]}" --duration=true \
        >"$out/tests-shard$i.txt" 2>&1
     echo $? >"$out/tests-shard$i.rc") &
done
if ((repeat)); then
    for r in pool no-pool; do
        (env_args=()
         [[ $r == no-pool ]] && env_args=(STRATA_PROGRAM_POOL=0)
         env "${env_args[@]}" XDG_CACHE_HOME=/tmp/gpu-diag-xdg-$r STRATA_TEST_DUMP=$out/images/repeat-$r \
             timeout --kill-after=10 "$shard_limit" "$tests" --no-skip -tc='diagnostic*' >"$out/repeat-$r.txt" 2>&1
         echo $? >"$out/repeat-$r.rc") &
    done
fi
if ((ties > 0)); then
    (STRATA_DEBUG_DEPTH_TIE_ULPS=$ties XDG_CACHE_HOME=/tmp/gpu-diag-xdg-ties STRATA_TEST_DUMP=$out/images/ties \
         timeout --kill-after=10 "$shard_limit" "$tests" -sf='*coplanar*' --duration=true >"$out/ties-$ties.txt" 2>&1
     echo $? >"$out/ties-$ties.rc") &
fi
wait
for i in "${!shards[@]}"; do
    summary+=("- shard $i (\`${shards[$i]}\`): $(tally "$out/tests-shard$i.txt" "$(cat "$out/tests-shard$i.rc")")")
    summary+=("  - failed checks per test case: $(failing "$out/tests-shard$i.txt")")
done
if ((repeat)); then
    for r in pool no-pool; do
        summary+=("- repeated-render diagnostic, $r: $(tally "$out/repeat-$r.txt" "$(cat "$out/repeat-$r.rc")");" \
            "  $(grep -c 'differs in [1-9]\|opaque colour in [1-9]\|opaque depth in [1-9]' "$out/repeat-$r.txt") settings with a differing render")
    done
fi
if ((ties > 0)); then
    summary+=("- the coplanarity tests at a default tie tolerance of $ties ulps: $(tally "$out/ties-$ties.txt" "$(cat "$out/ties-$ties.rc")")")
    summary+=("  - failed checks per test case: $(failing "$out/ties-$ties.txt")")
fi
summary+=("- wall $((SECONDS - start)) s" "")
readme
fi

if ((!skip_group2)); then
# 2. Group 2 under each suspect removed, side by side.
summary+=("## 2. One object missing in one render of many: the suspects removed one at a time" "")
group2='reversing*,abuffer?s compute*,skipping*,*MASK*,*COLOR_0*,*emissive texture*,*TEXCOORD_1*,*transmission 0*'
configs=(base threaded-off finish-builds no-cache)
start=$SECONDS
for c in "${configs[@]}"; do
    (env_args=()
     case $c in
         threaded-off) env_args=(__GL_THREADED_OPTIMIZATIONS=0) ;;
         finish-builds) env_args=(STRATA_DEBUG_FINISH_BUILDS=1) ;;
         no-cache) env_args=(STRATA_PROGRAM_CACHE=0) ;;
     esac
     env "${env_args[@]}" XDG_CACHE_HOME=/tmp/gpu-diag-xdg-$c STRATA_TEST_DUMP=$out/images/$c \
         timeout --kill-after=10 "$repeat_limit" "$tests" -tc="$group2" --duration=true >"$out/group2-$c.txt" 2>&1
     echo $? >"$out/group2-$c.rc") &
done
wait
for c in "${configs[@]}"; do
    summary+=("- $c: $(tally "$out/group2-$c.txt" "$(cat "$out/group2-$c.rc")")")
    summary+=("  - failed checks per test case: $(failing "$out/group2-$c.txt")")
done
summary+=("- wall $((SECONDS - start)) s" "")
readme
fi

finish() {
    echo "gpu_diag.sh: done; summary in $out/README.md"
    cat "$out/README.md"
    if [[ -n $tarball ]]; then tar -czf "$tarball" -C "$(dirname "$out")" "$(basename "$out")"; fi
    exit 0
}
((run_bench)) || finish

# 3. The peeling techniques against the probe, one process at a time (timings).
summary+=("## 3. Peeling at $size: object skipping and precision against the naive probe" "")
# GPU ms (the sum of the passes), then f2b's frame span on the GPU clock, and f2b's and abuffer's
# wall times of untimed frames (bench --wall), which compare with the probe's wall times (passes
# issued ahead overlap: their sum overstates).
summary+=("| layers | settings | floor | f2b | f2b2 | dual | blend-sorted | abuffer | f2b span | f2b wall | abuffer wall | probe F2B (wall) | probe lists (wall) |"
          "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
readme
w=${size%x*}
h=${size#*x}
IFS=, read -r -a layer_list <<<"$peel_layers"
IFS=';' read -r -a setting_list <<<"$peel_settings"
for layers in "${layer_list[@]}"; do
    probe_ms=-
    probe_ll=-
    if [[ -x $bundle/oitprobe ]]; then
        timeout 60 "$bundle/oitprobe" "$w" "$h" "$layers" 0 0 10 >"$out/probe-$layers.txt" 2>&1
        probe_ms=$(awk '/^F2B peel:/ {print $3}' "$out/probe-$layers.txt")
        probe_ll=$(awk '/^PPLL:/ {print $2}' "$out/probe-$layers.txt")
    fi
    for setting in "${setting_list[@]}"; do
        name="layers-$layers-${setting// /-}"
        set_args=()
        for s in $setting; do set_args+=(--set "$s"); done
        timeout --kill-after=10 90 "$strata" bench "builtin:layers:$layers" --lod geometry --size "$size" \
            --modes floor,f2b,f2b2,dual,blend-sorted,abuffer --wall "${set_args[@]}" --json "$out/$name.json" >"$out/$name.txt" 2>&1
        row=$(python3 - "$out/$name.json" <<'EOF'
import json, sys
try:
    modes = {m["id"]: m for m in json.load(open(sys.argv[1]))["modes"]}
    cells = ["%.2f" % modes[k]["ms_median"] if k in modes else "-" for k in ("floor", "f2b", "f2b2", "dual", "blend-sorted", "abuffer")]
    f2b = modes.get("f2b", {})
    cells += ["%.2f" % f2b["frame_span_ms_median"] if "frame_span_ms_median" in f2b else "-"]
    # Wall: the untimed frames of --wall (no timer queries, no fragment count), as the probe's.
    cells += ["%.2f" % modes[k]["wall_ms_median"] if modes.get(k, {}).get("wall_ms_median") is not None else "-"
              for k in ("f2b", "abuffer")]
    print(" | ".join(cells))
except Exception as e:
    print("failed: %s" % e)
EOF
)
        summary+=("| $layers | $setting | $row | $probe_ms | $probe_ll |")
        readme
    done
done
summary+=("")

# 3b. dual on single meshes, where the object skipper cannot leave out the peeled back layers:
# back_depth_test and atomic_range off and on (docs/gpu-h200-session5.md), f2b beside them. The
# scenes' model paths point at ../shared; here they point into the bundle.
if [[ -d $bundle/scenes-data ]]; then
    summary+=("## 3b. dual on meshes at $size (GPU ms: dual, its peel, f2b)" ""
              "| scene | atomic_range | back_depth_test | dual | dual peel | f2b |" "|---|---:|---:|---:|---:|---:|")
    for scene in bunny-glass fandisk-glass; do
        sed "s#\.\./\.\./shared/scenes-data#$bundle/scenes-data#" "$root/scenes/$scene.json" >"$out/$scene.json"
        for cfg in "0 0" "0 1" "1 0" "1 1"; do
            read -r atomic back <<<"$cfg"
            name="mesh-$scene-atomic$atomic-back$back"
            timeout --kill-after=10 60 "$strata" bench "$out/$scene.json" --lod geometry --size "$size" \
                --modes f2b,dual --set dual.atomic_range=$atomic --set dual.back_depth_test=$back \
                --json "$out/$name.json" >"$out/$name.txt" 2>&1
            row=$(python3 -c "
import json
m = {x['id']: x for x in json.load(open('$out/$name.json'))['modes']}
print('%.2f | %.2f | %.2f' % (m['dual']['ms_median'], m['dual']['pass_ms_median'].get('dual peel', 0),
      m['f2b']['ms_median']))" 2>/dev/null || echo "failed | - | -")
            summary+=("| $scene | $atomic | $back | $row |")
            readme
        done
    done
    summary+=("")
fi
((run_orchard)) || finish

# 4. LOD: does --lod auto choose right on this device.
summary+=("## 4. $orchard at $size, blend-sorted" "")
# auto twice: the first run calibrates the cost model and bakes, the second finds both kept.
export XDG_CACHE_HOME=/tmp/gpu-diag-xdg-orchard
for run in geometry auto auto-again; do
    lod=${run%-again}
    timeout --kill-after=10 120 "$strata" bench "$orchard" --lod "$lod" --size "$size" --modes blend-sorted \
        --json "$out/orchard-$run.json" >"$out/orchard-$run.txt" 2>&1
    summary+=("- $run: $(python3 -c "
import json, sys
d = json.load(open('$out/orchard-$run.json')); m = d['modes'][0]
print('frame %.2f ms GPU, CPU %.2f ms, %s objects as impostors, PSNR %s; model %s' % (m['frame_ms_median'],
      m['cpu_ms_median'], m['impostor_objects'], m['psnr'], d['lod'].get('model')))
" 2>&1 | tail -1)")
    readme
done
finish
