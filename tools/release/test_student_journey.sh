#!/usr/bin/env bash
# A student's whole loop in the release (ctest release:student-journey), in
# the tree release:build unpacked and set up (a second release would cost a
# second first build):
#  1. `npm ci` for the viewer's browser test, as tests/viewer/README.md says,
#     from npm's cache only (skipped, saying so, when it cannot be: offline
#     with an empty cache, or no npm);
#  2. the solution of every part as the student's own files, the TODO(PnTm)
#     comments of the finished tasks removed, as a student leaves them;
#  3. the README's set-up commands again: every release test passes;
#  4. "Before you submit": READY, every part yours.
# Usage: test_student_journey.sh RELEASE_DIR CHECKOUT
set -euo pipefail
release=$1 source=$2
here=$(cd "$(dirname "$0")" && pwd)
t0=$(date +%s)
[ -f "$release/README.md" ] || { echo "no release at $release: release:build unpacks and sets it up"; exit 1; }
cd "$release"
. "$here/readme_commands.sh"

echo "== 1. npm ci (tests/viewer/README.md)"
if ! command -v npm > /dev/null; then
  echo "SKIPPED npm ci: npm is not installed (viewer:browser skips, saying so)"
elif (cd tests/viewer/browser && npm ci --offline --no-audit --no-fund > npm.log 2>&1); then
  echo "npm ci: done"
else
  echo "SKIPPED npm ci: not possible offline (npm's cache lacks puppeteer-core; .ci/run fills it):"
  tail -n 3 tests/viewer/browser/npm.log || true
fi
rm -f tests/viewer/browser/npm.log

echo "== 2. every part's solution as the student's, TODO comments removed"
for f in tasks/part*_*.cpp; do
  sed '/TODO(P[0-9]*T[0-9]*)/d' "$source/reference/$(basename "$f")" > "$f"
done
! grep -n 'TODO(P' tasks/*.cpp || { echo "a TODO tag is left"; exit 1; }

echo "== 3. the README's set-up commands: every release test passes"
run_section "Set up (Debian 12 or Ubuntu 22.04+)" 2>&1 | tee setup.out
grep -q '100% tests passed' setup.out || { echo "not every release test passed"; exit 1; }

echo "== 4. the README's check before submitting: READY, every part yours"
run_section "Before you submit" > check.out 2> /dev/null || { cat check.out; echo "check-submission: not READY"; exit 1; }
cat check.out
for n in 1 2 3 4 5; do
  grep -Eq "^$n +yours " check.out || { echo "part $n is not answered as yours"; exit 1; }
done
grep -q '^READY' check.out || { echo "check-submission did not say READY"; exit 1; }
echo "student journey OK ($(( $(date +%s) - t0 )) s)"
