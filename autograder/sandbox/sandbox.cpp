#include "sandbox/sandbox.h"

#include <fcntl.h>
#include <linux/openat2.h>
#include <pwd.h>
#include <sched.h>
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
#include <optional>
#include <sstream>
#include <stdexcept>

#include "process/launcher.h"
#include "sandbox/output_keeper.h"
#include "sandbox/confine.h"
#include "sandbox/landlock.h"
#include "sandbox/seccomp_filter.h"

namespace pt::grade {

struct Sandbox::Plan : confine::Plan {};

namespace {

namespace fs = std::filesystem;

// The wardens of the runs in progress (a verifier's and its worker's), for
// the interrupt handler: a grader stopped with Ctrl-C or SIGTERM takes the
// runs with it.
volatile sig_atomic_t g_wardens[2] = {0, 0};

void kill_run_and_die(int sig) {
  for (const sig_atomic_t warden : g_wardens)
    if (warden > 0) ::kill(warden, SIGKILL);
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

// The pipes of one run: the warden's status lines, the run's output and,
// with a key, its verdict channel and the key it reads.
struct RunPipes {
  Pipe status, output, verdicts, key;

  // "" or what failed.
  std::string open(const std::string& key_text) {
    if (!status.open() || !output.open() || (!key_text.empty() && (!verdicts.open() || !key.open())))
      return std::string("pipe: ") + std::strerror(errno);
    if (!key_text.empty()) {
      [[maybe_unused]] auto n = ::write(key.write.get(), key_text.data(), key_text.size());
      key.write.reset();  // the test main reads the key, then end of file
    }
    return "";
  }
};

// What the warden is given (confine.h), with the strings it points into.
struct WardenArgs {
  std::vector<std::string> argv, env;
  confine::ChildArgs child;

  WardenArgs(const confine::Plan& plan, const std::string& workdir, const RunRequest& req, const RunPipes& pipes,
             int binary, bool probe)
      : env{"PATH=/usr/bin:/bin", "HOME=" + workdir, "TMPDIR=" + workdir, "LANG=C.UTF-8"} {
    argv.push_back(req.binary);
    argv.insert(argv.end(), req.args.begin(), req.args.end());
    confine::ChildArgs& a = child;
    a.plan = &plan;
    a.probe = probe;
    a.status = pipes.status.write.get();
    a.output = pipes.output.write.get();
    const bool worker = req.key.empty();  // its link where a verdict channel would be
    a.verdicts = worker ? req.link_write : pipes.verdicts.write.get();
    a.key = worker ? req.link_read : pipes.key.read.get();
    a.link_read = worker ? -1 : req.link_read;
    a.link_write = worker ? -1 : req.link_write;
    a.binary = binary;
    a.binary_path = req.binary;
    a.workdir = workdir;
    a.output_dir = req.output_dir;
    for (auto& s : argv) a.argv.push_back(s.data());
    a.argv.push_back(nullptr);
    for (auto& s : env) a.envp.push_back(s.data());
    a.envp.push_back(nullptr);
    a.outer_uid = ::geteuid();
    a.outer_gid = ::getegid();
  }
};

unsigned long namespace_flags(const confine::Plan& plan) {
  unsigned long flags = 0;
  if (plan.user_ns) flags |= CLONE_NEWUSER;
  if (plan.pid_ns) flags |= CLONE_NEWPID;
  if (plan.mount_ns) flags |= CLONE_NEWNS;
  if (plan.ipc_ns) flags |= CLONE_NEWIPC;
  return flags;
}

// The warden's status lines (confine.h): the steps that failed, and the
// run's wait status when it said one.
struct WardenReport {
  std::vector<Failure> failures;
  bool reported = false;
  int wait_status = 0;
};

WardenReport read_status(const std::string& text) {
  WardenReport w;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "exit") {
      w.reported = static_cast<bool>(words >> w.wait_status);
    } else if (kind == "fail") {
      Failure f;
      words >> f.step >> f.err;
      std::getline(words >> std::ws, f.what);
      w.failures.push_back(f);
    }
  }
  return w;
}

// How the run ended: its deadline, a step of the sandbox that failed, a
// warden killed before it could say, or the exit status it said.
Exit exit_of(const WardenReport& w, const Deadline* timed_out, bool probe, int warden_status) {
  if (timed_out) return Exit::timed_out(timed_out->limit_seconds);
  if (!probe && !w.failures.empty()) {
    const Failure& f = w.failures.front();
    return Exit::not_started(f.step == "exec" ? f.what : "the sandbox's step \"" + f.step + "\" failed: " + f.what);
  }
  if (w.reported) return Exit::of_wait_status(w.wait_status);
  Exit e;
  e.how = Exit::How::Lost;
  e.error = "the sandbox's warden was killed" +
            (WIFSIGNALED(warden_status) ? " by signal " + std::to_string(WTERMSIG(warden_status)) : "") +
            " before it could say how the run ended";
  return e;
}

// One run in flight: its warden started in the run's namespaces
// (confine.h), its output, verdicts and status read into it by a watch.
// Never moved: the warden and the streams point into it.
struct Flight {
  explicit Flight(const SandboxLimits& l) : kept(l.output_head, l.output_tail) {}

  RunPipes pipes;
  std::optional<WardenArgs> args;
  std::optional<Child> warden;
  OutputKeeper kept;
  std::string status_text;
  std::vector<Stream> streams;  // output, verdicts, status
  Clock::time_point start = Clock::now();
  int warden_status = 0;
  RunOutcome outcome;             // why it never started, or how it ended (land())
  std::vector<Failure> failures;  // steps that failed (a probe carries on past optional ones)
  int clone_errno = 0;            // clone() itself failed
};

// Starts the run; false, with f.outcome saying why, when it could not.
bool take_off(Flight& f, const confine::Plan& plan, const std::string& workdir, const RunRequest& req,
              RunObserver& observer, bool probe, Fd& link_read, Fd& link_write) {
  if (const std::string error = f.pipes.open(req.key); !error.empty()) {
    f.outcome = RunOutcome::not_started(error);
    return false;
  }
  Fd binary(::open(req.binary.c_str(), O_PATH | O_CLOEXEC));
  if (binary.get() < 0) {
    f.outcome = RunOutcome::not_started(req.binary + ": " + std::strerror(errno));
    return false;
  }
  f.args.emplace(plan, workdir, req, f.pipes, binary.get(), probe);
  LaunchOptions launch;
  launch.namespaces = namespace_flags(plan);
  // The child has its own: the peer sees the end of the link when this run ends.
  RunPipes& p = f.pipes;
  launch.child_ends = {p.status.write.release(), p.output.write.release(), p.verdicts.write.release(),
                       p.key.read.release(),     binary.release(),         link_read.release(),
                       link_write.release()};
  const confine::ChildArgs& child = f.args->child;
  f.warden.emplace(launch, [&child] { confine::warden_main(child); });
  if (!f.warden->started()) {
    f.clone_errno = f.warden->start_error();
    f.outcome = RunOutcome::not_started(std::string("clone: ") + std::strerror(f.clone_errno));
    return false;
  }
  for (auto& slot : g_wardens)
    if (slot == 0) {
      slot = f.warden->pid();
      break;
    }
  f.streams = {{p.output.read.get(), [&f](const char* d, size_t n) { f.kept.add(d, n); }},
               {p.verdicts.read.get(), [&observer](const char* d, size_t n) { observer.on_channel({d, n}); }},
               {p.status.read.get(), [&f](const char* d, size_t n) {
                  if (f.status_text.size() < 65536) f.status_text.append(d, n);
                }}};
  return true;
}

// Its warden killed (a timeout; otherwise it has already gone) and reaped.
void stop(Flight& f) {
  for (auto& slot : g_wardens)
    if (slot == f.warden->pid()) slot = 0;
  f.warden->kill(SIGKILL);
  f.warden_status = f.warden->wait();
}

// How the run ended, once every process of it is dead.
void land(Flight& f, const Deadline* timed_out, bool probe) {
  for (const Stream& s : f.streams) drain(s);
  const WardenReport report = read_status(f.status_text);
  f.failures = report.failures;
  f.outcome.exit = exit_of(report, timed_out, probe, f.warden_status);
  f.outcome.exit.seconds = std::chrono::duration<double>(Clock::now() - f.start).count();
  f.outcome.output = f.kept.text();
  f.outcome.output_bytes = f.kept.total();
}

// Watches a run started (and a worker started before it, beside) until its
// warden reports or the observer's deadline passes; the worker then has a
// second more to read the end of its link and leave. Every process of both is
// dead when this returns; `before` are the caller's own children, never killed.
void fly(const confine::Plan& plan, Flight& f, RunObserver& observer, bool probe, Flight* beside,
         const std::set<pid_t>& before) {
  std::vector<Stream> streams = f.streams;
  if (beside) streams.insert(streams.end(), beside->streams.begin(), beside->streams.end());
  Deadline deadline{};
  const bool ended = f.warden->watch(streams, 2, [&] { return (deadline = observer.deadline()).when; });
  stop(f);
  const Deadline beside_end{Clock::now() + std::chrono::seconds(1), 0};
  const bool beside_ended = beside && beside->warden->watch(beside->streams, 2, [&] { return beside_end.when; });
  if (beside) stop(*beside);
  if (!plan.pid_ns) kill_descendants(before);  // what the killed wardens left is handed here
  if (beside) land(*beside, beside_ended ? nullptr : &beside_end, probe);
  land(f, ended ? nullptr : &deadline, probe);
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

std::string sandbox_unavailable() { return ""; }

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

namespace {

// Why each layer the sandbox could have is missing ("" where it holds).
struct LayerNotes {
  std::string namespaces, tmpfs, proc, user, landlock, seccomp;
};

const std::string kTurnedOff = ": left out (--sandbox-without)";

bool wanted(const SandboxOptions& options, const char* layer) {
  return std::find(options.without.begin(), options.without.end(), layer) == options.without.end();
}

// Who runs the code under test: the unprivileged account when the grader is
// root, else the grader's own user.
void choose_user(confine::Plan& p, const SandboxOptions& options, LayerNotes& notes) {
  const bool root = ::geteuid() == 0;
  if (root && !wanted(options, "user")) {
    notes.user = "unprivileged user" + kTurnedOff + " (the code under test runs as root)";
  } else if (root) {
    if (const passwd* pw = ::getpwnam(options.user.c_str())) {
      p.switch_user = true;
      p.uid = pw->pw_uid;
      p.gid = pw->pw_gid;
    } else {
      notes.user = "unprivileged user: there is no account \"" + options.user + "\" (the code under test runs as root)";
    }
  } else {
    notes.user = "unprivileged user: the grader is not root, so the code under test runs as the grader's own user";
  }
}

void drop_namespaces(confine::Plan& p) { p.user_ns = p.pid_ns = p.mount_ns = p.ipc_ns = p.tmpfs = p.proc = false; }

// Every layer this build and kernel could offer, less those left out.
void offered_layers(confine::Plan& p, const SandboxOptions& options, LayerNotes& notes) {
  p.user_ns = ::geteuid() != 0;
  p.pid_ns = p.mount_ns = p.ipc_ns = p.tmpfs = p.proc = true;
  p.landlock_abi = landlock_abi();
  p.seccomp = true;
  if (p.landlock_abi == 0) notes.landlock = "Landlock: this kernel does not offer it";
  if (!wanted(options, "namespaces")) {
    drop_namespaces(p);
    notes.namespaces = "namespaces" + kTurnedOff;
  }
  if (!wanted(options, "landlock")) {
    p.landlock_abi = 0;
    notes.landlock = "Landlock" + kTurnedOff;
  }
  if (!wanted(options, "seccomp")) {
    p.seccomp = false;
    notes.seccomp = "seccomp" + kTurnedOff;
  }
}

// A probe run's failed step: the layer it drops, and why. False for a step
// no run can do without.
bool drop_failed_layer(confine::Plan& p, const Failure& f, const std::string& user, LayerNotes& notes,
                       bool& namespaces_dropped) {
  if (f.step == "uid-map" || f.step == "mount-private") {
    if (!namespaces_dropped) {
      notes.namespaces = "namespaces: " + f.step + ": " + f.what;
      drop_namespaces(p);
      namespaces_dropped = true;
    }
  } else if (f.step == "tmpfs") {
    p.tmpfs = false;
    notes.tmpfs = "private tmpfs working directory: " + f.what + " (a folder on disk instead)";
  } else if (f.step == "proc") {
    p.proc = false;
    notes.proc = "private /proc: " + f.what;
  } else if (f.step == "landlock") {
    p.landlock_abi = 0;
    notes.landlock = "Landlock: " + f.what;
  } else if (f.step == "seccomp") {
    p.seccomp = false;
    notes.seccomp = "seccomp: " + f.what;
  } else if (f.step == "user") {
    p.switch_user = false;
    notes.user = "unprivileged user: cannot become " + user + ": " + f.what;
  } else {
    return false;
  }
  return true;
}

// Runs this program through every layer planned, up to exec, and drops what
// fails, until a probe run passes them all.
void keep_layers_that_work(confine::Plan& p, const std::string& scratch, const std::string& user, LayerNotes& notes) {
  char self[4096];
  const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
  RunRequest request;
  request.binary = n > 0 ? std::string(self, static_cast<size_t>(n)) : "/proc/self/exe";
  for (int attempt = 0; attempt < 4; ++attempt) {
    p.nproc = p.switch_user || p.user_ns;
    const std::string workdir = scratch + "/probe-" + std::to_string(attempt);
    ::mkdir(workdir.c_str(), 0700);
    FixedDeadline observer(10);
    Fd no_link_read, no_link_write;
    const std::set<pid_t> before = children_of(::getpid());
    Flight r(p.limits);
    if (take_off(r, p, workdir, request, observer, /*probe=*/true, no_link_read, no_link_write))
      fly(p, r, observer, /*probe=*/true, nullptr, before);
    std::error_code ec;
    fs::remove_all(workdir, ec);
    if (r.clone_errno != 0) {
      notes.namespaces = std::string("namespaces: clone() refused them: ") + std::strerror(r.clone_errno);
      drop_namespaces(p);
      continue;
    }
    bool namespaces_dropped = false;
    for (const Failure& f : r.failures)
      if (!drop_failed_layer(p, f, user, notes, namespaces_dropped))
        throw std::runtime_error("the sandbox cannot start here: " + f.step + ": " + f.what);
    if (r.failures.empty()) return;
    if (attempt == 3) throw std::runtime_error("the sandbox's probe does not settle");
  }
}

// The layers in force: their ids (`pt-grade sandbox`, an expect.json's
// `needs`) and, in words for the report, what each does ("" where it has no
// line of its own).
std::vector<std::pair<std::string, std::string>> layers_in_force(const confine::Plan& p, const std::string& user) {
  const SandboxLimits& l = p.limits;
  std::vector<std::pair<std::string, std::string>> in;
  auto add = [&in](bool holds, std::string id, std::string text) {
    if (holds) in.emplace_back(std::move(id), std::move(text));
  };
  add(p.pid_ns, "pid-ns", "PID namespace: every process of a run dies with it");
  add(!p.pid_ns, "subreaper", "child subreaper: whatever a run leaves behind is killed at its end");
  add(p.user_ns, "user-ns", "user namespace: no capability inside or out");
  add(p.ipc_ns, "ipc-ns", "IPC namespace: System V objects and POSIX message queues die with the run");
  add(true, "workdir", p.tmpfs ? "" : "private working directory");
  add(p.tmpfs, "tmpfs", "private tmpfs working directory (" + mebibytes(l.workdir_bytes) + ")");
  add(p.proc, "proc", "private /proc: other processes are invisible");
  add(p.switch_user, "user", "runs as " + user);
  add(true, "session", "own session, no terminal");
  std::ostringstream limits;
  limits << "limits: address space " << mebibytes(l.address_space) << ", CPU " << l.cpu_seconds << " s, files "
         << mebibytes(l.file_size) << ", " << l.open_files << " open files";
  if (p.nproc) limits << ", " << l.processes << " processes and threads";
  add(true, "rlimits", limits.str());
  add(p.nproc, "nproc", "");
  add(p.landlock_abi > 0, "landlock",
      "Landlock ABI " + std::to_string(p.landlock_abi) +
          ": reads only the system and the given paths, writes only its working directory, executes only itself" +
          (p.landlock_abi >= 4 ? ", no TCP" : "") + (p.landlock_abi >= 6 ? ", no signals out" : ""));
  add(p.seccomp, "seccomp",
      "seccomp: an allowlist; no fork, exec, ptrace, sockets, System V IPC or message queues; signals only to itself");
  add(p.seccomp || p.nproc, "no-fork", "");
  add(true, "", "output through a pipe: the first " + std::to_string(l.output_head >> 10) + " KiB and the last " +
                    std::to_string(l.output_tail >> 10) + " KiB kept");
  return in;
}

}  // namespace

void Sandbox::probe() {
  if (!options_.confine) {
    active_.push_back("none but limits, its own session and a child subreaper (--no-sandbox)");
    return;
  }
  Plan& p = *plan_;
  LayerNotes notes;
  choose_user(p, options_, notes);
  offered_layers(p, options_, notes);
  keep_layers_that_work(p, scratch_, options_.user, notes);
  for (const auto& [id, text] : layers_in_force(p, options_.user)) {
    if (!id.empty()) ids_.push_back(id);
    if (!text.empty()) active_.push_back(text);
  }
  for (const std::string* note : {&notes.namespaces, &notes.tmpfs, &notes.proc, &notes.user, &notes.landlock,
                                  &notes.seccomp})
    if (!note->empty()) missing_.push_back(*note);
  if (!p.nproc && !p.seccomp) missing_.push_back("process limit: nothing stops a fork bomb but the time limits");
}

std::string Sandbox::prepare(const RunRequest& request, RunRequest& absolute, std::string& workdir) {
  workdir = scratch_ + "/run-" + std::to_string(++runs_);
  if (::mkdir(workdir.c_str(), 0700) != 0) return "cannot create " + workdir + ": " + std::strerror(errno);
  if (plan_->switch_user && !plan_->tmpfs && !hand_over(workdir, plan_->uid, plan_->gid))
    return "cannot hand " + workdir + " to " + options_.user + ": " + std::strerror(errno);
  absolute = request;  // the child resolves paths from its own working directory
  absolute.binary = fs::absolute(request.binary).lexically_normal().string();
  if (request.output_dir.empty()) return "";
  absolute.output_dir = fs::absolute(request.output_dir).lexically_normal().string();
  if (plan_->switch_user && !hand_over(absolute.output_dir, plan_->uid, plan_->gid))
    return "cannot hand " + absolute.output_dir + " to " + options_.user + ": " + std::strerror(errno);
  return "";
}

RunOutcome Sandbox::run(const RunRequest& request, RunObserver& observer, const RunRequest* worker,
                        RunOutcome* worker_run) {
  const RunRequest none;
  const RunRequest& beside = worker ? *worker : none;
  Fd links[] = {Fd(request.link_read), Fd(request.link_write), Fd(beside.link_read), Fd(beside.link_write)};
  RunRequest absolute[2];
  std::string workdirs[2];
  const std::string errors[2] = {worker ? prepare(beside, absolute[0], workdirs[0]) : "",
                                 prepare(request, absolute[1], workdirs[1])};
  const std::set<pid_t> before = children_of(::getpid());
  Flight w(plan_->limits), v(plan_->limits);
  const bool worker_started =
      worker && errors[0].empty() && take_off(w, *plan_, workdirs[0], absolute[0], observer, false, links[2], links[3]);
  if (!errors[0].empty()) w.outcome = RunOutcome::not_started(errors[0]);
  links[2].reset();  // a worker that never started: its verifier sees the end of its link
  links[3].reset();
  const bool started =
      errors[1].empty() && take_off(v, *plan_, workdirs[1], absolute[1], observer, false, links[0], links[1]);
  if (!errors[1].empty()) v.outcome = RunOutcome::not_started(errors[1]);
  links[0].reset();  // a verifier that never started: its worker sees the end of its link
  links[1].reset();
  FixedDeadline one_second(1);
  if (started)
    fly(*plan_, v, observer, false, worker_started ? &w : nullptr, before);
  else if (worker_started)
    fly(*plan_, w, one_second, false, nullptr, before);
  for (const std::string& dir : workdirs) {
    std::error_code ec;
    if (!dir.empty()) fs::remove_all(dir, ec);
  }
  if (worker_run) *worker_run = std::move(w.outcome);
  return std::move(v.outcome);
}

}  // namespace pt::grade
