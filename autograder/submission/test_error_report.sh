#!/usr/bin/env bash
# ctest submission:error-report: when pt-grade submission meets an error it
# did not foresee once it has started (here a --work folder it cannot make:
# a path under a regular file), it still writes a complete report that says
# what failed, exits 2, and leaves nothing behind. Before, the exception left
# results.json at "not graded yet" and "complete": false.
# Usage: test_error_report.sh PT_GRADE KIT CHECKOUT WORKDIR
set -uo pipefail
pt_grade=$1 kit=$2 source=$3 work=$4
rm -rf "$work" && mkdir -p "$work/out" || exit 2
touch "$work/not-a-folder"
"$pt_grade" submission "$source/tasks" --kit "$kit" --json "$work/out/results.json" \
  --work "$work/not-a-folder/work" --no-renders > "$work/grade.log" 2>&1
status=$?
failed=0
check() {  # check WHAT COMMAND...: prints WHAT when COMMAND fails
  local what=$1
  shift
  if ! "$@"; then echo "FAILED: $what"; failed=1; fi
}
check "exit status 2 (it was $status)" test "$status" -eq 2
check "results.json says it is complete" grep -q '"complete": true' "$work/out/results.json"
check "results.json says what failed" grep -q 'the grader failed (an instructor must look): cannot use' "$work/out/results.json"
check "nothing left beside the report" test "$(ls "$work/out")" = results.json
[ $failed -eq 0 ] && echo "a complete report that names the error"
exit $failed
