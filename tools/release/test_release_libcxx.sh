#!/usr/bin/env bash
# The student release as a Mac builds it, on Linux (ctest: release:libcxx):
# clang with libc++ (macOS's standard library), only the third-party code the
# release ships (third_party/, the system's packages ignored), and no grader
# (-DPT_GRADER=OFF, as off Linux):
#  1. unpack student-release.tar.gz into an empty folder;
#  2. configure with CXX=clang++ CXXFLAGS=-stdlib=libc++ -DPT_SYSTEM_DEPS=OFF
#     -DPT_GRADER=OFF: every shipped copy in use, the prebuilt solution for
#     linux-<arch>-libc++ found, the grader's absence said;
#  3. the README's second set-up command (build everything, every release
#     test passes); no object read a third-party header from the system
#     (ninja's record of the headers each compile read), and no binary links
#     GCC's libstdc++;
#  4. the untouched stubs fail every visible graded test naming its task
#     (check-stubs of the checkout's own pt-grade, per part);
#  5. the reference's task files as a student's: every partN_tests passes;
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

echo "== 2. configure with clang and libc++, the system's third-party packages ignored, no grader"
cmake --preset default -DPT_SYSTEM_DEPS=OFF -DPT_GRADER=OFF 2>&1 | tee configure.out
tr -s ' \n' ' ' < configure.out | grep -q "No grader in this build (it needs Linux)" ||
  { echo "configure did not say the grader is left out"; exit 1; }
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
[ ! -e build/autograder/pt-grade ] || { echo "the grader was built"; exit 1; }
for b in build/tests/part1_tests build/pathtracer; do
  ldd "$b" | grep -q 'libc++\.so' || { ldd "$b"; echo "$b: not linked with libc++"; exit 1; }
  ! ldd "$b" | grep -Eq 'libgtest|libtinyexr|libtinyobjloader|libstb' || { ldd "$b"; echo "$b: links a system library"; exit 1; }
done
for n in 1 2 3 4 5; do
  ! ldd "build/tests/part${n}_tests" | grep -q 'libstdc++' || { echo "part${n}_tests links libstdc++"; exit 1; }
done

echo "== 4. the stubs fail every visible graded test, naming its task"
for n in 1 2 3 4 5; do
  # The checkout's pt-grade reads its own checkout's scenes: this tree's too.
  "$grade" check-stubs --sandbox-read "$PWD/scenes" --part "$n" "build/tests/part${n}_tests"
done

echo "== 5. the reference's task files: every visible graded test passes"
cp tasks/part*.cpp "$work/"
cp "$source"/reference/part*.cpp tasks/
cmake --build --preset default
for n in 1 2 3 4 5; do
  "build/tests/part${n}_tests" > "reference-part$n.out" 2>&1 || { tail -30 "reference-part$n.out"; echo "part $n: a test failed"; exit 1; }
  grep -E '^\[  PASSED  \] [0-9]+ tests?\.$' "reference-part$n.out"
done
cp "$work"/part*.cpp tasks/

echo "== 6. no libraries for this platform: the student's own parts, said, never a link error"
mv "prebuilt/$platform" "$work/prebuilt-aside"
cmake -S . -B build-none -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPT_SYSTEM_DEPS=OFF -DPT_GRADER=OFF \
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
