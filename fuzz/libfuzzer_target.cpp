// libFuzzer entry point (clang -fsanitize=fuzzer; fuzz/README.md): the same check as deck_fuzz,
// with coverage guidance and the sanitizers. A located rejection is the expected outcome of most
// inputs; anything else is a finding, so the target aborts and libFuzzer keeps the input.
// ABUT_FUZZ_FORMAT (keyword, inp) picks the reader; ABUT_FUZZ_STAGE (set_up, read) whether the
// solver is set up after the deck is read (deck_libfuzzer_keyword) or not (the fast
// deck_libfuzzer_keyword_reader, hundreds of inputs a second).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "deck_check.hpp"

#ifndef ABUT_FUZZ_FORMAT
#define ABUT_FUZZ_FORMAT keyword
#endif
#ifndef ABUT_FUZZ_STAGE
#define ABUT_FUZZ_STAGE set_up
#endif

// A deck may ask for a mesh of any size; the reader refuses one that would not fit in the
// memory it may count on (src/io/memory_budget.hpp), which is the machine's unless ABUT_MEMORY_MB
// says less. Under libFuzzer's -rss_limit_mb=4096 (and AddressSanitizer's overhead) that must be
// less, or a request for a large model would be reported as an out-of-memory finding. 256 MB (about
// 170 000 hexahedra) also keeps the slowest input well inside -timeout=20: a sphere of 688 000
// hexahedra, which 1024 MB let through, took 24 s to generate under AddressSanitizer. Larger
// meshes take the same reader paths, only slower. Set ABUT_MEMORY_MB to fuzz with another limit.
extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  setenv("ABUT_MEMORY_MB", "256", /*overwrite=*/0);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace abut::fuzz;
  const Outcome r = check_deck(std::string_view(reinterpret_cast<const char*>(data), size),
                               DeckFormat::ABUT_FUZZ_FORMAT, Stage::ABUT_FUZZ_STAGE);
  if (r.verdict == Verdict::rejected_unlocated || r.verdict == Verdict::unexpected) {
    std::fprintf(stderr, "deck fuzz finding: %s: %s\n", verdict_name(r.verdict), r.message.c_str());
    std::abort();
  }
  return 0;
}
