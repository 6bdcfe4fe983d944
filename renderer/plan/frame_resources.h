// What a frame's passes run over and touch, by enumeration: the views, and each view's images and
// the frame's buffers. The frame plan (frame_plan.h) turns these keys into the render graph's
// typed handles; the executor binds each key to the device object that holds it this frame. One
// name table per enumeration (frame_resources.cpp) is what `render --json`, bench.json's pass
// names and the tests print.
//
// When may this be called: any time; pure values.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace monoplane::plan {

// The camera a pass draws for. kEyes: both eyes in one pass (single-pass stereo); kNone: a pass
// over every view (culling, shadow, the pyramid, the eyes' SSAO, the read-back).
enum class ViewId : std::uint8_t { kLeft, kRight, kEyes, kMono, kNone };
std::string view_name(ViewId view);  // "left", "right", "eyes", "mono", ""
std::optional<ViewId> parse_view(const std::string& name);
// The eye of kLeft or kRight (0 or 1); the others are a programming error.
int eye_index(ViewId view);
ViewId eye_view(int eye);  // 0 -> kLeft, 1 -> kRight
// The two eyes in order (left, right): what per-eye passes and resources iterate over.
constexpr std::array<ViewId, 2> kEyeViews = {ViewId::kLeft, ViewId::kRight};

// A view's images (per camera) and the frame's shared images.
enum class ImageRole : std::uint8_t {
    kHdr,                 // linear HDR colour
    kDepth,               // reversed-Z depth attachment
    kLinearDepth,         // metres in front of the eyes' plane
    kVelocity,            // TAA: screen-space velocity
    kHdrSamples,          // MSAA: the multisampled targets resolved into hdr and linear_depth
    kLinearDepthSamples,  //
    kDepthSamples,        //
    kAo,                  // ambient occlusion (1 = unoccluded)
    kAoScratch,           // SSAO's intermediate images (raw estimate, filtered, the other eye's)
    kHistory,             // TAA: this frame's resolve
    kHistoryPrevious,     // TAA: the previous frame's resolve (read before anything writes it)
    kDisplay,             // tone-mapped colour
    kShadowMap,           // shared: the sun's shadow map
    kPyramidBlocks,       // shared: the eyes' depth reduced to blocks
    kMergedDepth,         // shared: the merged depth pyramid of both eyes
};
std::string image_role_name(ImageRole role);  // "hdr", "linear_depth", ...

enum class BufferRole : std::uint8_t {
    kDrawLists,       // shared: the culling pass's indirect draw lists
    kPredicates,      // shared: its counts and the words conditional rendering reads
    kDepthHistogram,  // shared: `--mono-plane auto`'s bins
    kReadback,        // a view's colour, read by the host
    kDepthReadback,   // a view's linear depth, read by the host
    kAoReadback,      // a view's AO, read by the host
    kCountsReadback,  // shared: the culling counts, read by the host
    kListsReadback,   // shared: the draw lists, read by the host
    kLodState,        // shared: each chunk's level of detail last frame (hysteresis)
};
std::string buffer_role_name(BufferRole role);

// One resource of a frame: a view's image or buffer, or a shared one (view kNone).
struct ResourceKey {
    ViewId view = ViewId::kNone;
    bool is_buffer = false;
    ImageRole image = ImageRole::kHdr;
    BufferRole buffer = BufferRole::kDrawLists;
    bool operator==(const ResourceKey&) const = default;
};
// "left.hdr", "shadow_map", "mono.readback": the graph's name for a key.
std::string resource_name(const ResourceKey& key);

}  // namespace monoplane::plan
