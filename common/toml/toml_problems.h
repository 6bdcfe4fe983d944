// Error reporting for the TOML files monoplane reads (HMD profiles, study protocols): every
// problem found in a document, each prefixed "source:line:column:" like a compiler's, so a user
// sees all mistakes in a file at once and editors can jump to them. Shared by hmd/ and study/,
// which may not include each other (docs/architecture.md).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "common/result.h"

namespace monoplane {

class TomlProblems {
  public:
    explicit TomlProblems(std::string_view source_name) : source_name_(source_name) {}

    // A problem at a place in the document; a region without a line (e.g. the document's root)
    // is reported against the source alone.
    void add(const toml::source_region& where, std::string_view message);
    // A problem that belongs to no line, e.g. a key missing from the document's top level.
    void add(std::string_view message);

    bool empty() const { return problems_.empty(); }
    // All problems, one per line, in document order (those without a line first). May be called
    // only when !empty().
    Error error() const;

  private:
    struct Problem {
        toml::source_position position;  // line 0: no place in the document
        std::string text;
    };
    std::string source_name_;
    std::vector<Problem> problems_;
};

// "an integer", "a string", ...: for "must be a number, but is a string".
std::string_view toml_type_phrase(toml::node_type type);

// Shortest text that reads back as the same double ("1.6", "nan", "inf").
std::string format_number(double value);

// "a, b, c": for "allowed: ..." lists.
std::string join(std::span<const std::string_view> words);

// The candidate within edit distance 2 of word, else the only candidate that word begins; empty
// if there is none. For "did you mean ...?" hints on misspelt or shortened keys and values.
std::string_view closest_match(std::string_view word, std::span<const std::string_view> candidates);

// Parses TOML text; a syntax error becomes "source:line:column: TOML syntax error: ...".
Result<toml::table> parse_toml(std::string_view text, std::string_view source_name);

}  // namespace monoplane
