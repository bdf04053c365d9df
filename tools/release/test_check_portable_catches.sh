#!/usr/bin/env bash
# check_portable.sh can fail (ctest: release:portable-catches): a two-file
# project built with Ninja, first with a source that includes <sys/prctl.h>,
# then with one that calls pipe2() through <unistd.h>, then glibc's own
# sigabbrev_np() through <string.h>, each named; then with none, passed.
# Usage: test_check_portable_catches.sh WORKDIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$1
rm -rf "$work"
mkdir -p "$work/src"
cd "$work"
cat > src/CMakeLists.txt <<'CMAKE'
cmake_minimum_required(VERSION 3.22)
project(portable_fixture LANGUAGES CXX)
add_library(fixture OBJECT clean.cpp linux_header.cpp linux_call.cpp)
CMAKE
echo 'int clean() { return 0; }' > src/clean.cpp
printf '#include <sys/prctl.h>\nint header() { return PR_SET_NAME; }\n' > src/linux_header.cpp
printf '#include <unistd.h>\nint call(int* fds) { return pipe2(fds, 0); }\n' > src/linux_call.cpp
expect() {  # expect PASS|FAIL REGEX
  cmake --build build > build.out 2>&1 || { cat build.out; exit 1; }
  if "$here/check_portable.sh" build > check.out 2>&1; then result=PASS; else result=FAIL; fi
  [ "$result" = "$1" ] && grep -Eq -- "$2" check.out || { cat check.out; echo "expected $1 matching: $2"; exit 1; }
  echo "$1: $(tail -1 check.out)"
}
cmake -S src -B build -G Ninja > configure.out 2>&1 || { cat configure.out; exit 1; }
expect FAIL 'linux_header\.cpp\.o .*/sys/prctl\.h'
echo 'int header() { return 0; }' > src/linux_header.cpp
expect FAIL 'linux_call\.cpp\.o pipe2'
printf '#include <string.h>\nconst char* call(int sig) { return sigabbrev_np(sig); }\n' > src/linux_call.cpp
expect FAIL 'linux_call\.cpp\.o sigabbrev_np'
echo 'int call(int*) { return 0; }' > src/linux_call.cpp
expect PASS '^portable: 3 objects'
