// Forward shading of one view into an HDR target, then the sky where nothing was drawn.
// Reads: view constants (set 0, binding 0), the shadow map (binding 1), the scene's textures
// (set 2, SceneTextures).
// Writes: HDR colour, reversed-Z depth, linear depth (metres in front of the eyes' plane), and with
// ForwardConfig::velocity the screen-space velocity TAA reprojects with.
#pragma once

#include <optional>
#include <span>

#include "renderer/passes/shared/indirect_draws.h"
#include "renderer/passes/shared/scene_geometry.h"
#include "renderer/passes/shared/scene_textures.h"
#include "renderer/passes/shared/view_constants.h"
#include "renderer/plan/frame_plan.h"
#include "renderer/plan/render_choices.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/descriptor_set.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace monoplane::passes {

struct ForwardShaders;  // forward_shaders.h

// The multisampled images an MSAA pass draws into; ForwardTargets' hdr and linear depth then
// receive their resolve (the average of the samples), and its depth image is not written.
struct MultisampleTargets {
    const vk_core::Image& hdr;           // kHdrFormat, ForwardConfig::samples
    const vk_core::Image& linear_depth;  // kLinearDepthFormat, likewise
    const vk_core::Image& depth;         // kDepthFormat, likewise
};

struct ForwardTargets {
    const vk_core::Image& hdr;  // kHdrFormat, colour attachment
    // kDepthFormat, reversed Z; not written under MSAA (MultisampleTargets::depth is), may be
    // null then.
    const vk_core::Image* depth;
    const vk_core::Image& linear_depth;  // kLinearDepthFormat
    // The region drawn, from the images' top-left corner: the whole image for the eyes, the
    // viewport of eq. 8 inside its larger allocation for C.
    vk::Extent2D area;
    // Clear the colour targets first (black, sky depth) instead of leaving them undefined: only
    // where pixels may stay unwritten and are read anyway (C's image read back for mono.png
    // when fragments hidden in both eyes were discarded).
    bool clear_color = false;
    // kVelocityFormat: required with ForwardConfig::velocity, ignored without.
    const vk_core::Image* velocity = nullptr;
    // Required with ForwardConfig::samples > 1.
    const MultisampleTargets* multisample = nullptr;
};

// Hybrid's blended chunks nearer than m or straddling it, drawn into an eye after the composite
// (record_after_composite): blended into the eye's HDR image, each fragment tested against the
// composite's linear depth (the near content's and C's mapped in), which set 1 holds
// (write_composite_depth).
struct AfterCompositeTargets {
    const vk_core::Image& hdr;  // kHdrFormat, eColorAttachmentOptimal; kept and blended into
    vk::Extent2D area;
};

// How one forward pass draws both eyes (plan::StereoPass): kTwoPasses is a pass of one view. With
// another form, the targets are two-layer images (layer 0 the left eye, 1 the right) and set 0's
// constants are both eyes' ViewConstants in that order (renderer/passes/shared/view_block.glsl).
// kMultiview: every draw covers both layers, gl_ViewIndex picks the eye. kGeometryShader
// (papers/001): vertices shaded once, each triangle emitted into both layers. kInstanced (Unity's
// Single Pass Instanced, Unreal's Instanced Stereo): each draw of the both-eyes list has two
// instances (CullFrame::both_eyes_instances); the vertex shader takes the eye from the instance
// index minus the base instance (the chunk's index) and writes that eye's layer.

// Which of the forward shading's programs a ForwardPass makes: the forward passes' (the chunks,
// the sky, the mask, the routing view), or only the transparency's (record_after_composite).
enum class ForwardPrograms { kForward, kBlendedAfterComposite };

struct ForwardConfig {
    bool velocity = false;  // write screen-space velocity (TAA)
    vk::SampleCountFlagBits samples = vk::SampleCountFlagBits::e1;  // MSAA (stereo modes)
    plan::StereoPass stereo = plan::StereoPass::kTwoPasses;
    // The benchmark's vertex-heavy configuration: rounds of synthetic per-vertex work that leave
    // the image unchanged (forward_vertex.glsl); 0 in normal rendering.
    std::uint32_t vertex_work = 0;
    // The scene has chunks of alphaMode MASK / BLEND: their pipelines are made (and the steps
    // draw them); a scene without leaves them out.
    bool masked_chunks = false;
    bool blended_chunks = false;
    // kBlendedAfterComposite: a pass of one view with blended_chunks, without MSAA; needs the
    // depthClamp capability (UserError otherwise, naming it).
    ForwardPrograms programs = ForwardPrograms::kForward;
};

// One step of a forward pass (plan::DrawStep says what each draws), under a GPU predicate or not.
struct ForwardDraw {
    plan::DrawStep step = plan::DrawStep::kChunks;
    std::optional<Predicate> when;
};

class ForwardPass {
  public:
    static constexpr vk::Format kHdrFormat = vk::Format::eR16G16B16A16Sfloat;
    static constexpr vk::Format kDepthFormat = vk::Format::eD32Sfloat;
    static constexpr vk::Format kLinearDepthFormat = vk::Format::eR32Sfloat;
    // NDC now minus NDC in the previous frame: a pixel is 2 / width, well within half precision.
    static constexpr vk::Format kVelocityFormat = vk::Format::eR16G16Sfloat;

    // scene_textures_layout: SceneTextures::layout() of the scene this pass will draw (its set
    // 2); the layout must outlive the pass.
    ForwardPass(const vk_core::Context& ctx, vk::DescriptorSetLayout scene_textures_layout,
                const ForwardConfig& config = {});

    const ForwardConfig& config() const { return config_; }

    // Set 0 of a view: its constants (ViewConstants; single-pass stereo: both eyes' in one
    // buffer) and the shadow map (eShaderReadOnlyOptimal), written by write_view_set.
    vk_core::DescriptorSet make_view_set() const;
    void write_view_set(vk::DescriptorSet set, const vk_core::Buffer& constants,
                        vk::ImageView shadow, vk::Sampler shadow_sampler) const;
    // Set 1 of the mask and routing steps: the merged depth pyramid (binding 0, eGeneral) and
    // the culling pass's per-chunk routing words (binding 1), written by write_merged_depth
    // before the first frame and whenever the pyramid is made anew.
    vk_core::DescriptorSet make_merged_depth_set() const;
    void write_merged_depth(vk::DescriptorSet set, vk::ImageView pyramid, vk::Sampler nearest,
                            vk::Buffer routing) const;
    // Set 1 of record_after_composite (made by make_merged_depth_set): the eye's linear depth
    // after the composite (sampled, eShaderReadOnlyOptimal).
    void write_composite_depth(vk::DescriptorSet set, vk::ImageView linear_depth,
                               vk::Sampler nearest) const;

    // Expects the targets in eUndefined (their contents are replaced); leaves the colour targets
    // (velocity included) in eColorAttachmentOptimal and depth in eDepthAttachmentOptimal.
    // merged_depth_set is needed only by the kMaskHidden and kChunksShowRouting steps (set 1).
    // textures: the scene's, made with the layout this pass was made with.
    void record(const vk::raii::CommandBuffer& cmd, const ForwardTargets& targets,
                vk::DescriptorSet view_set, vk::DescriptorSet merged_depth_set,
                const SceneGeometry& geometry, const SceneTextures& textures,
                const ChunkDraws& chunks, std::span<const ForwardDraw> steps) const;

    // Hybrid: the blended chunks of one eye's list, back to front, after the composite, with
    // depth clamping instead of clipping at the eye's far plane m, so a pane straddling m is
    // drawn whole. The kBlendedAfterComposite programs only; expects the HDR image in
    // eColorAttachmentOptimal and leaves it there.
    void record_after_composite(const vk::raii::CommandBuffer& cmd,
                                const AfterCompositeTargets& targets, vk::DescriptorSet view_set,
                                vk::DescriptorSet composite_depth_set,
                                const SceneGeometry& geometry, const SceneTextures& textures,
                                const IndirectDraws& blended) const;

  private:
    // A chunk pipeline twice: testing and writing depth, and testing for the depth a pre-pass left.
    struct ChunkPipelines {
        vk::raii::Pipeline first{nullptr};
        vk::raii::Pipeline after_prepass{nullptr};

        // desc: everything but the depth test and write, which each pipeline sets itself.
        static ChunkPipelines make(const vk_core::Context& ctx, vk_core::GraphicsPipelineDesc desc);
        vk::Pipeline pick(bool prepassed) const { return prepassed ? *after_prepass : *first; }
    };

    // The pipelines drawing the scene's chunks: shading, routing, and the depth pre-pass.
    void make_chunk_pipelines();
    // The fullscreen pipelines: the sky, and in one-view passes the mask of hidden pixels.
    void make_fullscreen_pipelines();
    // kBlendedAfterComposite's one pipeline, from make_chunk_pipelines's chunk description.
    void make_after_composite_pipeline(const ForwardShaders& shaders,
                                       const vk_core::GraphicsPipelineDesc& chunks);
    // The pipelines of alphaMode MASK and BLEND chunks, from make_chunk_pipelines's.
    void make_alpha_pipelines(const ForwardShaders& shaders,
                              const vk_core::GraphicsPipelineDesc& chunks,
                              const vk_core::GraphicsPipelineDesc& prepass);
    void make_masked_pipelines(const vk_core::GraphicsPipelineDesc& chunks,
                               const vk_core::GraphicsPipelineDesc& prepass,
                               std::span<const std::uint32_t> masked_depth_spirv);
    // One step of record, inside the rendering; prepassed: a depth pre-pass came before it.
    void record_step(const vk::raii::CommandBuffer& cmd, plan::DrawStep step, bool prepassed,
                     vk::DescriptorSet merged_depth_set, const ChunkDraws& chunks) const;

    const vk_core::Context& ctx_;
    ForwardConfig config_;
    vk::raii::DescriptorSetLayout set_layout_{nullptr};
    vk::raii::DescriptorSetLayout merged_depth_layout_{nullptr};
    vk::raii::PipelineLayout layout_{nullptr};
    vk::raii::Pipeline depth_prepass_pipeline_{nullptr};
    vk::raii::Pipeline mask_hidden_pipeline_{nullptr};  // one-view passes only (C's)
    ChunkPipelines shading_pipelines_;
    ChunkPipelines show_routing_pipelines_;
    vk::raii::Pipeline sky_pipeline_{nullptr};
    vk::raii::Pipeline masked_prepass_pipeline_{nullptr};
    ChunkPipelines masked_pipelines_;
    vk::raii::Pipeline blended_pipeline_{nullptr};
    vk::raii::Pipeline after_composite_pipeline_{nullptr};  // kBlendedAfterComposite
};

}  // namespace monoplane::passes
