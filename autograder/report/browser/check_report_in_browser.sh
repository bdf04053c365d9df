#!/usr/bin/env bash
# Opens a report.html in headless Chromium and checks what the browser made of
# it (check_page.html: every image inlined and decoded, no script, every
# section there). Writes <workdir>/screenshot.png for a person to look at.
# Usage: check_report_in_browser.sh REPORT.html WORKDIR
# Exit status: 0 the page is whole, 1 it is not, 77 no Chromium (ctest: skipped).
set -euo pipefail
report=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
browser=$(command -v chromium || command -v chromium-browser || command -v google-chrome || true)
if [ -z "$browser" ]; then
  echo "SKIPPED: no Chromium on this machine (Debian: apt-get install chromium); the report was not opened in a browser"
  exit 77
fi
rm -rf "$work" && mkdir -p "$work"
cp "$report" "$work/report.html"
cp "$here/check_page.html" "$work/check_page.html"
# No network, no profile of the user's, no GPU; --no-sandbox because CI runs
# as root, where Chromium's own sandbox refuses to start.
flags=(--headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking
       --disable-component-update --disable-sync --disable-extensions --user-data-dir="$work/profile")
verdict=$(timeout 120 "$browser" "${flags[@]}" --allow-file-access-from-files --virtual-time-budget=20000 \
            --dump-dom "file://$work/check_page.html" 2> "$work/chromium.log" |
          sed -n 's/.*<pre id="verdict">\([^<]*\).*/\1/p')
timeout 120 "$browser" "${flags[@]}" --window-size=1200,3000 --screenshot="$work/screenshot.png" \
  "file://$work/report.html" >> "$work/chromium.log" 2>&1 || true
echo "${verdict:-FAIL: Chromium printed no verdict (see $work/chromium.log)}"
echo "screenshot: $work/screenshot.png"
case "$verdict" in OK:*) exit 0 ;; *) exit 1 ;; esac
