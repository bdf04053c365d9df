#include "intake/submission_files.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>

#include <archive.h>
#include <archive_entry.h>

namespace pt::grade {

namespace {

namespace fs = std::filesystem;

// One entry of the submission, before its path is judged.
struct Entry {
  std::string path;  // '/'-separated, relative
  bool regular = true;
  std::string text;  // at most kMaxTaskFileBytes + 1 bytes
};

bool is_metadata(const std::string& path) {
  const std::string name = path.substr(path.find_last_of('/') + 1);
  return path.rfind("__MACOSX/", 0) == 0 || path.find("/__MACOSX/") != std::string::npos || name == ".DS_Store" ||
         name == "Thumbs.db" || name == "desktop.ini";
}

std::string read_prefix(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::string text(kMaxTaskFileBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(in.gcount()));
  return text;
}

bool read_folder(const fs::path& root, std::vector<Entry>* entries, std::vector<std::string>* problems) {
  std::error_code ec;
  fs::recursive_directory_iterator it(root, fs::directory_options::none, ec), end;
  if (ec) {
    problems->push_back("cannot read the folder " + root.string() + ": " + ec.message());
    return false;
  }
  for (; it != end; it.increment(ec)) {
    if (ec) {
      problems->push_back("cannot read the folder " + root.string() + ": " + ec.message());
      return false;
    }
    if (entries->size() >= kMaxSubmissionEntries) {
      problems->push_back("more than " + std::to_string(kMaxSubmissionEntries) + " files: not a set of task files");
      return false;
    }
    const fs::file_status st = it->symlink_status(ec);
    if (fs::is_directory(st)) continue;
    Entry e;
    e.path = it->path().lexically_relative(root).generic_string();  // of the link, not its target
    e.regular = fs::is_regular_file(st);
    if (e.regular && !is_metadata(e.path)) e.text = read_prefix(it->path());
    entries->push_back(std::move(e));
  }
  return true;
}

bool read_zip(const std::string& path, std::vector<Entry>* entries, std::vector<std::string>* problems) {
  std::unique_ptr<archive, int (*)(archive*)> a(archive_read_new(), archive_read_free);
  archive_read_support_format_zip(a.get());
  archive_read_support_filter_none(a.get());
  if (archive_read_open_filename(a.get(), path.c_str(), 64 * 1024) != ARCHIVE_OK) {
    problems->push_back("cannot read " + path + " as a zip file: " + archive_error_string(a.get()));
    return false;
  }
  archive_entry* entry = nullptr;
  for (;;) {
    const int r = archive_read_next_header(a.get(), &entry);
    if (r == ARCHIVE_EOF) break;
    if (r != ARCHIVE_OK && r != ARCHIVE_WARN) {
      problems->push_back(path + " is damaged: " + std::string(archive_error_string(a.get())));
      return false;
    }
    if (entries->size() >= kMaxSubmissionEntries) {
      problems->push_back("more than " + std::to_string(kMaxSubmissionEntries) + " files: not a set of task files");
      return false;
    }
    const char* name = archive_entry_pathname(entry);
    Entry e;
    e.path = name ? name : "";
    while (e.path.rfind("./", 0) == 0) e.path = e.path.substr(2);
    const auto type = archive_entry_filetype(entry);
    if (type == AE_IFDIR || (!e.path.empty() && e.path.back() == '/')) continue;
    e.regular = type == AE_IFREG;
    if (e.regular && !is_metadata(e.path)) {
      e.text.resize(kMaxTaskFileBytes + 1);
      size_t got = 0;
      while (got < e.text.size()) {
        const la_ssize_t n = archive_read_data(a.get(), e.text.data() + got, e.text.size() - got);
        if (n < 0) {
          problems->push_back(e.path + " in " + path + " cannot be unpacked: " + archive_error_string(a.get()));
          return false;
        }
        if (n == 0) break;
        got += static_cast<size_t>(n);
      }
      e.text.resize(got);
    }
    entries->push_back(std::move(e));
  }
  return true;
}

// The folder every entry lies in, if there is exactly one (zipping a folder).
std::string common_folder(const std::vector<Entry>& entries) {
  std::string first;
  for (const Entry& e : entries) {
    if (is_metadata(e.path)) continue;
    const size_t slash = e.path.find('/');
    if (slash == std::string::npos) return "";
    const std::string top = e.path.substr(0, slash + 1);
    if (top == "tasks/") return "";
    if (first.empty()) first = top;
    else if (top != first) return "";
  }
  return first;
}

}  // namespace

Submission read_submission(const std::string& path, const std::map<int, std::string>& expected) {
  Submission sub;
  std::vector<Entry> entries;
  std::error_code ec;
  const bool ok = fs::is_directory(path, ec)                              ? read_folder(path, &entries, &sub.problems)
                  : fs::is_regular_file(path, ec) && path.size() > 4 &&
                          path.compare(path.size() - 4, 4, ".zip") == 0 ? read_zip(path, &entries, &sub.problems)
                                                                           : false;
  if (!ok) {
    if (sub.problems.empty()) sub.problems.push_back(path + " is neither a folder nor a .zip file");
    return sub;
  }
  const std::string wrapper = common_folder(entries);
  std::vector<std::string> unknown;
  std::map<int, std::string> seen_where;
  for (Entry& e : entries) {
    if (is_metadata(e.path)) {
      sub.notes.push_back("skipped " + e.path + " (operating system metadata)");
      continue;
    }
    std::string rel = e.path.substr(wrapper.size());
    if (rel.rfind("tasks/", 0) == 0) rel = rel.substr(6);
    int part = 0;
    for (const auto& [n, name] : expected)
      if (rel == name) part = n;
    if (part == 0 || e.path.find("..") != std::string::npos) {
      unknown.push_back(e.path);
      continue;
    }
    if (!e.regular) {
      sub.problems.push_back(e.path + " is not a regular file (a link or a device)");
      continue;
    }
    if (seen_where.count(part)) {
      sub.problems.push_back("part " + std::to_string(part) + " is submitted twice: " + seen_where[part] + " and " + e.path);
      continue;
    }
    seen_where[part] = e.path;
    TaskFile f;
    f.part = part;
    f.name = rel;
    f.where = e.path;
    f.too_large = e.text.size() > kMaxTaskFileBytes;
    if (!f.too_large) f.text = std::move(e.text);
    sub.files.push_back(std::move(f));
  }
  if (!unknown.empty()) {
    std::string list;
    for (size_t i = 0; i < unknown.size() && i < 8; ++i) list += (i ? ", " : "") + unknown[i];
    if (unknown.size() > 8) list += ", ... (" + std::to_string(unknown.size()) + " in all)";
    std::string names;
    for (const auto& [n, name] : expected) names += (names.empty() ? "" : ", ") + name;
    sub.problems.push_back("files other than the task files: " + list + ". Submit only " + names +
                           " (at the top level or in tasks/), and nothing else.");
  }
  if (sub.problems.empty() && sub.files.empty()) sub.problems.push_back("no task file found in " + path);
  std::sort(sub.files.begin(), sub.files.end(), [](const TaskFile& a, const TaskFile& b) { return a.part < b.part; });
  return sub;
}

}  // namespace pt::grade
