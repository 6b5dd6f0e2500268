#include "mutator.hpp"

#include <algorithm>
#include <cstring>

namespace strata::fuzz {

Mutator::Mutator(std::uint64_t seed, std::vector<std::string> dictionary, std::size_t maxSize)
    : rng_(seed), dictionary_(std::move(dictionary)), maxSize_(maxSize) {}

std::uint64_t Mutator::below(std::uint64_t n) { return rng_() % n; }

std::vector<std::string> commonTokens() {
    return {"0", "-0", "1", "-1", "0.5", "1e38", "3.5e38", "1e39", "-1e39", "1e300", "1e308", "1e309", "1e400",
            "-1e400", "1e-400", "nan", "NaN", "inf", "-inf", "Infinity", "2147483647", "2147483648", "4294967295",
            "4294967296", "9223372036854775807", "18446744073709551615", "18446744073709551616", "1e6", "1e7",
            "0x10", "+1", "--1", "1..2", "1e", ".", " ", "\t", "\n", "\r\n", "#", ",", "\"", "\\", "[", "]", "{", "}",
            ":", "null", "true", "false", "\"\"", "[]", "{}", std::string(1, '\0'), "\xff\xfe", "\xef\xbb\xbf",
            "\xc3", "\x1b[2J", std::string(300, '9')};
}

void Mutator::mutate(std::string& input, const std::string& other) {
    const int count = 1 << below(5);  // 1, 2, 4, 8 or 16
    for (int i = 0; i < count; ++i) mutateOnce(input, other);
    if (input.size() > maxSize_) input.resize(maxSize_);
}

void Mutator::mutateOnce(std::string& s, const std::string& other) {
    static const unsigned char kBytes[] = {0, 1, 0x7f, 0x80, 0xff, '0', '9', '-', '.', 'e', ' ', '\n', '"', ',', ':', '[', ']', '{', '}'};
    static const std::uint32_t kWords[] = {0, 1, 2, 3, 4, 12, 16, 0x7fffffff, 0x80000000, 0xffffffff, 0xfffffffe, 0x4E4F534A, 0x004E4942};
    auto at = [&] { return std::size_t(below(s.size() + 1)); };
    switch (below(s.empty() ? 3 : 10)) {
        case 0: {  // insert a dictionary token
            const std::string& t = dictionary_[below(dictionary_.size())];
            s.insert(at(), t);
            break;
        }
        case 1: {  // insert random bytes
            std::size_t n = 1 + below(8), p = at();
            for (std::size_t i = 0; i < n; ++i) s.insert(s.begin() + std::ptrdiff_t(p), char(below(256)));
            break;
        }
        case 2: {  // splice a range of another corpus entry
            if (other.empty()) break;
            std::size_t from = below(other.size()), n = 1 + below(std::min<std::size_t>(other.size() - from, 256));
            s.insert(at(), other.substr(from, n));
            break;
        }
        case 3: {  // flip a bit
            std::size_t p = below(s.size());
            s[p] = char(s[p] ^ (1u << below(8)));
            break;
        }
        case 4: s[below(s.size())] = char(kBytes[below(sizeof kBytes)]); break;
        case 5: {  // erase a range
            std::size_t p = below(s.size());
            s.erase(p, 1 + below(std::min<std::size_t>(s.size() - p, 64)));
            break;
        }
        case 6: {  // copy a range elsewhere (repeats structure: more accessors, nested arrays)
            std::size_t p = below(s.size()), n = 1 + below(std::min<std::size_t>(s.size() - p, 128));
            std::string piece = s.substr(p, n);
            s.insert(at(), piece);
            break;
        }
        case 7: {  // overwrite a 32-bit little-endian word (GLB lengths, chunk types)
            if (s.size() < 4) break;
            std::uint32_t w = kWords[below(sizeof kWords / sizeof kWords[0])];
            if (below(4) == 0) {  // or nudge the existing one
                std::memcpy(&w, s.data() + (below(s.size() - 3) & ~std::size_t(3)), 4);
                w += std::uint32_t(below(33)) - 16u;
            }
            std::memcpy(s.data() + below(s.size() - 3), &w, 4);
            break;
        }
        default: {  // replace a number by a token (the number parsers' edge cases)
            std::size_t p = below(s.size());
            auto digit = [&](std::size_t i) { return s[i] >= '0' && s[i] <= '9'; };
            while (p < s.size() && !digit(p)) ++p;
            if (p == s.size()) break;
            std::size_t e = p;
            while (e < s.size() && (digit(e) || s[e] == '.' || s[e] == 'e' || s[e] == '-')) ++e;
            s.replace(p, e - p, dictionary_[below(dictionary_.size())]);
        }
    }
}

}  // namespace strata::fuzz
