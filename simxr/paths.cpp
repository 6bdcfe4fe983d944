// xrStringToPath / xrPathToString (spec 6.2 "Path Atom Type" and 6.1 "Path Names").
#include <string_view>

#include "simxr/entry_points.h"
#include "simxr/runtime_state.h"

namespace monoplane::simxr {
namespace {

// spec 6.1: a well-formed path starts with '/', has no empty, "." or ".." segment, does not end
// with '/', and uses only lower-case ASCII letters, digits, '-', '_' and '.'.
bool well_formed(std::string_view path) {
    if (path.size() < 2 || path.size() >= XR_MAX_PATH_LENGTH || path.front() != '/' ||
        path.back() == '/') {
        return false;
    }
    std::size_t segment_start = 1;
    for (std::size_t i = 1; i <= path.size(); ++i) {
        if (i == path.size() || path[i] == '/') {
            const std::string_view segment = path.substr(segment_start, i - segment_start);
            if (segment.empty() || segment == "." || segment == "..") return false;
            segment_start = i + 1;
            continue;
        }
        const char c = path[i];
        const bool allowed =
            (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
        if (!allowed) return false;
    }
    return true;
}

}  // namespace

XrPath PathTable::intern(const std::string& path) {
    if (auto found = atoms.find(path); found != atoms.end()) return found->second;
    strings.push_back(path);
    const auto atom = static_cast<XrPath>(strings.size());
    atoms.emplace(path, atom);
    return atom;
}

const std::string* PathTable::find(XrPath path) const {
    if (path == XR_NULL_PATH || path > strings.size()) return nullptr;
    return &strings[path - 1];
}

XrResult XRAPI_CALL xrStringToPath(XrInstance handle, const char* text, XrPath* path) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = lookup<Instance>(handle);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (text == nullptr || path == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (!well_formed(text)) return XR_ERROR_PATH_FORMAT_INVALID;
    *path = instance->paths.intern(text);
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrPathToString(XrInstance handle, XrPath path, uint32_t capacity,
                                   uint32_t* count, char* buffer) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = lookup<Instance>(handle);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    const std::string* text = instance->paths.find(path);
    if (text == nullptr) return XR_ERROR_PATH_INVALID;
    return fill_string(capacity, count, buffer, *text);
}

}  // namespace monoplane::simxr
