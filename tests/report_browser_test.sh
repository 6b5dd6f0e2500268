#!/usr/bin/env bash
# The demo report as a user sees it: `strata demo --headless` at a small size, then the page
# checked without a network the way a browser shows it.
#   - the markup validates (tidy: no error, no warning);
#   - every image and link of the page names a file of the folder;
#   - headless Chromium at two widths (desktop and phone) logs no console message (the page logs
#     none; a script error or a failed load is one), reports no image that failed to load (the
#     page's own check, body[data-broken-images]), and its screenshot is not blank;
#   - the folder stays under 4 MB.
# The screenshots are kept in OUT for a person to look at.
set -euo pipefail
strata=${1:?usage: report_browser_test.sh STRATA SCREENSHOT_CONTENT OUT}
content=${2:?usage: report_browser_test.sh STRATA SCREENSHOT_CONTENT OUT}
out=${3:?usage: report_browser_test.sh STRATA SCREENSHOT_CONTENT OUT}
fail() { echo "report_browser: $*"; exit 1; }
for tool in chromium tidy; do
    command -v "$tool" >/dev/null || fail "$tool is not installed: run 'bash scripts/install-deps.sh --test'"
done

rm -rf "$out"
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
report=$out/report
EGL_PLATFORM=${EGL_PLATFORM:-surfaceless} timeout 600 "$strata" demo --headless --size 256x160 --frames 1 \
    --out "$report" >"$out/demo.log" 2>&1 || { cat "$out/demo.log"; fail "strata demo failed"; }
page=$report/index.html
[[ -f $page ]] || fail "no index.html in $report"

tidy -q -e "$page" >"$out/tidy.txt" 2>&1 || { cat "$out/tidy.txt"; fail "index.html does not validate (tidy)"; }

# Every src and href (in-page anchors aside) resolves inside the folder: nothing refers outside
# it, so the page works offline and when the folder is moved.
refs=$(grep -oE '(src|href)="[^"#]+"' "$page" | sed -E 's/^(src|href)="(.*)"$/\2/' | sort -u)
count=0
while IFS= read -r ref; do
    [[ -n $ref ]] || continue
    [[ $ref != *://* && $ref != /* && $ref != *..* ]] || fail "index.html refers outside its folder: $ref"
    [[ -f $report/$ref ]] || fail "index.html refers to $ref, which is not in the folder"
    count=$((count + 1))
done <<<"$refs"
(( count >= 60 )) || fail "index.html refers to only $count files (a contact sheet of every technique has more)"
echo "report_browser: $count images and links resolve"

# Anchors (#m-ID) name an element of the page.
while IFS= read -r anchor; do
    grep -q "id=\"$anchor\"" "$page" || fail "index.html links to #$anchor, which no element has"
done < <(grep -oE 'href="#[^"]+"' "$page" | sed -E 's/^href="#(.*)"$/\1/' | sort -u)

browse() {  # WIDTH HEIGHT: screenshot and DOM after load, console messages in the log
    local w=$1 h=$2
    timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --user-data-dir="$tmp/profile-$w" \
        --enable-logging=stderr --v=0 --window-size="$w,$h" --virtual-time-budget=5000 \
        --screenshot="$out/page-$w.png" "file://$(realpath "$page")" >"$out/chromium-$w.log" 2>&1 ||
        { cat "$out/chromium-$w.log"; fail "chromium could not take the screenshot at width $w"; }
    timeout 120 chromium --headless --no-sandbox --disable-gpu --user-data-dir="$tmp/profile-$w" \
        --enable-logging=stderr --v=0 --window-size="$w,$h" --virtual-time-budget=5000 \
        --dump-dom "file://$(realpath "$page")" >"$out/dom-$w.html" 2>>"$out/chromium-$w.log" ||
        { cat "$out/chromium-$w.log"; fail "chromium could not load the page at width $w"; }
    if grep -E ':CONSOLE[:(]' "$out/chromium-$w.log"; then fail "the page logged to the console at width $w"; fi
    grep -q 'data-broken-images="0"' "$out/dom-$w.html" ||
        fail "at width $w the page's image check did not report 0 broken images: $(grep -oE 'data-broken-images="[^"]*"' "$out/dom-$w.html" || echo 'it did not run')"
    "$content" "$out/page-$w.png" || fail "the screenshot at width $w is blank"
}
browse 1280 2400
browse 420 2400

kb=$(du -sk "$report" | cut -f1)
(( kb < 4096 )) || fail "the report folder is $kb KB (at most 4 MB at this size)"
echo "report_browser: folder $kb KB; screenshots in $out (page-1280.png, page-420.png)"
