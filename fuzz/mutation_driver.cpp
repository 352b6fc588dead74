// deck_fuzz: a mutation fuzzer for the deck readers that needs nothing but the project's own
// compiler (fuzz/README.md). It takes the decks of a corpus (examples/, tests/), changes them the
// way a hurried user or a broken file would (bytes, lines, numbers, keywords swapped in from other
// decks), and runs each mutant through what `abut check` does (deck_check.hpp) in a child
// process, with a time and memory limit, so that a crash, a hang or a runaway allocation is
// caught and the input kept. The mutations follow libFuzzer's kinds (byte flips, insertions,
// erasures, dictionary words, cross-over), with deck lines and numbers as the units.
//
//   deck_fuzz [--seconds S] [--runs N] [--seed R] [--timeout T] [--memory-mb M] [--out DIR]
//             CORPUS...      (files or folders; .inp files are read as Abaqus/CalculiX input,
//                             .msh files by the Gmsh mesh reader)
//
// Exit code 0 when every mutant was accepted, rejected with file:line, too large for the memory
// limit or slower than the time limit; 1 on any other finding. A timeout is listed with its input
// but does not fail the run: a mutant that asks for millions of elements (a sphere's density
// 3 -> 30) is slow by request, and a hang shows in the list as well.
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "deck_check.hpp"

// AddressSanitizer reserves terabytes of address space for its shadow memory: under it a limit
// on the address space (RLIMIT_AS) makes every child fail to start. GCC says so with
// __SANITIZE_ADDRESS__, clang with __has_feature(address_sanitizer).
#if defined(__SANITIZE_ADDRESS__)
#define ABUT_FUZZ_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ABUT_FUZZ_ASAN 1
#endif
#endif

namespace fs = std::filesystem;
using abut::fuzz::DeckFormat;
using abut::fuzz::Verdict;

namespace {

struct Seed {
  std::string text;
  DeckFormat format;
};

struct Options {
  double seconds = 60.0;
  long runs = -1;  // no limit
  unsigned seed = 1;
  unsigned timeout = 20;  // seconds per mutant
  long memory_mb = 4096;
  fs::path out = "fuzz_findings";
  std::vector<fs::path> corpus;
};

bool is_deck(const fs::path& p) {
  const std::string e = p.extension().string();
  return e == ".k" || e == ".key" || e == ".inp" || e == ".msh";
}

std::vector<Seed> load_corpus(const std::vector<fs::path>& roots) {
  std::vector<fs::path> files;
  for (const fs::path& r : roots) {
    if (fs::is_directory(r)) {
      for (const auto& e : fs::recursive_directory_iterator(r))
        if (e.is_regular_file() && is_deck(e.path())) files.push_back(e.path());
    } else if (fs::is_regular_file(r)) {
      files.push_back(r);
    }
  }
  std::sort(files.begin(), files.end());  // the same order, so the same mutants, on every machine
  std::vector<Seed> seeds;
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    const DeckFormat format = f.extension() == ".inp"   ? DeckFormat::inp
                              : f.extension() == ".msh" ? DeckFormat::msh
                                                        : DeckFormat::keyword;
    seeds.push_back({s.str(), format});
  }
  return seeds;
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::string line;
  std::istringstream in(text);
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

// Values a deck field is most likely to break on.
const std::vector<std::string> kNumbers{
    "0",          "-1",          "1",      "2",   "-0.0",
    "1e308",      "-1e308",      "1e-308", "nan", "inf",
    "-inf",       "1e400",       "",       "x",   "9223372036854775807",
    "2147483648", "-2147483649", "1e6",    "0.5", "1.0e-12",
    "3"};

class Mutator {
 public:
  Mutator(const std::vector<Seed>& seeds, unsigned seed) : seeds_(seeds), rng_(seed) {
    for (const Seed& s : seeds_)
      for (const std::string& l : split_lines(s.text)) {
        if (!l.empty() && l[0] == '*') keywords_.push_back(l);
        if (!l.empty()) lines_.push_back(l);
      }
  }

  std::string mutate(std::string text) {
    const int n = 1 + static_cast<int>(pick(4));
    for (int i = 0; i < n; ++i) text = once(std::move(text));
    return text;
  }

 private:
  std::size_t pick(std::size_t n) {
    return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_);
  }

  std::string once(std::string text) {
    std::vector<std::string> lines = split_lines(text);
    switch (pick(11)) {
      case 0:  // change a byte
        if (!text.empty()) text[pick(text.size())] = static_cast<char>(pick(256));
        return text;
      case 1:  // insert a byte
        text.insert(text.begin() + static_cast<long>(pick(text.size() + 1)),
                    static_cast<char>(pick(4) == 0 ? pick(256) : 32 + pick(95)));
        return text;
      case 2: {  // erase a range of bytes
        if (text.empty()) return text;
        const std::size_t at = pick(text.size());
        text.erase(at, 1 + pick(std::min<std::size_t>(64, text.size() - at)));
        return text;
      }
      case 3:  // duplicate a line
        if (!lines.empty()) {
          const std::size_t i = pick(lines.size());
          lines.insert(lines.begin() + static_cast<long>(pick(lines.size() + 1)), lines[i]);
        }
        return join_lines(lines);
      case 4:  // erase a line
        if (!lines.empty()) lines.erase(lines.begin() + static_cast<long>(pick(lines.size())));
        return join_lines(lines);
      case 5:  // swap two lines
        if (lines.size() > 1) std::swap(lines[pick(lines.size())], lines[pick(lines.size())]);
        return join_lines(lines);
      case 6:  // a keyword line from any seed
        if (!keywords_.empty())
          lines.insert(lines.begin() + static_cast<long>(pick(lines.size() + 1)),
                       keywords_[pick(keywords_.size())]);
        return join_lines(lines);
      case 7:  // cross-over: a line from any seed in place of one of ours
        if (!lines.empty() && !lines_.empty())
          lines[pick(lines.size())] = lines_[pick(lines_.size())];
        return join_lines(lines);
      case 8:  // an empty field, or one field too many
        if (!lines.empty()) {
          std::string& l = lines[pick(lines.size())];
          l.insert(pick(l.size() + 1), 1, ',');
        }
        return join_lines(lines);
      case 9:  // a line break inside a line, or CR line ends
        if (pick(4) == 0) {
          std::replace(text.begin(), text.end(), '\n', '\r');
          return text;
        }
        text.insert(text.begin() + static_cast<long>(pick(text.size() + 1)), '\n');
        return text;
      default:  // a number replaced by a hostile one
        return replace_number(text);
    }
  }

  std::string replace_number(const std::string& text) {
    static const std::regex number(R"([-+]?[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?)");
    std::vector<std::pair<std::size_t, std::size_t>> spans;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), number);
         it != std::sregex_iterator(); ++it)
      spans.emplace_back(static_cast<std::size_t>(it->position()),
                         static_cast<std::size_t>(it->length()));
    if (spans.empty()) return text;
    const auto [at, length] = spans[pick(spans.size())];
    std::string value = kNumbers[pick(kNumbers.size())];
    if (pick(3) == 0) {  // scaled rather than replaced
      const double v = std::strtod(text.substr(at, length).c_str(), nullptr);
      std::ostringstream s;
      s << v * (pick(2) ? 10.0 : -1.0);
      value = s.str();
    }
    return text.substr(0, at) + value + text.substr(at + length);
  }

  const std::vector<Seed>& seeds_;
  std::mt19937_64 rng_;
  std::vector<std::string> keywords_, lines_;
};

enum class Result { accepted, located, unlocated, too_large, unexpected, timeout, crash };
constexpr int kResults = 7;
const char* kResultNames[kResults] = {"accepted",
                                      "rejected with file:line",
                                      "rejected without a line",
                                      "too large for the memory limit",
                                      "unexpected exception",
                                      "timeout",
                                      "crash (signal)"};

// Runs one mutant in a child process; the child's message comes back through a pipe.
Result run_child(const std::string& text, DeckFormat format, const Options& o,
                 std::string& message) {
  int fd[2];
  if (pipe(fd) != 0) std::abort();
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
#if defined(ABUT_FUZZ_ASAN)
    // No address-space limit: the reader's memory budget (src/io/memory_budget.hpp) refuses a
    // model above 256 MB, as in the libFuzzer targets, so that it is a located refusal and the
    // largest accepted mesh stays within the time limit under AddressSanitizer.
    setenv("ABUT_MEMORY_MB", "256", /*overwrite=*/0);
#else
    const rlimit limit{static_cast<rlim_t>(o.memory_mb) << 20, static_cast<rlim_t>(o.memory_mb)
                                                                   << 20};
    setrlimit(RLIMIT_AS, &limit);
#endif
    alarm(o.timeout);
    const abut::fuzz::Outcome r = abut::fuzz::check_deck(text, format);
    const std::string m = r.message.substr(0, 400);
    if (write(fd[1], m.data(), m.size()) < 0) _exit(99);
    _exit(static_cast<int>(r.verdict));
  }
  close(fd[1]);
  char buffer[512];
  message.clear();
  for (ssize_t k; (k = read(fd[0], buffer, sizeof buffer)) > 0;)
    message.append(buffer, static_cast<std::size_t>(k));
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFSIGNALED(status)) return WTERMSIG(status) == SIGALRM ? Result::timeout : Result::crash;
  switch (WEXITSTATUS(status)) {
    case static_cast<int>(Verdict::accepted):
      return Result::accepted;
    case static_cast<int>(Verdict::rejected_located):
      return Result::located;
    case static_cast<int>(Verdict::rejected_unlocated):
      return Result::unlocated;
    case static_cast<int>(Verdict::too_large):
      return Result::too_large;
    default:
      return Result::unexpected;
  }
}

// A message with its numbers blanked, so that findings group by kind.
std::string kind_of(const std::string& message) {
  static const std::regex digits("[0-9.eE+-]*[0-9][0-9.eE+-]*");
  return std::regex_replace(message.substr(0, 160), digits, "#");
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << "deck_fuzz: " << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--seconds")
      o.seconds = std::stod(value());
    else if (a == "--runs")
      o.runs = std::stol(value());
    else if (a == "--seed")
      o.seed = static_cast<unsigned>(std::stoul(value()));
    else if (a == "--timeout")
      o.timeout = static_cast<unsigned>(std::stoul(value()));
    else if (a == "--memory-mb")
      o.memory_mb = std::stol(value());
    else if (a == "--out")
      o.out = value();
    else
      o.corpus.emplace_back(a);
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  const std::vector<Seed> seeds = load_corpus(o.corpus);
  if (seeds.empty()) {
    std::cerr << "deck_fuzz: no decks (.k, .key, .inp, .msh) in the corpus given\n";
    return 2;
  }
  setenv("OMP_NUM_THREADS", "1", 1);
  fs::create_directories(o.out);
  Mutator mutator(seeds, o.seed);
  std::mt19937_64 choose(o.seed);
  long counts[kResults] = {};
  std::map<std::string, std::pair<long, std::string>> findings;  // kind -> count, first file
  const auto start = std::chrono::steady_clock::now();
  long run = 0;
  for (; o.runs < 0 || run < o.runs; ++run) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (o.runs < 0 && elapsed >= o.seconds) break;
    const Seed& s = seeds[std::uniform_int_distribution<std::size_t>(0, seeds.size() - 1)(choose)];
    const std::string text = mutator.mutate(s.text);
    std::string message;
    const Result r = run_child(text, s.format, o, message);
    ++counts[static_cast<int>(r)];
    if (r == Result::accepted || r == Result::located) continue;
    const std::string kind =
        std::string(kResultNames[static_cast<int>(r)]) + ": " + kind_of(message);
    auto& f = findings[kind];
    if (f.first++ == 0) {
      const fs::path file = o.out / ("finding-" + std::to_string(findings.size()) +
                                     (s.format == DeckFormat::inp   ? ".inp"
                                      : s.format == DeckFormat::msh ? ".msh"
                                                                    : ".k"));
      std::ofstream(file, std::ios::binary) << text;
      f.second = file.string();
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("deck_fuzz: %ld mutants of %zu decks in %.1f s (%.0f per second), seed %u\n", run,
              seeds.size(), seconds, run / seconds, o.seed);
  for (int k = 0; k < kResults; ++k) std::printf("  %-32s %ld\n", kResultNames[k], counts[k]);
  for (const auto& [kind, f] : findings)
    std::printf("finding (%ld x, first in %s): %s\n", f.first, f.second.c_str(), kind.c_str());
  const bool clean = counts[static_cast<int>(Result::unlocated)] == 0 &&
                     counts[static_cast<int>(Result::unexpected)] == 0 &&
                     counts[static_cast<int>(Result::crash)] == 0;
  return clean ? 0 : 1;
}
