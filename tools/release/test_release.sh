#!/usr/bin/env bash
# The student release, tested as a student meets it (ctest: release:build):
#  1. unpack student-release.tar.gz into an empty folder;
#  2. check it holds no solution (pt-release-check);
#  3. run the set-up commands of its own README.md, exactly as written;
#  4. the untouched stubs grade 0, every graded test failing with the name of
#     its task (pt-grade check-stubs, per part); check-submission says so
#     first, each part "not started", its failures folded into one line;
#  5. with the reference's task files copied in as a student's: the commands
#     of the README's "Working on a part" (build, tests, score, render, the
#     solution standing in, the comparison with its relMSE bound) and "Before
#     you submit", exactly as written; every visible point (pt-grade run --json,
#     expect_score.cmake), and check-submission says READY with each part's
#     hidden points listed as not run, with what the .gitignore ignores
#     (node_modules/ of `npm ci`, a render) left in the tree; every document
#     of the release names only paths, build outputs, targets and tests that
#     exist in it (tests/docs/check_docs.sh, as the checkout's documents);
#  6. check-submission on what the grader would refuse: a task file with a
#     Boost header (the grader's rejection message), an edited and an added
#     framework file (each named), both NOT READY.
# Usage: test_release.sh ARCHIVE CHECKOUT RELEASE_CHECK MANIFEST WORKDIR
set -euo pipefail
archive=$1 source=$2 release_check=$3 manifest=$4 work=$5
here=$(cd "$(dirname "$0")" && pwd)
seconds() { date +%s; }
t0=$(seconds)

rm -rf "$work"
mkdir -p "$work"
tar xzf "$archive" -C "$work"
cd "$work/student-release"

echo "== 2. no solution in the release"
"$release_check" --release . --source "$source" --manifest "$manifest"

. "$here/readme_commands.sh"

echo "== 3. the README's set-up commands"
# PT_CCACHE_DIR (set by ctest when the instructor's build uses ccache): the
# release's build, configured from its own files, compiles through the same
# cache, so the files it shares with the instructor's tree are not compiled twice.
[ -n "${PT_CCACHE_DIR:-}" ] && CCACHE_DIR=$PT_CCACHE_DIR ccache -z > /dev/null
run_section "Set up (Debian 12 or Ubuntu 22.04+)"
echo "first build and test of the release: $(( $(seconds) - t0 )) s"
[ -n "${PT_CCACHE_DIR:-}" ] && { echo "compiler cache:"; CCACHE_DIR=$PT_CCACHE_DIR ccache -s; }

grade=./build/autograder/pt-grade
echo "== 4. the stubs grade 0, naming their tasks"
for n in 1 2 3 4 5; do
  "$grade" check-stubs --part "$n" "build/tests/part${n}_tests"
done

echo "== 4b. check-submission on the stubs leads with the answer, their failures folded"
"$grade" check-submission > stubs-check.out 2> /dev/null || { cat stubs-check.out; echo "check-submission on the stubs: not READY"; exit 1; }
head -n 12 stubs-check.out | grep -q '^READY' || { cat stubs-check.out; echo "the answer is not in the first 12 lines"; exit 1; }
for n in 1 2 3 4 5; do
  grep -Eq "^$n +not started +0 / [0-9.]+ +\+ hidden: [0-9]+ tests, [0-9.]+ points? not run here" stubs-check.out &&
    grep -Eq "^  part $n: not started: its [0-9]+ visible tests fail" stubs-check.out ||
    { cat stubs-check.out; echo "part $n: not answered as not started, or its failures not folded into one line"; exit 1; }
done
! grep -q '^Failed graded tests' stubs-check.out || { cat stubs-check.out; echo "an untouched part's failures listed one by one"; exit 1; }

echo "== 5. the reference's task files, with the README's commands"
cp "$source"/reference/part*.cpp tasks/
run_section "Working on a part"
"$grade" run --json reference-results.json
cmake -DRESULTS=reference-results.json -P "$here/expect_score.cmake"
# What the release's own instructions leave in its tree (the viewer test's
# `npm ci`, a render saved beside a test) is no framework file added.
mkdir -p tests/viewer/browser/node_modules/puppeteer-core
echo '{"name": "puppeteer-core"}' > tests/viewer/browser/node_modules/puppeteer-core/package.json
touch tests/part1/mine.png
run_section "Before you submit" | tee check.out
rm -rf tests/viewer/browser/node_modules tests/part1/mine.png
grep -q '^READY' check.out || { echo "check-submission did not say READY"; exit 1; }
for n in 1 2 3 4 5; do
  grep -Eq "^$n +yours +([0-9.]+) / \\1 +\\+ hidden: [0-9]+ tests, [0-9.]+ points? not run here" check.out &&
    grep -Eq "^$n +([0-9]+) / \\1 +([0-9.]+) / \\2 .*hidden: [0-9]+ tests, [0-9.]+ points? not run here" check.out ||
    { echo "part $n: not yours with every visible point, or its hidden points not listed as not run"; exit 1; }
done

echo "== 5b. the release's documents name only what exists in it, as the checkout's do"
cmake --build --preset default --target library-scenes pt-bvh-boxes-reference > /dev/null  # scenes/ and tools/bench/README.md say to
mapfile -t docs < <(find . -name '*.md' -not -path './build/*' -not -path '*/node_modules/*' | sed 's|^\./||' | sort)
"$source/tests/docs/check_docs.sh" "$PWD" "$PWD/build" "${docs[@]}"

echo "== 6. check-submission on what the grader refuses"
expect_not_ready() {  # expect_not_ready WHAT REGEX...: check-submission exits 1 and prints each REGEX
  local what=$1; shift
  if "$grade" check-submission > "$what.out" 2>&1; then cat "$what.out"; echo "$what: check-submission said ready"; exit 1; fi
  for re in "$@"; do
    grep -Eq -- "$re" "$what.out" || { cat "$what.out"; echo "$what: no line matches: $re"; exit 1; }
  done
  echo "$what: NOT READY, as the grader would have it"
}
part5=$(ls tasks/part5_*.cpp)
cp "$part5" part5.saved
{ echo '#include <boost/math/special_functions/gamma.hpp>'; cat part5.saved; } > "$part5"
# No header of its own on the task file's path (a fatal error), or the system's
# (the compiler's list of the files it read names it): either way, step 4.
expect_not_ready boost_header "boost/math/special_functions/gamma\.hpp" "^NOT READY" \
                 "part 5: (does not build|reads files the grader refuses) \(step 4\)"
cp part5.saved "$part5"
cp skeleton/README.md skeleton.saved
echo "a student's note" >> skeleton/README.md
printf 'inline int my_helper() { return 1; }\n' > skeleton/core/my_helpers.h
expect_not_ready edited_skeleton "skeleton/README.md: edited" "skeleton/core/my_helpers.h: added" "^NOT READY"
cp skeleton.saved skeleton/README.md
rm skeleton/core/my_helpers.h
echo "release OK ($(( $(seconds) - t0 )) s)"
