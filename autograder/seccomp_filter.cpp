#include "seccomp_filter.h"

#ifdef PT_HAVE_SECCOMP
#include <fcntl.h>
#include <sched.h>
#include <seccomp.h>
#endif

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <initializer_list>

namespace pt::grade {

#ifndef PT_HAVE_SECCOMP

bool seccomp_available() { return false; }
std::string seccomp_confine(int, pid_t) { return "pt-grade was built without libseccomp"; }

#else

bool seccomp_available() { return true; }

std::string seccomp_confine(int exec_fd, pid_t self) {
  scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ALLOW);
  if (!ctx) return "seccomp_init failed";
  const uint32_t kill_process = SCMP_ACT_KILL_PROCESS, refuse = SCMP_ACT_ERRNO(EPERM);
  const auto me = static_cast<scmp_datum_t>(static_cast<uint32_t>(self));
  int rc = 0;
  auto rule = [&](uint32_t action, int syscall, std::initializer_list<scmp_arg_cmp> args = {}) {
    if (rc == 0) rc = seccomp_rule_add_array(ctx, action, syscall, static_cast<unsigned>(args.size()), args.begin());
  };
  // New processes: none. Threads are clone() with CLONE_THREAD; clone3 hides
  // its flags in memory, so it says ENOSYS and glibc falls back to clone().
  rule(kill_process, SCMP_SYS(fork));
  rule(kill_process, SCMP_SYS(vfork));
  rule(kill_process, SCMP_SYS(clone), {SCMP_A0_64(SCMP_CMP_MASKED_EQ, CLONE_THREAD, 0)});
  rule(SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3));
  // Exec: only the descriptor the sandbox opened, which dies with that exec.
  rule(kill_process, SCMP_SYS(execve));
  rule(kill_process, SCMP_SYS(execveat), {SCMP_A0_32(SCMP_CMP_NE, static_cast<scmp_datum_t>(exec_fd))});
  rule(kill_process, SCMP_SYS(execveat), {SCMP_A4_32(SCMP_CMP_NE, AT_EMPTY_PATH)});
  // Other processes: no tracing, no reading or writing their memory.
  rule(kill_process, SCMP_SYS(ptrace));
  rule(kill_process, SCMP_SYS(process_vm_readv));
  rule(kill_process, SCMP_SYS(process_vm_writev));
  // Signals: to itself, by its pid (raise and abort use tgkill), and nothing
  // else. (libseccomp takes one comparison per argument and rule, so kill(0)
  // and kill(-pgid) are refused too.)
  for (int sc : {SCMP_SYS(kill), SCMP_SYS(tgkill), SCMP_SYS(rt_sigqueueinfo), SCMP_SYS(rt_tgsigqueueinfo)})
    rule(refuse, sc, {SCMP_A0_32(SCMP_CMP_NE, me)});
  for (int sc : {SCMP_SYS(tkill), SCMP_SYS(pidfd_open), SCMP_SYS(pidfd_send_signal), SCMP_SYS(pidfd_getfd)})
    rule(refuse, sc);
  // No network, no new namespaces or mounts, no io_uring (whose operations
  // would not pass through this filter).
  for (int sc : {SCMP_SYS(socket), SCMP_SYS(socketpair), SCMP_SYS(unshare), SCMP_SYS(setns), SCMP_SYS(mount),
                 SCMP_SYS(umount2), SCMP_SYS(pivot_root), SCMP_SYS(chroot), SCMP_SYS(io_uring_setup),
                 SCMP_SYS(io_uring_enter), SCMP_SYS(io_uring_register), SCMP_SYS(bpf), SCMP_SYS(perf_event_open),
                 SCMP_SYS(userfaultfd), SCMP_SYS(keyctl), SCMP_SYS(add_key), SCMP_SYS(request_key)})
    rule(refuse, sc);
  if (rc == 0) rc = seccomp_load(ctx);
  seccomp_release(ctx);
  return rc == 0 ? "" : std::string("seccomp: ") + std::strerror(-rc);
}

#endif

}  // namespace pt::grade
