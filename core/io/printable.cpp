#include "io/printable.hpp"

#include <cstdio>
#include <vector>

namespace strata {
namespace {

// Length of the well-formed UTF-8 sequence starting at text[i] (RFC 3629: no overlong forms,
// no surrogates, nothing above U+10FFFF), or 0 when the byte there does not start one.
std::size_t utf8Length(std::string_view text, std::size_t i) {
    auto at = [&](std::size_t k) { return i + k < text.size() ? (unsigned char)text[i + k] : 0u; };
    auto cont = [&](std::size_t k) { return (at(k) & 0xC0u) == 0x80u; };
    unsigned b = at(0);
    if (b >= 0xC2 && b <= 0xDF) return cont(1) ? 2 : 0;
    if (b >= 0xE0 && b <= 0xEF) {
        unsigned lo = b == 0xE0 ? 0xA0 : 0x80, hi = b == 0xED ? 0x9F : 0xBF;
        return at(1) >= lo && at(1) <= hi && cont(2) ? 3 : 0;
    }
    if (b >= 0xF0 && b <= 0xF4) {
        unsigned lo = b == 0xF0 ? 0x90 : 0x80, hi = b == 0xF4 ? 0x8F : 0xBF;
        return at(1) >= lo && at(1) <= hi && cont(2) && cont(3) ? 4 : 0;
    }
    return 0;
}

// The text as a list of display units (an escape or one character), each kept whole.
std::vector<std::string> units(std::string_view text, std::size_t stopAfter) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < text.size() && out.size() < stopAfter;) {
        unsigned char c = (unsigned char)text[i];
        if (c >= 0x20 && c < 0x7f) {
            out.push_back(c == '\\' ? "\\\\" : std::string(1, char(c)));
            ++i;
            continue;
        }
        if (c >= 0x80) {
            if (std::size_t n = utf8Length(text, i)) {
                out.emplace_back(text.substr(i, n));
                i += n;
                continue;
            }
        }
        switch (c) {
            case '\n': out.push_back("\\n"); break;
            case '\r': out.push_back("\\r"); break;
            case '\t': out.push_back("\\t"); break;
            case '\0': out.push_back("\\0"); break;
            default: {
                char hex[5];
                std::snprintf(hex, sizeof hex, "\\x%02X", unsigned(c));
                out.push_back(hex);
            }
        }
        ++i;
    }
    return out;
}

std::size_t width(const std::string& unit) { return unit.size() > 1 && unit[0] == '\\' ? unit.size() : 1; }

}  // namespace

std::string printable(std::string_view text, std::size_t maxChars) {
    // Never more than maxChars + 1 units are needed to decide; a 10 MB token costs nothing more.
    std::vector<std::string> parts = units(text, maxChars + 1);
    std::string out;
    std::size_t used = 0;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        if (used + width(parts[k]) > maxChars) return out + "...";
        used += width(parts[k]);
        out += parts[k];
    }
    return out;
}

std::string printableMessage(std::string_view text, std::size_t maxChars) {
    // A unit takes at most 4 bytes of input, so the head and the tail are found in windows of
    // 4 * maxChars bytes at either end; a message of any length costs no more than that.
    const std::size_t window = 4 * maxChars;
    const bool whole = text.size() <= window;
    std::vector<std::string> head = units(whole ? text : text.substr(0, window), window);
    std::size_t total = 0;
    for (const auto& p : head) total += width(p);
    std::string out;
    if (whole && total <= maxChars) {
        for (const auto& p : head) out += p;
        return out;
    }
    std::vector<std::string> tail = whole ? head : units(text.substr(text.size() - window), window);
    // Two thirds for the head (the input's name), the rest for the tail (the cause).
    const std::size_t budget = maxChars > 3 ? maxChars - 3 : 0;
    const std::size_t headBudget = budget * 2 / 3, tailBudget = budget - headBudget;
    std::size_t used = 0, k = 0;
    for (; k < head.size() && used + width(head[k]) <= headBudget; ++k) {
        used += width(head[k]);
        out += head[k];
    }
    // With one window, the tail must not reach back into the head.
    const std::size_t tailFloor = whole ? k : 0;
    std::size_t tailStart = tail.size(), tailUsed = 0;
    while (tailStart > tailFloor && tailUsed + width(tail[tailStart - 1]) <= tailBudget)
        tailUsed += width(tail[--tailStart]);
    out += "...";
    for (std::size_t j = tailStart; j < tail.size(); ++j) out += tail[j];
    return out;
}

}  // namespace strata
