#!/usr/bin/env bash
# ctest docs:self-contained-catches — check_self_contained.sh must fail on
# planted_outside_refs.md and name each of its five citations (one broken across two lines).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$("$here/check_self_contained.sh" "$1" tests/docs/planted_outside_refs.md)
status=$?
echo "$out"
[ "$status" -ne 0 ] || { echo "the check passed a file that cites outside documents"; exit 1; }
for line in 4 5 6 7 8; do
  grep -q "^tests/docs/planted_outside_refs.md:$line: " <<< "$out" || { echo "line $line not caught"; exit 1; }
done
echo "every planted citation caught"
