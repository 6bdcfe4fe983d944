// ModeRenderer's results of a completed frame: its statistics (GPU times, pipeline statistics
// with each view's chunk draws) and what it read back (images, depths, AO, draw lists).
#include <algorithm>
#include <utility>

#include "common/programming_error.h"
#include "renderer/modes/mode_renderer_internals.h"
#include "renderer/passes/culling/cull_constants.h"

namespace monoplane::modes {
namespace {

// The culling pass's draw list of a view.
std::uint32_t cull_list(plan::ViewId view) {
    switch (view) {
        case plan::ViewId::kLeft:
            return MONOPLANE_CULL_LEFT;
        case plan::ViewId::kRight:
            return MONOPLANE_CULL_RIGHT;
        case plan::ViewId::kEyes:
            return MONOPLANE_CULL_BOTH_EYES;
        case plan::ViewId::kMono:
            return MONOPLANE_CULL_MONO;
        case plan::ViewId::kNone:
            break;
    }
    programming_error("cull_list: a pass over every view has no draw list of its own");
}

}  // namespace

profile::FrameStats ModeRenderer::collect_frame(std::uint32_t slot, double record_ms) const {
    profile::FrameStats stats = profiler_.collect(slot);
    stats.cpu_record_ms = record_ms;
    const auto counts = culling_.counts(slot);
    // A list's draws of one alpha class, and of the classes its forward pass draws: all three,
    // but in hybrid the eyes' blended chunks, which their transparency passes draw.
    const auto drawn = [&](std::uint32_t list, std::uint32_t alpha_class) {
        return counts[passes::ChunkLists::count_word(list, alpha_class)];
    };
    // This slot's frame had transparency passes if its statistics have their scopes (the plan
    // may since have changed).
    const bool transparency =
        std::any_of(stats.views.begin(), stats.views.end(), [&](const profile::ViewStatistics& v) {
            return v.pass_kind == plan::PassKind::kTransparency;
        });
    const auto forward_draws = [&](std::uint32_t list) {
        const std::uint32_t blended = drawn(list, MONOPLANE_CLASS_BLENDED);
        return drawn(list, MONOPLANE_CLASS_OPAQUE) + drawn(list, MONOPLANE_CLASS_MASKED) +
               (transparency && list != MONOPLANE_CULL_MONO ? 0u : blended);
    };
    for (profile::ViewStatistics& view : stats.views) {
        const plan::PassKind kind = view.pass_kind;
        const plan::ViewId view_id = view.pass_view;
        if (kind == plan::PassKind::kForward) view.draws = forward_draws(cull_list(view_id));
        if (kind == plan::PassKind::kTransparency) {
            view.draws = drawn(cull_list(view_id), MONOPLANE_CLASS_BLENDED);
        }
        if (kind == plan::PassKind::kForward && view_id == plan::ViewId::kMono) {
            view.draws_before_occlusion_culling = counts[MONOPLANE_COUNT_MONO_CANDIDATES];
        }
    }
    return stats;
}

void ModeRenderer::read_back_last_frame() {
    // One read-back buffer per view for every slot: after a drain it holds the last frame's.
    auto read_image = [](const View& view, vk::Extent2D extent, RgbaImage& image) {
        image.width = extent.width;
        image.height = extent.height;
        const auto* bytes = reinterpret_cast<const std::uint8_t*>(view.readback.mapped());
        image.pixels.assign(bytes, bytes + std::size_t{extent.width} * extent.height * 4);
    };
    if (options_.read_back) {
        for (auto& eye : eyes_) read_image(*eye, eye->extent, eye->image);
        if (mono_rendered_) read_image(*mono_, mono_->area, mono_->image);
    }
    if (options_.read_back_ao) {
        for (auto& eye : eyes_) eye->ao = eye->ssao->ao_values();
    }
    if (options_.read_back_depth) {
        for (auto& eye : eyes_) {
            const auto* values = reinterpret_cast<const float*>(eye->depth_readback.mapped());
            eye->linear.assign(values,
                               values + std::size_t{eye->extent.width} * eye->extent.height);
        }
    }
}

std::vector<std::uint32_t> ModeRenderer::drawn_chunks(passes::CullView view) const {
    // Without the option the lists were never copied to the host: nothing to report.
    if (!options_.read_back_draw_lists) return {};
    return culling_.drawn_chunks(view, last_slot_);
}

std::vector<vk::DrawIndexedIndirectCommand> ModeRenderer::drawn_commands(
    passes::CullView view) const {
    if (!options_.read_back_draw_lists) return {};
    return culling_.drawn_commands(view, last_slot_);
}

const vk_core::Image& ModeRenderer::display_image(Eye eye) const {
    return eyes_[static_cast<int>(eye)]->display;
}

const RgbaImage& ModeRenderer::eye_image(Eye eye) const {
    return eyes_[static_cast<int>(eye)]->image;
}

const RgbaImage* ModeRenderer::mono_image() const {
    return mono_rendered_ && mono_ ? &mono_->image : nullptr;
}

const std::vector<float>& ModeRenderer::eye_linear_depth(Eye eye) const {
    return eyes_[static_cast<int>(eye)]->linear;
}

const std::vector<float>& ModeRenderer::eye_ao(Eye eye) const {
    return eyes_[static_cast<int>(eye)]->ao;
}

const EyeFrameGeometry& ModeRenderer::eye_geometry(Eye eye) const {
    return eyes_[static_cast<int>(eye)]->geometry;
}

}  // namespace monoplane::modes
