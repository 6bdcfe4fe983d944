#include "renderer/passes/forward/forward_shaders.h"

namespace monoplane::passes {
namespace {
const std::uint32_t kForwardVert[] = {
#include "forward.vert.spv.inc"
};
const std::uint32_t kForwardFrag[] = {
#include "forward.frag.spv.inc"
};
const std::uint32_t kForwardShowRoutingVert[] = {
#include "forward_show_routing.vert.spv.inc"
};
const std::uint32_t kForwardShowRoutingFrag[] = {
#include "forward_show_routing.frag.spv.inc"
};
const std::uint32_t kFullscreenVert[] = {
#include "fullscreen.vert.spv.inc"
};
const std::uint32_t kSkyFrag[] = {
#include "sky.frag.spv.inc"
};
const std::uint32_t kForwardVelocityFrag[] = {
#include "forward_velocity.frag.spv.inc"
};
const std::uint32_t kForwardShowRoutingVelocityFrag[] = {
#include "forward_show_routing_velocity.frag.spv.inc"
};
const std::uint32_t kSkyVelocityFrag[] = {
#include "sky_velocity.frag.spv.inc"
};
const std::uint32_t kMaskHiddenFrag[] = {
#include "mask_hidden.frag.spv.inc"
};

const std::uint32_t kForwardMultiviewVert[] = {
#include "forward_multiview.vert.spv.inc"
};
const std::uint32_t kForwardShowRoutingMultiviewVert[] = {
#include "forward_show_routing_multiview.vert.spv.inc"
};
const std::uint32_t kForwardMultiviewFrag[] = {
#include "forward_multiview.frag.spv.inc"
};
const std::uint32_t kForwardVelocityMultiviewFrag[] = {
#include "forward_velocity_multiview.frag.spv.inc"
};
const std::uint32_t kForwardShowRoutingMultiviewFrag[] = {
#include "forward_show_routing_multiview.frag.spv.inc"
};
const std::uint32_t kForwardShowRoutingVelocityMultiviewFrag[] = {
#include "forward_show_routing_velocity_multiview.frag.spv.inc"
};
const std::uint32_t kSkyMultiviewFrag[] = {
#include "sky_multiview.frag.spv.inc"
};
const std::uint32_t kSkyVelocityMultiviewFrag[] = {
#include "sky_velocity_multiview.frag.spv.inc"
};

const std::uint32_t kForwardGsVert[] = {
#include "forward_gs.vert.spv.inc"
};
const std::uint32_t kForwardShowRoutingGsVert[] = {
#include "forward_show_routing_gs.vert.spv.inc"
};
const std::uint32_t kForwardGsFrag[] = {
#include "forward_gs.frag.spv.inc"
};
const std::uint32_t kForwardVelocityGsFrag[] = {
#include "forward_velocity_gs.frag.spv.inc"
};
const std::uint32_t kForwardShowRoutingGsFrag[] = {
#include "forward_show_routing_gs.frag.spv.inc"
};
const std::uint32_t kForwardShowRoutingVelocityGsFrag[] = {
#include "forward_show_routing_velocity_gs.frag.spv.inc"
};
const std::uint32_t kSkyGsFrag[] = {
#include "sky_gs.frag.spv.inc"
};
const std::uint32_t kSkyVelocityGsFrag[] = {
#include "sky_velocity_gs.frag.spv.inc"
};
const std::uint32_t kStereoDuplicateGeom[] = {
#include "stereo_duplicate.geom.spv.inc"
};
const std::uint32_t kStereoDuplicateShowRoutingGeom[] = {
#include "stereo_duplicate_show_routing.geom.spv.inc"
};
const std::uint32_t kStereoDuplicateSkyGeom[] = {
#include "stereo_duplicate_sky.geom.spv.inc"
};

const std::uint32_t kForwardInstancedVert[] = {
#include "forward_instanced.vert.spv.inc"
};
const std::uint32_t kForwardShowRoutingInstancedVert[] = {
#include "forward_show_routing_instanced.vert.spv.inc"
};
const std::uint32_t kStereoInstancedSkyVert[] = {
#include "stereo_instanced_sky.vert.spv.inc"
};
const std::uint32_t kForwardInstancedFrag[] = {
#include "forward_instanced.frag.spv.inc"
};
const std::uint32_t kForwardVelocityInstancedFrag[] = {
#include "forward_velocity_instanced.frag.spv.inc"
};
const std::uint32_t kForwardShowRoutingInstancedFrag[] = {
#include "forward_show_routing_instanced.frag.spv.inc"
};
const std::uint32_t kForwardShowRoutingVelocityInstancedFrag[] = {
#include "forward_show_routing_velocity_instanced.frag.spv.inc"
};
const std::uint32_t kSkyInstancedFrag[] = {
#include "sky_instanced.frag.spv.inc"
};
const std::uint32_t kSkyVelocityInstancedFrag[] = {
#include "sky_velocity_instanced.frag.spv.inc"
};

const std::uint32_t kForwardAfterCompositeFrag[] = {
#include "forward_after_composite.frag.spv.inc"
};
const std::uint32_t kAlphaTestFrag[] = {
#include "alpha_test.frag.spv.inc"
};
const std::uint32_t kAlphaToCoverageFrag[] = {
#include "alpha_to_coverage.frag.spv.inc"
};

// A form's fragment shaders, without and with velocity output (TAA).
struct FragmentShaders {
    Spirv forward, forward_velocity;
    Spirv show_routing, show_routing_velocity;
    Spirv sky, sky_velocity;
    // Hybrid's blended chunks after the composite (never velocity; one view per pass, so the
    // single-pass forms have none).
    Spirv after_composite;
};

void set_fragment_shaders(ForwardShaders& shaders, const FragmentShaders& form, bool velocity) {
    shaders.forward = velocity ? form.forward_velocity : form.forward;
    shaders.show_routing = velocity ? form.show_routing_velocity : form.show_routing;
    shaders.sky = velocity ? form.sky_velocity : form.sky;
    shaders.after_composite = form.after_composite;
}

}  // namespace

ForwardShaders forward_shaders(const ForwardConfig& config) {
    ForwardShaders shaders;
    shaders.sky_vertex = kFullscreenVert;
    shaders.mask_hidden = kMaskHiddenFrag;
    const bool multisampled = config.samples != vk::SampleCountFlagBits::e1;
    shaders.masked_depth = multisampled ? Spirv(kAlphaToCoverageFrag) : Spirv(kAlphaTestFrag);
    FragmentShaders fragment;
    switch (config.stereo) {
        case plan::StereoPass::kTwoPasses:
            shaders.vertex = kForwardVert;
            shaders.show_routing_vertex = kForwardShowRoutingVert;
            fragment = {kForwardFrag,
                        kForwardVelocityFrag,
                        kForwardShowRoutingFrag,
                        kForwardShowRoutingVelocityFrag,
                        kSkyFrag,
                        kSkyVelocityFrag,
                        kForwardAfterCompositeFrag};
            break;
        case plan::StereoPass::kMultiview:
            shaders.vertex = kForwardMultiviewVert;
            shaders.show_routing_vertex = kForwardShowRoutingMultiviewVert;
            fragment = {kForwardMultiviewFrag,
                        kForwardVelocityMultiviewFrag,
                        kForwardShowRoutingMultiviewFrag,
                        kForwardShowRoutingVelocityMultiviewFrag,
                        kSkyMultiviewFrag,
                        kSkyVelocityMultiviewFrag,
                        {}};
            break;
        case plan::StereoPass::kGeometryShader:
            shaders.vertex = kForwardGsVert;
            shaders.show_routing_vertex = kForwardShowRoutingGsVert;
            shaders.geometry = kStereoDuplicateGeom;
            shaders.show_routing_geometry = kStereoDuplicateShowRoutingGeom;
            shaders.sky_geometry = kStereoDuplicateSkyGeom;
            fragment = {kForwardGsFrag,
                        kForwardVelocityGsFrag,
                        kForwardShowRoutingGsFrag,
                        kForwardShowRoutingVelocityGsFrag,
                        kSkyGsFrag,
                        kSkyVelocityGsFrag,
                        {}};
            break;
        case plan::StereoPass::kInstanced:
            shaders.vertex = kForwardInstancedVert;
            shaders.show_routing_vertex = kForwardShowRoutingInstancedVert;
            shaders.sky_vertex = kStereoInstancedSkyVert;  // the eye from the instance
            fragment = {kForwardInstancedFrag,
                        kForwardVelocityInstancedFrag,
                        kForwardShowRoutingInstancedFrag,
                        kForwardShowRoutingVelocityInstancedFrag,
                        kSkyInstancedFrag,
                        kSkyVelocityInstancedFrag,
                        {}};
            break;
    }
    set_fragment_shaders(shaders, fragment, config.velocity);
    return shaders;
}

}  // namespace monoplane::passes
