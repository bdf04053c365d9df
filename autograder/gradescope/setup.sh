#!/usr/bin/env bash
# Gradescope's image set-up (autograder.zip's setup.sh, run once as root when
# the image is built): the course's repository, unpacked beside this script,
# built into a grader (../build_grader_image.sh in the repository).
set -euo pipefail
root=${PT_GRADESCOPE_ROOT:-/autograder}
exec bash "$root/source/pathtracer/autograder/build_grader_image.sh" "$root/source/pathtracer"
