#!/usr/bin/env bash
# Runs every command the docs show, at a tiny size, so the docs cannot drift from the code.
# Usage: scripts/check_docs.sh PATH/TO/strata
#
# What runs. Every fenced code block whose info string is exactly `sh`, in README.md and
# docs/*.md. In such a block, a line that starts with `strata ` runs (a line ending in a
# backslash continues on the next); blank lines and `#` comment lines are passed over; any
# other line (`make demo`, `bash scripts/...`, `ctest ...`) is not run and is listed as
# "not run: ...". Blocks that show output rather than commands use `text` or `console` and are
# not read.
#
# How a line is changed before it runs:
#   - a trailing comment (` # ...`) is dropped, and the leading `strata` becomes the binary;
#   - paths: a word that starts with `scenes/` or `../shared/` is relative to the repository
#     root, and becomes "$STRATA_ROOT/scenes/..." or "$STRATA_ROOT/../shared/...". So write
#     every path in the docs as it is typed in the repository root; absolute paths and
#     anything else are left alone (STRATA_ROOT is exported to the commands);
#   - sizes: `--size WxH` becomes `--size 64x40`, `--frames N` `--frames 1`, `--warmup N`
#     `--warmup 0`, and `--inspect X,Y` `--inspect 32,20` (the middle of a 64x40 window);
#   - `strata demo` gets `--headless`, `--size 64x40` and `--frames 1` where not given;
#   - `strata view` gets `--size 64x40` where not given and `--exit-after-frames 2`, and runs
#     under `xvfb-run -a -s "-screen 0 1024x768x24"` with LIBGL_ALWAYS_SOFTWARE=1.
# Each block runs in a fresh temporary folder (cd there; outputs land there, and are removed at
# the end), its lines in order, so a line may read what an earlier line of its block wrote. A
# relative output path with a folder (`--out docs/images/demo.png`; also --heatmap,
# --highlight-coplanar, --json, --csv, --sweep-csv, --screenshot) gets that folder made there
# first, as it exists in the repository; nothing in the repository is written.
# EGL_PLATFORM defaults to surfaceless.
#
# It prints each command as written, with its file and line, and at the end
# "N commands run, M skipped". When any command exits non-zero it prints that command as run
# and its stderr, and the script exits 1 after running the rest.
set -uo pipefail

usage() { echo "usage: scripts/check_docs.sh PATH/TO/strata" >&2; exit 2; }
[[ $# -eq 1 ]] || usage
[[ -x $1 && -f $1 ]] || { echo "check_docs: $1 is not an executable file" >&2; exit 2; }
STRATA=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
STRATA_ROOT=$(cd "$(dirname "$0")/.." && pwd)
export STRATA STRATA_ROOT
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless}
small=64x40
per_command_timeout=300

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Every logical line of every sh block, as records: BLOCK \t FILE:LINE \t TEXT. BLOCK numbers
# the fenced blocks of all files in one sequence (the global `block`).
block=0
extract() {
    local file=$1 rel=${1#"$STRATA_ROOT"/} n=0 in_fence=0 run=0 pending="" start=0 info line
    while IFS= read -r line || [[ -n $line ]]; do
        n=$((n + 1))
        if (( ! in_fence )); then
            if [[ $line =~ ^[[:space:]]*\`\`\`(.*)$ ]]; then
                info=${BASH_REMATCH[1]}
                info=${info#"${info%%[![:space:]]*}"}
                info=${info%"${info##*[![:space:]]}"}
                in_fence=1
                block=$((block + 1))
                [[ $info == sh ]] && run=1 || run=0
            fi
            continue
        fi
        if [[ $line =~ ^[[:space:]]*\`\`\`[[:space:]]*$ ]]; then
            in_fence=0
            [[ -n $pending ]] && printf '%s\t%s:%s\t%s\n' "$block" "$rel" "$start" "$pending"
            pending=""
            continue
        fi
        (( run )) || continue
        line=${line#"${line%%[![:space:]]*}"}
        if [[ -z $pending ]]; then start=$n; fi
        if [[ $line == *\\ ]]; then
            pending+="${line%\\} "
            continue
        fi
        pending+=$line
        printf '%s\t%s:%s\t%s\n' "$block" "$rel" "$start" "$pending"
        pending=""
    done <"$file"
}

# The command line to run for one documented strata line.
rewrite() {
    local cmd=$1 sub
    cmd=$(sed -E 's/[[:space:]]+#.*$//' <<<"$cmd")
    cmd=$(sed -E \
        -e 's/(^|[[:space:]])--size[[:space:]]+[0-9]+x[0-9]+/\1--size '"$small"'/g' \
        -e 's/(^|[[:space:]])--frames[[:space:]]+[0-9]+/\1--frames 1/g' \
        -e 's/(^|[[:space:]])--warmup[[:space:]]+[0-9]+/\1--warmup 0/g' \
        -e 's/(^|[[:space:]])--inspect[[:space:]]+[0-9]+,[0-9]+/\1--inspect 32,20/g' \
        -e 's#(^|[[:space:]])scenes/#\1"$STRATA_ROOT"/scenes/#g' \
        -e 's#(^|[[:space:]])\.\./shared/#\1"$STRATA_ROOT"/../shared/#g' <<<"$cmd")
    sub=$(awk '{ print $2 }' <<<"$cmd")
    cmd=${cmd#strata}
    case $sub in
        demo)
            [[ $cmd =~ (^|[[:space:]])--headless([[:space:]]|$) ]] || cmd+=" --headless"
            [[ $cmd =~ (^|[[:space:]])--size[[:space:]] ]] || cmd+=" --size $small"
            [[ $cmd =~ (^|[[:space:]])--frames[[:space:]] ]] || cmd+=" --frames 1"
            cmd="\"\$STRATA\"$cmd"
            ;;
        view)
            [[ $cmd =~ (^|[[:space:]])--size[[:space:]] ]] || cmd+=" --size $small"
            cmd="LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s \"-screen 0 1024x768x24\" \"\$STRATA\"$cmd --exit-after-frames 2"
            ;;
        *)
            cmd="\"\$STRATA\"$cmd"
            ;;
    esac
    printf '%s' "$cmd"
}

records=$work/records
: >"$records"
for doc in "$STRATA_ROOT/README.md" "$STRATA_ROOT"/docs/*.md; do
    [[ -f $doc ]] && extract "$doc" >>"$records"
done

ran=0
skipped=0
failed=0
current_block=""
dir=""
while IFS=$'\t' read -r block where text; do
    [[ -z $text || $text == \#* ]] && continue
    if [[ $text != "strata "* ]]; then
        echo "not run: $where: $text"
        skipped=$((skipped + 1))
        continue
    fi
    if [[ $block != "$current_block" ]]; then
        current_block=$block
        dir=$(mktemp -d "$work/block-XXXX")
    fi
    cmd=$(rewrite "$text")
    echo "$where: $text"
    if [[ $cmd == *xvfb-run* ]] && ! command -v xvfb-run >/dev/null; then
        echo "FAILED: $where: xvfb-run is not installed (scripts/install-deps.sh --test)"
        failed=$((failed + 1))
        ran=$((ran + 1))
        continue
    fi
    read -ra words <<<"$text"
    for ((i = 0; i + 1 < ${#words[@]}; i++)); do
        case ${words[i]} in
            --out | --heatmap | --highlight-coplanar | --json | --csv | --sweep-csv | --screenshot)
                next=${words[i + 1]}
                [[ $next != /* && $next != *..* && $next == */* ]] && mkdir -p "$dir/$(dirname "$next")" ;;
        esac
    done
    started=$EPOCHREALTIME
    (cd "$dir" && timeout "$per_command_timeout" bash -c "$cmd") >"$work/stdout" 2>"$work/stderr" </dev/null
    status=$?
    ran=$((ran + 1))
    awk -v a="$started" -v b="$EPOCHREALTIME" 'BEGIN { printf "  %.1f s\n", b - a }'
    if (( status != 0 )); then
        failed=$((failed + 1))
        echo "FAILED (exit $status): $where"
        echo "  ran: $cmd"
        echo "  stderr:"
        sed 's/^/    /' "$work/stderr" | tail -n 40
    fi
done <"$records"

echo "$ran commands run, $skipped skipped"
if (( failed > 0 )); then
    echo "check_docs: $failed of $ran commands failed"
    exit 1
fi
