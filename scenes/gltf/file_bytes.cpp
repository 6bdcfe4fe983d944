#include "scenes/gltf/file_bytes.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <system_error>

namespace monoplane::scenes::gltf {
namespace {

struct CloseFile {
    void operator()(std::FILE* file) const { std::fclose(file); }
};

}  // namespace

Result<std::vector<unsigned char>> read_file_bytes(const std::filesystem::path& path) {
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (error || !std::filesystem::exists(status)) return Error{"not found"};
    if (std::filesystem::is_directory(status)) return Error{"is a directory, not a file"};
    if (!std::filesystem::is_regular_file(status)) return Error{"is not a regular file"};
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error) return Error{"cannot be read (" + error.message() + ")"};
    if (size > kMaxFileBytes) {
        return Error{"is larger than 4 GiB (" + std::to_string(size) +
                     " bytes), more than glTF can address"};
    }
    const std::unique_ptr<std::FILE, CloseFile> file(std::fopen(path.c_str(), "rb"));
    if (!file) return Error{std::string("cannot be opened (") + std::strerror(errno) + ")"};
    std::vector<unsigned char> bytes(static_cast<std::size_t>(size));
    if (!bytes.empty() && std::fread(bytes.data(), 1, bytes.size(), file.get()) != bytes.size()) {
        return Error{"cannot be read to its end (it changed while being read?)"};
    }
    return bytes;
}

}  // namespace monoplane::scenes::gltf
