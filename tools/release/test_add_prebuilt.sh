#!/usr/bin/env bash
# add_prebuilt.cmake (ctest: release:add-prebuilt): another platform's six
# libraries (here this build's own, under a Mac's name) land in the build's
# prebuilt/ and the next export runs again; a folder misnamed, a library
# missing, a file that is no archive and an extra file are each refused.
# Usage: test_add_prebuilt.sh CHECKOUT PREBUILT_DIR WORKDIR
set -euo pipefail
source=$1 libs=$2 work=$3
add="$source/tools/release/add_prebuilt.cmake"
rm -rf "$work" && mkdir -p "$work/build" "$work/macos-arm64-libc++"
touch "$work/build/CMakeCache.txt" "$work/build/student-release.tar.gz"
cp "$libs"/*.a "$work/macos-arm64-libc++/"
cmake -DLIBRARIES="$work/macos-arm64-libc++" -DBUILD="$work/build" -P "$add"
cmp "$libs/libpt_part3_reference.a" "$work/build/prebuilt/macos-arm64-libc++/libpt_part3_reference.a"
[ ! -e "$work/build/student-release.tar.gz" ] || { echo "the export would not run again"; exit 1; }
refused() {  # refused WHAT FOLDER REGEX
  if cmake -DLIBRARIES="$2" -DBUILD="$work/build" -P "$add" > "$work/$1.out" 2>&1; then echo "$1: accepted"; exit 1; fi
  tr '\n' ' ' < "$work/$1.out" | grep -Eq "$3" || { cat "$work/$1.out"; echo "$1: not refused for the right reason"; exit 1; }
  echo "$1: refused"
}
cp -r "$work/macos-arm64-libc++" "$work/macos"
refused misnamed "$work/macos" "must +be +named"
rm "$work/macos-arm64-libc++/libpt_part4_reference.a"
refused missing "$work/macos-arm64-libc++" "libpt_part4_reference.a +is +missing"
echo "not an archive" > "$work/macos-arm64-libc++/libpt_part4_reference.a"
refused not_archive "$work/macos-arm64-libc++" "is +not +a +static +library"
cp "$libs/libpt_part4_reference.a" "$work/macos-arm64-libc++/" && touch "$work/macos-arm64-libc++/notes.txt"
refused extra_file "$work/macos-arm64-libc++" "more +than +the +six +libraries"
rm -rf "$work"
echo "add_prebuilt OK"
