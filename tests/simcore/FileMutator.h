#pragma once
// Mutates the text of a scene or brain file the way a careless hand, a bad merge or a
// buggy exporter would: numbers replaced by 0, -1, 1e30, nan, huge counts; lines dropped,
// duplicated, repeated many times or swapped; the file truncated; a byte changed. The
// same (seed, index) always gives the same mutant. Test-only; never reads or writes files.

#include <cstdint>
#include <string>

namespace throng::test {

struct Mutant {
    std::string text;
    std::string what;  // the mutations applied, for the failure message
};

Mutant mutateText(const std::string& text, std::uint64_t seed, std::uint64_t index);

}  // namespace throng::test
