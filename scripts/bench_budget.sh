#!/usr/bin/env bash
# One frame budget for zoom and LOD (issue 24; frame/budget_governor.hpp): along a camera path
# that sweeps from an empty view into a dense grid (scripts/lib/sweep_path.py), each scene is
# first drawn without a budget (zoom 1, auto LOD at its least bound), then under a budget of
# --budget-share (default half) of that run's median frame time with each lever set (zoom alone,
# LOD alone, both) and each policy (reactive, predictive). Table per scene: frames not over the
# budget by more than 10 %, mean PSNR of the frames against the same frame at zoom 1 drawn as
# geometry (the bench JSON's budget.frame_psnr), median frame ms, mean zoom and mean LOD bound.
# Each run's JSON stays in the output folder; the tables go to stdout (markdown).
#
# Scenes (--scenes, a comma list of names below):
#   orchard: builtin:orchard:1000 at 320x240, least bound 4 px (auto LOD's default). After LOD,
#            the frame is the impostors' fill: only the zoom can take more off it.
#   field:   builtin:field:100 at 640x480, least bound 0.5 px. Geometry-bound (46080 triangles an
#            instance): the zoom takes little off it, raising the bound a lot.
#
# usage: scripts/bench_budget.sh [--out DIR] [--strata PATH] [--scenes orchard,field] [--frames N]
#        [--mode ID] [--budget-share F] [--merged-slices] [--least-bound PX] [--size WxH] [--quick]
#        [--oracle]
#   --quick: 12 frames, orchard only.
#   --merged-slices: every run with --impostor-merged-slices, so that raising the LOD bound
#            also draws stand-ins at fewer slices (layered-impostors.md, "Levels of merged slices").
#   --least-bound PX: the least LOD bound for every scene, in place of the scene's own.
#   --size WxH: the image size for every scene, in place of the scene's own.
#   --oracle: also draw the whole path at every state (zoom 1..8 x the 4 LOD ladder levels,
#            `strata bench --budget-pin`) and print what the best frame-by-frame choice of each
#            lever set would score (scripts/lib/budget_oracle.py): the most any policy can gain.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/docs/bench/budget
strata=$root/build/viewer/strata
scenes=orchard,field
frames=24
mode=blend-sorted
share=0.5
merged=()
least=
sizeArg=
oracle=0
while [[ $# -gt 0 ]]; do
    case $1 in
        --out) out=$2; shift 2 ;;
        --strata) strata=$2; shift 2 ;;
        --scenes) scenes=$2; shift 2 ;;
        --frames) frames=$2; shift 2 ;;
        --mode) mode=$2; shift 2 ;;
        --budget-share) share=$2; shift 2 ;;
        --merged-slices) merged=(--impostor-merged-slices); shift ;;
        --least-bound) least=$2; shift 2 ;;
        --size) sizeArg=$2; shift 2 ;;
        --quick) frames=12; scenes=orchard; shift ;;
        --oracle) oracle=1; shift ;;
        -h|--help) sed -n '2,27p' "$0"; exit 0 ;;
        *) echo "bench_budget.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done
[[ -x $strata ]] || { echo "bench_budget.sh: no strata executable at $strata (run scripts/build.sh build)" >&2; exit 1; }
mkdir -p "$out"
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless}

for name in ${scenes//,/ }; do
    case $name in
        orchard) scene=builtin:orchard:1000; size=320x240; base=4; count=1000; spacing=2.5 ;;
        field) scene=builtin:field:100; size=640x480; base=0.5; count=100; spacing=3 ;;
        *) echo "bench_budget.sh: unknown scene '$name' (orchard, field)" >&2; exit 2 ;;
    esac
    [[ -z $least ]] || base=$least
    [[ -z $sizeArg ]] || size=$sizeArg
    path=$out/$name-sweep.path
    python3 "$root/scripts/lib/sweep_path.py" "$count" "$spacing" "$path"
    common=(bench "$scene" --size "$size" --modes "$mode" --frames "$frames" --warmup 1 --camera-path "$path"
            --lod auto --lod-max-error-px "$base" ${merged[@]+"${merged[@]}"})
    echo "bench_budget: $name: no budget" >&2
    # A budget nothing reaches (1e6 ms) keeps the zoom at 1 and gives the per-frame figures.
    "$strata" "${common[@]}" --frame-budget-ms 1e6 --budget-levers zoom --json "$out/$name-none.json" >/dev/null 2>"$out/$name-none.log"
    budget=$(python3 -c "
import json, statistics, sys
d = json.load(open(sys.argv[1]))
print('%.2f' % (float(sys.argv[2]) * statistics.median(d['modes'][0]['budget']['frame_ms'])))" "$out/$name-none.json" "$share")
    for levers in zoom lod zoom,lod; do
        for policy in reactive predictive; do
            echo "bench_budget: $name: budget $budget ms, levers $levers, $policy" >&2
            "$strata" "${common[@]}" --frame-budget-ms "$budget" --budget-levers "$levers" --zoom-controller "$policy" \
                --json "$out/$name-${levers/,/+}-$policy.json" >/dev/null 2>"$out/$name-${levers/,/+}-$policy.log"
        done
    done
    python3 - "$out" "$name" "$scene" "$size" "$base" "$budget" "$share" <<'PY'
import json, statistics, sys
out, name, scene, size, base, budget, share = sys.argv[1:]
budget = float(budget)
def row(label, policy, path):
    d = json.load(open(path))
    b = d['modes'][0]['budget']
    ms, psnr, zoom, bound = b['frame_ms'], b['frame_psnr'], b['frame_zoom'], b['frame_lod_bound_px']
    not_over = sum(t <= budget * 1.1 for t in ms) / len(ms)
    bound_text = '%.2f' % statistics.mean(bound) if any(bound) else '%s (fixed)' % base
    print('| %s | %s | %.0f %% | %.2f | %.1f | %.2f | %s |' % (label, policy, 100 * not_over, statistics.mean(psnr),
          statistics.median(ms), statistics.mean(zoom), bound_text))
print()
print('%s at %s, %s, least LOD bound %s px; budget %.2f ms (%s x the median without one)' % (scene, size, name, base, budget, share))
print()
print('| levers | policy | frames not over (+10 %) | mean PSNR dB | median ms | mean zoom | mean bound px |')
print('|---|---|---:|---:|---:|---:|---:|')
row('none (no budget)', '-', '%s/%s-none.json' % (out, name))
for levers in ('zoom', 'lod', 'zoom,lod'):
    for policy in ('reactive', 'predictive'):
        row(levers, policy, '%s/%s-%s-%s.json' % (out, name, levers.replace(',', '+'), policy))
PY
    [[ $oracle == 1 ]] || continue
    pinned=()
    for zoom in 1 2 3 4 5 6 7 8; do
        for level in 0 1 2 3; do
            echo "bench_budget: $name: every frame at zoom $zoom, LOD level $level" >&2
            json=$out/$name-pin-z$zoom-l$level.json
            "$strata" "${common[@]}" --frame-budget-ms "$budget" --budget-levers zoom,lod --budget-pin "$zoom,$level" \
                --json "$json" >/dev/null 2>"${json%.json}.log"
            pinned+=("$json")
        done
    done
    policies=()
    for levers in zoom lod zoom+lod; do
        for policy in reactive predictive; do
            policies+=(--policy "$levers $policy=$out/$name-$levers-$policy.json")
        done
    done
    echo
    echo "$name: the best state frame by frame (oracle) beside the policies, budget $budget ms"
    echo
    python3 "$root/scripts/lib/budget_oracle.py" "$budget" "${pinned[@]}" "${policies[@]}"
done
