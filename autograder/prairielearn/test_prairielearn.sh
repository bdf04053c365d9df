#!/usr/bin/env bash
# PrairieLearn, simulated (ctest: prairielearn:grader). The export's image
# definition is checked as text (no Docker here: pt-prairielearn-check image),
# then its entry point runs in folders laid out like PrairieLearn's /grade,
# with this build's grading kit, on
#   reference  the reference's task files: score 1, every test passed, renders
#   stubs      the untouched stubs: score 0, gradable, each test naming its task
#   hostile    autograder/hostile/huge_messages (part 1 throws 150 KB of JSON per
#              test) beside the reference's part 5: the text at its bounds and
#              the renders together, still complete and within 1 MB
#   missing    no student folder: not gradable
# and pt-prairielearn-check checks each results.json field by field.
# Usage: test_prairielearn.sh EXPORT KIT CHECKOUT HOSTILE_TASKS CHECKER WORKDIR
set -euo pipefail
export=$1 kit=$2 checkout=$3 hostile=$4 check=$5 work=$6
"$check" image "$export" --from debian:bookworm
entry="$export/pathtracer/autograder/prairielearn/run_prairielearn"
rm -rf "$work" && mkdir -p "$work"

grade() {  # grade LABEL [FILES...]: one grading job in a fresh /grade; no FILES, no student folder
  local label=$1; shift
  local root="$work/$label/grade"
  mkdir -p "$root"/{tests,serverFilesCourse,data}
  echo '{"params": {}, "correct_answers": {}, "submitted_answers": {}, "format_errors": {}}' > "$root/data/data.json"
  if [ $# -gt 0 ]; then mkdir "$root/student" && cp "$@" "$root/student/"; fi
  local t0=$SECONDS
  PT_GRADER_KIT=$kit "$entry" "$root" > "$work/$label/stdout.txt" 2>&1
  echo "$label: graded in $(( SECONDS - t0 )) s"
}
results() { echo "$work/$1/grade/results/results.json"; }

grade reference "$checkout"/reference/part*.cpp
"$check" results "$(results reference)" --manifest "$kit/manifest.json" --passed 1,2,3,4,5 --images
grade stubs "$checkout"/tasks/part*.cpp
"$check" results "$(results stubs)" --manifest "$kit/manifest.json" --not-implemented 1,2,3,4,5
grade hostile "$hostile"/part1_*.cpp "$checkout"/reference/part5_*.cpp
"$check" results "$(results hostile)" --manifest "$kit/manifest.json" --not-implemented 1 --passed 5 --images
grade missing
"$check" results "$(results missing)" --manifest "$kit/manifest.json" --ungradable
echo "prairielearn OK"
