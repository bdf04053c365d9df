// The sandbox where Linux's confinement is not (a build with PT_SANDBOX off:
// macOS). Every layer of sandbox.h is missing and said so; a run is a plain
// child of the grader in a folder of its own and a process group of its own,
// with its output's head and tail kept, its verdict channel, its deadline,
// and its group killed when it ends. That is enough for a student's own check
// of their own code (check-submission); pt-grade refuses to grade anyone
// else's with it (sandbox_unavailable()).
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "process/launcher.h"
#include "sandbox/output_keeper.h"
#include "sandbox/sandbox.h"

namespace pt::grade {

struct Sandbox::Plan {};

namespace {

namespace fs = std::filesystem;

// The child's side: descriptors to the numbers the test main reads (output
// 1 and 2, verdicts 3, key 4, as confine.cpp places them), its own group and
// folder, then exec. Only async-signal-safe calls.
[[noreturn]] void exec_plain(int output, int verdicts, int key, const char* workdir, char* const argv[],
                             char* const envp[]) {
  const int null_fd = ::open("/dev/null", O_RDONLY);
  // Out of the way first, so that no dup2 below overwrites a source.
  const int in = ::fcntl(null_fd, F_DUPFD, 100), out = ::fcntl(output, F_DUPFD, 100);
  const int v = verdicts < 0 ? -1 : ::fcntl(verdicts, F_DUPFD, 100), k = key < 0 ? -1 : ::fcntl(key, F_DUPFD, 100);
  if (in < 0 || out < 0 || ::dup2(in, 0) != 0 || ::dup2(out, 1) != 1 || ::dup2(out, 2) != 2) ::_exit(126);
  if (v >= 0 ? ::dup2(v, 3) != 3 : ::close(3) != 0 && errno != EBADF) ::_exit(126);
  if (k >= 0 ? ::dup2(k, 4) != 4 : ::close(4) != 0 && errno != EBADF) ::_exit(126);
  for (int fd : {in, out, v, k, null_fd})
    if (fd > 4) ::close(fd);
  if (::setsid() < 0 || ::chdir(workdir) != 0) ::_exit(126);
  ::execve(argv[0], argv, envp);
  ::_exit(127);
}

}  // namespace

std::string sandbox_unavailable() {
  return "this pt-grade has no sandbox (it needs Linux's namespaces, Landlock and seccomp): grading runs on your "
         "course's grader; here, pt-grade check-submission checks what it can and says what it cannot";
}

Sandbox::Sandbox(SandboxOptions options) : options_(std::move(options)), plan_(new Plan) {
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/pt-grade-XXXXXX";
  if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot create a temporary folder in " + pattern);
  scratch_ = fs::canonical(pattern).string();
  ids_ = {"none"};
  missing_ = {"the sandbox: this build has none (PT_SANDBOX is off: it needs Linux); tests run as plain processes"};
}

Sandbox::~Sandbox() {
  std::error_code ec;
  fs::remove_all(scratch_, ec);
  delete plan_;
}

void Sandbox::probe() {}

// No worker here: no part is graded across the process boundary (worker_run_unavailable.cpp).
RunOutcome Sandbox::run(const RunRequest& request, RunObserver& observer, const RunRequest*, RunOutcome*) {
  Fd link_read(request.link_read), link_write(request.link_write);  // never used here: closed
  const std::string workdir = scratch_ + "/run-" + std::to_string(++runs_);
  if (::mkdir(workdir.c_str(), 0700) != 0)
    return RunOutcome::not_started("cannot create " + workdir + ": " + std::strerror(errno));
  Pipe output, verdicts, key;
  if (!output.open() || (!request.key.empty() && (!verdicts.open() || !key.open())))
    return RunOutcome::not_started(std::string("pipe: ") + std::strerror(errno));
  if (!request.key.empty()) {
    [[maybe_unused]] auto n = ::write(key.write.get(), request.key.data(), request.key.size());
    key.write.reset();  // the test main reads the key, then end of file
  }
  std::vector<std::string> args{fs::absolute(request.binary).lexically_normal().string()};
  args.insert(args.end(), request.args.begin(), request.args.end());
  std::vector<std::string> env{"PATH=/usr/bin:/bin", "HOME=" + workdir, "TMPDIR=" + workdir, "LANG=C.UTF-8"};
  std::vector<char*> argv, envp;
  for (auto& a : args) argv.push_back(a.data());
  for (auto& e : env) envp.push_back(e.data());
  argv.push_back(nullptr);
  envp.push_back(nullptr);

  const auto start = Clock::now();
  LaunchOptions launch;
  launch.child_ends = {output.write.release(), verdicts.write.release(), key.read.release()};
  const int out_fd = launch.child_ends[0], verdicts_fd = launch.child_ends[1], key_fd = launch.child_ends[2];
  Child child(launch, [&] { exec_plain(out_fd, verdicts_fd, key_fd, workdir.c_str(), argv.data(), envp.data()); });
  if (!child.started()) return RunOutcome::not_started(std::string("fork: ") + std::strerror(child.start_error()));
  OutputKeeper kept(options_.limits.output_head, options_.limits.output_tail);
  std::vector<Stream> streams{
      {output.read.get(), [&](const char* d, size_t n) { kept.add(d, n); }},
      {verdicts.read.get(), [&](const char* d, size_t n) { observer.on_channel(std::string_view(d, n)); }}};
  Deadline deadline{};
  const bool ended = child.watch(streams, -1, [&] { return (deadline = observer.deadline()).when; });
  child.kill_group(SIGKILL);  // what the run left behind in its group
  child.kill(SIGKILL);        // a timeout; otherwise it has already gone
  const int status = child.wait();
  for (const Stream& s : streams) drain(s);
  RunOutcome r;
  r.exit = ended ? Exit::of_wait_status(status) : Exit::timed_out(deadline.limit_seconds);
  r.exit.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  r.output = kept.text();
  r.output_bytes = kept.total();
  std::error_code ec;
  fs::remove_all(workdir, ec);
  return r;
}

}  // namespace pt::grade
