#!/usr/bin/env bash
# Gradescope's Part 2 leaderboard (ctest submission:leaderboard;
# autograder/report/leaderboard.h): part 2 alone graded with `pt-grade submission`
# in the grading kit, as on Gradescope,
#  - the reference's task file with --leaderboard: three entries, each
#    "asc", its SAH cost 1 against the solution's (the same tree: 1 up to the
#    four digits kept), its work per ray plausible;
#  - the gallery's single_axis_midpoint mutant (a split without a cost model,
#    tests/mutants/part2.cmake) with --leaderboard: a worse SAH cost and more
#    primitive tests per ray;
#  - the reference's file without --leaderboard: no "leaderboard" key;
#  - the stubs with --leaderboard: no key either (nothing was measured).
# Usage: test_leaderboard.sh PT_GRADE KIT CHECKOUT MUTANT_FILE WORKDIR
set -euo pipefail
grade=$1 kit=$2 source=$3 mutant=$4 work=$5
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
submit() {  # submit NAME TASK_FILE [OPTION]: results.json of part 2 alone in $work/NAME/
  local dir=$work/$1
  mkdir -p "$dir/submission"
  cp "$2" "$dir/submission/part2_bvh.cpp"
  "$grade" submission "$dir/submission" --kit "$kit" --json "$dir/results.json" --no-renders "${@:3}" \
    > "$dir/out.txt" 2>&1 || { cat "$dir/out.txt"; echo "$1: pt-grade submission failed"; exit 1; }
  echo "$1: graded"
}
submit reference "$source/reference/part2_bvh.cpp" --leaderboard
submit mutant "$mutant" --leaderboard
submit plain "$source/reference/part2_bvh.cpp"
submit stubs "$source/tasks/part2_bvh.cpp" --leaderboard
cmake -DWORK="$work" -P "$here/check_leaderboard.cmake"
