#pragma once
// Integers from command-line text, whole or not at all: std::from_chars, which refuses a value
// outside int's range (sscanf's "%d" is undefined there), leading spaces and signs other than
// '-', and anything left over.
#include <optional>
#include <string_view>
#include <utility>

namespace strata {

// "A<sep>B" with A and B whole ints (as written, no spaces): {A, B}, else nullopt. `seps` lists
// the separators accepted ("xX" for a size, "," for a pixel).
std::optional<std::pair<int, int>> parseIntPair(std::string_view text, std::string_view seps);

}  // namespace strata
