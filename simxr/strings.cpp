// xrResultToString and xrStructureTypeToString, from the enumerant lists in
// openxr_reflection.h, so every value the headers know is named.
#include <cstdio>
#include <cstring>
#include <string_view>

#include <openxr/openxr_reflection.h>

#include "simxr/entry_points.h"
#include "simxr/runtime_state.h"

namespace monoplane::simxr {
namespace {

#define SIMXR_NAME_CASE(name, value) \
    case name:                       \
        return #name;

std::string_view result_name(XrResult result) {
    switch (result) { XR_LIST_ENUM_XrResult(SIMXR_NAME_CASE) default : return {}; }
}

std::string_view structure_type_name(XrStructureType type) {
    switch (type) { XR_LIST_ENUM_XrStructureType(SIMXR_NAME_CASE) default : return {}; }
}

#undef SIMXR_NAME_CASE

void copy_name(std::string_view name, char* buffer, std::size_t size) {
    const std::size_t length = std::min(name.size(), size - 1);
    std::memcpy(buffer, name.data(), length);
    buffer[length] = '\0';
}

}  // namespace

XrResult XRAPI_CALL xrResultToString(XrInstance instance, XrResult value,
                                     char buffer[XR_MAX_RESULT_STRING_SIZE]) {
    std::lock_guard lock(runtime_mutex());
    if (lookup<Instance>(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (buffer == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    std::string_view name = result_name(value);
    char unknown[XR_MAX_RESULT_STRING_SIZE];
    if (name.empty()) {
        // spec: values the runtime does not know read XR_UNKNOWN_SUCCESS_n / XR_UNKNOWN_FAILURE_n.
        std::snprintf(unknown, sizeof(unknown), "XR_UNKNOWN_%s_%d",
                      value >= 0 ? "SUCCESS" : "FAILURE", static_cast<int>(value));
        name = unknown;
    }
    copy_name(name, buffer, XR_MAX_RESULT_STRING_SIZE);
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrStructureTypeToString(XrInstance instance, XrStructureType value,
                                            char buffer[XR_MAX_STRUCTURE_NAME_SIZE]) {
    std::lock_guard lock(runtime_mutex());
    if (lookup<Instance>(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (buffer == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    std::string_view name = structure_type_name(value);
    char unknown[XR_MAX_STRUCTURE_NAME_SIZE];
    if (name.empty()) {
        std::snprintf(unknown, sizeof(unknown), "XR_UNKNOWN_STRUCTURE_TYPE_%d",
                      static_cast<int>(value));
        name = unknown;
    }
    copy_name(name, buffer, XR_MAX_STRUCTURE_NAME_SIZE);
    return XR_SUCCESS;
}

}  // namespace monoplane::simxr
