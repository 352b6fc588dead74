#include "plot_command.hpp"

#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string_view>
#include <vector>

// The build tree's copy of the Python package (apps/abut/CMakeLists.txt).
#ifndef ABUT_PYTHON_BUILD_DIR
#define ABUT_PYTHON_BUILD_DIR ""
#endif

extern char** environ;  // POSIX: the environment the plotting process inherits

namespace abut_cli {

namespace {

namespace fs = std::filesystem;

bool holds_package(const fs::path& dir) {
  std::error_code error;
  return !dir.empty() && fs::is_regular_file(dir / "abut" / "plot.py", error);
}

// <prefix>/lib/python3/dist-packages for the program <prefix>/bin/abut (cmake --install).
fs::path installed_package_dir() {
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (error) return {};
  return (program.parent_path() / ".." / "lib" / "python3" / "dist-packages").lexically_normal();
}

// The environment of the plotting process: this one, with `package` first on PYTHONPATH and
// without the working directory on sys.path (PYTHONSAFEPATH, Python 3.11), so that a directory
// named abut where abut plot is typed (the source tree's python/) does not stand in for it.
std::vector<std::string> plotting_environment(const fs::path& package) {
  std::vector<std::string> environment{"PYTHONSAFEPATH=1"};
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string_view variable = *entry;
    if (!variable.starts_with("PYTHONPATH=") && !variable.starts_with("PYTHONSAFEPATH="))
      environment.emplace_back(variable);
  }
  const char* previous = std::getenv("PYTHONPATH");
  environment.push_back(
      "PYTHONPATH=" + package.string() +
      (previous != nullptr && *previous != '\0' ? std::string(":") + previous : std::string()));
  return environment;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
  std::vector<char*> result;
  for (std::string& s : strings) result.push_back(s.data());
  result.push_back(nullptr);
  return result;
}

}  // namespace

fs::path python_package_dir() {
  for (const fs::path& dir : {installed_package_dir(), fs::path(ABUT_PYTHON_BUILD_DIR)})
    if (holds_package(dir)) return dir;
  return {};
}

int plot_output(const std::string& out_dir, const std::string& to) {
  std::error_code error;
  const fs::file_status status_of_dir = fs::status(out_dir, error);
  if (!fs::is_directory(status_of_dir)) {
    std::cerr << (fs::exists(status_of_dir)
                      ? fmt::format("error: '{}' is not a directory, not an output directory\n",
                                    out_dir)
                      : fmt::format("error: output directory '{}' not found\n", out_dir));
    return 2;
  }
  const fs::path package = python_package_dir();
  if (package.empty()) {
    std::cerr << fmt::format(
        "error: the abut Python package (abut/plot.py) is neither in {} nor in {}\n",
        installed_package_dir().string(), ABUT_PYTHON_BUILD_DIR);
    return 1;
  }
  // abut.plot's main, as `python3 -m abut.plot` runs it; -c rather than -m because the package
  // imports abut.plot itself, which -m would warn about (runpy) and execute a second time.
  std::vector<std::string> arguments{
      kPython, "-c", "import sys; from abut.plot import main; sys.exit(main())", out_dir};
  if (!to.empty()) arguments.insert(arguments.end(), {"--to", to});
  std::vector<std::string> environment = plotting_environment(package);
  std::vector<char*> argv = pointers(arguments);
  std::vector<char*> envp = pointers(environment);
  // posix_spawn rather than std::system: no shell to quote the directory names for. What the
  // run printed goes out first, so that the figures' paths follow it.
  std::cout.flush();
  pid_t child = 0;
  if (const int reason = posix_spawn(&child, kPython, nullptr, nullptr, argv.data(), envp.data());
      reason != 0) {
    std::cerr << fmt::format(
        "error: cannot run {}: {}; abut plot needs Python 3 with numpy and matplotlib\n", kPython,
        std::strerror(reason));
    return 1;
  }
  int status = 0;
  while (waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) {
      std::cerr << fmt::format("error: lost the plotting process: {}\n", std::strerror(errno));
      return 1;
    }
  }
  // 0 written, 2 not an output directory, 1 no matplotlib or a figure not written: Python has
  // said which (or, for a missing numpy, its traceback has).
  if (WIFEXITED(status) && WEXITSTATUS(status) <= 2) return WEXITSTATUS(status);
  std::cerr << (WIFEXITED(status)
                    ? fmt::format("error: plotting failed: {} (abut.plot) exited with code {}\n",
                                  kPython, WEXITSTATUS(status))
                    : fmt::format("error: plotting failed: {} (abut.plot) was stopped by "
                                  "signal {}\n",
                                  kPython, WTERMSIG(status)));
  return 1;
}

}  // namespace abut_cli
