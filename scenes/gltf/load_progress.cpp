#include "scenes/gltf/load_progress.h"

#include <cstdio>
#include <iostream>
#include <utility>

namespace monoplane::scenes::gltf {
namespace {

constexpr std::chrono::seconds kInterval{1};

}  // namespace

std::string rounded_count(std::size_t count) {
    char text[32];
    if (count >= 1'000'000) {
        std::snprintf(text, sizeof text, "%.1f M", static_cast<double>(count) / 1e6);
    } else if (count >= 10'000) {
        std::snprintf(text, sizeof text, "%.1f k", static_cast<double>(count) / 1e3);
    } else {
        std::snprintf(text, sizeof text, "%zu", count);
    }
    return text;
}

LoadProgress::LoadProgress(std::string file_name, bool enabled)
    : file_name_(std::move(file_name)),
      enabled_(enabled),
      last_(std::chrono::steady_clock::now()) {}

bool LoadProgress::due() {
    if (!enabled_) return false;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < kInterval) return false;
    last_ = now;
    return true;
}

void LoadProgress::print(const std::string& text) {
    std::cerr << "loading " << file_name_ << ": " << text << '\n' << std::flush;
}

void LoadProgress::meshes(std::size_t done, std::size_t total, std::size_t triangles) {
    if (!due()) return;
    print("mesh " + std::to_string(done) + "/" + std::to_string(total) + ", " +
          rounded_count(triangles) + " triangles");
}

void LoadProgress::chunking(std::size_t done, std::size_t total) {
    if (!due()) return;
    print("chunking, " + rounded_count(done) + " of " + rounded_count(total) + " triangles");
}

}  // namespace monoplane::scenes::gltf
