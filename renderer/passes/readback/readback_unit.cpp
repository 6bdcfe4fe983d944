// The read-back, a pass kind written as one unit: last in every frame, one step ("copy") of
// everything the host reads once the frame has completed, each into its host-visible buffer:
// the eyes' display images (`render`'s PNGs), linear depths and AO when the renderer was asked for
// them (RendererOptions::read_back, read_back_depth, read_back_ao), C's display image over its
// viewport in a hybrid frame that draws C, the culling's counts (always: the frame's statistics)
// and, when asked, its draw lists. Its placement marks each buffer as read by the host
// (UnitPlacement::read_by_host), so that the graph keeps the passes that write what it copies.
// Its time is not the frame's GPU time: the profiler leaves PassKind::kReadback out.
//
// The declaration (compiled Vulkan-free with MONOPLANE_UNIT_DECLARATION) and the recorder
// (MONOPLANE_UNIT_RECORDER) of renderer/plan/pass_unit.h and renderer/passes/shared/pass_unit.h,
// side by side.
#include "renderer/plan/pass_unit.h"

#ifdef MONOPLANE_UNIT_RECORDER
#include <optional>

#include "renderer/executor/image_layouts.h"
#include "renderer/passes/shared/pass_unit.h"
#endif

namespace monoplane::passes::readback {

#ifdef MONOPLANE_UNIT_DECLARATION
namespace {

using plan::BufferRole;
using plan::ImageRole;
using plan::ViewId;

void place(plan::UnitPlacement& placement) {
    const plan::PlanOptions& options = placement.options();
    plan::PlanResources& r = placement.resources();
    graph::Step& step = placement.add_pass().steps.emplace_back();
    step.name = "copy";
    graph::StepBuilder uses(step);
    const auto copy = [&](auto from, graph::BufferHandle to) {
        uses.use(from, graph::Use::kTransferSrc).use(to, graph::Use::kTransferDst);
        placement.read_by_host(to);
    };
    for (ViewId eye : plan::kEyeViews) {
        if (options.read_back)
            copy(r.image(eye, ImageRole::kDisplay), r.buffer(eye, BufferRole::kReadback));
        if (options.read_back_depth) {
            copy(r.image(eye, ImageRole::kLinearDepth), r.buffer(eye, BufferRole::kDepthReadback));
        }
        if (options.read_back_ao)
            copy(r.image(eye, ImageRole::kAo), r.buffer(eye, BufferRole::kAoReadback));
    }
    if (options.read_back && placement.draws_mono()) {
        copy(r.image(ViewId::kMono, ImageRole::kDisplay),
             r.buffer(ViewId::kMono, BufferRole::kReadback));
    }
    copy(r.shared(BufferRole::kPredicates), r.shared(BufferRole::kCountsReadback));
    if (options.read_back_draw_lists) {
        copy(r.shared(BufferRole::kDrawLists), r.shared(BufferRole::kListsReadback));
    }
}

}  // namespace

plan::PassUnitDeclaration declaration() {
    return plan::built_in_unit(
        plan::PassKind::kReadback, plan::UnitSlot::kReadBack,
        "the copies the host reads after the frame (images, the culling's counts)", &place);
}
#endif  // MONOPLANE_UNIT_DECLARATION

#ifdef MONOPLANE_UNIT_RECORDER
namespace {

using plan::BufferRole;
using plan::ImageRole;
using plan::ViewId;

class ReadbackRecorder final : public UnitRecorder {
  public:
    void record(UnitRecording& r) override {
        for (ViewId eye : plan::kEyeViews) {
            copy_image(r, eye, ImageRole::kDisplay, BufferRole::kReadback);
            copy_image(r, eye, ImageRole::kLinearDepth, BufferRole::kDepthReadback);
            copy_image(r, eye, ImageRole::kAo, BufferRole::kAoReadback);
        }
        // C's image holds the frame over its viewport alone (eq. 8): the allocation may be larger.
        copy_image(r, ViewId::kMono, ImageRole::kDisplay, BufferRole::kReadback,
                   r.values().mono_area);
        copy_buffer(r, BufferRole::kPredicates, BufferRole::kCountsReadback);
        copy_buffer(r, BufferRole::kDrawLists, BufferRole::kListsReadback);
    }

  private:
    // `view`'s image `from` (its extent, or `area` from its corner) into its buffer `to`, where
    // the step declares the copy.
    static void copy_image(UnitRecording& r, ViewId view, ImageRole from, BufferRole to,
                           std::optional<vk::Extent2D> area = std::nullopt) {
        if (!r.declares(view, to)) return;
        const vk_core::Image& image = r.image(view, from);
        const vk::Extent2D extent = area.value_or(image.desc().extent);
        r.cmd().copyImageToBuffer(
            image.handle(), executor::layout_for(graph::Use::kTransferSrc),
            r.buffer(view, to).handle(),
            vk::BufferImageCopy(0, 0, 0,
                                vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, 0,
                                                           image.base_layer(), 1),
                                {0, 0, 0}, vk::Extent3D(extent, 1)));
    }

    // A shared buffer whole into another, where the step declares the copy.
    static void copy_buffer(UnitRecording& r, BufferRole from, BufferRole to) {
        if (!r.declares(ViewId::kNone, to)) return;
        const vk_core::Buffer& source = r.buffer(ViewId::kNone, from);
        r.cmd().copyBuffer(source.handle(), r.buffer(ViewId::kNone, to).handle(),
                           vk::BufferCopy(0, 0, source.size()));
    }
};

}  // namespace

std::unique_ptr<UnitRecorder> make_recorder(const vk_core::Context&, const UnitScene&,
                                            const UnitPasses&, const UnitSettings&) {
    return std::make_unique<ReadbackRecorder>();
}
#endif  // MONOPLANE_UNIT_RECORDER

}  // namespace monoplane::passes::readback
