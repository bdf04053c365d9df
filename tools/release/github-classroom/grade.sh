#!/usr/bin/env bash
# GitHub Classroom's step (.github/workflows/classroom.yml, step "pathtracer"):
# installs the packages (./setup.sh --deps-only), builds the grader and the
# test manifest, runs `pt-grade check-submission --format github-classroom`
# on tasks/ and writes its result, base64, as the step's output `result`
# (to $GITHUB_OUTPUT), which the reporter step reads as PATHTRACER_RESULTS.
# It always writes a result and exits 0: a set-up that fails is a result with
# status "error" and the failed command's last lines, and the reporter then
# fails the run.
set -uo pipefail
cd "$(dirname "$0")/../.."
: "${GITHUB_OUTPUT:?GitHub Actions sets it: the file a step writes its outputs to}"
# The compiler cache the workflow keeps between runs (actions/cache, .ccache).
export PT_CCACHE_DIR=${PT_CCACHE_DIR:-$PWD/.ccache}
log=$(mktemp)
result=$(mktemp)

emit() {  # emit FILE: FILE's JSON as the step's output `result`
  echo "result=$(base64 -w0 < "$1")" >> "$GITHUB_OUTPUT"
}

# The message of an error result: a JSON string of the log's last lines,
# escaped by hand (nothing but bash and coreutils is sure to be there).
json_string() {
  local s
  s=$(tail -n 20 "$1" | LC_ALL=C tr -d '\000-\010\013-\037\177-\377')
  s=${s//\\/\\\\}
  s=${s//\"/\\\"}
  s=${s//$'\t'/ }
  s=${s//$'\n'/\\n}
  printf '"%s"' "$s"
}

stop() {  # stop WHAT: an "error" result naming the step that failed
  echo "::error::$1 failed (the lines above say why)"
  printf '{"version":1,"status":"error","max_score":0,"tests":[{"name":"Set-up: %s","status":"error","score":0,"message":%s,"test_code":"bash .github/classroom/grade.sh","filename":"","line_no":0,"duration":0}]}\n' \
    "$1" "$(json_string "$log")" > "$result"
  emit "$result"
  exit 0
}

run() {  # run WHAT COMMAND...: the command's output to the log and to the job's log
  echo "::group::$1"
  "${@:2}" 2>&1 | tee -a "$log"
  local rc=${PIPESTATUS[0]}
  echo "::endgroup::"
  [ "$rc" -eq 0 ] || stop "$1"
}

run "installing the packages" ./setup.sh --deps-only
run "configuring the build" cmake --preset default
run "building the grader" cmake --build --preset default --target pt-grade graded_manifest
# Exit status 1 (NOT READY) is a result like any other; only no result is an error.
./build/autograder/pt-grade check-submission --format github-classroom > "$result" 2> >(tee -a "$log" >&2)
rc=$?
if [ "$rc" -gt 1 ] && ! grep -q '"version":1' "$result"; then stop "pt-grade check-submission (exit status $rc)"; fi
grep -q '"version":1' "$result" || stop "pt-grade check-submission (no result)"
emit "$result"
