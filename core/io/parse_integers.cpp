#include "io/parse_integers.hpp"

#include <charconv>

namespace strata {

namespace {

std::optional<int> wholeInt(std::string_view text) {
    int value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end || text.empty()) return std::nullopt;
    return value;
}

}  // namespace

std::optional<std::pair<int, int>> parseIntPair(std::string_view text, std::string_view seps) {
    const std::size_t at = text.find_first_of(seps);
    if (at == std::string_view::npos) return std::nullopt;
    const std::optional<int> a = wholeInt(text.substr(0, at)), b = wholeInt(text.substr(at + 1));
    if (!a || !b) return std::nullopt;
    return std::pair<int, int>{*a, *b};
}

}  // namespace strata
