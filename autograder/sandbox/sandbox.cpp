#include "sandbox/sandbox.h"

#include <fcntl.h>
#include <linux/openat2.h>
#include <poll.h>
#include <pwd.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "sandbox/confine.h"
#include "sandbox/landlock.h"
#include "sandbox/seccomp_filter.h"

namespace pt::grade {

struct Sandbox::Plan : confine::Plan {};

namespace {

namespace fs = std::filesystem;

struct Fd {
  int fd = -1;
  Fd() = default;
  explicit Fd(int f) : fd(f) {}
  Fd(Fd&& o) noexcept : fd(o.fd) { o.fd = -1; }
  Fd& operator=(Fd&& o) noexcept {
    std::swap(fd, o.fd);
    return *this;
  }
  ~Fd() { reset(); }
  void reset() {
    if (fd >= 0) ::close(fd);
    fd = -1;
  }
};

struct Pipe {
  Fd read, write;
  bool open() {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) return false;
    read = Fd(fds[0]);
    write = Fd(fds[1]);
    return true;
  }
};

// The head and the tail of whatever the run prints: a flood costs the grader
// CPU time (bounded by the time limits), never disk or memory.
class OutputKeeper {
 public:
  OutputKeeper(size_t head, size_t tail) : head_max_(head), tail_max_(tail) {}
  void add(const char* data, size_t n) {
    total_ += n;
    const size_t to_head = std::min(n, head_max_ - head_.size());
    head_.append(data, to_head);
    data += to_head;
    n -= to_head;
    if (n == 0) return;
    tail_.append(data, n);
    if (tail_.size() > 2 * tail_max_) tail_.erase(0, tail_.size() - tail_max_);
  }
  uint64_t total() const { return total_; }
  std::string text() const {
    const std::string tail = tail_.size() > tail_max_ ? tail_.substr(tail_.size() - tail_max_) : tail_;
    const uint64_t dropped = total_ - head_.size() - tail.size();
    if (dropped == 0) return head_ + tail;
    return head_ + "\n[... pt-grade kept the first " + std::to_string(head_max_ >> 10) + " KiB and the last " +
           std::to_string(tail_max_ >> 10) + " KiB: " + std::to_string(dropped) + " bytes not kept ...]\n" + tail;
  }

 private:
  size_t head_max_, tail_max_;
  std::string head_, tail_;
  uint64_t total_ = 0;
};

// The warden of the run in progress, for the interrupt handler: a grader
// stopped with Ctrl-C or SIGTERM takes the run with it.
volatile sig_atomic_t g_warden = 0;

void kill_run_and_die(int sig) {
  if (g_warden > 0) ::kill(g_warden, SIGKILL);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

void install_interrupt_handlers() {
  for (int sig : {SIGINT, SIGTERM, SIGHUP})
    if (::signal(sig, kill_run_and_die) == SIG_IGN) ::signal(sig, SIG_IGN);  // e.g. under nohup
}

struct Failure {
  std::string step, what;
  int err = 0;
};

struct SpawnResult {
  RunOutcome outcome;
  std::vector<Failure> failures;  // steps that failed (a probe carries on past optional ones)
  int clone_errno = 0;            // clone() itself failed
};

Exit not_started(std::string why) {
  Exit e;
  e.error = std::move(why);
  return e;
}

void read_available(int fd, const std::function<void(const char*, size_t)>& sink, bool* eof) {
  char buf[65536];
  const ssize_t n = ::read(fd, buf, sizeof buf);
  if (n > 0)
    sink(buf, static_cast<size_t>(n));
  else if (n == 0 || (errno != EINTR && errno != EAGAIN))
    *eof = true;
}

void drain(int fd, const std::function<void(const char*, size_t)>& sink) {
  if (fd < 0) return;
  ::fcntl(fd, F_SETFL, O_NONBLOCK);
  for (bool eof = false; !eof;) {
    char buf[65536];
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n > 0)
      sink(buf, static_cast<size_t>(n));
    else if (n == 0 || errno != EINTR)
      eof = true;
  }
}

SpawnResult spawn(const confine::Plan& plan, const std::string& workdir, const RunRequest& req, RunObserver& observer,
                  bool probe, Fd& link_read, Fd& link_write) {
  SpawnResult r;
  Pipe status, output, verdicts, key;
  if (!status.open() || !output.open() || (!req.key.empty() && (!verdicts.open() || !key.open()))) {
    r.outcome.exit = not_started(std::string("pipe: ") + std::strerror(errno));
    return r;
  }
  if (!req.key.empty()) {
    [[maybe_unused]] auto n = ::write(key.write.fd, req.key.data(), req.key.size());
    key.write.reset();  // the test main reads the key, then end of file
  }
  Fd binary(::open(req.binary.c_str(), O_PATH | O_CLOEXEC));
  if (binary.fd < 0) {
    r.outcome.exit = not_started(req.binary + ": " + std::strerror(errno));
    return r;
  }

  std::vector<std::string> args{req.binary};
  args.insert(args.end(), req.args.begin(), req.args.end());
  std::vector<std::string> env{"PATH=/usr/bin:/bin", "HOME=" + workdir, "TMPDIR=" + workdir, "LANG=C.UTF-8"};
  confine::ChildArgs a;
  a.plan = &plan;
  a.probe = probe;
  a.status = status.write.fd;
  a.output = output.write.fd;
  a.verdicts = verdicts.write.fd;
  a.key = key.read.fd;
  if (req.key.empty()) {  // a worker: its link where a verdict channel would be
    a.verdicts = req.link_write;
    a.key = req.link_read;
  } else {
    a.link_read = req.link_read;
    a.link_write = req.link_write;
  }
  a.binary = binary.fd;
  a.binary_path = req.binary;
  a.workdir = workdir;
  a.output_dir = req.output_dir;
  for (auto& s : args) a.argv.push_back(s.data());
  a.argv.push_back(nullptr);
  for (auto& s : env) a.envp.push_back(s.data());
  a.envp.push_back(nullptr);
  a.outer_uid = ::geteuid();
  a.outer_gid = ::getegid();

  long flags = SIGCHLD;
  if (plan.user_ns) flags |= CLONE_NEWUSER;
  if (plan.pid_ns) flags |= CLONE_NEWPID;
  if (plan.mount_ns) flags |= CLONE_NEWNS;
  if (plan.ipc_ns) flags |= CLONE_NEWIPC;
  // Children the caller already had are not the run's: never killed.
  const std::set<pid_t> before = confine::children_of(::getpid());
  const auto start = Clock::now();
  // fork() with namespaces: the child is PID 1 of the new PID namespace.
  const pid_t warden = static_cast<pid_t>(::syscall(SYS_clone, flags, nullptr, nullptr, nullptr, 0));
  if (warden < 0) {
    r.clone_errno = errno;
    r.outcome.exit = not_started(std::string("clone: ") + std::strerror(errno));
    return r;
  }
  if (warden == 0) confine::warden_main(a);
  g_warden = warden;
  status.write.reset();
  output.write.reset();
  verdicts.write.reset();
  key.read.reset();
  binary.reset();
  link_read.reset();  // the child has its own: the peer sees the end of the link when this run ends
  link_write.reset();

  const SandboxLimits& limits = plan.limits;
  OutputKeeper kept(limits.output_head, limits.output_tail);
  std::string status_text;
  auto keep_output = [&](const char* d, size_t n) { kept.add(d, n); };
  auto to_observer = [&](const char* d, size_t n) { observer.on_channel(std::string_view(d, n)); };
  auto to_status = [&](const char* d, size_t n) {
    if (status_text.size() < 65536) status_text.append(d, n);
  };
  bool status_eof = false, output_eof = false, verdicts_eof = verdicts.read.fd < 0;
  bool timed_out = false;
  double limit = 0;
  while (!status_eof) {
    const Deadline d = observer.deadline();
    const auto now = Clock::now();
    if (now >= d.when) {
      timed_out = true;
      limit = d.limit_seconds;
      break;
    }
    const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(d.when - now).count() + 1;
    pollfd fds[3] = {{status.read.fd, POLLIN, 0},
                     {output_eof ? -1 : output.read.fd, POLLIN, 0},
                     {verdicts_eof ? -1 : verdicts.read.fd, POLLIN, 0}};
    if (::poll(fds, 3, static_cast<int>(std::min<long long>(wait, 200))) < 0 && errno != EINTR) break;
    if (fds[1].revents) read_available(output.read.fd, keep_output, &output_eof);
    if (fds[2].revents) read_available(verdicts.read.fd, to_observer, &verdicts_eof);
    if (fds[0].revents) read_available(status.read.fd, to_status, &status_eof);
  }
  ::kill(warden, SIGKILL);  // a timeout; otherwise it has already gone
  int warden_status = 0;
  while (::waitpid(warden, &warden_status, 0) < 0 && errno == EINTR) {
  }
  g_warden = 0;
  // Without a PID namespace, whatever the killed warden left is handed here.
  if (!plan.pid_ns) confine::kill_descendants(before);
  drain(output.read.fd, keep_output);
  if (!verdicts_eof) drain(verdicts.read.fd, to_observer);
  drain(status.read.fd, to_status);

  RunOutcome& out = r.outcome;
  out.exit.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  out.output = kept.text();
  out.output_bytes = kept.total();
  bool reported = false;
  int wait_status = 0;
  std::istringstream lines(status_text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string kind, step;
    words >> kind;
    if (kind == "exit") {
      reported = static_cast<bool>(words >> wait_status);
    } else if (kind == "fail") {
      Failure f;
      words >> f.step >> f.err;
      std::getline(words >> std::ws, f.what);
      r.failures.push_back(f);
    }
  }
  if (timed_out) {
    out.exit.how = Exit::How::TimedOut;
    out.exit.limit = limit;
  } else if (!probe && !r.failures.empty()) {
    const Failure& f = r.failures.front();
    out.exit = not_started(f.step == "exec" ? f.what : "the sandbox's step \"" + f.step + "\" failed: " + f.what);
  } else if (!reported) {
    out.exit.how = Exit::How::Lost;
    out.exit.error = "the sandbox's warden was killed" +
                     (WIFSIGNALED(warden_status) ? " by signal " + std::to_string(WTERMSIG(warden_status)) : "") +
                     " before it could say how the run ended";
  } else if (WIFSIGNALED(wait_status)) {
    out.exit.how = Exit::How::Signaled;
    out.exit.code = WTERMSIG(wait_status);
  } else {
    out.exit.how = Exit::How::Exited;
    out.exit.code = WEXITSTATUS(wait_status);
  }
  return r;
}

class FixedDeadline : public RunObserver {
 public:
  explicit FixedDeadline(double seconds)
      : when_(Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds))),
        seconds_(seconds) {}
  void on_channel(std::string_view) override {}
  Deadline deadline() const override { return {when_, seconds_}; }

 private:
  Clock::time_point when_;
  double seconds_;
};

std::string mebibytes(uint64_t bytes) {
  std::ostringstream os;
  if (bytes >= (1ull << 30) && bytes % (1ull << 30) == 0)
    os << (bytes >> 30) << " GiB";
  else
    os << (bytes >> 20) << " MiB";
  return os.str();
}

// Hands a folder the grader made to the sandbox's user. The path is opened
// without following any link (openat2's RESOLVE_NO_SYMLINKS, or O_NOFOLLOW
// for its last part on kernels before 5.6), so a link planted by an earlier
// run can never make the grader give away another folder (results.json's).
bool hand_over(const std::string& dir, uid_t uid, gid_t gid) {
  open_how how{};
  how.flags = O_RDONLY | O_DIRECTORY | O_CLOEXEC;
  how.resolve = RESOLVE_NO_SYMLINKS;
  int fd = static_cast<int>(::syscall(SYS_openat2, AT_FDCWD, dir.c_str(), &how, sizeof how));
  if (fd < 0 && errno == ENOSYS) fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::fchown(fd, uid, gid) == 0;
  ::close(fd);
  return ok;
}

}  // namespace

Sandbox::Sandbox(SandboxOptions options) : options_(std::move(options)), plan_(new Plan) {
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/pt-grade-XXXXXX";
  if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot create a temporary folder in " + pattern);
  scratch_ = fs::canonical(pattern).string();  // no link in it: hand_over() follows none
  // Every orphan of a run is handed to the grader, which kills it: the last
  // resort when no PID namespace holds the run together.
  ::prctl(PR_SET_CHILD_SUBREAPER, 1);
  install_interrupt_handlers();
  plan_->limits = options_.limits;
  for (const auto& p : options_.readable) plan_->readable.push_back(fs::absolute(p).lexically_normal().string());
  probe();
}

Sandbox::~Sandbox() {
  std::error_code ec;
  fs::remove_all(scratch_, ec);
  delete plan_;
}

void Sandbox::probe() {
  active_.clear();
  missing_.clear();
  Plan& p = *plan_;
  if (!options_.confine) {
    active_.push_back("none but limits, its own session and a child subreaper (--no-sandbox)");
    return;
  }
  const bool root = ::geteuid() == 0;
  auto wanted = [&](const char* layer) {
    return std::find(options_.without.begin(), options_.without.end(), layer) == options_.without.end();
  };
  const std::string turned_off = ": left out (--sandbox-without)";
  std::string user_note;
  if (root && !wanted("user")) {
    user_note = "unprivileged user" + turned_off + " (the code under test runs as root)";
  } else if (root) {
    if (const passwd* pw = ::getpwnam(options_.user.c_str())) {
      p.switch_user = true;
      p.uid = pw->pw_uid;
      p.gid = pw->pw_gid;
    } else {
      user_note = "unprivileged user: there is no account \"" + options_.user + "\" (the code under test runs as root)";
    }
  } else {
    user_note = "unprivileged user: the grader is not root, so the code under test runs as the grader's own user";
  }
  p.user_ns = !root;
  p.pid_ns = p.mount_ns = p.ipc_ns = p.tmpfs = p.proc = true;
  p.landlock_abi = landlock_abi();
  p.seccomp = seccomp_available();
  std::string ns_note, tmpfs_note, proc_note, landlock_note, seccomp_note;
  if (p.landlock_abi == 0) landlock_note = "Landlock: this kernel does not offer it";
  if (!p.seccomp) seccomp_note = "seccomp: pt-grade was built without libseccomp (libseccomp-dev)";
  if (!wanted("namespaces")) {
    p.user_ns = p.pid_ns = p.mount_ns = p.ipc_ns = p.tmpfs = p.proc = false;
    ns_note = "namespaces" + turned_off;
  }
  if (!wanted("landlock")) {
    p.landlock_abi = 0;
    landlock_note = "Landlock" + turned_off;
  }
  if (!wanted("seccomp")) {
    p.seccomp = false;
    seccomp_note = "seccomp" + turned_off;
  }

  char self[4096];
  const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
  RunRequest request;
  request.binary = n > 0 ? std::string(self, static_cast<size_t>(n)) : "/proc/self/exe";
  for (int attempt = 0; attempt < 4; ++attempt) {
    p.nproc = p.switch_user || p.user_ns;
    const std::string workdir = scratch_ + "/probe-" + std::to_string(attempt);
    ::mkdir(workdir.c_str(), 0700);
    FixedDeadline observer(10);
    Fd no_link_read, no_link_write;
    const SpawnResult r = spawn(p, workdir, request, observer, /*probe=*/true, no_link_read, no_link_write);
    std::error_code ec;
    fs::remove_all(workdir, ec);
    bool retry = false;
    auto drop_namespaces = [&](const std::string& why) {
      ns_note = "namespaces: " + why;
      p.user_ns = p.pid_ns = p.mount_ns = p.ipc_ns = p.tmpfs = p.proc = false;
      retry = true;
    };
    if (r.clone_errno != 0) {
      drop_namespaces(std::string("clone() refused them: ") + std::strerror(r.clone_errno));
      continue;
    }
    for (const Failure& f : r.failures) {
      const std::string why = f.step + ": " + f.what;
      if (f.step == "uid-map" || f.step == "mount-private") {
        if (!retry) drop_namespaces(why);
      } else if (f.step == "tmpfs") {
        p.tmpfs = false;
        tmpfs_note = "private tmpfs working directory: " + f.what + " (a folder on disk instead)";
      } else if (f.step == "proc") {
        p.proc = false;
        proc_note = "private /proc: " + f.what;
      } else if (f.step == "landlock") {
        p.landlock_abi = 0;
        landlock_note = "Landlock: " + f.what;
      } else if (f.step == "seccomp") {
        p.seccomp = false;
        seccomp_note = "seccomp: " + f.what;
      } else if (f.step == "user") {
        p.switch_user = false;
        user_note = "unprivileged user: cannot become " + options_.user + ": " + f.what;
      } else {
        throw std::runtime_error("the sandbox cannot start here: " + why);
      }
      retry = true;
    }
    if (!retry) break;
    if (attempt == 3) throw std::runtime_error("the sandbox's probe does not settle");
  }

  const SandboxLimits& l = p.limits;
  if (p.pid_ns)
    active_.push_back("PID namespace: every process of a run dies with it");
  else
    active_.push_back("child subreaper: whatever a run leaves behind is killed at its end");
  if (p.user_ns) active_.push_back("user namespace: no capability inside or out");
  if (p.ipc_ns)
    active_.push_back("IPC namespace: System V objects and POSIX message queues die with the run");
  if (p.tmpfs) active_.push_back("private tmpfs working directory (" + mebibytes(l.workdir_bytes) + ")");
  if (!p.tmpfs) active_.push_back("private working directory");
  if (p.proc) active_.push_back("private /proc: other processes are invisible");
  if (p.switch_user) active_.push_back("runs as " + options_.user);
  active_.push_back("own session, no terminal");
  std::ostringstream limits;
  limits << "limits: address space " << mebibytes(l.address_space) << ", CPU " << l.cpu_seconds << " s, files "
         << mebibytes(l.file_size) << ", " << l.open_files << " open files";
  if (p.nproc) limits << ", " << l.processes << " processes and threads";
  active_.push_back(limits.str());
  if (p.landlock_abi > 0)
    active_.push_back("Landlock ABI " + std::to_string(p.landlock_abi) +
                      ": reads only the system and the given paths, writes only its working directory, executes only "
                      "itself" +
                      (p.landlock_abi >= 4 ? ", no TCP" : "") + (p.landlock_abi >= 6 ? ", no signals out" : ""));
  if (p.seccomp)
    active_.push_back("seccomp: an allowlist; no fork, exec, ptrace, sockets, System V IPC or message queues; "
                      "signals only to itself");
  active_.push_back("output through a pipe: the first " + std::to_string(l.output_head >> 10) + " KiB and the last " +
                    std::to_string(l.output_tail >> 10) + " KiB kept");
  for (const std::string* note : {&ns_note, &tmpfs_note, &proc_note, &user_note, &landlock_note, &seccomp_note})
    if (!note->empty()) missing_.push_back(*note);
  if (!p.nproc && !p.seccomp) missing_.push_back("process limit: nothing stops a fork bomb but the time limits");
}

std::vector<std::string> Sandbox::layer_ids() const {
  const Plan& p = *plan_;
  if (!options_.confine) return {};
  std::vector<std::string> ids{p.pid_ns ? "pid-ns" : "subreaper", "session", "rlimits", "workdir"};
  if (p.user_ns) ids.push_back("user-ns");
  if (p.ipc_ns) ids.push_back("ipc-ns");
  if (p.tmpfs) ids.push_back("tmpfs");
  if (p.proc) ids.push_back("proc");
  if (p.switch_user) ids.push_back("user");
  if (p.nproc) ids.push_back("nproc");
  if (p.landlock_abi > 0) ids.push_back("landlock");
  if (p.seccomp) ids.push_back("seccomp");
  if (p.seccomp || p.nproc) ids.push_back("no-fork");
  return ids;
}

RunOutcome Sandbox::run(const RunRequest& request, RunObserver& observer) {
  Fd link_read(request.link_read), link_write(request.link_write);  // the run's, whatever happens
  // The process id too: a verifier's worker is run by a helper process with
  // a copy of this Sandbox (grade_part.cpp).
  const std::string workdir = scratch_ + "/run-" + std::to_string(::getpid()) + "-" + std::to_string(++runs_);
  if (::mkdir(workdir.c_str(), 0700) != 0) {
    RunOutcome r;
    r.exit = not_started("cannot create " + workdir + ": " + std::strerror(errno));
    return r;
  }
  if (plan_->switch_user && !plan_->tmpfs && !hand_over(workdir, plan_->uid, plan_->gid)) {
    RunOutcome r;
    r.exit = not_started("cannot hand " + workdir + " to " + options_.user + ": " + std::strerror(errno));
    return r;
  }
  RunRequest absolute = request;  // the child resolves paths from its own working directory
  absolute.binary = fs::absolute(request.binary).lexically_normal().string();
  if (!request.output_dir.empty()) {
    absolute.output_dir = fs::absolute(request.output_dir).lexically_normal().string();
    if (plan_->switch_user && !hand_over(absolute.output_dir, plan_->uid, plan_->gid)) {
      RunOutcome r;
      r.exit = not_started("cannot hand " + absolute.output_dir + " to " + options_.user + ": " + std::strerror(errno));
      return r;
    }
  }
  SpawnResult r = spawn(*plan_, workdir, absolute, observer, /*probe=*/false, link_read, link_write);
  std::error_code ec;
  fs::remove_all(workdir, ec);
  return std::move(r.outcome);
}

}  // namespace pt::grade
