#!/usr/bin/env bash
# A build without the sandbox (PT_SANDBOX off) must build where Linux's
# interfaces are not (macOS). Nobody here has a Mac, so this keeps that build
# honest from what its compiles did on Linux (release:libcxx runs it):
#  1. ninja's record of the headers each compile read: none of the headers
#     only Linux has and that the C library never includes by itself
#     (<sys/prctl.h>, <sys/mount.h>, <seccomp.h>, <linux/landlock.h>, ...);
#     glibc's own <unistd.h> reads <linux/close_range.h>, so a whole linux/
#     folder cannot be the test;
#  2. the undefined symbols of every object it compiled (nm -u): none of the
#     calls only Linux's C library has, which portable headers declare on
#     glibc (pipe2, sched_setaffinity, getrandom, close_range, syscall, ...),
#     nor glibc's own extensions named *_np (sigabbrev_np, pthread_setname_np).
# The shipped third-party code (third_party/: GoogleTest's death tests clone()
# on Linux, fork() elsewhere) chooses its own calls per platform: left out.
# Usage: check_portable.sh BUILD_DIR
set -euo pipefail
build=$1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
linux_headers='/(sys/(prctl|mount|syscall|personality|epoll|signalfd|inotify|fanotify|sysinfo|capability|timerfd|eventfd|fsuid|klog|reboot|swap)\.h|seccomp\.h|linux/(openat2|landlock|seccomp|filter|audit|sched|mount|prctl|capability)\.h)$'
ninja -C "$build" -t deps > "$out/portable-deps.out"
# Each object with the Linux-only headers it read (the header probe only
# preprocesses, to list what a task file may include: not code that runs).
awk -v re="$linux_headers" '/^[^ ].*: #deps/ { obj = $1; sub(/:$/, "", obj); next }
  obj !~ /pt_header_probe|third_party\// && $1 ~ re { print obj " " $1 }' "$out/portable-deps.out" | sort -u > "$out/portable-headers.out"
if [ -s "$out/portable-headers.out" ]; then
  cat "$out/portable-headers.out"; echo "a compile without the sandbox read a header only Linux has"; exit 1
fi
linux_calls='^(prctl|syscall|clone|clone3|unshare|setns|mount|umount2|pivot_root|pipe2|dup3|accept4|close_range|sched_setaffinity|sched_getaffinity|sched_getcpu|getrandom|memfd_create|execveat|pidfd_open|pidfd_send_signal|epoll_create1?|epoll_ctl|epoll_wait|signalfd|inotify_init1?|personality|prlimit(64)?|seccomp_.*|landlock_.*|__sched_cpucount|__sched_cpualloc|[a-z_]+_np)(@.*)?$'
objects=$(awk '/^[^ ].*: #deps/ { sub(/:$/, "", $1); print $1 }' "$out/portable-deps.out" | grep -Ev 'pt_header_probe|third_party/' | sort -u)
count=0
: > "$out/portable-calls.out"
for o in $objects; do
  [ -f "$build/$o" ] || continue
  count=$((count + 1))
  nm -u "$build/$o" 2>/dev/null | awk '{ print $NF }' | grep -E "$linux_calls" | sed "s|^|$o |" >> "$out/portable-calls.out" || true
done
if [ -s "$out/portable-calls.out" ]; then
  sort -u "$out/portable-calls.out"; echo "an object built without the sandbox calls what only Linux has"; exit 1
fi
echo "portable: $count objects, no Linux-only header read, no Linux-only call"
