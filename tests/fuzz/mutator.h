// Deterministic mutations of text inputs for the parser fuzz targets (fuzz_runner.h). A mutant is
// a function of (seed, iteration) and the corpus alone: the generator below is splitmix64 with
// its own bounded draws, never std::uniform_int_distribution, whose outputs differ between
// standard libraries, so a seed and an iteration name the same bytes everywhere.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace monoplane::fuzz {

// splitmix64 (Steele, Lea and Flood 2014): small, fast and good enough to pick mutations.
class Prng {
  public:
    explicit Prng(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next() {
        std::uint64_t x = (state_ += 0x9E3779B97F4A7C15ull);
        x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
        x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
        return x ^ (x >> 31);
    }
    // 0..n-1 (n > 0); the modulo bias is irrelevant for picking mutations.
    std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }
    bool one_in(std::size_t n) { return below(n) == 0; }

  private:
    std::uint64_t state_;
};

struct Mutant {
    std::string bytes;
    std::string history;  // the mutations applied, e.g. "seed 3; flip-bit@17; extreme-number@40"
};

// Mutations of the corpus inputs: bit flips, byte insertion, deletion and duplication, splices of
// two inputs, numbers replaced by extreme values (0, -1, 1e308, nan, inf, huge integers),
// truncation, duplicated, dropped, swapped and transplanted lines, TOML and CSV special
// characters, and words replaced by the dictionary's (the target's own plus those of the corpus).
class Mutator {
  public:
    // corpus: at least one input. max_size bounds a mutant, so that repeated duplication cannot
    // make inputs grow until each takes seconds.
    Mutator(std::vector<std::string> corpus, std::vector<std::string> dictionary,
            std::size_t max_size = 64 * 1024);

    // The mutant for this seed and iteration: one to a dozen mutations of one corpus input.
    Mutant mutant(std::uint64_t seed, std::uint64_t iteration) const;

    const std::vector<std::string>& corpus() const { return corpus_; }
    const std::vector<std::string>& dictionary() const { return dictionary_; }

  private:
    void mutate_once(std::string& bytes, Prng& rng, std::string& history) const;

    std::vector<std::string> corpus_;
    std::vector<std::string> dictionary_;  // the target's words, then the corpus's, no duplicates
    std::size_t max_size_;
};

// The whitespace-separated words of a text: a dictionary written as one string.
std::vector<std::string> split_words(std::string_view text);

// The words of a text ([A-Za-z_][A-Za-z0-9_.-/]*, and quoted strings with their quotes), without
// duplicates, in order of first appearance: keys, enum values and paths a mutation can move.
std::vector<std::string> words_of(std::string_view text);

}  // namespace monoplane::fuzz
