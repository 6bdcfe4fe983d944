// The runtime side of the OpenXR loader interface (OpenXR loader specification, "Runtime
// Interface Negotiation"). libopenxr-dev 1.0.20 does not install loader_interfaces.h, so the
// structures are declared here from the specification's text.
#pragma once

#include <cstddef>
#include <cstdint>

#include <openxr/openxr.h>

namespace monoplane::simxr {

enum XrLoaderInterfaceStructs : std::uint32_t {
    XR_LOADER_INTERFACE_STRUCT_UNINTIALIZED = 0,  // sic: the specification's spelling
    XR_LOADER_INTERFACE_STRUCT_LOADER_INFO = 1,
    XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST = 2,
    XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST = 3,
    XR_LOADER_INTERFACE_STRUCT_API_LAYER_CREATE_INFO = 4,
    XR_LOADER_INTERFACE_STRUCT_API_LAYER_NEXT_INFO = 5,
};

constexpr std::uint32_t XR_LOADER_INFO_STRUCT_VERSION = 1;
constexpr std::uint32_t XR_RUNTIME_INFO_STRUCT_VERSION = 1;
constexpr std::uint32_t XR_CURRENT_LOADER_RUNTIME_VERSION = 1;

struct XrNegotiateLoaderInfo {
    XrLoaderInterfaceStructs structType;  // XR_LOADER_INTERFACE_STRUCT_LOADER_INFO
    std::uint32_t structVersion;          // XR_LOADER_INFO_STRUCT_VERSION
    std::size_t structSize;               // sizeof(XrNegotiateLoaderInfo)
    std::uint32_t minInterfaceVersion;
    std::uint32_t maxInterfaceVersion;
    XrVersion minApiVersion;
    XrVersion maxApiVersion;
};

struct XrNegotiateRuntimeRequest {
    XrLoaderInterfaceStructs structType;            // XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST
    std::uint32_t structVersion;                    // XR_RUNTIME_INFO_STRUCT_VERSION
    std::size_t structSize;                         // sizeof(XrNegotiateRuntimeRequest)
    std::uint32_t runtimeInterfaceVersion;          // out
    XrVersion runtimeApiVersion;                    // out
    PFN_xrGetInstanceProcAddr getInstanceProcAddr;  // out
};

}  // namespace monoplane::simxr
