#!/usr/bin/env bash
# The GitHub Classroom workflow is valid (ctest release:classroom-workflow):
# check_workflow.py (Debian has no actionlint) on the release's
# .github/workflows/classroom.yml, then on copies with one fault planted each,
# every one of which it must refuse. Skips (77) without python3's yaml module
# (Debian: python3-yaml).
# Usage: test_classroom_workflow.sh RELEASE_DIR
set -euo pipefail
release=$1
here=$(cd "$(dirname "$0")" && pwd)
check=$here/github-classroom/check_workflow.py
python3 -c 'import yaml' 2> /dev/null || { echo "SKIPPED: no python3 with yaml (apt-get install python3-yaml)"; exit 77; }
workflow=$release/.github/workflows/classroom.yml
python3 "$check" "$workflow" "$release"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
planted() {  # planted WHAT SED-SCRIPT: the workflow with SED-SCRIPT applied must be refused
  sed "$2" "$workflow" > "$work/planted.yml"
  if cmp -s "$workflow" "$work/planted.yml"; then echo "$1: the edit changed nothing"; exit 1; fi
  if python3 "$check" "$work/planted.yml" "$release" > "$work/out" 2>&1; then
    cat "$work/out"; echo "$1: not refused"; exit 1
  fi
  echo "$1: refused: $(head -n 1 "$work/out")"
}
planted "no push event" '/^  - push$/d'
planted "no permission to write checks" 's/checks: write/checks: read/'
planted "reporter reads another step" 's/steps\.pathtracer\.outputs\.result/steps.tests.outputs.result/'
planted "runner without its _RESULTS" 's/PATHTRACER_RESULTS:/RESULTS:/'
planted "reporter reads another output" 's/outputs\.result/outputs.results/'
planted "runners name another id" 's/runners: pathtracer/runners: pathtracer,other/'
planted "step with both run and uses" 's|^        run: bash .github/classroom/grade.sh|        run: bash .github/classroom/grade.sh\n        uses: actions/checkout@v4|'
planted "script that is not there" 's|classroom/grade.sh|classroom/grades.sh|'
planted "unclosed expression" 's/\${{ steps\.pathtracer\.outputs\.result }}/${{ steps.pathtracer.outputs.result/'
planted "uses without a ref" 's|actions/checkout@v4|actions/checkout|'
planted "a key GitHub does not know" 's/^    timeout-minutes: \([0-9]*\)/    timeout: \1/'
planted "not YAML" 's/^jobs:/jobs: [/'
planted "no reporter" 's|classroom-resources/autograding-grading-reporter@v1|classroom-resources/autograding-command-grader@v1|'
echo "workflow OK"
