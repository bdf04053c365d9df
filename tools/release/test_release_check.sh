#!/usr/bin/env bash
# pt-release-check must fail on a release that leaks (ctest: release:check-catches-leaks):
# a telling line of the reference pasted into a shipped test, a hidden test's
# name in a comment, a hidden/ folder, a hidden contract table's rows in the
# visible one, a source file among the scene library's reference images and a
# reference/ folder elsewhere; and what a
# student would be misled by: a document naming a path the release
# does not hold, a quoted failure whose line is not an assertion, a prebuilt
# library with a local symbol, an image sidecar with a commit hash. Each alone.
# Usage: test_release_check.sh RELEASE_DIR CHECKOUT RELEASE_CHECK MANIFEST WORKDIR
set -euo pipefail
release=$1 source=$2 check=$3 manifest=$4 work=$5
leak() {  # leak NAME COMMAND...: copy the release, apply COMMAND in it, expect a finding
  local name=$1; shift
  rm -rf "$work/$name" && mkdir -p "$work" && cp -r "$release" "$work/$name"
  (cd "$work/$name" && eval "$@")
  if "$check" --release "$work/$name" --source "$source" --manifest "$manifest" > "$work/$name.out"; then
    echo "pt-release-check missed the leak '$name'"; cat "$work/$name.out"; exit 1
  fi
  echo "caught '$name': $(sed -n 2p "$work/$name.out")"
}
line=$(grep -hF '* n1() +' "$source"/reference/part1_raygen_intersect.cpp | head -1)
[ -n "$line" ] || { echo "the reference line this test pastes is gone: choose another"; exit 1; }
leak solution_line "printf '%s\n' '$line' >> tests/support/scene_builders.cpp"
hidden=$(awk -F'"' '/"test":/{t=$4} /"visibility": *"hidden"/{print t; exit}' "$manifest")
[ -n "$hidden" ] || { echo "no hidden test in $manifest"; exit 1; }
leak hidden_name "echo '// see $hidden' >> tests/part1/test_camera.cpp"
leak hidden_folder "mkdir -p tests/part1/hidden && touch tests/part1/hidden/x.cpp"
# A hidden contract table's rows copied into the visible one name hidden tests.
[ -f "$source/tests/part1/hidden/CONTRACT.md" ] || { echo "no tests/part1/hidden/CONTRACT.md to leak"; exit 1; }
leak hidden_contract_rows "grep '^| P1T' '$source/tests/part1/hidden/CONTRACT.md' >> tests/part1/CONTRACT.md"
# scenes/reference/ may hold the library's images, and nothing else.
leak source_among_images "touch scenes/reference/part1_raygen_intersect.cpp"
leak reference_folder "mkdir -p tools/reference && touch tools/reference/notes.txt"
leak missing_path "echo 'More in tests/autograder/README.md.' >> handouts/part1.md"
leak design_reference "echo '// as DESIGN section 5 says' >> skeleton/core/rng.h"
leak wrong_citation "sed -i 's/test_triangle.cpp:[0-9]*: Failure/test_triangle.cpp:12: Failure/' handouts/part1.md"
leak local_symbol "printf 'static int best_split(int x) { return x * 3; }\nint pt_entry(int x) { return best_split(x); }\n' > l.cpp &&
  c++ -O0 -c l.cpp -o l.o && mkdir -p prebuilt/linux-x86_64-libstdc++ && ar rcs prebuilt/linux-x86_64-libstdc++/libpt_extra.a l.o && rm l.cpp l.o"
leak commit_hash "sed -i 's/\"name\"/\"head\": \"0123456789abcdef0123456789abcdef01234567\", \"name\"/' scenes/reference/cornell_spheres.json"
rm -rf "$work"
