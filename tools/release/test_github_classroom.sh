#!/usr/bin/env bash
# The student release as a GitHub Classroom template repository (ctest
# release:github-classroom), in the tree release:build unpacked and built (a
# fixture: the runner's checkout is that tree, its build/ standing in for a
# first build; building the release again would cost a third build):
#  1. the workflow and its script are where GitHub looks for them
#     (.github/workflows/classroom.yml) and as the checkout has them;
#  2. every `run:` line of the workflow, run as the runner runs it (bash -eo
#     pipefail, in $GITHUB_WORKSPACE, with GITHUB_OUTPUT and CI set), for the
#     stubs and then for the reference's task files; the step output `result`
#     decoded from base64 and checked field by field (check_result.cmake): per
#     task its visible points, each part's hidden tests named as not run,
#     max_score the visible points, the stubs "fail" at 0 and the reference
#     "pass" with every visible point;
#  3. a set-up that fails (cmake missing) still gives a result: "error",
#     naming the step.
# The tree's tasks/ is left as it was found.
# Usage: test_github_classroom.sh RELEASE_DIR CHECKOUT
set -euo pipefail
release=$1 source=$2
here=$(cd "$(dirname "$0")" && pwd)
t0=$(date +%s)
[ -x "$release/build/autograder/pt-grade" ] || { echo "no built release at $release: release:build makes it"; exit 1; }
cd "$release"
work=$(mktemp -d)
cp -a tasks "$work/tasks.saved"
trap 'rm -rf tasks && cp -a "$work/tasks.saved" tasks && rm -rf "$work"' EXIT

echo "== 1. the workflow where GitHub looks for it"
workflow=.github/workflows/classroom.yml
cmp "$workflow" "$source/tools/release/github-classroom/classroom.yml"
cmp .github/classroom/grade.sh "$source/tools/release/github-classroom/grade.sh"
mapfile -t runs < <(sed -n 's/^ *run: *//p' "$workflow")
[ ${#runs[@]} -gt 0 ] || { echo "$workflow has no run: line"; exit 1; }
printf 'run: %s\n' "${runs[@]}"

# run_workflow OUT: every run: line as a step of the runner, then the step
# output `result` decoded into OUT.
run_workflow() {
  local out=$1 outputs=$work/github_output
  : > "$outputs"
  for cmd in "${runs[@]}"; do
    echo "\$ $cmd"
    env GITHUB_OUTPUT="$outputs" GITHUB_WORKSPACE="$PWD" GITHUB_ACTIONS=true CI=true \
      bash --noprofile --norc -eo pipefail -c "$cmd" > "$work/step.log" 2>&1 || { tail -n 40 "$work/step.log"; echo "the step failed"; exit 1; }
  done
  [ "$(grep -c '^result=' "$outputs")" -eq 1 ] || { cat "$outputs"; echo "not one output named result"; exit 1; }
  local encoded
  encoded=$(sed -n 's/^result=//p' "$outputs")
  # The reporter reads it from an environment variable: Linux takes at most 128 KiB in one.
  [ ${#encoded} -lt 131072 ] || { echo "result: ${#encoded} bytes of base64, too long for an environment variable"; exit 1; }
  base64 -d <<< "$encoded" > "$out" || { echo "result is not base64"; exit 1; }
  echo "result: ${#encoded} bytes of base64, $(wc -c < "$out") of JSON"
}

echo "== 2a. the stubs"
cp "$source"/tasks/part*.cpp tasks/
run_workflow "$work/stubs.json"
cmake -DRESULT="$work/stubs.json" -DMANIFEST=build/tests/graded_manifest.json -DFACTS=prebuilt/release.json \
      -DTREE="$PWD" -DEXPECT=stubs -P "$here/github-classroom/check_result.cmake"

echo "== 2b. the reference's task files"
cp "$source"/reference/part*.cpp tasks/
run_workflow "$work/reference.json"
cmake -DRESULT="$work/reference.json" -DMANIFEST=build/tests/graded_manifest.json -DFACTS=prebuilt/release.json \
      -DTREE="$PWD" -DEXPECT=reference -P "$here/github-classroom/check_result.cmake"
echo "one decoded result (the reference's), its first entries:"
head -c 1200 "$work/reference.json"; echo

echo "== 3. a set-up that fails still reports"
mkdir "$work/bin"
printf '#!/bin/sh\necho "cmake: not here" >&2\nexit 127\n' > "$work/bin/cmake"
chmod +x "$work/bin/cmake"
PATH="$work/bin:$PATH" run_workflow "$work/error.json"
grep -q '"status":"error"' "$work/error.json" && grep -q '"name":"Set-up: configuring the build"' "$work/error.json" &&
  grep -q 'cmake: not here' "$work/error.json" ||
  { cat "$work/error.json"; echo "a failed set-up did not give an error result naming its step and why"; exit 1; }
echo "github classroom OK ($(( $(date +%s) - t0 )) s)"
