#!/usr/bin/env bash
# check_page.sh DIR [SCREENSHOT]: loads DIR/index.html (written by pt-study) in
# headless Chromium and fails when the page does not load or any image on it
# did not load (the page's own script counts images with a natural width into
# <body data-images="ok/total"> once the load event has fired). Writes a
# screenshot of the page's top. Exit 77 (ctest: skipped) without Chromium.
set -euo pipefail
dir=$(realpath "$1")
shot=${2:-$dir/page.png}
chromium=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$chromium" ]; then
  echo "SKIP: Chromium is not installed (Debian's chromium); the study page was not checked in a browser"
  exit 77
fi
[ -f "$dir/index.html" ] || { echo "FAIL: $dir/index.html does not exist"; exit 1; }
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
flags=(--headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking
       --disable-component-update --disable-sync --disable-extensions --user-data-dir="$profile"
       --virtual-time-budget=10000)
url="file://$dir/index.html"
if ! dom=$(timeout 120 "$chromium" "${flags[@]}" --dump-dom "$url" 2>"$profile/stderr"); then
  echo "FAIL: Chromium could not load $url:"; cat "$profile/stderr"; exit 1
fi
expected=$(grep -o '<img ' "$dir/index.html" | wc -l)
state=$(printf '%s' "$dom" | grep -o 'data-images="[0-9]*/[0-9]*"' | head -1 | tr -dc '0-9/')
if [ -z "$state" ]; then
  echo "FAIL: the page's load script did not run (no data-images on <body>): the page did not finish loading"; exit 1
fi
ok=${state%/*}; total=${state#*/}
echo "Chromium loaded $url: $ok of $total images loaded; index.html has $expected <img> elements"
if [ "$total" -ne "$expected" ] || [ "$ok" -ne "$total" ] || [ "$total" -lt 6 ]; then
  echo "FAIL: images missing or broken on the page"; exit 1
fi
timeout 120 "$chromium" "${flags[@]}" --hide-scrollbars --window-size=1400,2400 --screenshot="$shot" "$url" \
  2>"$profile/stderr" >/dev/null || { echo "FAIL: no screenshot:"; cat "$profile/stderr"; exit 1; }
[ -s "$shot" ] || { echo "FAIL: the screenshot $shot is empty"; exit 1; }
echo "screenshot: $shot"
