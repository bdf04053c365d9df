#pragma once
// A seccomp filter (libseccomp) for the code under test: threads yes, new
// processes no. It kills the process (SIGSYS, which the report names) on
// fork, vfork, clone without CLONE_THREAD, exec of anything but the test
// binary itself, ptrace and process_vm_*; it refuses signals to any process
// but itself, sockets, namespaces, mounts and io_uring.
#include <sys/types.h>

#include <string>

namespace pt::grade {

// False when pt-grade was built without libseccomp.
bool seccomp_available();

// The one exec the filter allows: execveat(exec_fd, "", argv, envp,
// AT_EMPTY_PATH) with exec_fd above the open-files limit the code under test
// runs with, so that it can never open a descriptor with that number itself.
// `self` is the process's own pid, the only target its signals may have.
// Requires no_new_privs. Returns "" or what failed.
std::string seccomp_confine(int exec_fd, pid_t self);

}  // namespace pt::grade
