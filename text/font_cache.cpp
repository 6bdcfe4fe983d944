#include "text/font_cache.h"

#include <map>
#include <mutex>

namespace monoplane::text {

Result<std::shared_ptr<const Font>> cached_font(const std::filesystem::path& path) {
    static std::mutex mutex;
    static std::map<std::filesystem::path, std::shared_ptr<const Font>> fonts;
    const std::lock_guard guard(mutex);
    if (const auto found = fonts.find(path); found != fonts.end()) return found->second;
    Result<Font> font = Font::open(path);
    MONOPLANE_TRY(font);
    auto shared = std::make_shared<const Font>(std::move(font).value());
    fonts.emplace(path, shared);
    return shared;
}

}  // namespace monoplane::text
