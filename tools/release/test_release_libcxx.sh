#!/usr/bin/env bash
# The student release as a Mac builds it, on Linux (ctest: release:libcxx):
# clang with libc++ (macOS's standard library), only the third-party code the
# release ships (third_party/, the system's packages ignored), and no sandbox
# (-DPT_SANDBOX=OFF, as off Linux: pt-grade with check-submission only):
#  1. unpack student-release.tar.gz into an empty folder;
#  2. configure with CXX=clang++ CXXFLAGS=-stdlib=libc++ -DPT_SYSTEM_DEPS=OFF
#     -DPT_SANDBOX=OFF: every shipped copy in use, the prebuilt solution for
#     linux-<arch>-libc++ found, the sandbox's absence said;
#  3. the README's second set-up command (build everything, every release
#     test passes); no object read a third-party header from the system
#     (ninja's record of the headers each compile read), and no binary links
#     GCC's libstdc++; pt-grade built, without pt-link-guard, verifiers or
#     workers; no compile read a header only Linux has, no object calls what
#     only Linux's C library has (check_portable.sh); the commands that grade
#     refuse, naming where to run them;
#  4. the untouched stubs fail every visible graded test naming its task
#     (check-stubs of the checkout's own pt-grade, per part); the release's
#     pt-grade check-submission on them: what it could not check said first,
#     then per step, READY as far as it goes, every part not started; and on a
#     folder with a file the grader refuses: NOT READY, nothing built;
#  5. the reference's task files as a student's: check-submission says READY
#     with every visible point of every part (its tests run unconfined);
#  6. the same tree with no libraries for its platform (the libc++ folder
#     taken away): configure warns, part 2's tests and pathtracer build and
#     link, every part is the student's, said at start; with part 2 done, its
#     tests run, and those that need the compiled test support fail saying why.
# Usage: test_release_libcxx.sh ARCHIVE CHECKOUT PT_GRADE WORKDIR
set -euo pipefail
archive=$1 source=$2 grade=$3 work=$4
here=$(cd "$(dirname "$0")" && pwd)
seconds() { date +%s; }
t0=$(seconds)

rm -rf "$work"
mkdir -p "$work"
tar xzf "$archive" -C "$work"
cd "$work/student-release"
export CXX=clang++ CXXFLAGS=-stdlib=libc++

echo "== 2. configure with clang and libc++, the system's third-party packages ignored, no sandbox"
cmake --preset default -DPT_SYSTEM_DEPS=OFF -DPT_SANDBOX=OFF 2>&1 | tee configure.out
tr -s ' \n' ' ' < configure.out | grep -q "No sandbox in this build (it needs Linux): pt-grade check-submission" ||
  { echo "configure did not say the sandbox is left out"; exit 1; }
grep -q "Shipped third-party copies in use (third_party/): glm;nlohmann-json;CLI11;pcg;boost;tinyexr;tinyobjloader;stb;googletest" \
  configure.out || { echo "not every shipped copy is in use"; exit 1; }
platform="linux-$(uname -m | sed 's/aarch64/arm64/')-libc++"
[ -f "prebuilt/$platform/libpt_part1_reference.a" ] || { echo "the release has no prebuilt/$platform/"; exit 1; }
! grep -q "no prebuilt solution" configure.out || { echo "configure did not find prebuilt/$platform/"; exit 1; }

echo "== 3. the README's second command: build everything, run the release's tests"
[ -n "${PT_CCACHE_DIR:-}" ] && CCACHE_DIR=$PT_CCACHE_DIR ccache -z > /dev/null
t_build=$(seconds)
cmake --workflow --preset test
echo "build and tests with clang and libc++: $(( $(seconds) - t_build )) s"
[ -n "${PT_CCACHE_DIR:-}" ] && { echo "compiler cache:"; CCACHE_DIR=$PT_CCACHE_DIR ccache -s; }
# Every header a compile read (ninja's deps log): none of the third-party
# packages' from the system (the shipped copies come first on the include
# path, so a header missing from them would quietly be the system's).
ninja -C build -t deps > deps.out
if grep -E '^ +/usr/(local/)?include/(glm/|nlohmann/|CLI/|boost/|gtest/|stb/|tinyexr\.h|tiny_obj_loader\.h|pcg_)' deps.out |
   sort -u > system_headers.out && [ -s system_headers.out ]; then
  head system_headers.out; echo "a compile read a third-party header from the system"; exit 1
fi
grep -q "third_party/boost/include/boost/math/distributions/students_t.hpp" deps.out ||
  { echo "the shipped Boost.Math was not read"; exit 1; }
own=build/autograder/pt-grade  # the release's ($grade is the checkout's, with its sandbox)
[ -x "$own" ] || { echo "pt-grade was not built"; exit 1; }
for b in build/autograder/compile/pt-link-guard build/tests/part1_verify build/tests/part1_worker; do
  [ ! -e "$b" ] || { echo "$b was built without the sandbox"; exit 1; }
done
if ninja -C build -t targets all | grep -E '^(autograder/compile/pt-link-guard|tests/part[1-5]_(verify|worker)):'; then
  echo "a target of the grader's Linux part is defined without the sandbox"; exit 1
fi
"$here/check_portable.sh" build
for cmd in "run" "submission tasks" "check-stubs --part 1 build/tests/part1_tests" "sandbox"; do
  # shellcheck disable=SC2086  # the command's words
  if "$own" $cmd > refused.out 2>&1; then cat refused.out; echo "pt-grade $cmd ran without the sandbox"; exit 1; fi
  grep -q "grading needs Linux's sandbox, which this build does not have (PT_SANDBOX is off): run it on your course's grader, in WSL or in the dev container" refused.out ||
    { cat refused.out; echo "pt-grade $cmd did not say why it refuses"; exit 1; }
done
# ldd's list read from a file: `ldd | grep -q` under pipefail fails when grep
# stops reading first and ldd dies of SIGPIPE (seen: a binary that does link
# libc++ called "not linked").
for b in build/tests/part1_tests build/pathtracer; do
  ldd "$b" > ldd.out
  grep -q 'libc++\.so' ldd.out || { cat ldd.out; echo "$b: not linked with libc++"; exit 1; }
  ! grep -Eq 'libgtest|libtinyexr|libtinyobjloader|libstb' ldd.out || { cat ldd.out; echo "$b: links a system library"; exit 1; }
done
for n in 1 2 3 4 5; do
  ldd "build/tests/part${n}_tests" > ldd.out
  ! grep -q 'libstdc++' ldd.out || { echo "part${n}_tests links libstdc++"; exit 1; }
done

echo "== 4. the stubs fail every visible graded test, naming its task"
for n in 1 2 3 4 5; do
  # The checkout's pt-grade reads its own checkout's scenes: this tree's too.
  "$grade" check-stubs --sandbox-read "$PWD/scenes" --part "$n" "build/tests/part${n}_tests"
done

# What check-submission says first without the sandbox, and in steps 4 and 5.
expect_not_checked() {  # expect_not_checked FILE
  head -n 12 "$1" | grep -q '^Not checked on this platform (this pt-grade has no sandbox: it needs Linux); the grader checks each:' &&
    grep -q '^  - the sandbox: tests run here as plain processes' "$1" &&
    grep -q '^  - the process boundary: here each part' "$1" &&
    grep -q "^  - pt-link-guard: what your task file's compiled code defines and calls;" "$1" &&
    grep -q '^  - the hidden tests' "$1" ||
    { cat "$1"; echo "$1: check-submission did not say first what it could not check"; exit 1; }
}
echo "== 4b. check-submission without the sandbox: the stubs, then a file the grader refuses"
"$own" check-submission > stubs-check.out 2> /dev/null || { cat stubs-check.out; echo "check-submission on the stubs: not READY"; exit 1; }
expect_not_checked stubs-check.out
grep -q '^READY, as far as this platform can check:' stubs-check.out &&
  grep -q '^   not checked here: pt-link-guard (it needs Linux)' stubs-check.out &&
  grep -q '^   run here as plain processes, each part' stubs-check.out ||
  { cat stubs-check.out; echo "check-submission did not say how far its READY goes, or what steps 4 and 5 left out"; exit 1; }
for n in 1 2 3 4 5; do
  grep -Eq "^$n +not started +0 / [0-9.]+ +\+ hidden: [0-9]+ tests, [0-9.]+ points? not run here" stubs-check.out ||
    { cat stubs-check.out; echo "part $n: not answered as not started"; exit 1; }
done
mkdir -p refused && cp tasks/*.cpp refused/ && echo "notes" > refused/notes.txt
if "$own" check-submission refused > refused-check.out 2> /dev/null; then cat refused-check.out; echo "a refused folder was READY"; exit 1; fi
expect_not_checked refused-check.out
grep -q '^NOT READY: the grader would reject every part. Nothing was built.' refused-check.out ||
  { cat refused-check.out; echo "a refused folder was not NOT READY"; exit 1; }

echo "== 5. the reference's task files: check-submission says READY, every visible point"
cp tasks/part*.cpp "$work/"
cp "$source"/reference/part*.cpp tasks/
"$own" check-submission > reference-check.out 2> /dev/null || { cat reference-check.out; echo "the reference: not READY"; exit 1; }
expect_not_checked reference-check.out
grep -q '^READY, as far as this platform can check:' reference-check.out || { cat reference-check.out; echo "not READY"; exit 1; }
for n in 1 2 3 4 5; do
  grep -Eq "^$n +yours +([0-9.]+) / \1 +\+ hidden: [0-9]+ tests, [0-9.]+ points? not run here" reference-check.out ||
    { cat reference-check.out; echo "part $n: not every visible point"; exit 1; }
done
cp "$work"/part*.cpp tasks/

echo "== 6. no libraries for this platform: the student's own parts, said, never a link error"
mv "prebuilt/$platform" "$work/prebuilt-aside"
# (No pt-grade here: step 3 built it; this tree is about the libraries.)
cmake -S . -B build-none -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPT_SYSTEM_DEPS=OFF -DPT_SANDBOX=OFF -DPT_GRADER=OFF \
  > none-configure.out 2>&1 || { cat none-configure.out; exit 1; }
tr -s ' \n' ' ' < none-configure.out | grep -q "This release has no prebuilt solution for $platform" ||
  { cat none-configure.out; echo "configure did not warn"; exit 1; }
cmake --build build-none --target part2_tests pathtracer
./build-none/pathtracer scenes/cornell_spheres.json -s 1 -r 8 6 -f none.png > none-render.out 2>&1 || true
grep -q "from tasks/ (yours): 1, 2, 3, 4, 5; from the course's solution: none" none-render.out ||
  { cat none-render.out; echo "pathtracer did not say every part is the student's"; exit 1; }
# With part 2 done (the reference's file as the student's), its tests that
# compare with the compiled baseline fail saying why; the stubs of parts 1 and
# 3 to 5 stand where the solution would.
cp "$source"/reference/part2_*.cpp tasks/
cmake --build build-none --target part2_tests
./build-none/tests/part2_tests > none-tests.out 2>&1 && { echo "part 2's tests all passed without the compiled support"; exit 1; }
cp "$work"/part2_*.cpp tasks/
grep -q "note: this release has no prebuilt solution for $platform" none-tests.out &&
  grep -q "is part of the course's compiled test support (prebuilt/), which this release does not have for $platform" \
    none-tests.out && grep -Eq '^\[  PASSED  \] [1-9][0-9]* tests?\.$' none-tests.out ||
  { tail -40 none-tests.out; echo "part 2's tests did not run, or did not say why some cannot"; exit 1; }
grep -E '^\[  (PASSED|FAILED)  \] [0-9]+ tests?' none-tests.out
mv "$work/prebuilt-aside" "prebuilt/$platform"
echo "release with clang and libc++ OK ($(( $(seconds) - t0 )) s)"
