#pragma once
// `abut plot` (and `abut run --plot`): hands a run's output directory to the Python package's
// plotting module (python/abut/plot.py), which writes the PNG figures.
#include <filesystem>
#include <string>

namespace abut_cli {

// The interpreter that runs the plotting (Debian's, which has python3-numpy and -matplotlib).
inline constexpr const char* kPython = "/usr/bin/python3";

// The directory that holds the abut Python package (abut/plot.py): the installed one beside the
// program (<prefix>/lib/python3/dist-packages for <prefix>/bin/abut), else the build tree's
// (ABUT_PYTHON_BUILD_DIR); empty if neither has it.
std::filesystem::path python_package_dir();

// `abut plot`: runs abut.plot's main (as `python3 -m abut.plot out_dir [--to to]` would) with that
// directory first on PYTHONPATH and returns the exit code for main: 0 when the figures are written,
// 2 for a directory that is not an abut output directory, 1 when Python, numpy, matplotlib or the
// package is missing or a figure cannot be written (the message is on stderr).
int plot_output(const std::string& out_dir, const std::string& to);

}  // namespace abut_cli
