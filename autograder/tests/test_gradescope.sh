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
bash "$PT_GRADESCOPE_ROOT/source/setup.sh"

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
