// ModeRenderer's side of the render graph: which device image each of the plan's resources is
// this frame (the executor records the barriers; renderer/executor/graph_executor.h).

#include "common/programming_error.h"
#include "renderer/modes/mode_renderer_internals.h"

namespace monoplane::modes {
namespace {

// One layer of a two-layer image (single-pass stereo's multisampled targets).
vk_core::ImageRange layer_of(const vk_core::Image& both, std::uint32_t layer) {
    vk_core::ImageRange range = both.range();
    range.base_layer += layer;
    range.layers = 1;
    return range;
}

}  // namespace

const ModeRenderer::View* ModeRenderer::view_of(plan::ViewId view) const {
    MONOPLANE_EXPECTS(view != plan::ViewId::kNone && view != plan::ViewId::kEyes);
    return view == plan::ViewId::kMono ? mono_.get() : eyes_[plan::eye_index(view)].get();
}

std::vector<vk_core::ImageRange> ModeRenderer::view_images(const plan::ResourceKey& key) const {
    const View* view = view_of(key.view);
    if (view == nullptr) return {};  // C not made yet: only passes the frame leaves out use it
    const auto samples = [&](const std::optional<vk_core::Image>& own,
                             const std::optional<vk_core::Image> ForwardImages::*both)
        -> std::vector<vk_core::ImageRange> {
        if (own) return {own->range()};
        // Single-pass stereo draws both eyes' samples into two-layer images.
        if (eye_layers_ && key.view != plan::ViewId::kMono && (*eye_layers_).*both) {
            return {layer_of(*((*eye_layers_).*both),
                             static_cast<std::uint32_t>(plan::eye_index(key.view)))};
        }
        return {};
    };
    switch (key.image) {
        case plan::ImageRole::kHdr:
            return {view->hdr.range()};
        case plan::ImageRole::kDepth:
            return {view->depth.range()};
        case plan::ImageRole::kLinearDepth:
            return {view->linear_depth.range()};
        case plan::ImageRole::kVelocity:
            return view->velocity ? std::vector{view->velocity->range()}
                                  : std::vector<vk_core::ImageRange>{};
        case plan::ImageRole::kHdrSamples:
            return samples(view->hdr_samples, &ForwardImages::hdr_samples);
        case plan::ImageRole::kLinearDepthSamples:
            return samples(view->linear_depth_samples, &ForwardImages::linear_depth_samples);
        case plan::ImageRole::kDepthSamples:
            return samples(view->depth_samples, &ForwardImages::depth_samples);
        case plan::ImageRole::kAo:
            return view->ssao ? std::vector{view->ssao->ao().range()}
                              : std::vector<vk_core::ImageRange>{};
        case plan::ImageRole::kAoScratch: {
            std::vector<vk_core::ImageRange> scratch;
            if (view->ssao) {
                for (const vk_core::Image* image : view->ssao->scratch())
                    scratch.push_back(image->range());
            }
            return scratch;
        }
        case plan::ImageRole::kHistory:
            return {view->history[history_parity_]->range()};
        case plan::ImageRole::kHistoryPrevious:
            return {view->history[1 - history_parity_]->range()};
        case plan::ImageRole::kDisplay:
            return {view->display.range()};
        default:
            programming_error("bind: " + plan::resource_name(key) + " is not a view's image");
    }
}

const vk_core::Image& ModeRenderer::view_image(const plan::ResourceKey& key) const {
    MONOPLANE_EXPECTS(!key.is_buffer);
    if (key.view == plan::ViewId::kEyes) {
        // Single-pass stereo's two-layer images, which both eyes' forward pass draws into.
        const vk_core::Image* image = eye_layers_ ? eye_layers_->forward_image(key.image) : nullptr;
        if (image == nullptr) {
            programming_error("a pass unit asked for " + plan::resource_name(key) +
                              ", which is no two-layer image of both eyes this frame");
        }
        return *image;
    }
    if (key.view == plan::ViewId::kNone) {
        // The shared images offered to units: the scene's shadow map, the merged depth pyramid.
        if (key.image == plan::ImageRole::kShadowMap) return resources_->shadow().map();
        if (key.image == plan::ImageRole::kMergedDepth) return pyramid_.pyramid();
        if (key.image == plan::ImageRole::kPyramidBlocks) return pyramid_.blocks();
        programming_error("a pass unit asked for " + plan::resource_name(key) +
                          ", which no unit is offered yet");
    }
    const View* view = view_of(key.view);
    const vk_core::Image* image = nullptr;
    if (view != nullptr) {
        image = view->forward_image(key.image);
        switch (key.image) {
            case plan::ImageRole::kHistory:
                image = view->history[history_parity_] ? &*view->history[history_parity_] : nullptr;
                break;
            case plan::ImageRole::kHistoryPrevious:
                image = view->history[1 - history_parity_] ? &*view->history[1 - history_parity_]
                                                           : nullptr;
                break;
            case plan::ImageRole::kDisplay:
                image = &view->display;
                break;
            case plan::ImageRole::kAo:
                image = view->ssao ? &view->ssao->ao() : nullptr;
                break;
            default:
                break;
        }
    }
    if (image == nullptr) {
        programming_error("a pass unit asked for " + plan::resource_name(key) +
                          ", which is not one image of a view this frame");
    }
    return *image;
}

std::vector<const vk_core::Image*> ModeRenderer::view_image_set(
    const plan::ResourceKey& key) const {
    if (key.image != plan::ImageRole::kAoScratch) return {&view_image(key)};
    const View* view = key.view == plan::ViewId::kNone ? nullptr : view_of(key.view);
    if (view == nullptr || !view->ssao) {
        programming_error("a pass unit asked for " + plan::resource_name(key) +
                          ", which is no view's images this frame");
    }
    return view->ssao->scratch();
}

const vk_core::Buffer& ModeRenderer::frame_buffer(const plan::ResourceKey& key,
                                                  std::uint32_t slot) const {
    MONOPLANE_EXPECTS(key.is_buffer);
    if (key.view == plan::ViewId::kNone) {
        switch (key.buffer) {
            case plan::BufferRole::kDepthHistogram:
                if (auto_mono_plane_) return auto_mono_plane_->histogram_buffer(slot);
                break;
            case plan::BufferRole::kDrawLists:
                return culling_.commands_buffer();
            case plan::BufferRole::kPredicates:
                return culling_.counts_buffer();
            case plan::BufferRole::kLodState:
                return culling_.lod_state();
            case plan::BufferRole::kCountsReadback:
                return culling_.counts_readback(slot);
            case plan::BufferRole::kListsReadback:
                return culling_.commands_readback();
            default:
                break;
        }
    } else if (key.view != plan::ViewId::kEyes) {
        const View* view = view_of(key.view);
        if (view != nullptr) {
            switch (key.buffer) {
                case plan::BufferRole::kReadback:
                    return view->readback;
                case plan::BufferRole::kDepthReadback:
                    return view->depth_readback;
                case plan::BufferRole::kAoReadback:
                    if (view->ssao) return view->ssao->readback();
                    break;
                default:
                    break;
            }
        }
    }
    programming_error("a pass unit asked for " + plan::resource_name(key) +
                      ", which no unit is offered yet");
}

std::vector<executor::BoundResource> ModeRenderer::bind_resources() {
    std::vector<executor::BoundResource> bindings;
    for (const plan::ResourceKey& key : last_plan_.keys) {
        executor::BoundResource& bound = bindings.emplace_back();
        if (key.is_buffer) continue;  // buffers take memory barriers
        switch (key.image) {
            case plan::ImageRole::kShadowMap:
                bound.images = {resources_->shadow().map().range()};
                bound.shared_state = &resources_->shadow_map_state();
                break;
            case plan::ImageRole::kPyramidBlocks:
                bound.images = {pyramid_.blocks().range()};
                break;
            case plan::ImageRole::kMergedDepth:
                bound.images = {pyramid_.pyramid().range()};
                break;
            default:
                bound.images = view_images(key);
        }
    }
    return bindings;
}

void ModeRenderer::forget_images(const View& view) {
    for (const vk_core::Image* image :
         {&view.hdr, &view.depth, &view.linear_depth, &view.display}) {
        executor_.forget(image->range());
    }
    for (const auto* image : {&view.velocity, &view.hdr_samples, &view.linear_depth_samples,
                              &view.depth_samples, &view.history[0], &view.history[1]}) {
        if (*image) executor_.forget((*image)->range());
    }
    if (view.ssao) {
        executor_.forget(view.ssao->ao().range());
        for (const vk_core::Image* image : view.ssao->scratch()) executor_.forget(image->range());
    }
}

}  // namespace monoplane::modes
