// The one exported symbol: the loader calls it right after loading the library named in the
// manifest and gets xrGetInstanceProcAddr back, through which it finds everything else.
#include "simxr/loader_negotiation.h"

#include "simxr/entry_points.h"

using monoplane::simxr::XrNegotiateLoaderInfo;
using monoplane::simxr::XrNegotiateRuntimeRequest;

extern "C" __attribute__((visibility("default"))) XrResult XRAPI_CALL
xrNegotiateLoaderRuntimeInterface(const XrNegotiateLoaderInfo* loader_info,
                                  XrNegotiateRuntimeRequest* runtime_request) {
    using namespace monoplane::simxr;
    // Loader spec: the runtime checks every field it relies on and fails with
    // XR_ERROR_INITIALIZATION_FAILED when it cannot work with the loader.
    if (loader_info == nullptr || runtime_request == nullptr ||
        loader_info->structType != XR_LOADER_INTERFACE_STRUCT_LOADER_INFO ||
        loader_info->structVersion != XR_LOADER_INFO_STRUCT_VERSION ||
        loader_info->structSize != sizeof(XrNegotiateLoaderInfo) ||
        runtime_request->structType != XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST ||
        runtime_request->structVersion != XR_RUNTIME_INFO_STRUCT_VERSION ||
        runtime_request->structSize != sizeof(XrNegotiateRuntimeRequest)) {
        return XR_ERROR_INITIALIZATION_FAILED;
    }
    if (loader_info->minInterfaceVersion > XR_CURRENT_LOADER_RUNTIME_VERSION ||
        loader_info->maxInterfaceVersion < XR_CURRENT_LOADER_RUNTIME_VERSION) {
        return XR_ERROR_INITIALIZATION_FAILED;
    }
    // simxr implements OpenXR 1.0: refuse loaders that only speak a later major.minor.
    constexpr XrVersion kApi = XR_CURRENT_API_VERSION;
    if (XR_VERSION_MAJOR(loader_info->minApiVersion) > XR_VERSION_MAJOR(kApi) ||
        (XR_VERSION_MAJOR(loader_info->minApiVersion) == XR_VERSION_MAJOR(kApi) &&
         XR_VERSION_MINOR(loader_info->minApiVersion) > XR_VERSION_MINOR(kApi))) {
        return XR_ERROR_INITIALIZATION_FAILED;
    }
    runtime_request->runtimeInterfaceVersion = XR_CURRENT_LOADER_RUNTIME_VERSION;
    runtime_request->runtimeApiVersion = kApi;
    runtime_request->getInstanceProcAddr = &monoplane::simxr::xrGetInstanceProcAddr;
    return XR_SUCCESS;
}
