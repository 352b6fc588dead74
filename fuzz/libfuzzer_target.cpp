// libFuzzer entry point (clang -fsanitize=fuzzer; fuzz/README.md): the same check as deck_fuzz,
// with coverage guidance and the sanitizers. A located rejection is the expected outcome of most
// inputs; anything else is a finding, so the target aborts and libFuzzer keeps the input.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "deck_check.hpp"

#ifndef ABUT_FUZZ_FORMAT
#define ABUT_FUZZ_FORMAT keyword
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace abut::fuzz;
  const Outcome r = check_deck(std::string_view(reinterpret_cast<const char*>(data), size),
                               DeckFormat::ABUT_FUZZ_FORMAT);
  if (r.verdict == Verdict::rejected_unlocated || r.verdict == Verdict::unexpected) {
    std::fprintf(stderr, "deck fuzz finding: %s: %s\n", verdict_name(r.verdict), r.message.c_str());
    std::abort();
  }
  return 0;
}
