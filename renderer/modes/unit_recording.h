// What a pass unit's recorder may reach of a frame (passes::UnitRecording), checked against the
// pass's declared steps: ModeRenderer makes one per unit pass it records (record_unit).
//
// When may this be called: while the frame's command buffer records, inside the pass's scope.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "renderer/passes/shared/pass_unit.h"
#include "renderer/passes/shared/step_sync.h"
#include "renderer/plan/frame_plan.h"

namespace monoplane::modes {

// What the frame's resources and predicates are on the device: the image or buffer of a
// resource this frame, and the GPU predicate of a planned `when`.
struct UnitResolvers {
    std::function<const vk_core::Image&(const plan::ResourceKey&)> image;
    // Every image of a role that is several (SSAO's scratch images).
    std::function<std::vector<const vk_core::Image*>(const plan::ResourceKey&)> images;
    std::function<const vk_core::Buffer&(plan::ViewId)> view_constants;
    passes::CullInputs cull_inputs;
    std::function<passes::ChunkDraws(passes::CullView)> chunk_draws;
    std::function<const vk_core::Buffer&(const plan::ResourceKey&)> buffer;
    std::function<std::optional<passes::Predicate>(plan::GpuPredicate)> predicate;
    // The scene the renderer draws (UnitRecording::scene); must be set for a unit that asks.
    const passes::UnitScene* scene = nullptr;
};

// `pass` must be one of `plan`'s, with at least one step; the recording begins its first step
// (through `sync` for a pass of several).
std::unique_ptr<passes::UnitRecording> make_unit_recording(
    const vk::raii::CommandBuffer& cmd, const plan::FramePlan& plan, const plan::PlannedPass& pass,
    passes::StepSync& sync, passes::UnitFrameValues values, UnitResolvers resolvers);

}  // namespace monoplane::modes
