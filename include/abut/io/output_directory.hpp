#pragma once
// The output directory of a run, owned by one run at a time. Two runs writing the same files
// would interleave their rows; so a run locks the directory (flock on `.abut.lock`, which holds
// its pid) for as long as it writes, and a second run stops with an error naming the first.
// Once it owns the directory, the run removes the files a previous run wrote there, and only
// those: results.pvd, states/state_NNNN.vtu, energy.csv, parts.csv, contact.csv,
// increments.csv, nodes.csv, results.dat, summary.json and restart.abr. Other files in the
// directory are left alone.
#include <filesystem>

namespace abut {

class OutputDirectory {
 public:
  // Creates `dir` (and its parents) if missing, locks it and cleans it (unless `clean` is false:
  // a restart continues the files of the run it continues). Throws InputError when the
  // directory cannot be created or written, or another run holds it: the user chooses another
  // with -o.
  explicit OutputDirectory(std::filesystem::path dir, bool clean = true);
  ~OutputDirectory();  // releases the lock and removes the lock file
  OutputDirectory(const OutputDirectory&) = delete;
  OutputDirectory& operator=(const OutputDirectory&) = delete;

  const std::filesystem::path& path() const { return dir_; }

 private:
  std::filesystem::path dir_;
  int lock_fd_ = -1;
};

}  // namespace abut
