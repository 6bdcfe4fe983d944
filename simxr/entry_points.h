// Every OpenXR function simxr implements, under the spec's names inside this namespace (the
// library is built with XR_NO_PROTOTYPES, so nothing clashes with the loader's symbols). The
// loader reaches them only through xrGetInstanceProcAddr (dispatch.cpp).
#pragma once

// openxr_platform.h needs Vulkan's types declared first.
#include <vulkan/vulkan.h>

#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

namespace monoplane::simxr {

#define SIMXR_ENTRY XrResult XRAPI_CALL

SIMXR_ENTRY xrGetInstanceProcAddr(XrInstance, const char*, PFN_xrVoidFunction*);

// instance.cpp
SIMXR_ENTRY xrEnumerateInstanceExtensionProperties(const char*, uint32_t, uint32_t*,
                                                   XrExtensionProperties*);
SIMXR_ENTRY xrEnumerateApiLayerProperties(uint32_t, uint32_t*, XrApiLayerProperties*);
SIMXR_ENTRY xrCreateInstance(const XrInstanceCreateInfo*, XrInstance*);
SIMXR_ENTRY xrDestroyInstance(XrInstance);
SIMXR_ENTRY xrGetInstanceProperties(XrInstance, XrInstanceProperties*);
SIMXR_ENTRY xrGetSystem(XrInstance, const XrSystemGetInfo*, XrSystemId*);
SIMXR_ENTRY xrGetSystemProperties(XrInstance, XrSystemId, XrSystemProperties*);
SIMXR_ENTRY xrEnumerateEnvironmentBlendModes(XrInstance, XrSystemId, XrViewConfigurationType,
                                             uint32_t, uint32_t*, XrEnvironmentBlendMode*);
SIMXR_ENTRY xrEnumerateViewConfigurations(XrInstance, XrSystemId, uint32_t, uint32_t*,
                                          XrViewConfigurationType*);
SIMXR_ENTRY xrGetViewConfigurationProperties(XrInstance, XrSystemId, XrViewConfigurationType,
                                             XrViewConfigurationProperties*);
SIMXR_ENTRY xrEnumerateViewConfigurationViews(XrInstance, XrSystemId, XrViewConfigurationType,
                                              uint32_t, uint32_t*, XrViewConfigurationView*);

// strings.cpp
SIMXR_ENTRY xrResultToString(XrInstance, XrResult, char[XR_MAX_RESULT_STRING_SIZE]);
SIMXR_ENTRY xrStructureTypeToString(XrInstance, XrStructureType, char[XR_MAX_STRUCTURE_NAME_SIZE]);

// events.cpp
SIMXR_ENTRY xrPollEvent(XrInstance, XrEventDataBuffer*);

// paths.cpp
SIMXR_ENTRY xrStringToPath(XrInstance, const char*, XrPath*);
SIMXR_ENTRY xrPathToString(XrInstance, XrPath, uint32_t, uint32_t*, char*);

// vulkan_enable.cpp (XR_KHR_vulkan_enable2)
SIMXR_ENTRY xrGetVulkanGraphicsRequirements2KHR(XrInstance, XrSystemId,
                                                XrGraphicsRequirementsVulkanKHR*);
SIMXR_ENTRY xrCreateVulkanInstanceKHR(XrInstance, const XrVulkanInstanceCreateInfoKHR*, VkInstance*,
                                      VkResult*);
SIMXR_ENTRY xrGetVulkanGraphicsDevice2KHR(XrInstance, const XrVulkanGraphicsDeviceGetInfoKHR*,
                                          VkPhysicalDevice*);
SIMXR_ENTRY xrCreateVulkanDeviceKHR(XrInstance, const XrVulkanDeviceCreateInfoKHR*, VkDevice*,
                                    VkResult*);

// session.cpp
SIMXR_ENTRY xrCreateSession(XrInstance, const XrSessionCreateInfo*, XrSession*);
SIMXR_ENTRY xrDestroySession(XrSession);
SIMXR_ENTRY xrBeginSession(XrSession, const XrSessionBeginInfo*);
SIMXR_ENTRY xrEndSession(XrSession);
SIMXR_ENTRY xrRequestExitSession(XrSession);

// frame_loop.cpp
SIMXR_ENTRY xrWaitFrame(XrSession, const XrFrameWaitInfo*, XrFrameState*);
SIMXR_ENTRY xrBeginFrame(XrSession, const XrFrameBeginInfo*);
SIMXR_ENTRY xrEndFrame(XrSession, const XrFrameEndInfo*);

// spaces.cpp
SIMXR_ENTRY xrEnumerateReferenceSpaces(XrSession, uint32_t, uint32_t*, XrReferenceSpaceType*);
SIMXR_ENTRY xrCreateReferenceSpace(XrSession, const XrReferenceSpaceCreateInfo*, XrSpace*);
SIMXR_ENTRY xrGetReferenceSpaceBoundsRect(XrSession, XrReferenceSpaceType, XrExtent2Df*);
SIMXR_ENTRY xrCreateActionSpace(XrSession, const XrActionSpaceCreateInfo*, XrSpace*);
SIMXR_ENTRY xrLocateSpace(XrSpace, XrSpace, XrTime, XrSpaceLocation*);
SIMXR_ENTRY xrDestroySpace(XrSpace);
SIMXR_ENTRY xrLocateViews(XrSession, const XrViewLocateInfo*, XrViewState*, uint32_t, uint32_t*,
                          XrView*);

// swapchain.cpp
SIMXR_ENTRY xrEnumerateSwapchainFormats(XrSession, uint32_t, uint32_t*, int64_t*);
SIMXR_ENTRY xrCreateSwapchain(XrSession, const XrSwapchainCreateInfo*, XrSwapchain*);
SIMXR_ENTRY xrDestroySwapchain(XrSwapchain);
SIMXR_ENTRY xrEnumerateSwapchainImages(XrSwapchain, uint32_t, uint32_t*,
                                       XrSwapchainImageBaseHeader*);
SIMXR_ENTRY xrAcquireSwapchainImage(XrSwapchain, const XrSwapchainImageAcquireInfo*, uint32_t*);
SIMXR_ENTRY xrWaitSwapchainImage(XrSwapchain, const XrSwapchainImageWaitInfo*);
SIMXR_ENTRY xrReleaseSwapchainImage(XrSwapchain, const XrSwapchainImageReleaseInfo*);

// actions.cpp
SIMXR_ENTRY xrCreateActionSet(XrInstance, const XrActionSetCreateInfo*, XrActionSet*);
SIMXR_ENTRY xrDestroyActionSet(XrActionSet);
SIMXR_ENTRY xrCreateAction(XrActionSet, const XrActionCreateInfo*, XrAction*);
SIMXR_ENTRY xrDestroyAction(XrAction);
SIMXR_ENTRY xrSuggestInteractionProfileBindings(XrInstance,
                                                const XrInteractionProfileSuggestedBinding*);
SIMXR_ENTRY xrAttachSessionActionSets(XrSession, const XrSessionActionSetsAttachInfo*);
SIMXR_ENTRY xrGetCurrentInteractionProfile(XrSession, XrPath, XrInteractionProfileState*);
SIMXR_ENTRY xrSyncActions(XrSession, const XrActionsSyncInfo*);
SIMXR_ENTRY xrGetActionStateBoolean(XrSession, const XrActionStateGetInfo*, XrActionStateBoolean*);
SIMXR_ENTRY xrGetActionStateFloat(XrSession, const XrActionStateGetInfo*, XrActionStateFloat*);
SIMXR_ENTRY xrGetActionStateVector2f(XrSession, const XrActionStateGetInfo*,
                                     XrActionStateVector2f*);
SIMXR_ENTRY xrGetActionStatePose(XrSession, const XrActionStateGetInfo*, XrActionStatePose*);
SIMXR_ENTRY xrEnumerateBoundSourcesForAction(XrSession, const XrBoundSourcesForActionEnumerateInfo*,
                                             uint32_t, uint32_t*, XrPath*);
SIMXR_ENTRY xrGetInputSourceLocalizedName(XrSession, const XrInputSourceLocalizedNameGetInfo*,
                                          uint32_t, uint32_t*, char*);
SIMXR_ENTRY xrApplyHapticFeedback(XrSession, const XrHapticActionInfo*, const XrHapticBaseHeader*);
SIMXR_ENTRY xrStopHapticFeedback(XrSession, const XrHapticActionInfo*);

#undef SIMXR_ENTRY

}  // namespace monoplane::simxr
