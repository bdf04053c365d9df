#!/usr/bin/env bash
# Builds a grader's image from the course's repository SRC (run once, as root,
# when Gradescope or Docker builds the image: gradescope/setup.sh,
# prairielearn/Dockerfile): installs the Debian packages and builds the
# grading kit (the framework, the verifiers with the hidden tests, the
# solution compiled only, the manifest, pt-grade) in SRC/build/grader-kit.
# The solution's source stays readable by root only: graded code runs as an
# unprivileged user and could not read it even where Landlock is missing.
# Usage: build_grader_image.sh SRC
set -euo pipefail
src=$1
cd "$src"
PT_GRADER_IMAGE=1 ./setup.sh --deps-only  # without the release's tools (setup.sh)
# The preset's build type (RelWithDebInfo), as in the student's build and the
# instructor's: the kit compiled here is the kit the repository's tests grade
# with, and a crash in the grading log has a backtrace with lines.
cmake --preset default
cmake --build --preset default --target grader-kit
rm -rf "$src/build/ccache"  # a compiler cache, if setup.sh installed one: the image need not keep it
chmod -R go-rwx "$src/reference"
echo "grading kit ready: $src/build/grader-kit"
