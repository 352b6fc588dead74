#pragma once
// Before a mesh generator allocates: would the run the deck asks for fit in the memory the
// machine can still give? A sphere of density N = 1000 is a few characters of deck and
// billions of elements; refusing it with the numbers beats swapping for minutes and bad_alloc.
#include <optional>
#include <string>

#include "abut/core/error.hpp"
#include "abut/core/memory.hpp"
#include "abut/mesh/generators.hpp"

namespace abut::deck {

// available_memory() and gigabytes(): abut/core/memory.hpp.
using abut::available_memory;

// Estimated peak bytes of `abut run` for a mesh of this size (solver state included).
double run_memory(const MeshSize& size);

// InputError at `where` when a mesh of `total` size (what the deck asked for so far, this command
// included) needs more than `available` bytes; the message gives both numbers.
void require_memory(const MeshSize& total, std::optional<double> available,
                    const SourceLocation& where);

// InputError when a deck file of `bytes` would not fit in `available` bytes while it is read
// (the text is held about three times over as it is split into lines).
void require_readable(const std::string& file, double bytes, std::optional<double> available);

}  // namespace abut::deck
