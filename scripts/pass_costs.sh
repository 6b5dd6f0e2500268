#!/usr/bin/env bash
# Per-pass median GPU time of every technique in one bench run, as a markdown table:
#   scripts/pass_costs.sh [SCENE] [WxH] [FRAMES] > table.md
# Reads the bench JSON's pass_ms_median; run from the repository root (or set STRATA).
set -euo pipefail
scene=${1:-builtin:layers:16}
size=${2:-256x256}
frames=${3:-5}
strata=${STRATA:-build/viewer/strata}
json=$(mktemp --suffix=.json)
trap 'rm -f "$json"' EXIT
echo "pass_costs: $strata bench $scene --modes all --size $size --frames $frames" >&2
"$strata" bench "$scene" --lod geometry --modes all --size "$size" --frames "$frames" --json "$json" >/dev/null
python3 - "$json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
floor = next((m["ms_median"] for m in j["modes"] if m["id"] == "floor"), None)
print(f"`{j['scene']}` {j['size'][0]}x{j['size'][1]}, {j['frames']} frames, {j['device']['renderer']}\n")
print("| mode | total ms | x floor | passes | per pass name: median ms per frame (all passes of that name) |")
print("|---|---:|---:|---:|---|")
for m in j["modes"]:
    passes = ", ".join(f"{k} {v:.2f}" for k, v in sorted(m["pass_ms_median"].items(), key=lambda kv: -kv[1]) if k != "opaque")
    ratio = f"{m['ms_median'] / floor:.2f}" if floor else ""
    print(f"| `{m['id']}` | {m['ms_median']:.2f} | {ratio} | {m['passes']} | {passes} |")
PY
