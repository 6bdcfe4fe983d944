// The render modes of DESIGN.md section 6 as lists of passes over shared resources:
//   stereo:          culling, shadow*, per eye {forward+sky}, [ssao], per eye {[taa], tonemap}
//                    (stereo-multiview, stereo-gs: one forward+sky pass for both eyes)
//   hybrid:          culling, shadow*, per eye {forward n..m, sky only if C has nothing},
//                    [depth pyramid, [occlusion culling]], C {forward m-eps..f + sky, [ssao]},
//                    per eye {composite C through M_{E->C}}, [ssao of the near content],
//                    per eye {[taa], tonemap}
//   hybrid-farfield: as hybrid with C at the eyes' centre, no overlap, an offset copy
// then read-backs (* only when the light's region changed). One GPU culling pass sorts the chunks
// into the views' indirect draw lists; predicates computed by it skip, on the GPU, C and the
// composite when C has nothing to draw, and the pyramid when no eye drew anything. With m >= f,
// hybrid records exactly the stereo list: nothing lies beyond the plane.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/modes/view_setup.h"
#include "renderer/passes/composite/composite_pass.h"
#include "renderer/passes/culling/chunk_culling_pass.h"
#include "renderer/passes/depth_pyramid/depth_pyramid_pass.h"
#include "renderer/passes/forward/forward_pass.h"
#include "renderer/passes/shadow/shadow_pass.h"
#include "renderer/passes/ssao/ssao_pass.h"
#include "renderer/passes/taa/taa_pass.h"
#include "renderer/passes/tonemap/tonemap_pass.h"
#include "renderer/profile/frame_profiler.h"
#include "renderer/rig/rig.h"

namespace monoplane::modes {

enum class Mode { kStereo, kHybrid, kHybridFarfield };

// How the eyes' forward passes are drawn, in stereo and in hybrid's near region: one pass per eye,
// or one pass for both (papers/001's geometry-shader duplication, or VK_KHR_multiview) into the
// layers of two-layer targets. All three draw the same images (tests/gpu/single_pass_stereo_test).
enum class StereoPass { kTwoPasses, kMultiview, kGeometryShader };
std::optional<StereoPass> parse_stereo_pass(const std::string& name);  // "two", "multiview", "gs"
std::string stereo_pass_name(StereoPass pass);

// A mode as the CLI, protocols and bench.json name it: stereo-multiview and stereo-gs are stereo
// with a single-pass StereoPass (DESIGN.md section 6).
struct RenderModeChoice {
    Mode mode = Mode::kStereo;
    StereoPass stereo_pass = StereoPass::kTwoPasses;
};
std::optional<RenderModeChoice> parse_render_mode(const std::string& name);
// "stereo", "stereo-multiview", "stereo-gs", "hybrid", "hybrid-farfield" (the hybrid modes'
// stereo pass is not part of their name).
std::string render_mode_name(const RenderModeChoice& choice);

// Debug views (DESIGN.md section 6) of the hybrid modes.
// kRouting (any mode) colours each chunk by the lists the GPU culling put it in: green eyes
// only, blue C only, magenta both (papers/003's tool for choosing force-mono objects).
enum class DebugView { kNone, kTintMono, kStereoOnly, kMonoOnly, kRouting };

std::optional<Mode> parse_mode(const std::string& name);
std::string mode_name(Mode mode);
std::optional<DebugView> parse_debug_view(const std::string& name);

// How much of C's work the merged depth pyramid of both eyes saves (papers/000 Sect. 4.4 and the
// three variants of Sect. 5.1, Fig. 5): none ("No Opt.", frustum culling only), C's fragments
// hidden in both eyes discarded ("Discard"), and C's chunks hidden in both eyes not drawn at all
// ("Occl. Cull.", with Discard). hybrid-farfield uses frustum culling only.
enum class MonoCulling { kNoOpt, kDiscard, kOcclusionCull };
std::optional<MonoCulling> parse_mono_culling(const std::string& name);
std::string mono_culling_name(MonoCulling culling);  // "no-opt", "discard", "occlusion-cull"

// Anti-aliasing (papers/000 Sect. 4.5). TAA works in every mode; MSAA only in stereo, because
// resolving before the composite leaves C's samples out and resolving after it would need every
// sample mapped (docs/hybrid.md, "MSAA: stereo only, and why").
enum class AntiAliasing { kNone, kTaa, kMsaa2, kMsaa4, kMsaa8 };
std::optional<AntiAliasing> parse_anti_aliasing(const std::string& name);  // "none", "taa", "msaa4"
std::string anti_aliasing_name(AntiAliasing aa);
vk::SampleCountFlagBits msaa_samples(AntiAliasing aa);  // e1 for none and TAA

struct RendererOptions {
    StereoPass stereo_pass = StereoPass::kTwoPasses;
    // The benchmark's vertex-heavy configuration (passes::ForwardConfig::vertex_work).
    std::uint32_t vertex_work = 0;
    passes::ShadowParams shadow;
    passes::TonemapParams tonemap;
    AntiAliasing anti_aliasing = AntiAliasing::kNone;
    passes::TaaParams taa;
    std::optional<passes::SsaoVariant> ssao;  // none: no ambient occlusion
    passes::SsaoParams ssao_params;
    bool read_back_ao = false;          // the eyes' AO to the host (needs ssao)
    bool read_back = true;              // display images to the host (PNGs, tests)
    bool read_back_depth = false;       // linear depth to the host (tests, later analyses)
    bool read_back_draw_lists = false;  // each view's chunk list to the host (tests)
};

struct FrameInputs {
    StereoViewInputs views;
    double mono_plane = 8.0;       // m, metres in front of the eyes (hybrid modes)
    double overlap_k = 2.0;        // k of eq. 3
    double view_blend_band = 0.3;  // metres below m over which view vectors blend (Sect. 4.3)
    DebugView debug = DebugView::kNone;
    MonoCulling mono_culling = MonoCulling::kOcclusionCull;
    // Drives TAA's jitter and tells whether the history continues: a frame whose index does not
    // follow the renderer's previous one starts the history anew. Unset: the next index.
    std::optional<std::uint64_t> frame_index{};
};

// Where an eye looked from in the last frame, as rasterised (TAA's jitter included): what a
// measurement on its read-back images needs to reproject pixels.
struct EyeFrameGeometry {
    glm::dmat4 view_proj{1.0};
    glm::dvec3 position{0.0};
};

class ModeRenderer {
  public:
    // The scene must outlive the renderer. nearest_mono_plane sizes C's render target once
    // (eq. 8 allocation); 0 sizes it for the first frame's m and grows it if a later m needs more.
    ModeRenderer(const vk_core::Context& ctx, const scenes::Scene& scene, Mode mode,
                 vk::Extent2D eye_extent, const RendererOptions& options,
                 double nearest_mono_plane = 0.0);
    ~ModeRenderer();

    // Renders one frame and waits for it. Fails (UserError) for inputs the rig refuses.
    // record_after: commands recorded after the frame's last pass into the same submission
    // (a headset's swapchain copies), so a frame costs one submission and one wait; not timed.
    profile::FrameStats render_frame(
        const FrameInputs& inputs,
        const std::function<void(const vk::raii::CommandBuffer&)>& record_after = {});

    Mode mode() const { return mode_; }
    // Display images to the host from the next frame on (or not: timed benchmark frames).
    void set_read_back(bool read_back) { options_.read_back = read_back; }
    // The last frame's images (options.read_back).
    const RgbaImage& eye_image(Eye eye) const;
    // The last frame's tone-mapped eye on the GPU (R8G8B8A8_SRGB, transfer-source usage): in
    // COLOR_ATTACHMENT_OPTIMAL without read_back, else TRANSFER_SRC_OPTIMAL. For a headset's
    // swapchain; the next frame overwrites it.
    const vk_core::Image& display_image(Eye eye) const;
    // C's tone-mapped image, or nullptr when the last frame had none (stereo, or m >= f).
    const RgbaImage* mono_image() const;
    // Metres in front of the eyes' plane per pixel, MONOPLANE_SKY_LINEAR_DEPTH for the sky
    // (options.read_back_depth).
    const std::vector<float>& eye_linear_depth(Eye eye) const;
    // The eye's ambient occlusion in [0, 1] per pixel (options.ssao and read_back_ao); in hybrid
    // mode the far region shows C's AO as mapped into the eye.
    const std::vector<float>& eye_ao(Eye eye) const;
    const EyeFrameGeometry& eye_geometry(Eye eye) const;
    // Whether the last frame started TAA's history anew (no TAA: always).
    bool history_restarted() const { return !history_valid_; }
    // The rig of the last hybrid frame.
    const std::optional<rig::Rig>& last_rig() const { return rig_; }
    // The chunk indices the last frame drew in a view, in draw order (read_back_draw_lists).
    std::vector<std::uint32_t> drawn_chunks(passes::CullView view) const;

  private:
    struct ForwardImages;
    struct View;
    struct MonoView;

    void ensure_mono_view(int width, int height);
    // Points a view's forward and tone-mapping descriptor sets at its own resources.
    void write_view_sets(const View& view) const;
    // Makes the pyramid large enough for C's allocation and points its readers at it.
    void ensure_pyramid();
    // Points set 1 of the forward pass at the pyramid and the routing words.
    void write_merged_depth_set() const;
    // view_proj: as rasterised (jittered under TAA); unjittered: the same without the jitter,
    // for velocity.
    void update_view(View& view, const glm::dmat4& view_proj, const glm::dmat4& unjittered,
                     const glm::dvec3& position, const FrameInputs& inputs,
                     const glm::dvec3& mono_position, double blend_band,
                     const glm::dmat4& light_view_proj, double hidden_depth_threshold = 0.0);
    // Allocates a view's TAA and tone-mapping sets over its history images.
    void write_taa_sets(View& view) const;
    void record_taa(const vk::raii::CommandBuffer& cmd, View& view, Eye eye);
    void record_ssao(const vk::raii::CommandBuffer& cmd, bool use_mono);
    // Whether the scene's routing flags may be honoured this frame (scenes::ChunkRouting).
    void decide_routing(const FrameInputs& inputs, passes::CullFrame& cull) const;

    const vk_core::Context& ctx_;
    const scenes::Scene& scene_;
    Mode mode_;
    vk::Extent2D eye_extent_;
    RendererOptions options_;
    double nearest_mono_plane_;
    passes::SceneGeometry geometry_;
    passes::ShadowPass shadow_;
    passes::ForwardPass forward_;
    std::unique_ptr<passes::ForwardPass> eyes_forward_;  // single-pass stereo: both eyes at once
    passes::TonemapPass tonemap_;
    passes::CompositePass composite_;
    passes::DrawList shadow_draws_;
    passes::ChunkCullingPass culling_;
    passes::DepthPyramidPass pyramid_;
    passes::TaaPass taa_;
    std::unique_ptr<passes::SsaoPass> ssao_;
    profile::FrameProfiler profiler_;
    vk::raii::DescriptorPool descriptor_pool_{nullptr};
    vk::raii::DescriptorSet merged_depth_set_{nullptr};  // after its pool: destroyed before it
    // Single-pass stereo: both eyes' ViewConstants in one buffer, and eyes_forward_'s set 0.
    std::optional<vk_core::Buffer> eye_pair_constants_;
    vk::raii::DescriptorSet eye_pair_set_{nullptr};
    // Single-pass stereo: both eyes' forward images as two-layer images; outlives eyes_.
    std::unique_ptr<ForwardImages> eye_layers_;
    std::array<std::unique_ptr<View>, 2> eyes_;
    std::unique_ptr<MonoView> mono_;
    bool mono_rendered_ = false;
    std::optional<rig::Rig> rig_;
    std::optional<glm::dmat4> shadow_light_view_proj_;
    // TAA's history: which of each view's two output images holds it, and what it continues.
    std::uint64_t next_frame_index_ = 0;
    int history_parity_ = 0;
    bool history_valid_ = false;
    double history_mono_plane_ = -1.0;
};

}  // namespace monoplane::modes
