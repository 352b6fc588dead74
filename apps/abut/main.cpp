// abut command-line program (placeholder until the solver lands).
#include <CLI/CLI.hpp>
#include <cstdio>

int main(int argc, char** argv) {
  CLI::App app{"abut: contact-centred explicit finite-element solver"};
  app.set_version_flag("--version", ABUT_VERSION);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
