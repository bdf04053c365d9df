#pragma once
// A seccomp filter (libseccomp) for the code under test: an allowlist. What a
// test binary, a worker or a renderer needs (memory, threads, files, time,
// signals to itself) is allowed; the list, grouped with the reason for each
// group, is autograder/README.md's threat model, and seccomp_filter.cpp is
// the same list in code. Anything else returns ENOSYS, as on a kernel that
// lacks it. Process creation and escapes are named and kill the process
// (SIGSYS, which the report names): fork, vfork, clone without CLONE_THREAD,
// exec of anything but the test binary itself, ptrace, process_vm_*. What
// outlives a process or reaches past it (System V shared memory, message
// queues and semaphores, POSIX message queues, sockets, namespaces, mounts,
// io_uring, signals to another process) is refused with EPERM.
#include <sys/types.h>

#include <string>

namespace pt::grade {

// The one exec the filter allows: execveat(exec_fd, "", argv, envp,
// AT_EMPTY_PATH) with exec_fd above the open-files limit the code under test
// runs with, so that it can never open a descriptor with that number itself.
// `self` is the process's own pid, the only target its signals may have.
// Requires no_new_privs. Returns "" or what failed.
std::string seccomp_confine(int exec_fd, pid_t self);

}  // namespace pt::grade
