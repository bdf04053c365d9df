#!/usr/bin/env bash
# ctest docs:names-catches — check_docs.sh must fail on planted.md and name
# each of its six wrong names.
# Usage: check_docs_catches.sh SOURCE_DIR BUILD_DIR
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$("$here/check_docs.sh" "$1" "$2" tests/docs/planted.md)
status=$?
echo "$out"
[ "$status" -ne 0 ] || { echo "the check passed a document with wrong names"; exit 1; }
for expected in "names tools/no_such_tool.cpp, which does not exist" \
                "names handouts/part1.md:100000, but handouts/part1.md has" \
                "names ./build/no-such-binary, which the build does not make" \
                "names the build target no-such-target, which does not exist" \
                "names the preset no-such-preset, which does not exist" \
                "ctest -L no-such-label selects no test"; do
  grep -qF -- "$expected" <<< "$out" || { echo "not caught: $expected"; exit 1; }
done
echo "every planted name caught"
