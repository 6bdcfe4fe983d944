#include "renderer/modes/unit_recording.h"

#include <algorithm>
#include <string>
#include <utility>

#include "common/programming_error.h"
#include "renderer/modes/mode_renderer_internals.h"
#include "renderer/passes/pass_units.h"
#include "rig/temporal_jitter.h"

namespace monoplane::modes {
namespace {

class Recording final : public passes::UnitRecording {
  public:
    Recording(const vk::raii::CommandBuffer& cmd, const plan::FramePlan& plan,
              const plan::PlannedPass& pass, passes::StepSync& sync, passes::UnitFrameValues values,
              UnitResolvers resolvers)
        : cmd_(cmd),
          plan_(plan),
          pass_(pass),
          sync_(sync),
          values_(values),
          resolvers_(std::move(resolvers)) {
        MONOPLANE_EXPECTS(!pass.steps.empty());
        // The executor begins a pass of one step; a pass of several asks for each, the first too.
        if (pass.steps.size() > 1) sync_.next(cmd_, pass.steps.front().name);
    }

    const vk::raii::CommandBuffer& cmd() const override { return cmd_; }
    const plan::PlannedPass& pass() const override { return pass_; }
    const passes::UnitFrameValues& values() const override { return values_; }

    const vk_core::Image& image(plan::ViewId view, plan::ImageRole role) override {
        if (view == plan::ViewId::kEyes) {
            for (plan::ViewId eye : plan::kEyeViews) expect_declared(image_key(eye, role));
        } else {
            expect_declared(image_key(view, role));
        }
        return resolvers_.image(image_key(view, role));
    }

    std::vector<const vk_core::Image*> images(plan::ViewId view, plan::ImageRole role) override {
        const plan::ResourceKey key{view, false, role, plan::BufferRole::kDrawLists};
        expect_declared(key);
        return resolvers_.images(key);
    }

    const vk_core::Buffer& view_constants(plan::ViewId view) const override {
        return resolvers_.view_constants(view);
    }

    passes::CullInputs cull_inputs() const override { return resolvers_.cull_inputs; }

    bool declares(plan::ViewId view, plan::ImageRole role) const override {
        if (view == plan::ViewId::kEyes) {
            return declares(plan::ViewId::kLeft, role) && declares(plan::ViewId::kRight, role);
        }
        const std::optional<std::uint16_t> handle = plan_.handle(image_key(view, role));
        return handle && plan::step_declares(pass_.steps[step_], *handle);
    }

    passes::ChunkDraws chunk_draws(passes::CullView view) override {
        for (plan::BufferRole role :
             {plan::BufferRole::kDrawLists, plan::BufferRole::kPredicates}) {
            expect_declared({plan::ViewId::kNone, true, plan::ImageRole::kHdr, role});
        }
        return resolvers_.chunk_draws(view);
    }

    bool declares(plan::ViewId view, plan::BufferRole role) const override {
        const std::optional<std::uint16_t> handle =
            plan_.handle({view, true, plan::ImageRole::kHdr, role});
        return handle && plan::step_declares(pass_.steps[step_], *handle);
    }

    const vk_core::Buffer& buffer(plan::ViewId view, plan::BufferRole role) override {
        const plan::ResourceKey key{view, true, plan::ImageRole::kHdr, role};
        expect_declared(key);
        return resolvers_.buffer(key);
    }

    void next_step(std::string_view step) override {
        // The executor checks the name and the order; a repeating last step stays the current.
        sync_.next(cmd_, step);
        step_ = std::min(step_ + 1, pass_.steps.size() - 1);
    }

    std::optional<passes::Predicate> predicate(plan::GpuPredicate when) const override {
        return resolvers_.predicate(when);
    }

    const passes::UnitScene& scene() const override {
        MONOPLANE_EXPECTS(resolvers_.scene != nullptr);
        return *resolvers_.scene;
    }

  private:
    static plan::ResourceKey image_key(plan::ViewId view, plan::ImageRole role) {
        return {view, false, role, plan::BufferRole::kDrawLists};
    }

    void expect_declared(const plan::ResourceKey& key) const {
        const std::optional<std::uint16_t> handle = plan_.handle(key);
        const graph::Step& step = pass_.steps[step_];
        if (!handle || !plan::step_declares(step, *handle)) {
            programming_error(pass_.name + " touched " + plan::resource_name(key) + " in step '" +
                              step.name + "', which does not declare it");
        }
    }

    const vk::raii::CommandBuffer& cmd_;
    const plan::FramePlan& plan_;
    const plan::PlannedPass& pass_;
    passes::StepSync& sync_;
    passes::UnitFrameValues values_;
    UnitResolvers resolvers_;
    std::size_t step_ = 0;  // the step being recorded
};

}  // namespace

std::unique_ptr<passes::UnitRecording> make_unit_recording(
    const vk::raii::CommandBuffer& cmd, const plan::FramePlan& plan, const plan::PlannedPass& pass,
    passes::StepSync& sync, passes::UnitFrameValues values, UnitResolvers resolvers) {
    return std::make_unique<Recording>(cmd, plan, pass, sync, values, std::move(resolvers));
}

passes::UnitSettings ModeRenderer::unit_settings() const {
    passes::UnitSettings settings;
    settings.tonemap = options_.tonemap;
    settings.taa = options_.taa;
    settings.ssao = options_.ssao_params;
    if (auto_mono_plane_) settings.depth_histogram = auto_mono_plane_->histogram_range();
    settings.forward.msaa_samples =
        static_cast<std::uint32_t>(msaa_samples(options_.anti_aliasing));
    settings.forward.stereo_pass = options_.stereo_pass;
    settings.forward.vertex_work = options_.vertex_work;
    return settings;
}

passes::UnitFrameValues ModeRenderer::unit_frame_values(const FrameState& frame) const {
    passes::UnitFrameValues values;
    values.use_mono = frame.use_mono;
    values.mono_plane = frame.inputs->mono_plane;
    values.slot = frame.slot;
    values.history_restarted = !history_valid_;
    values.settings = unit_settings();
    // What only some kinds read, worked out where this frame's plan runs them.
    const auto runs = [&](plan::PassKind kind, plan::ViewId view) {
        return last_plan_.runs(kind, view);
    };
    if (runs(plan::PassKind::kComposite, plan::ViewId::kLeft) ||
        runs(plan::PassKind::kComposite, plan::ViewId::kRight)) {
        values.composite = composite_values(frame);
    }
    if (runs(plan::PassKind::kDepthPyramid, plan::ViewId::kNone)) {
        for (int e = 0; e < 2; ++e) {
            values.mono_pixel_to_eye[e] = rig::jittered_pixel_mapping(
                rig::mono_pixel_to_eye_pixel(*rig_, e), frame.jitter_px);
        }
    }
    if (frame.use_mono) values.mono_area = mono_->area;
    values.mono_hidden_pixels_read = options_.read_back || options_.ssao.has_value();
    values.light_view_proj = glm::mat4(frame.light_view_proj);
    return values;
}

void ModeRenderer::record_unit(const vk::raii::CommandBuffer& cmd, const plan::PlannedPass& pass,
                               const FrameState& frame, passes::StepSync& sync) {
    MONOPLANE_EXPECTS(!pass.unit.empty());
    auto& recorder = unit_recorders_[pass.unit];
    if (!recorder) {
        passes::UnitPasses passes;
        passes.passes.emplace_back(&last_plan_, &pass);
        recorder =
            passes::make_unit_recorder(pass.unit, ctx_, unit_scene_, passes, unit_settings());
    }
    UnitResolvers resolvers;
    resolvers.image = [this](const plan::ResourceKey& key) -> const vk_core::Image& {
        return view_image(key);
    };
    resolvers.images = [this](const plan::ResourceKey& key) { return view_image_set(key); };
    resolvers.view_constants = [this](plan::ViewId view) -> const vk_core::Buffer& {
        // Single-pass stereo's both eyes: their constants in one buffer.
        if (view == plan::ViewId::kEyes) return *eye_pair_constants_;
        const View* of = view_of(view);
        MONOPLANE_EXPECTS(of != nullptr);
        return of->constants;
    };
    resolvers.cull_inputs = culling_.inputs();
    resolvers.chunk_draws = [this](passes::CullView view) { return culling_.chunk_draws(view); };
    resolvers.buffer = [this, &frame](const plan::ResourceKey& key) -> const vk_core::Buffer& {
        return frame_buffer(key, frame.slot);
    };
    resolvers.predicate = [this](plan::GpuPredicate when) { return predicate(when); };
    resolvers.scene = &unit_scene_;
    const std::unique_ptr<passes::UnitRecording> recording =
        make_unit_recording(cmd, last_plan_, pass, sync, frame.unit_values, std::move(resolvers));
    recorder->record(*recording);
}

}  // namespace monoplane::modes
