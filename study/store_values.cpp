#include "study/store_values.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <system_error>

namespace monoplane::study {

std::string stored_hash_text(std::uint64_t hash) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

std::optional<std::uint64_t> parse_stored_u64(std::string_view text, int base) {
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value, base);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
    return value;
}

std::string join_scenes(const std::vector<std::string>& scenes) {
    std::string text;
    for (const std::string& scene : scenes) text += (text.empty() ? "" : ",") + scene;
    return text;
}

std::vector<std::string> split_scenes(const std::string& text) {
    std::vector<std::string> scenes;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        scenes.push_back(text.substr(start, comma - start));
        start = comma + 1;
    }
    return scenes;
}

}  // namespace monoplane::study
