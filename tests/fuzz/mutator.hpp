#pragma once
// A seeded, deterministic byte mutator for the fuzz driver (fuzz_loaders.cpp): the same seed
// gives the same inputs on every machine, so a failure is reproduced from its seed and index.
// The mutations are libFuzzer's usual ones (bit flips, interesting bytes and 32-bit words,
// inserted, erased and copied ranges, splices with another corpus file) plus tokens that the
// input formats hold: numbers that overflow a float or a double, NaN, JSON and glTF keys.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace strata::fuzz {

class Mutator {
public:
    Mutator(std::uint64_t seed, std::vector<std::string> dictionary, std::size_t maxSize);
    // `input` changed by 1 to 16 mutations; `other` is another corpus entry to splice from.
    void mutate(std::string& input, const std::string& other);
    std::uint64_t below(std::uint64_t n);  // uniform in [0, n), n > 0

private:
    void mutateOnce(std::string& input, const std::string& other);
    std::mt19937_64 rng_;
    std::vector<std::string> dictionary_;
    std::size_t maxSize_;
};

// Tokens every text format meets: special numbers, separators, bytes that are not UTF-8.
std::vector<std::string> commonTokens();

}  // namespace strata::fuzz
