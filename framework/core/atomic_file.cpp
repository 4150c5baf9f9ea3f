// Atomic file writes (atomic_file.hpp).
#include "core/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace corrmp {

namespace {

namespace fs = std::filesystem;

constexpr const char* kTemporaryTag = ".tmp.";

std::string this_host() {
  char buffer[256] = {};
  if (::gethostname(buffer, sizeof buffer - 1) != 0 || buffer[0] == '\0') return "localhost";
  std::string host = buffer;
  for (char& c : host) {
    if (c == '/') c = '_';
  }
  return host;
}

bool all_digits(const std::string& text) {
  if (text.empty()) return false;
  for (const char c : text) {
    if (c < '0' || c > '9') return false;
  }
  return true;
}

// The host and process of a temporary name's "<host>.<pid>.<n>" tail, or false.
bool parse_tail(const std::string& tail, std::string& host, long& pid) {
  const size_t last = tail.rfind('.');
  if (last == std::string::npos || last == 0 || !all_digits(tail.substr(last + 1))) return false;
  const size_t middle = tail.rfind('.', last - 1);
  if (middle == std::string::npos || middle == 0) return false;
  const std::string pid_text = tail.substr(middle + 1, last - middle - 1);
  if (!all_digits(pid_text) || pid_text.size() > 9) return false;
  host = tail.substr(0, middle);
  pid = std::stol(pid_text);
  return true;
}

bool process_ended(long pid) { return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH; }

// Removes the temporary files of `path` that ended processes of this host
// left; best effort: a file that cannot be listed or removed stays.
void remove_stale_temporaries(const fs::path& target, const std::string& host) {
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const std::string name = target.filename().string();
  std::error_code ec;
  fs::directory_iterator it(folder, ec);
  for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
    const std::string entry = it->path().filename().string();
    if (!is_temporary_name(entry, name)) continue;
    std::string entry_host;
    long pid = 0;
    parse_tail(entry.substr(name.size() + std::strlen(kTemporaryTag)), entry_host, pid);
    if (entry_host == host && pid != ::getpid() && process_ended(pid)) {
      std::error_code ignored;
      fs::remove(it->path(), ignored);
    }
  }
}

// Makes a rename in `folder` durable; best effort, since some file systems
// cannot sync a folder and the file itself is already in place.
void sync_folder(const fs::path& folder) {
  const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

bool is_temporary_name(const std::string& name, const std::string& target) {
  const std::string prefix = target + kTemporaryTag;
  if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) return false;
  std::string host;
  long pid = 0;
  return parse_tail(name.substr(prefix.size()), host, pid);
}

void write_file_atomically(const std::string& path, const std::string& bytes) {
  static std::atomic<unsigned long> counter{0};
  const std::string host = this_host();
  const fs::path target(path);
  if (target.filename().empty()) throw FileError(path, "cannot write: not a file name");
  std::string temporary;
  int fd = -1;
  for (int attempt = 0; fd < 0; ++attempt) {
    temporary = path + kTemporaryTag + host + "." + std::to_string(::getpid()) + "." +
                std::to_string(counter++);
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0 && (errno != EEXIST || attempt == 100)) {
      if (errno == ENOENT) throw FileError(path, "cannot write: its folder does not exist");
      throw FileError(path, std::string("cannot create a temporary file: ") + std::strerror(errno));
    }
  }
  const auto fail = [&](const std::string& problem) {
    if (fd >= 0) ::close(fd);
    std::remove(temporary.c_str());
    throw FileError(path, problem);
  };
  const auto failed = [&](const char* what, int error) {
    fail(std::string("cannot ") + what + ": " + std::strerror(error));
  };
  size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) failed("write", n < 0 ? errno : ENOSPC);
    written += static_cast<size_t>(n);
  }
  if (::fsync(fd) != 0) failed("sync", errno);
  const int closed = ::close(fd);
  fd = -1;
  if (closed != 0) failed("close", errno);
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    if (errno == EISDIR) fail("is a directory");
    failed("rename into place", errno);
  }
  sync_folder(target.parent_path());
  remove_stale_temporaries(target, host);
}

}  // namespace corrmp
