#include "sandbox/landlock.h"

#include <elf.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <utility>

namespace pt::grade {
namespace {

// Debian 12's kernel headers stop at ABI 2; the ABI is stable, so the later
// rights and fields are spelt out here (Documentation/userspace-api/landlock.rst).
struct RulesetAttr {
  uint64_t handled_access_fs;
  uint64_t handled_access_net;  // ABI 4
  uint64_t scoped;              // ABI 6
};
struct PathBeneathAttr {
  uint64_t allowed_access;
  int32_t parent_fd;
} __attribute__((packed));

constexpr uint32_t kCreateRulesetVersion = 1u << 0;
constexpr int kRulePathBeneath = 1;

constexpr uint64_t kExecute = 1ull << 0, kWriteFile = 1ull << 1, kReadFile = 1ull << 2, kReadDir = 1ull << 3,
                   kRemoveDir = 1ull << 4, kRemoveFile = 1ull << 5, kMakeChar = 1ull << 6, kMakeDir = 1ull << 7,
                   kMakeReg = 1ull << 8, kMakeSock = 1ull << 9, kMakeFifo = 1ull << 10, kMakeBlock = 1ull << 11,
                   kMakeSym = 1ull << 12, kRefer = 1ull << 13, kTruncate = 1ull << 14, kIoctlDev = 1ull << 15;
constexpr uint64_t kNetBindTcp = 1ull << 0, kNetConnectTcp = 1ull << 1;
constexpr uint64_t kScopeAbstractUnixSocket = 1ull << 0, kScopeSignal = 1ull << 1;

// Every filesystem right the ABI can handle: what is handled and not granted is denied.
uint64_t handled_fs(int abi) {
  uint64_t rights = kExecute | kWriteFile | kReadFile | kReadDir | kRemoveDir | kRemoveFile | kMakeChar | kMakeDir |
                    kMakeReg | kMakeSock | kMakeFifo | kMakeBlock | kMakeSym;
  if (abi >= 2) rights |= kRefer;
  if (abi >= 3) rights |= kTruncate;
  if (abi >= 5) rights |= kIoctlDev;
  return rights;
}

// Rights that only make sense on a folder; a rule on a file must not carry them.
constexpr uint64_t kFolderOnly =
    kReadDir | kRemoveDir | kRemoveFile | kMakeChar | kMakeDir | kMakeReg | kMakeSock | kMakeFifo | kMakeBlock |
    kMakeSym | kRefer;

std::string add_rule(int ruleset, const std::string& path, uint64_t rights, uint64_t handled) {
  const int fd = ::open(path.c_str(), O_PATH | O_CLOEXEC);
  if (fd < 0) return errno == ENOENT ? "" : path + ": " + std::strerror(errno);
  struct stat st;
  if (::fstat(fd, &st) == 0 && !S_ISDIR(st.st_mode)) rights &= ~kFolderOnly;
  PathBeneathAttr attr{rights & handled, fd};
  const long r = ::syscall(SYS_landlock_add_rule, ruleset, kRulePathBeneath, &attr, 0);
  const int err = errno;
  ::close(fd);
  return r == 0 ? "" : "rule for " + path + ": " + std::strerror(err);
}

}  // namespace

int landlock_abi() {
  const long abi = ::syscall(SYS_landlock_create_ruleset, nullptr, 0, kCreateRulesetVersion);
  return abi > 0 ? static_cast<int>(abi) : 0;
}

int landlock_ruleset(const LandlockRules& rules, int abi, std::string* error) {
  RulesetAttr attr{handled_fs(abi), 0, 0};
  size_t size = sizeof(uint64_t);
  if (abi >= 4) {
    attr.handled_access_net = kNetBindTcp | kNetConnectTcp;  // handled, never granted: no TCP at all
    size = 2 * sizeof(uint64_t);
  }
  if (abi >= 6) {
    attr.scoped = kScopeAbstractUnixSocket | kScopeSignal;
    size = sizeof attr;
  }
  const int ruleset = static_cast<int>(::syscall(SYS_landlock_create_ruleset, &attr, size, 0));
  if (ruleset < 0) {
    *error = std::string("landlock_create_ruleset: ") + std::strerror(errno);
    return -1;
  }
  const uint64_t read = kReadFile | kReadDir;
  const uint64_t write = read | kWriteFile | kRemoveDir | kRemoveFile | kMakeDir | kMakeReg | kRefer | kTruncate;
  error->clear();
  using Granted = std::pair<const std::vector<std::string>*, uint64_t>;
  for (const auto& [paths, rights] : {Granted{&rules.read, read}, Granted{&rules.write, write},
                                      Granted{&rules.execute, kExecute | kReadFile},
                                      Granted{&rules.devices, kReadFile | kWriteFile | kTruncate}})
    for (const auto& p : *paths)
      if (error->empty()) *error = add_rule(ruleset, p, rights, attr.handled_access_fs);
  if (error->empty()) return ruleset;
  ::close(ruleset);
  return -1;
}

std::string landlock_enforce(int ruleset) {
  return ::syscall(SYS_landlock_restrict_self, ruleset, 0) == 0
             ? ""
             : std::string("landlock_restrict_self: ") + std::strerror(errno);
}

std::string elf_interpreter(const std::string& binary) {
  std::ifstream in(binary, std::ios::binary);
  Elf64_Ehdr eh{};
  if (!in.read(reinterpret_cast<char*>(&eh), sizeof eh) || std::memcmp(eh.e_ident, ELFMAG, SELFMAG) != 0 ||
      eh.e_ident[EI_CLASS] != ELFCLASS64)
    return "";
  for (int i = 0; i < eh.e_phnum; ++i) {
    Elf64_Phdr ph{};
    in.seekg(static_cast<std::streamoff>(eh.e_phoff + static_cast<uint64_t>(i) * eh.e_phentsize));
    if (!in.read(reinterpret_cast<char*>(&ph), sizeof ph)) return "";
    if (ph.p_type != PT_INTERP || ph.p_filesz == 0 || ph.p_filesz > 4096) continue;
    std::string path(ph.p_filesz, '\0');
    in.seekg(static_cast<std::streamoff>(ph.p_offset));
    if (!in.read(path.data(), static_cast<std::streamsize>(path.size()))) return "";
    return path.c_str();  // drops the terminating NUL
  }
  return "";
}

}  // namespace pt::grade
