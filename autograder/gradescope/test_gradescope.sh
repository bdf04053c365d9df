#!/usr/bin/env bash
# Gradescope, simulated (ctest: gradescope:autograder): autograder.zip unpacked
# into a folder laid out like Gradescope's /autograder (PT_GRADESCOPE_ROOT),
# its setup.sh run once, then run_autograder on the reference's task files
# (every point) and on the untouched stubs (0, each test naming its task).
# Usage: test_gradescope.sh AUTOGRADER_ZIP CHECKOUT WORKDIR
set -euo pipefail
zip=$1 checkout=$2 work=$3
export PT_GRADESCOPE_ROOT="$work/autograder"
rm -rf "$work" && mkdir -p "$PT_GRADESCOPE_ROOT"/{source,submission,results}
cmake -E chdir "$PT_GRADESCOPE_ROOT/source" cmake -E tar xf "$zip"
# PT_CCACHE_DIR (set by ctest when the instructor's build uses ccache): the
# kit's build from the zip compiles through the same cache.
[ -n "${PT_CCACHE_DIR:-}" ] && CCACHE_DIR=$PT_CCACHE_DIR ccache -z > /dev/null
t0=$(date +%s)
bash "$PT_GRADESCOPE_ROOT/source/setup.sh"
echo "setup.sh: $(( $(date +%s) - t0 )) s"
[ -n "${PT_CCACHE_DIR:-}" ] && { echo "compiler cache:"; CCACHE_DIR=$PT_CCACHE_DIR ccache -s; }

grade() {  # grade LABEL FILES...: one submission through run_autograder
  local label=$1; shift
  rm -rf "$PT_GRADESCOPE_ROOT"/submission/* "$PT_GRADESCOPE_ROOT"/results/*
  cp "$@" "$PT_GRADESCOPE_ROOT/submission/"
  "$PT_GRADESCOPE_ROOT/source/run_autograder"
  [ -s "$PT_GRADESCOPE_ROOT/results/results.json" ] || { echo "$label: no results.json"; exit 1; }
  [ -s "$PT_GRADESCOPE_ROOT/results/report.html" ] || { echo "$label: no report.html"; exit 1; }
  cp "$PT_GRADESCOPE_ROOT/results/results.json" "$work/$label-results.json"
}
grade reference "$checkout"/reference/part*.cpp
cmake -DRESULTS="$work/reference-results.json" -P "$checkout/tools/release/expect_score.cmake"
grade stubs "$checkout"/tasks/part*.cpp
cmake -DRESULTS="$work/stubs-results.json" -P "$checkout/tools/release/expect_stubs.cmake"
echo "gradescope OK"
