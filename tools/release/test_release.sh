#!/usr/bin/env bash
# The student release, tested as a student meets it (ctest: release:build):
#  1. unpack student-release.tar.gz into an empty folder;
#  2. check it holds no solution (pt-release-check);
#  3. run the set-up commands of its own README.md, exactly as written;
#  4. the untouched stubs grade 0, every graded test failing with the name of
#     its task (pt-grade check-stubs, per part);
#  5. the reference's task files, copied in as a student's, earn every visible
#     point (pt-grade run --json, then expect_score.cmake).
# Usage: test_release.sh ARCHIVE CHECKOUT RELEASE_CHECK MANIFEST WORKDIR
set -euo pipefail
archive=$1 source=$2 release_check=$3 manifest=$4 work=$5
here=$(cd "$(dirname "$0")" && pwd)

rm -rf "$work"
mkdir -p "$work"
tar xzf "$archive" -C "$work"
cd "$work/student-release"

echo "== 2. no solution in the release"
"$release_check" --release . --source "$source" --manifest "$manifest"

echo "== 3. the README's set-up commands"
# The fenced block under '## Set up': each line that is a command (comments off).
setup=$(awk '/^## Set up/{s=1} s&&/^```sh/{b=1;next} b&&/^```/{exit} b{print}' README.md | sed 's/[[:space:]]*#.*$//' | sed '/^[[:space:]]*$/d')
[ -n "$setup" ] || { echo "README.md has no '## Set up' block"; exit 1; }
while IFS= read -r cmd; do
  echo "\$ $cmd"
  bash -c "$cmd"
done <<< "$setup"

grade=./build/autograder/pt-grade
echo "== 4. the stubs grade 0, naming their tasks"
for n in 1 2 3 4 5; do
  "$grade" check-stubs --part "$n" "build/tests/part${n}_tests"
done

echo "== 5. the reference's task files earn every visible point"
cp "$source"/reference/part*.cpp tasks/
cmake --build --preset default
"$grade" run --json reference-results.json
cmake -DRESULTS=reference-results.json -P "$here/expect_score.cmake"
echo "release OK"
