#include "renderer/plan/frame_resources.h"

#include "common/name_table.h"
#include "common/programming_error.h"

namespace monoplane::plan {
namespace {

constexpr NameTable<ViewId> kViewNames = {{ViewId::kLeft, "left"},
                                          {ViewId::kRight, "right"},
                                          {ViewId::kEyes, "eyes"},
                                          {ViewId::kMono, "mono"},
                                          {ViewId::kNone, ""}};

constexpr NameTable<ImageRole> kImageRoleNames = {
    {ImageRole::kHdr, "hdr"},
    {ImageRole::kDepth, "depth"},
    {ImageRole::kLinearDepth, "linear_depth"},
    {ImageRole::kVelocity, "velocity"},
    {ImageRole::kHdrSamples, "hdr_samples"},
    {ImageRole::kLinearDepthSamples, "linear_depth_samples"},
    {ImageRole::kDepthSamples, "depth_samples"},
    {ImageRole::kAo, "ao"},
    {ImageRole::kAoScratch, "ao_scratch"},
    {ImageRole::kHistory, "history"},
    {ImageRole::kHistoryPrevious, "history_previous"},
    {ImageRole::kDisplay, "display"},
    {ImageRole::kShadowMap, "shadow_map"},
    {ImageRole::kPyramidBlocks, "pyramid_blocks"},
    {ImageRole::kMergedDepth, "merged_depth"}};

constexpr NameTable<BufferRole> kBufferRoleNames = {
    {BufferRole::kDrawLists, "draw_lists"},
    {BufferRole::kPredicates, "predicates"},
    {BufferRole::kDepthHistogram, "depth_histogram"},
    {BufferRole::kReadback, "readback"},
    {BufferRole::kDepthReadback, "depth_readback"},
    {BufferRole::kAoReadback, "ao_readback"},
    {BufferRole::kCountsReadback, "counts_readback"},
    {BufferRole::kListsReadback, "lists_readback"},
    {BufferRole::kLodState, "lod_state"}};

}  // namespace

std::string view_name(ViewId view) {
    return name_of(kViewNames, view);
}

std::optional<ViewId> parse_view(const std::string& name) {
    return parse_name(kViewNames, name);
}

int eye_index(ViewId view) {
    if (view == ViewId::kLeft) return 0;
    if (view == ViewId::kRight) return 1;
    programming_error("eye_index: view \"" + view_name(view) + "\" is not an eye");
}

ViewId eye_view(int eye) {
    return eye == 0 ? ViewId::kLeft : ViewId::kRight;
}

std::string image_role_name(ImageRole role) {
    return name_of(kImageRoleNames, role);
}

std::string buffer_role_name(BufferRole role) {
    return name_of(kBufferRoleNames, role);
}

std::string resource_name(const ResourceKey& key) {
    const std::string role =
        key.is_buffer ? buffer_role_name(key.buffer) : image_role_name(key.image);
    return key.view == ViewId::kNone ? role : view_name(key.view) + "." + role;
}

}  // namespace monoplane::plan
