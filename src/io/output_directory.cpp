#include "abut/io/output_directory.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "abut/core/error.hpp"

namespace abut {
namespace {

namespace fs = std::filesystem;

constexpr const char* kLockName = ".abut.lock";

// The files of a run directly in the directory (see the header); the states are matched by name.
constexpr std::array<const char*, 9> kRunFiles{"results.pvd",    "summary.json", "results.dat",
                                               "energy.csv",     "parts.csv",    "contact.csv",
                                               "increments.csv", "nodes.csv",    "restart.abr"};

std::string unusable(const fs::path& dir, const std::string& reason) {
  return "cannot write the output directory '" + dir.string() + "': " + reason +
         "; give a writable directory with -o DIR";
}

bool is_state_file(const std::string& name) {
  const auto ends_with = [&](std::string_view end) {
    return name.size() >= end.size() &&
           name.compare(name.size() - end.size(), end.size(), end) == 0;
  };
  return name.rfind("state_", 0) == 0 && (ends_with(".vtu") || ends_with(".vtu.tmp"));
}

// The pid that the holder of the lock wrote into the lock file; empty if it cannot be read.
std::string holder_pid(int fd) {
  std::array<char, 32> text{};
  const ssize_t n = pread(fd, text.data(), text.size() - 1, 0);
  if (n <= 0) return {};
  std::string pid(text.data(), static_cast<std::size_t>(n));
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
  return pid;
}

void remove_previous_run(const fs::path& dir) {
  std::error_code ignored;  // a file that cannot be removed is overwritten or left, not an error
  for (const char* name : kRunFiles) {
    fs::remove(dir / name, ignored);
    fs::remove(dir / (std::string(name) + ".tmp"), ignored);
  }
  // The figures of `abut plot` (python/abut/plot.py writes these three) are of the previous run.
  const fs::path plots = dir / "plots";
  for (const char* figure : {"energy.png", "contact.png", "velocities.png"})
    fs::remove(plots / figure, ignored);
  fs::remove(plots, ignored);  // only if now empty
  const fs::path states = dir / "states";
  if (!fs::is_directory(states, ignored)) return;
  for (const fs::directory_entry& entry : fs::directory_iterator(states, ignored))
    if (is_state_file(entry.path().filename().string())) fs::remove(entry.path(), ignored);
  fs::remove(states, ignored);  // only if now empty: a user's own files stay
}

}  // namespace

OutputDirectory::OutputDirectory(fs::path dir, bool clean) : dir_(std::move(dir)) {
  std::error_code error;
  if (fs::exists(dir_, error) && !fs::is_directory(dir_, error))
    throw InputError(unusable(dir_, "it is a file, not a directory"));
  fs::create_directories(dir_, error);
  if (error) throw InputError(unusable(dir_, error.message()));
  const fs::path lock = dir_ / kLockName;
  // The lock file is removed when a run ends; a run that opened it just before may then hold a
  // lock on a removed file. It notices that the file at the path is another one and tries again.
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) throw InputError(unusable(dir_, std::strerror(errno)));
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int reason = errno;
      const std::string pid = holder_pid(fd);
      close(fd);
      if (reason != EWOULDBLOCK) throw InputError(unusable(dir_, std::strerror(reason)));
      throw InputError("output directory '" + dir_.string() + "' is in use by another run" +
                       (pid.empty() ? std::string() : " (pid " + pid + ")") +
                       "; wait for it to end or give another directory with -o DIR");
    }
    struct stat held {};
    struct stat named {};
    if (fstat(fd, &held) == 0 && stat(lock.c_str(), &named) == 0 && held.st_dev == named.st_dev &&
        held.st_ino == named.st_ino) {
      lock_fd_ = fd;
      break;
    }
    close(fd);
  }
  if (lock_fd_ < 0) throw InputError(unusable(dir_, "cannot lock " + lock.string()));
  const std::string pid = std::to_string(getpid()) + "\n";
  if (ftruncate(lock_fd_, 0) != 0 ||
      pwrite(lock_fd_, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
    const int reason = errno;
    unlink(lock.c_str());
    close(lock_fd_);
    throw InputError(
        unusable(dir_, reason != 0 ? std::strerror(reason) : "cannot write " + lock.string()));
  }
  if (clean) remove_previous_run(dir_);
}

OutputDirectory::~OutputDirectory() {
  if (lock_fd_ < 0) return;
  unlink((dir_ / kLockName).c_str());  // while still locked: see the constructor
  close(lock_fd_);
}

}  // namespace abut
