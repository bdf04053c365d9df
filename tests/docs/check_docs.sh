#!/usr/bin/env bash
# ctest docs:names — every document's commands name things that exist: each
# repository path in backticks or a code block (and its line, for path:N),
# each ./build/ file (checked after the build), each --target, --preset, and
# each ctest -L label / -R pattern (at least one test). Commands too long to
# run in CI (a full study, the reference images) are still checked this way;
# the README's set-up commands are what CI itself runs.
# A path may be relative to the checkout or to the document's folder.
# Usage: check_docs.sh SOURCE_DIR BUILD_DIR FILE...   (files relative to SOURCE_DIR)
set -uo pipefail
src=$1 build=$2; shift 2
failures=0
fail() { echo "$1: $2"; failures=$((failures + 1)); }

# Read-only queries of the build: nothing here may rebuild or reconfigure.
targets=$(ninja -C "$build" -t targets all 2>/dev/null | sed -n 's/^\([^ :]*\): .*/\1/p')
# "name": or "name" : (CMake's own JSON writer, as in the release's copy)
presets=$(grep -o '"name" *: *"[^"]*"' "$src/CMakePresets.json" | sed 's/.*"\([^"]*\)"$/\1/')

for doc in "$@"; do
  [ -f "$src/$doc" ] || { fail "$doc" "no such document"; continue; }
  # Code: inline spans and fenced blocks, one token per line.
  # A fence marked ```text holds output, not names to check.
  code=$(awk '/^```text/{skip=1; f=1; next} /^```/{f=!f; skip=0; next} f{if (!skip) print; next} {while (match($0, /`[^`]+`/)) {print substr($0, RSTART+1, RLENGTH-2); $0=substr($0, RSTART+RLENGTH)}}' "$src/$doc")
  tokens=$(printf '%s\n' "$code" | tr -s ' \t"(),;=' '\n')
  while IFS= read -r t; do
    t=${t%.}; t=${t%:}
    case "$t" in
      *N*/*|*partN*|*PnTm*|*'<'*|*'*'*|*'…'*|*'{'*|*'$'*|*'...'*) continue ;;
    esac
    case "$t" in
      ./build/*|build/*)
        p=${t#./}; p=${p#build/}
        [ -e "$build/$p" ] || fail "$doc" "names $t, which the build does not make" ;;
      skeleton/*|tasks/*|reference/*|tests/*|autograder/*|tools/*|scenes/*|handouts/*|docs/*)
        path=${t%%:*} line=""
        [[ "$t" =~ :([0-9]+)$ ]] && line=${BASH_REMATCH[1]}
        if [ ! -e "$src/$path" ] && [ -e "$src/${doc%/*}/$path" ]; then
          path="${doc%/*}/$path"  # relative to the document's own folder
        fi
        if [ ! -e "$src/$path" ]; then
          fail "$doc" "names $path, which does not exist"
        elif [ -n "$line" ] && [ "$(wc -l < "$src/$path")" -lt "$line" ]; then
          fail "$doc" "names $t, but $path has $(wc -l < "$src/$path") lines"
        fi ;;
    esac
  done <<< "$tokens"
  # Targets, presets and ctest selections, from the code lines that have any.
  while IFS= read -r line; do
    [ -n "$line" ] || continue
    for t in $(grep -o -- '--target [A-Za-z0-9_.-]*' <<< "$line" | cut -d' ' -f2); do
      grep -qx -- "$t" <<< "$targets" || fail "$doc" "names the build target $t, which does not exist"
    done
    for p in $(grep -o -- '--preset [A-Za-z0-9_-]*' <<< "$line" | cut -d' ' -f2); do
      grep -qx -- "$p" <<< "$presets" || fail "$doc" "names the preset $p, which does not exist"
    done
    if [[ "$line" == *ctest* ]]; then
      for sel in $(grep -oE -- '-(L|R) [A-Za-z0-9_:.-]+' <<< "$line" | tr ' ' '='); do
        flag=${sel%%=*} value=${sel#*=}
        n=$(ctest --test-dir "$build" -N "$flag" "$value" 2>/dev/null | sed -n 's/^Total Tests: //p')
        [ "${n:-0}" -gt 0 ] || fail "$doc" "ctest $flag $value selects no test"
      done
    fi
  done < <(grep -E -- '--target |--preset |ctest' <<< "$code")
done
if [ "$failures" -gt 0 ]; then
  echo "FAILED: $failures name(s) in the documents do not exist"
  exit 1
fi
echo "every path, build output, target, preset and test selection the documents name exists ($# documents)"
