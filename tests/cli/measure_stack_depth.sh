#!/usr/bin/env bash
# Measures how deep the recursive path estimator of a renderer binary can go
# per MiB of stack (tests/cli/README.md): bisects on -m for the closed box
# with --rr 1 (every path runs to the maximum depth), one pixel, one thread,
# under `ulimit -s STACK_KIB`.
#   tests/cli/measure_stack_depth.sh build/pathtracer-reference 1024
# Meaningful for a renderer that runs a one-thread render on the main thread
# (as the renderer before render/limits.h did); the current one gives its
# threads 64 MiB whatever `ulimit -s` says, and bounds -m by 10,000.
set -u
binary=$1 kib=$2
scene=$(dirname "$0")/closed_box.json
lo=1 hi=2000000
while [ $((hi - lo)) -gt 1 ]; do
  mid=$(((lo + hi) / 2))
  if (ulimit -s "$kib"; "$binary" "$scene" -q -r 1 1 -t 1 -s 1 -m "$mid" --rr 1 -f /tmp/stack_depth.png) >/dev/null 2>&1; then
    lo=$mid
  else
    hi=$mid
  fi
done
echo "$binary, ${kib} KiB of stack: deepest -m $lo, $((kib * 1024 / lo)) bytes per bounce"
