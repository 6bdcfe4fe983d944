// A progress line on stderr for loads that take a while ("loading big.glb: mesh 3/10, 1.2 M
// triangles"), at most about once a second and only after the first second, so quick loads
// (every test) print nothing.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>

namespace monoplane::scenes::gltf {

class LoadProgress {
  public:
    LoadProgress(std::string file_name, bool enabled);

    // Reading mesh instance `done` of `total`, `triangles` collected so far.
    void meshes(std::size_t done, std::size_t total, std::size_t triangles);
    // A later stage: "chunking 1.2/2.0 M triangles".
    void chunking(std::size_t done, std::size_t total);

  private:
    bool due();
    void print(const std::string& text);

    std::string file_name_;
    bool enabled_;
    std::chrono::steady_clock::time_point last_;
};

// 1234567 -> "1.2 M", 12345 -> "12.3 k", 123 -> "123".
std::string rounded_count(std::size_t count);

}  // namespace monoplane::scenes::gltf
