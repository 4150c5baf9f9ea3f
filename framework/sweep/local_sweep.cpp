// Running a sweep's jobs as local processes (local_sweep.hpp).
#include "sweep/local_sweep.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <thread>

#include "core/interrupt.hpp"
#include "core/progress.hpp"
#include "experiment/interrupted_runs.hpp"
#include "store/result_store.hpp"
#include "sweep/sweep_folders.hpp"
#include "sweep/sweep_manifest.hpp"
#include "sweep/sweep_records.hpp"

namespace corrmp {

namespace fs = std::filesystem;

namespace {

// Held while this process drives the sweep; the kernel releases it when the process ends,
// however it ends, and the file is removed when the driver finishes (a killed driver leaves
// it, harmlessly: the next driver takes it).
class SweepLock {
 public:
  explicit SweepLock(const fs::path& path) : path_(path) {
    for (;;) {
      fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
      if (fd_ < 0) {
        throw std::runtime_error(fmt::format("cannot create the sweep's lock file {}: {}",
                                             path.string(), std::strerror(errno)));
      }
      if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        ::close(fd_);
        throw std::runtime_error(fmt::format(
            "another process is running this sweep (it holds {}); wait for it or stop it",
            path.string()));
      }
      // A driver that finished removes the file: the lock is ours only if the path still
      // names the file we locked.
      struct stat locked {
      }, named{};
      if (::fstat(fd_, &locked) == 0 && ::stat(path.c_str(), &named) == 0 &&
          locked.st_dev == named.st_dev && locked.st_ino == named.st_ino) {
        return;
      }
      ::close(fd_);
    }
  }
  ~SweepLock() {
    ::unlink(path_.c_str());  // while locked, so no other driver holds this file
    ::close(fd_);
  }
  SweepLock(const SweepLock&) = delete;
  SweepLock& operator=(const SweepLock&) = delete;

 private:
  fs::path path_;
  int fd_ = -1;
};

// Starts `argv` (argv[0] only names it: the child runs this very binary, even
// when the file was rebuilt meanwhile) with stdout and stderr appended to
// `log`; the child is killed when this process dies, so no job outlives its
// driver.
pid_t spawn(const std::vector<std::string>& argv, const fs::path& log) {
  const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (out < 0) throw std::runtime_error(fmt::format("cannot write {}", log.string()));
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(out);
    throw std::runtime_error("fork failed");
  }
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(137);  // the driver died before prctl took effect
    ::dup2(out, STDOUT_FILENO);
    ::dup2(out, STDERR_FILENO);
    ::execv("/proc/self/exe", args.data());
    const std::string reason =
        std::string("cannot start ") + args[0] + ": " + std::strerror(errno) + "\n";
    [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, reason.data(), reason.size());
    ::_exit(127);
  }
  ::close(out);
  return pid;
}

std::string progress_line(const Sweep& sweep, int total, int done, int running, int failed,
                          double elapsed, int finished_here) {
  std::string line = fmt::format("sweep {}: {}/{} done, {} running, {} failed", sweep.id, done,
                                 total, running, failed);
  if (finished_here > 0 && done + failed < total) {
    const double eta = elapsed / finished_here * (total - done - failed);
    line += ", ETA " + Progress::format_duration(eta);
  }
  return line;
}

}  // namespace

SweepOutcome run_sweep_locally(const Sweep& sweep, const LocalSweepOptions& options) {
  SweepOutcome outcome;
  const fs::path dir = fs::path(options.out_dir) / "sweeps" / sweep.id;
  outcome.directory = dir.string();
  const fs::path manifest = dir / "manifest.yaml";
  std::optional<SweepLock> lock;
  std::vector<int> pending;
  {
    // The database first: one that cannot be used is refused (StoreError) before anything
    // is written, and opening it makes the folder the lock goes in.
    ResultStore store(options.db_path);
    // Beside the database's real file (symlinks, '..' and relative paths resolved, as SQLite
    // resolves them for its own files): two drivers of one sweep into one database are refused
    // whatever the paths they were given and their --out.
    lock.emplace(fs::canonical(options.db_path).string() + ".sweep-" + sweep.id + ".lock");
    make_sweep_folder(dir, "--out");
    write_manifest(manifest.string(), sweep);
    mark_interrupted_runs(store);
    record_sweep(store, sweep);
    const auto done = completed_jobs(store, sweep.id);
    for (const auto& job : sweep.jobs) {
      if (done.count(job.index) == 0) pending.push_back(job.index);
    }
    outcome.skipped = static_cast<int>(done.size());
  }
  const int total = static_cast<int>(sweep.jobs.size());
  spdlog::info(
      "sweep {}: {} jobs, {} already completed, {} at a time, {} thread(s) each; "
      "logs in {}",
      sweep.id, total, outcome.skipped, options.parallel_jobs, options.threads_per_job,
      dir.string());

  const auto start = std::chrono::steady_clock::now();
  const bool terminal = isatty(STDERR_FILENO) == 1;
  std::map<pid_t, int> running;  // pid -> job index
  size_t next = 0;
  bool stopping = false;
  std::string last_line;
  int last_logged = -1;
  while (next < pending.size() || !running.empty()) {
    if (interrupt_requested() && !stopping) {
      stopping = true;
      for (const auto& [pid, job] : running) ::kill(pid, SIGINT);
    }
    while (!stopping && next < pending.size() &&
           static_cast<int>(running.size()) < options.parallel_jobs) {
      const int job = pending[next++];
      std::vector<std::string> argv{options.executable,
                                    "--sweep-job",
                                    manifest.string(),
                                    std::to_string(job),
                                    "--db",
                                    options.db_path,
                                    "--out",
                                    options.out_dir,
                                    "--threads",
                                    std::to_string(options.threads_per_job),
                                    "--quiet"};
      if (!options.use_cache) argv.push_back("--no-cache");
      running[spawn(argv, dir / fmt::format("job-{}.log", job))] = job;
    }
    // The progress line: redrawn on a terminal, logged when a job ends otherwise.
    const int finished = outcome.completed + outcome.failed;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string line =
        progress_line(sweep, total, outcome.skipped + outcome.completed,
                      static_cast<int>(running.size()), outcome.failed, elapsed, finished);
    if (terminal && line != last_line) {
      fmt::print(stderr, "\r\033[K{}", line);
    } else if (!terminal && finished + outcome.interrupted != last_logged) {
      spdlog::info("{}", line);
    }
    last_line = line;
    last_logged = finished + outcome.interrupted;
    if (stopping && running.empty()) break;
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, WNOHANG);
    if (pid > 0 && running.count(pid) > 0) {
      const int job = running[pid];
      running.erase(pid);
      const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      if (code == 0) {
        ++outcome.completed;
      } else if (code == 130 || (stopping && code > 128)) {
        ++outcome.interrupted;
      } else {
        ++outcome.failed;
        spdlog::warn("sweep {}: job {} failed (exit {}); see {}", sweep.id, job, code,
                     (dir / fmt::format("job-{}.log", job)).string());
      }
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }
  const std::string line =
      progress_line(sweep, total, outcome.skipped + outcome.completed, 0, outcome.failed, 0.0, 0);
  if (terminal) {
    fmt::print(stderr, "\r\033[K{}\n", line);
  } else if (outcome.completed + outcome.failed + outcome.interrupted != last_logged) {
    spdlog::info("{}", line);
  }
  outcome.not_started = static_cast<int>(pending.size() - next);
  return outcome;
}

}  // namespace corrmp
