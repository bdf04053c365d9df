#!/usr/bin/env bash
# Gradescope's image set-up (autograder.zip's setup.sh, run once as root when
# the image is built): installs the Debian/Ubuntu packages and builds the
# grading kit from the course's source: the framework, the verifiers (the
# graded tests, hidden ones included), the solution compiled only, the
# manifest, pt-grade.
# The solution's source stays readable by root only: graded code runs as an
# unprivileged user and could not read it even where Landlock is missing.
set -euo pipefail
root=${PT_GRADESCOPE_ROOT:-/autograder}
src="$root/source/pathtracer"
cd "$src"
./setup.sh --deps-only
# The preset's build type (RelWithDebInfo), as in the student's build and the
# instructor's: the kit compiled here is the kit the repository's tests grade
# with, and a crash in the grading log has a backtrace with lines.
cmake --preset default
cmake --build --preset default --target grader-kit
rm -rf "$src/build/ccache"  # a compiler cache, if setup.sh installed one: the image need not keep it
chmod -R go-rwx "$src/reference"
echo "grading kit ready: $src/build/grader-kit"
