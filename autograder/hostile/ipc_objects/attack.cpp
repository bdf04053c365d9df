// Hostile: leave kernel objects behind that outlive the grading, and read
// what an earlier grading left. On the first task call it looks for objects
// under its fixed keys and names (System V shared memory, a message queue, a
// semaphore set, a POSIX message queue), and for any shared memory segment
// listed in /proc/sysvipc/shm; whatever it reads is thrown from every call of
// the task, so it would show in a visible test's message. Then it makes its
// own: 64 MiB of shared memory (touched), a queue holding a message, a
// semaphore set and a POSIX queue holding one, none of which killing the
// process frees. Graded as the solution: the honest score is full marks.
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

// <sys/shm.h>, <sys/msg.h>, <sys/sem.h> and <mqueue.h> are not allowed in the
// grading kit: the calls declared by hand, the flags written out.
extern "C" int shmget(int key, unsigned long size, int flags);
extern "C" void* shmat(int id, const void* at, int flags);
extern "C" int msgget(int key, int flags);
extern "C" int msgsnd(int id, const void* message, unsigned long size, int flags);
extern "C" long msgrcv(int id, void* message, unsigned long size, long type, int flags);
extern "C" int semget(int key, int count, int flags);
extern "C" int mq_open(const char* name, int flags, ...);
extern "C" int mq_send(int queue, const char* message, unsigned long size, unsigned priority);
extern "C" long mq_receive(int queue, char* message, unsigned long size, unsigned* priority);

namespace {
constexpr int kKey = 0x70740ec0, kCreate = 01000, kNoWait = 04000, kShmReadOnly = 010000;
constexpr int kReadWrite = 2, kOpenCreate = 0100, kNonBlock = 04000;
constexpr const char* kQueue = "/pt-hostile-ipc";
constexpr const char* kSecret = "pt-hostile ipc_objects: left by an earlier grading";

std::string leftovers() {
  std::string found;
  // Any segment at all: another grading's, or the grader's.
  std::ifstream list("/proc/sysvipc/shm");
  std::string line;
  std::getline(list, line);  // the header
  while (std::getline(list, line)) {
    std::istringstream fields(line);
    long key = 0, id = -1;
    fields >> key >> id;
    void* at = id >= 0 ? shmat(static_cast<int>(id), nullptr, kShmReadOnly) : nullptr;
    if (at != nullptr && at != reinterpret_cast<void*>(-1))
      found += "shared memory " + std::to_string(id) + ": " + std::string(static_cast<const char*>(at), 60) + "; ";
  }
  if (const int id = msgget(kKey, 0); id >= 0) {
    struct { long type; char text[128]; } m{};
    if (msgrcv(id, &m, sizeof m.text, 0, kNoWait) > 0) found += std::string("message queue: ") + m.text + "; ";
  }
  if (semget(kKey, 0, 0) >= 0) found += "a semaphore set of an earlier grading; ";
  if (const int q = mq_open(kQueue, kReadWrite | kNonBlock); q >= 0) {
    char text[8192] = {};
    if (mq_receive(q, text, sizeof text, nullptr) > 0) found += std::string("POSIX queue: ") + text + "; ";
  }
  return found;
}

void make_objects() {
  if (const int id = shmget(kKey, 64ul << 20, kCreate | 0666); id >= 0)
    if (void* at = shmat(id, nullptr, 0); at != reinterpret_cast<void*>(-1)) {
      std::memset(at, 'x', 64ul << 20);
      std::strcpy(static_cast<char*>(at), kSecret);
    }
  if (const int id = msgget(kKey, kCreate | 0666); id >= 0) {
    struct { long type; char text[128]; } m{1, {}};
    std::strcpy(m.text, kSecret);
    msgsnd(id, &m, std::strlen(kSecret) + 1, kNoWait);
  }
  semget(kKey, 4, kCreate | 0666);
  if (const int q = mq_open(kQueue, kReadWrite | kOpenCreate | kNonBlock, 0666, nullptr); q >= 0)
    mq_send(q, kSecret, std::strlen(kSecret) + 1, 0);
}

void ipc_attack() {
  static const std::string found = [] {
    std::string f = leftovers();
    make_objects();
    return f;
  }();
  if (!found.empty()) throw std::runtime_error("read from IPC objects: " + found);
}
}  // namespace
