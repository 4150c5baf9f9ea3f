// Safe, bounded reading of config files. docs/architecture.md, "Configs".
#include "core/config/config_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/config/config_limits.hpp"

namespace corrmp {

namespace {

// Closes a file descriptor when it goes out of scope.
struct FileDescriptor {
  int fd = -1;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

[[noreturn]] void fail(const std::string& path, const SourceLocation* included_from,
                       const std::string& problem) {
  if (included_from != nullptr) {
    throw ConfigError(*included_from, "include", "included file '" + path + "' " + problem);
  }
  throw ConfigError(SourceLocation{path, 0, 0}, "", problem);
}

std::string too_large() {
  return "is larger than " + describe_bytes(kMaxConfigFileBytes) + ", the limit for a config file";
}

}  // namespace

std::string read_config_file(const std::string& path, const SourceLocation* included_from) {
  // Non-blocking, so that opening a FIFO does not wait for a writer; fstat on
  // the open descriptor then decides what it is.
  FileDescriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) {
    const int error = errno;
    if (error == ENOENT || error == ENOTDIR) fail(path, included_from, "does not exist");
    fail(path, included_from, std::string("cannot be opened: ") + std::strerror(error));
  }
  struct stat status {};
  if (::fstat(file.fd, &status) != 0) {
    fail(path, included_from, std::string("cannot be read: ") + std::strerror(errno));
  }
  if (S_ISDIR(status.st_mode)) fail(path, included_from, "is a directory, not a config file");
  if (!S_ISREG(status.st_mode)) {
    fail(path, included_from, "is not a regular file (a device, FIFO or socket?)");
  }
  if (static_cast<unsigned long long>(status.st_size) > kMaxConfigFileBytes) {
    fail(path, included_from, too_large());
  }
  // Read at most one byte past the limit: files such as those under /proc
  // report a size of 0 whatever they hold.
  std::string text;
  char buffer[65536];
  while (true) {
    const ssize_t got = ::read(file.fd, buffer, sizeof buffer);
    if (got < 0) {
      if (errno == EINTR) continue;
      fail(path, included_from, std::string("cannot be read: ") + std::strerror(errno));
    }
    if (got == 0) break;
    text.append(buffer, static_cast<std::size_t>(got));
    if (text.size() > kMaxConfigFileBytes) fail(path, included_from, too_large());
  }
  return text;
}

}  // namespace corrmp
