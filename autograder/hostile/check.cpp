// pt-hostile-check: grades one hostile case with the command given after
// `--` and checks that the results.json it wrote is honest (README.md).
//
//   pt-hostile-check --case DIR --manifest FILE --results FILE --source-dir DIR
//                    --pt-grade PT_GRADE [--fallback] [--submission [--zip FILE]]
//                    -- GRADING COMMAND...
//
// --fallback: the command leaves sandbox layers out (expect.json's
// "fallback"), and the case needs the layers that "fallback" lists instead.
// --submission: the command is `pt-grade submission` on the case's generated
// task files (--tasks, or the zip --zip that this program first writes from
// expect.json's "zip"); expect.json's "submission" object overrides its other
// keys, and every part of the manifest is checked, not only the case's.
//
// Honest means: the grader survived; every graded test is listed with the
// manifest's points (the maximum never shrinks); the tests of the case's
// lost_tasks (and its lost_tests, single tests) scored 0 with a message
// matching its failure pattern (and the layer that stopped it, "stopped_at")
// and every other test of a submitted part scored full marks; the total is
// their sum; the file does not change after the grader has finished; no line
// of the solution or of a hidden test that the submission does not itself
// hold appears in it; and no process of the run is left. Exit status 0
// honest, 1 not, 77 skipped (a sandbox layer the case needs is missing here),
// 2 could not check.
#include <sched.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <archive.h>
#include <archive_entry.h>
#include <nlohmann/json.hpp>

#include "process/command.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using pt::grade::hide_command_line;
using pt::grade::run_command;

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string trimmed(const std::string& line) {
  const auto b = line.find_first_not_of(" \t"), e = line.find_last_not_of(" \t\r");
  return b == std::string::npos ? "" : line.substr(b, e - b + 1);
}

// Lines of a solution file worth looking for: long enough to be code, not a
// brace or a common include.
std::vector<std::string> telling_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    line = trimmed(line);
    if (line.size() >= 24 && line.rfind("#include", 0) != 0) lines.push_back(line);
  }
  return lines;
}

// The value after `flag` in a command, "" when absent.
std::string argument_of(const std::vector<std::string>& command, const std::string& flag) {
  for (size_t i = 0; i + 1 < command.size(); ++i)
    if (command[i] == flag) return command[i + 1];
  return "";
}

// The processes descended from this one that are still alive (zombies are
// dead: only their exit status waits to be read), each named on standard
// output when `say`. This program is a child subreaper (main), so whatever the grader
// started, at any depth, is still its descendant after the grader has gone,
// daemons included; another test's processes never are, even when it grades
// the same binary at the same time.
std::vector<pid_t> live_descendants(bool say) {
  std::map<pid_t, std::vector<pid_t>> children;
  std::map<pid_t, std::string> cmdlines;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator("/proc", ec)) {
    const std::string name = entry.path().filename();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    // /proc/PID/stat: "pid (comm) state ppid ...", comm may hold spaces and parentheses.
    const std::string stat = read_file(entry.path() / "stat");
    const size_t close = stat.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(stat.substr(close + 1));
    char state = 0;
    pid_t ppid = 0;
    if (!(rest >> state >> ppid) || state == 'Z' || state == 'X') continue;
    const pid_t pid = std::stoi(name);
    children[ppid].push_back(pid);
    std::string cmdline = read_file(entry.path() / "cmdline");
    std::replace(cmdline.begin(), cmdline.end(), '\0', ' ');
    cmdlines[pid] = cmdline.substr(0, 200);
  }
  std::vector<pid_t> found, todo{::getpid()};
  while (!todo.empty()) {
    const pid_t pid = todo.back();
    todo.pop_back();
    for (pid_t child : children[pid]) {
      found.push_back(child);
      todo.push_back(child);
    }
  }
  if (say)
    for (pid_t pid : found) std::printf("left running: %d %s\n", pid, cmdlines[pid].c_str());
  return found;
}

// Ends what a failed case left behind (a stopped tree cannot refill itself),
// so that a failing test does not leave a fork bomb on the machine.
void end_descendants(const std::vector<pid_t>& pids) {
  for (pid_t pid : pids) ::kill(pid, SIGSTOP);
  for (pid_t pid : pids) ::kill(pid, SIGKILL);
  while (::waitpid(-1, nullptr, WNOHANG) > 0) {
  }
}

// The zip a "zip" case submits: each entry is {"name", and one of "from" (a
// file of the generated submission), "text", "symlink" (the link's target,
// where @PT_CHECKOUT@ is the instructor's checkout)}.
std::string write_zip(const fs::path& zip, const json& entries, const fs::path& tasks, const std::string& checkout) {
  std::unique_ptr<archive, int (*)(archive*)> a(archive_write_new(), archive_write_free);
  archive_write_set_format_zip(a.get());
  if (archive_write_open_filename(a.get(), zip.c_str()) != ARCHIVE_OK) return archive_error_string(a.get());
  for (const auto& e : entries) {
    std::unique_ptr<archive_entry, void (*)(archive_entry*)> entry(archive_entry_new(), archive_entry_free);
    archive_entry_set_pathname(entry.get(), e.at("name").get<std::string>().c_str());
    std::string data;
    if (e.contains("symlink")) {
      archive_entry_set_filetype(entry.get(), AE_IFLNK);
      archive_entry_set_perm(entry.get(), 0777);
      std::string target = e["symlink"];
      if (const auto at = target.find("@PT_CHECKOUT@"); at != std::string::npos) target.replace(at, 13, checkout);
      archive_entry_set_symlink(entry.get(), target.c_str());
    } else {
      data = e.contains("from") ? read_file(tasks / e["from"].get<std::string>()) : e.value("text", "");
      archive_entry_set_filetype(entry.get(), AE_IFREG);
      archive_entry_set_perm(entry.get(), 0644);
      archive_entry_set_size(entry.get(), static_cast<la_int64_t>(data.size()));
    }
    if (archive_write_header(a.get(), entry.get()) != ARCHIVE_OK) return archive_error_string(a.get());
    if (!data.empty() && archive_write_data(a.get(), data.data(), data.size()) < 0) return archive_error_string(a.get());
  }
  return archive_write_close(a.get()) == ARCHIVE_OK ? "" : archive_error_string(a.get());
}

// The words a lost test's message must hold when a layer before the run
// stopped its part (the messages of autograder/submission/submission.cpp).
std::string layer_pattern(const std::string& stopped_at) {
  if (stopped_at == "intake") return "rejected before building";
  if (stopped_at == "build") return "does not build|did not build within|the compiler read files outside";
  return "";
}

// The bytes in use on the filesystem that holds `path`.
uint64_t used_bytes(const std::string& path) {
  struct statvfs s{};
  if (::statvfs(path.c_str(), &s) != 0) return 0;
  return (uint64_t(s.f_blocks) - s.f_bfree) * s.f_frsize;
}

// The most the filesystem of `path` held beyond its use at the start, sampled
// every 20 ms while the grader runs: what the submission cost the host's disk
// (other work on the machine adds to it; a bound is set with room for that).
class DiskPeak {
 public:
  explicit DiskPeak(std::string path) : path_(std::move(path)), start_(used_bytes(path_)) {
    sampler_ = std::thread([this] {
      while (!stop_) {
        const uint64_t used = used_bytes(path_);
        if (used > peak_) peak_ = used;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    });
  }
  ~DiskPeak() { finish(); }
  uint64_t finish() {
    if (sampler_.joinable()) {
      stop_ = true;
      sampler_.join();
    }
    return peak_ > start_ ? peak_ - start_ : 0;
  }

 private:
  std::string path_;
  uint64_t start_;
  std::atomic<uint64_t> peak_{0};
  std::atomic<bool> stop_{false};
  std::thread sampler_;
};

// The folder of the results: who owns it, its mode, what is in it. Nothing
// but the grader's own files may change in it.
struct FolderState {
  uid_t owner = 0;
  mode_t mode = 0;
  std::set<std::string> entries;
};

FolderState folder_state(const fs::path& dir) {
  FolderState f;
  struct stat st{};
  if (::lstat(dir.c_str(), &st) == 0) f.owner = st.st_uid, f.mode = st.st_mode;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) f.entries.insert(e.path().filename().string());
  return f;
}

// The IPC objects this machine holds in the grader's IPC namespace: System V
// shared memory, queues and semaphore sets by kind, key and id, and POSIX
// message queues by name. Killing processes frees none of them, so a run's
// objects must never be here (the sandbox gives each run an IPC namespace
// and seccomp refuses the calls). POSIX queues are listed from /dev/mqueue,
// or, where it is not mounted, from an mqueue filesystem that a child mounts
// in a mount namespace of its own (as root; otherwise they are not compared,
// and *note says so).
std::set<std::string> ipc_objects(std::string* note) {
  std::set<std::string> found;
  for (const char* kind : {"shm", "msg", "sem"}) {
    std::ifstream list(std::string("/proc/sysvipc/") + kind);
    std::string line;
    std::getline(list, line);  // the header
    while (std::getline(list, line)) {
      std::istringstream fields(line);
      std::string key, id;
      if (fields >> key >> id) found.insert(std::string(kind) + " key " + key + " id " + id);
    }
  }
  auto list_queues = [&found](const std::string& dir) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) found.insert("mq " + e.path().filename().string());
  };
  if (fs::exists("/dev/mqueue/.")) {
    list_queues("/dev/mqueue");
    return found;
  }
  char dir[] = "/tmp/pt-hostile-mqueue-XXXXXX";
  int fds[2];
  if (!::mkdtemp(dir) || ::pipe(fds) != 0) {
    *note = "POSIX message queues not compared: no folder or pipe to list them";
    return found;
  }
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(fds[0]);
    if (::unshare(CLONE_NEWNS) != 0 || ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0 ||
        ::mount("mqueue", dir, "mqueue", 0, nullptr) != 0)
      ::_exit(1);
    std::string names;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) names += e.path().filename().string() + "\n";
    [[maybe_unused]] auto n = ::write(fds[1], names.data(), names.size());
    ::_exit(0);
  }
  ::close(fds[1]);
  std::string names;
  char buf[4096];
  for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;) names.append(buf, static_cast<size_t>(n));
  ::close(fds[0]);
  int status = 1;
  if (child > 0) ::waitpid(child, &status, 0);
  ::rmdir(dir);
  if (child < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    *note = "POSIX message queues not compared: /dev/mqueue is not mounted and this checker cannot mount one";
    return found;
  }
  std::istringstream lines(names);
  for (std::string name; std::getline(lines, name);) found.insert("mq " + name);
  return found;
}

struct Checker {
  std::vector<std::string> failures;
  void expect(bool ok, const std::string& what) {
    if (!ok) failures.push_back(what);
  }
};

}  // namespace

int main(int argc, char** argv) {
  std::string case_dir, manifest_path, results_path, source_dir, pt_grade, zip_path, tasks_dir;
  std::vector<std::string> command;
  bool fallback = false, submission = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](std::string& out) {
      if (i + 1 < argc) out = argv[++i];
    };
    if (a == "--case") value(case_dir);
    else if (a == "--manifest") value(manifest_path);
    else if (a == "--results") value(results_path);
    else if (a == "--source-dir") value(source_dir);
    else if (a == "--pt-grade") value(pt_grade);
    else if (a == "--fallback") fallback = true;
    else if (a == "--submission") submission = true;
    else if (a == "--zip") value(zip_path);
    else if (a == "--tasks") value(tasks_dir);
    else if (a == "--") {
      command.assign(argv + i + 1, argv + argc);
      break;
    }
  }
  if (case_dir.empty() || manifest_path.empty() || results_path.empty() || command.empty()) {
    std::fprintf(stderr, "usage: pt-hostile-check --case DIR --manifest FILE --results FILE --source-dir DIR "
                         "--pt-grade PT_GRADE [--fallback] [--submission [--tasks DIR] [--zip FILE]] -- COMMAND...\n");
    return 2;
  }
  // A harness (this program, or Gradescope's) should keep the grader's paths
  // off its own command line too: without a PID namespace the code under test
  // reads every ancestor's (proc_cmdline's fallback).
  hide_command_line(argc, argv, "pt-hostile-check");
  json expect, manifest;
  try {
    expect = json::parse(read_file(case_dir + "/expect.json"));
    manifest = json::parse(read_file(manifest_path));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pt-hostile-check: %s\n", e.what());
    return 2;
  }
  // Under `pt-grade submission` the case's "submission" keys replace the others.
  if (submission && expect.contains("submission"))
    for (const auto& [key, value] : expect["submission"].items()) {
      if (value.is_null())
        expect.erase(key);  // what the run would show, where the submission never runs
      else
        expect[key] = value;
    }
  const int part = expect.at("part").get<int>();
  std::printf("case %s%s: %s\n", case_dir.c_str(), submission ? " (pt-grade submission)" : "",
              expect.value("attack", "").c_str());

  // A case that needs a layer this machine does not offer is skipped before
  // it runs: a fork bomb is not something to try without a process limit.
  const json needs = fallback ? expect["fallback"].value("needs", json::array()) : expect.value("needs", json::array());
  if (!needs.empty()) {
    std::vector<std::string> query{pt_grade, "sandbox"};
    for (size_t i = 0; i < command.size(); ++i)  // the sandbox the command asks for
      if (command[i] == "--no-sandbox")
        query.push_back(command[i]);
      else if ((command[i] == "--sandbox-without" || command[i] == "--sandbox-user") && i + 1 < command.size())
        query.insert(query.end(), {command[i], command[i + 1]});
    std::string info;
    if (run_command(query, &info) != 0) {
      std::fprintf(stderr, "pt-hostile-check: %s sandbox failed\n", pt_grade.c_str());
      return 2;
    }
    const json layers = json::parse(info);
    for (const auto& need : needs) {
      const auto& ids = layers.at("ids");
      if (std::find(ids.begin(), ids.end(), need) == ids.end()) {
        std::printf("SKIPPED: this case needs the sandbox layer \"%s\", which this machine does not offer (%s)\n",
                    need.get<std::string>().c_str(), layers.at("missing").dump().c_str());
        return 77;
      }
    }
  }

  // The parts the submission holds: the case's, and its "others".
  std::set<int> submitted{part};
  const json others = expect.value("others", json::object());
  for (const auto& [n, other] : others.items()) submitted.insert(std::stoi(n));
  std::error_code made;
  fs::create_directories(fs::path(results_path).parent_path(), made);
  if (!zip_path.empty()) {
    const std::string error = write_zip(zip_path, expect.at("zip"), tasks_dir, source_dir);
    if (!error.empty()) {
      std::fprintf(stderr, "pt-hostile-check: cannot write %s: %s\n", zip_path.c_str(), error.c_str());
      return 2;
    }
  }
  const std::string work = argument_of(command, "--work");
  if (!work.empty()) {  // what a killed grader left last time
    std::error_code ec;
    fs::remove_all(work, ec);
  }

  // Orphans of the grader's runs are handed to this program, not to init: the
  // process check below finds them whatever they have become.
  ::prctl(PR_SET_CHILD_SUBREAPER, 1);
  ::unlink(results_path.c_str());
  const fs::path results_dir = fs::absolute(results_path).parent_path();
  const FolderState before = folder_state(results_dir);
  std::string ipc_note;
  const std::set<std::string> ipc_before = ipc_objects(&ipc_note);
  const double kill_after = expect.value("kill_grader_after", 0.0);
  DiskPeak disk(results_dir.string());
  // The grader's standard output is kept (its size, and no hidden name in it)
  // and passed on, its head, to this program's; a grader killed from outside
  // prints to this program's directly.
  std::string printed;
  pt::grade::CommandOptions keep_printed;
  keep_printed.max_output = 64u << 20;
  keep_printed.kill_after = kill_after;
  const int status = run_command(command, kill_after > 0 ? nullptr : &printed, keep_printed);
  if (!printed.empty()) std::printf("%s\n", printed.substr(0, 256u << 10).c_str());
  const uint64_t disk_peak = disk.finish();
  const std::string written = read_file(results_path);
  std::this_thread::sleep_for(std::chrono::duration<double>(expect.value("settle_seconds", 0.0)));
  const std::string settled = read_file(results_path);

  Checker c;
  const int want_status = kill_after > 0 ? 128 + SIGKILL : 0;
  c.expect(status == want_status,
           "the grader exited with status " + std::to_string(status) + ", not " + std::to_string(want_status));
  // A grader that returns has killed every process of its runs; one that is
  // killed takes them with it within moments (the warden's and the build's
  // death signals): up to 10 s on a loaded machine, where a process killed
  // may wait to be scheduled before it dies. A daemon that escaped stays.
  std::vector<pid_t> left_pids;
  if (kill_after > 0) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!live_descendants(false).empty() && std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  left_pids = live_descendants(true);
  end_descendants(left_pids);
  const size_t left = left_pids.size();
  c.expect(left == 0, std::to_string(left) + " process(es) of the run outlived the grader");
  // Nothing left in IPC: no System V object or POSIX queue that was not there before.
  for (const std::string& object : ipc_objects(&ipc_note))
    c.expect(ipc_before.count(object) > 0, "left in IPC after the grader: " + object);
  if (!ipc_note.empty()) std::printf("%s\n", ipc_note.c_str());
  if (!work.empty() && kill_after == 0) {
    std::error_code ec;
    c.expect(fs::is_empty(work, ec) || !fs::exists(work), "the grader left files in " + work);
  }
  // Nothing written beside the grader's own files, the folder still the grader's.
  const FolderState after = folder_state(results_dir);
  auto grader_wrote = [&](const std::string& e) {
    if (before.entries.count(e)) return true;
    for (const std::string& p : {results_path, argument_of(command, "--html"), work})
      if (!p.empty() && e.rfind(fs::path(p).filename().string(), 0) == 0) return true;
    return false;
  };
  for (const auto& e : after.entries) c.expect(grader_wrote(e), "something else wrote " + (results_dir / e).string());
  c.expect(after.owner == before.owner && after.mode == before.mode,
           results_dir.string() + " changed owner or mode (" + std::to_string(before.owner) + " -> " +
               std::to_string(after.owner) + ")");
  std::printf("disk: at most %.0f MiB more in use on the results' filesystem while the grader ran\n",
              double(disk_peak) / (1 << 20));
  if (expect.contains("max_disk_mib"))
    c.expect(disk_peak <= expect["max_disk_mib"].get<uint64_t>() << 20,
             "the grader's disk use reached " + std::to_string(disk_peak >> 20) + " MiB, over " +
                 std::to_string(expect["max_disk_mib"].get<uint64_t>()) + " MiB");
  c.expect(!written.empty(), "no results.json at " + results_path);
  c.expect(settled == written, "results.json changed after the grader had finished");
  json results;
  try {
    results = json::parse(settled);
  } catch (const std::exception& e) {
    c.expect(false, std::string("results.json does not parse: ") + e.what());
  }
  if (!results.is_object()) results = json::object();  // checked below as a report that lists nothing
  const json& pt = results.is_object() ? results["extra_data"]["pt_grade"] : json();
  c.expect(pt.is_object() && pt.value("complete", false) == (kill_after == 0),
           kill_after > 0 ? "results.json says it is complete, yet the grader was killed"
                          : "results.json does not say the grading completed");

  // Every test of the parts checked: the case's part, or under `submission` all.
  std::map<std::string, json> listed;
  for (const auto& t : results.value("tests", json::array()))
    if (t.contains("extra_data") && t["extra_data"].contains("part"))
      listed[std::to_string(t["extra_data"].value("part", 0)) + "/" + t["extra_data"].value("test", "")] = t;
  const std::string stopped_at = expect.value("stopped_at", "run");
  std::set<std::string> lost;
  for (const auto& task : expect.value("lost_tasks", json::array())) lost.insert(task.get<std::string>());
  std::set<std::string> lost_tests;  // single tests, where an attack loses part of a task
  for (const auto& test : expect.value("lost_tests", json::array())) lost_tests.insert(test.get<std::string>());
  if (stopped_at != "run" && !expect.contains("lost_tasks"))  // the whole part, by default
    for (const auto& m : manifest["parts"][std::to_string(part)]) lost.insert(m.at("task").get<std::string>());
  // Messages are several lines: [\s\S] matches any character in them.
  const std::regex failure(expect.value("failure", "[\\s\\S]*"));
  const std::regex layer(layer_pattern(stopped_at));
  const std::regex not_submitted("not submitted|submission rejected before building");
  double want_score = 0, got_score = 0, max_score = 0;
  size_t not_run = 0, checked = 0;
  // Extension tests are worth their points only when the grader counts them.
  const bool count_extensions = std::find(command.begin(), command.end(), "--count-extensions") != command.end();
  for (const auto& [n, tests] : manifest["parts"].items()) {
    const int p = std::stoi(n);
    if (!submission && p != part) continue;
    double part_max = 0;
    for (const auto& m : tests) {
      const std::string name = m.at("test"), task = m.at("task");
      const double points = m.value("extension", false) && !count_extensions ? 0.0 : m.at("points").get<double>();
      part_max += points;
      ++checked;
      auto it = listed.find(n + "/" + name);
      if (it == listed.end()) {
        c.expect(false, name + " (part " + n + ") is missing from results.json");
        continue;
      }
      const json& t = it->second;
      const double score = t.value("score", -1.0), max = t.value("max_score", -1.0);
      const std::string output = t.value("output", "");
      got_score += score;
      not_run += t["extra_data"].value("result", "") == "not-run";
      c.expect(max == points, name + ": max_score " + std::to_string(max) + ", the manifest says " + std::to_string(points));
      if (!submitted.count(p)) {
        c.expect(score == 0 && std::regex_search(output, not_submitted),
                 name + " (part " + n + ", not submitted) scored " + std::to_string(score) + ": " + output.substr(0, 200));
      } else if (lost.count(task) || lost_tests.count(name)) {
        c.expect(score == 0, name + " (" + task + ") scored " + std::to_string(score));
        c.expect(std::regex_search(output, failure),
                 name + ": its message does not match /" + expect.value("failure", "") + "/: " + output.substr(0, 300));
        if (p == part && stopped_at != "run")
          c.expect(std::regex_search(output, layer), name + ": its message does not say the " + stopped_at +
                                                         " stopped it: " + output.substr(0, 300));
      } else {
        want_score += points;
        c.expect(score == points, name + " (" + task + ") scored " + std::to_string(score) + " of " +
                                      std::to_string(points) + ": " + output.substr(0, 300));
      }
    }
    max_score += part_max;
    if (pt.is_object() && pt.contains("parts") && pt["parts"].contains(n)) {
      const json& summary = pt["parts"][n];
      c.expect(std::abs(summary.value("possible", -1.0) - part_max) < 1e-9,
               "part " + n + " is worth " + std::to_string(summary.value("possible", -1.0)) + ", the manifest says " +
                   std::to_string(part_max));
      // The layer that stopped the case's part: a part stopped before the run was never graded.
      if (submission && p == part && kill_after == 0)
        c.expect(summary.value("graded", false) == (stopped_at == "run"),
                 "part " + n + (stopped_at == "run" ? " was not graded" : " was graded, yet the " + stopped_at + " should have stopped it"));
    } else {
      c.expect(false, "results.json has no summary of part " + n);
    }
  }
  size_t listed_checked = 0;
  for (const auto& [key, t] : listed) listed_checked += submission || key.rfind(std::to_string(part) + "/", 0) == 0;
  c.expect(listed_checked == checked, "results.json lists " + std::to_string(listed_checked) + " graded tests, the manifest " +
                                          std::to_string(checked));
  const double total = results.value("score", -1.0);
  c.expect(std::abs(total - want_score) < 1e-9,
           "total score " + std::to_string(total) + ", expected " + std::to_string(want_score));
  c.expect(std::abs(total - got_score) < 1e-9, "the total is not the sum of the tests' scores");
  if (expect.value("budget_cut", false))
    c.expect(not_run > 0, "no test was left unrun: the part's budget was not what stopped the grading");
  if (expect.contains("note"))
    c.expect(std::regex_search(results.value("output", ""), std::regex(expect["note"].get<std::string>())),
             "no note matching /" + expect["note"].get<std::string>() + "/ in the report's output");
  std::printf("sizes: results.json %zu bytes, standard output %zu bytes\n", settled.size(), printed.size());
  if (expect.contains("max_results_bytes"))
    c.expect(settled.size() <= expect["max_results_bytes"].get<size_t>(),
             "results.json is " + std::to_string(settled.size()) + " bytes");
  if (expect.contains("max_stdout_bytes"))
    c.expect(printed.size() <= expect["max_stdout_bytes"].get<size_t>(),
             "the grader printed " + std::to_string(printed.size()) + " bytes");
  const std::string html_path = argument_of(command, "--html");
  const std::string page = html_path.empty() ? "" : read_file(html_path);
  if (!html_path.empty()) std::printf("sizes: report.html %zu bytes\n", page.size());
  if (expect.contains("max_report_bytes") && !html_path.empty())  // the page is written under `submission` alone
    c.expect(!page.empty() && page.size() <= expect["max_report_bytes"].get<size_t>(),
             "report.html is " + std::to_string(page.size()) + " bytes");
  // No hidden test's name where a student or the page could read it: in the
  // visible tests' messages and the notes of results.json, on standard
  // output, in report.html (where hidden tests appear only when they fail).
  if (expect.value("no_hidden_names", false)) {
    std::string visible = results.value("output", "");
    for (const auto& t : results.value("tests", json::array()))
      if (t.value("visibility", "") == "visible") visible += "\n" + t.value("output", "");
    for (const auto& [n, tests] : manifest["parts"].items())
      for (const auto& m : tests) {
        if (m.value("visibility", "") != "hidden") continue;
        const std::string name = m.at("test");
        c.expect(visible.find(name) == std::string::npos, "results.json shows the hidden test " + name + " to students");
        c.expect(printed.find(name) == std::string::npos, "the grader printed the hidden test " + name);
        c.expect(page.find(name) == std::string::npos, "report.html names the hidden test " + name);
      }
  }

  // No line of the solution or of a hidden test, unless the submission itself
  // holds it (a student may see their own code in a compiler's message).
  std::set<std::string> own;
  std::vector<fs::path> secrets;
  std::error_code ec;
  if (!tasks_dir.empty())
    for (const auto& e : fs::directory_iterator(tasks_dir, ec))
      for (const auto& line : telling_lines(read_file(e.path()))) own.insert(line);
  for (const auto& file : expect.value("no_text_of", json::array())) secrets.push_back(fs::path(source_dir) / file.get<std::string>());
  for (const char* folder : {"reference", "tests/part1/hidden", "tests/part2/hidden", "tests/part3/hidden",
                             "tests/part4/hidden", "tests/part5/hidden"})
    for (const auto& e : fs::directory_iterator(fs::path(source_dir) / folder, ec)) secrets.push_back(e.path());
  for (const auto& file : secrets)
    for (const auto& line : telling_lines(read_file(file))) {
      const std::string quoted = json(line).dump();
      if (!own.count(line) && settled.find(quoted.substr(1, quoted.size() - 2)) != std::string::npos) {
        c.expect(false, "results.json holds a line of " + fs::relative(file, source_dir).string() + ": " + line);
        break;
      }
    }

  // The grader's own paths (its command line) are not the code's to read.
  if (expect.value("no_grader_paths", false))
    for (const char* flag : {"--json", "--html", "--kit"}) {
      const std::string path = argument_of(command, flag);
      if (!path.empty())
        c.expect(settled.find(fs::absolute(path).string()) == std::string::npos,
                 "the report shows the grader's " + std::string(flag) + " " + path);
    }

  std::printf("score %g of %g (expected %g)\n", total, max_score, want_score);
  if (c.failures.empty()) {
    std::printf("honest\n");
    return 0;
  }
  // The first few say what is wrong; a whole part wrong the same way would repeat it for every test.
  for (size_t i = 0; i < c.failures.size() && i < 8; ++i) std::printf("NOT HONEST: %s\n", c.failures[i].c_str());
  if (c.failures.size() > 8) std::printf("NOT HONEST: ... and %zu more\n", c.failures.size() - 8);
  return 1;
}
