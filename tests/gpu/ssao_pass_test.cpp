// SSAO (renderer/passes/ssao) on an analytic scene ray-cast here on the CPU: a floor meeting a
// wall in a concave corner and a free-standing box, seen by two eyes 6.4 cm apart. The open
// floor stays unoccluded, the corner darkens, the sky is 1; the stereo-consistent variant
// (papers/002) gives the two eyes closer values at corresponding points than per-view HBAO+;
// the apply pass multiplies the HDR by exactly the AO, only over near content when asked.
// The pass records no barriers: it runs under the render graph (tests/gpu/graph_harness.h) with
// the steps the SSAO unit declares (ssao_steps.h), walking the unit's table of steps as its
// recorder does.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/packing.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "renderer/passes/forward/forward_pass.h"
#include "renderer/passes/shared/view_constants.h"
#include "renderer/passes/ssao/ssao_pass.h"
#include "renderer/passes/ssao/ssao_steps.h"
#include "renderer/plan/pass_steps.h"
#include "rig/projection.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/graph_harness.h"

namespace monoplane {
namespace {

using passes::SsaoBindings;
using passes::SsaoImages;
using passes::SsaoPass;
using passes::SsaoVariant;
using plan::ImageRole;
using Stage = vk::PipelineStageFlagBits2;
using Access = vk::AccessFlagBits2;
using testing::GraphHarness;

constexpr vk::Extent2D kArea{128, 96};
const rig::Tangents kTangents{-4.0 / 3.0, 4.0 / 3.0, -1.0, 1.0};  // square pixels at 128 x 96
constexpr double kHalfIpd = 0.032;

// The scene, in head space (the head at the origin looking down -z, y up).
constexpr double kFloorY = -1.0;
constexpr double kWallZ = -2.0;  // the wall stands on the floor up to kWallTop; sky above
constexpr double kWallTop = 0.8;
const glm::dvec3 kBoxMin(0.5, kFloorY, -1.5);
const glm::dvec3 kBoxMax(0.9, -0.6, -1.1);

constexpr float kSky = static_cast<float>(MONOPLANE_SKY_LINEAR_DEPTH);

glm::dvec3 eye_position(int eye) {
    return {eye == 0 ? -kHalfIpd : kHalfIpd, 0.0, 0.0};
}

// The nearest hit along origin + t dir (t > 0), or nothing: the sky.
std::optional<double> cast_ray(glm::dvec3 origin, glm::dvec3 dir) {
    double best = std::numeric_limits<double>::infinity();
    if (dir.y < 0.0) {  // the floor, up to the wall
        const double t = (kFloorY - origin.y) / dir.y;
        const glm::dvec3 x = origin + t * dir;
        if (t > 0.0 && x.z >= kWallZ && std::abs(x.x) < 20.0) best = std::min(best, t);
    }
    if (dir.z < 0.0) {  // the wall
        const double t = (kWallZ - origin.z) / dir.z;
        const glm::dvec3 x = origin + t * dir;
        if (t > 0.0 && x.y >= kFloorY && x.y <= kWallTop && std::abs(x.x) < 20.0) {
            best = std::min(best, t);
        }
    }
    double t_near = -std::numeric_limits<double>::infinity();  // the box, by slabs
    double t_far = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (dir[a] == 0.0) {
            if (origin[a] < kBoxMin[a] || origin[a] > kBoxMax[a]) t_far = -1.0;
            continue;
        }
        double t0 = (kBoxMin[a] - origin[a]) / dir[a];
        double t1 = (kBoxMax[a] - origin[a]) / dir[a];
        if (t0 > t1) std::swap(t0, t1);
        t_near = std::max(t_near, t0);
        t_far = std::min(t_far, t1);
    }
    if (t_near <= t_far && t_near > 0.0) best = std::min(best, t_near);
    if (!std::isfinite(best)) return std::nullopt;
    return best;
}

// The view-space ray through pixel (i, j)'s centre, from the tangents (not from the matrices the
// pass inverts): NDC x = -1 at tan_left, NDC y = -1 (row 0) at tan_up.
glm::dvec3 pixel_ray(double i, double j, vk::Extent2D area) {
    const double u = (i + 0.5) / area.width;
    const double v = (j + 0.5) / area.height;
    return {kTangents.left + u * (kTangents.right - kTangents.left),
            kTangents.up - v * (kTangents.up - kTangents.down), -1.0};
}

// One eye's synthetic inputs: its constants and its linear depth (metres in front of the eyes'
// plane; the head looks down -z, so that is -z of the hit).
struct EyeInputs {
    glm::dmat4 view_proj{1.0};
    std::vector<float> depth;  // extent-sized, row-major
    vk_core::Buffer constants;
    vk_core::Image linear_depth;
};

EyeInputs make_eye(const vk_core::Context& ctx, int eye, vk::Extent2D extent, vk::Extent2D area) {
    EyeInputs in;
    const glm::dvec3 position = eye_position(eye);
    glm::dmat4 view(1.0);
    view[3] = glm::dvec4(-position, 1.0);
    in.view_proj = rig::projection_reversed_z(kTangents, 0.1, 1000.0) * view;
    // Outside the area: a very near surface that would occlude everything if the pass read it.
    in.depth.assign(std::size_t{extent.width} * extent.height, 0.05f);
    for (std::uint32_t j = 0; j < area.height; ++j) {
        for (std::uint32_t i = 0; i < area.width; ++i) {
            const glm::dvec3 dir = pixel_ray(i, j, area);
            const std::optional<double> t = cast_ray(position, dir);
            in.depth[j * extent.width + i] =
                t ? static_cast<float>(-(position + *t * dir).z) : kSky;
        }
    }
    passes::ViewConstants c{};
    c.view_proj = glm::mat4(in.view_proj);
    c.inv_view_proj = glm::mat4(glm::inverse(in.view_proj));
    c.camera_position = glm::vec4(glm::vec3(position), 1.0f);
    c.head_position = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    c.head_forward = glm::vec4(0.0f, 0.0f, -1.0f, 0.0f);
    in.constants = vk_core::Buffer(ctx, sizeof(c), vk::BufferUsageFlagBits::eUniformBuffer,
                                   vk_core::MemoryUse::kHostVisible);
    in.constants.write(&c, sizeof(c));

    in.linear_depth = vk_core::Image(
        ctx, {extent, passes::ForwardPass::kLinearDepthFormat,
              vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferDst});
    const vk_core::Buffer staging(ctx, in.depth.size() * sizeof(float),
                                  vk::BufferUsageFlagBits::eTransferSrc,
                                  vk_core::MemoryUse::kHostVisible);
    staging.write(in.depth.data(), in.depth.size() * sizeof(float));
    ctx.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
        vk_core::transition(cmd, in.linear_depth, vk::ImageLayout::eUndefined,
                            vk::ImageLayout::eTransferDstOptimal, Stage::eNone, Access::eNone,
                            Stage::eCopy, Access::eTransferWrite);
        cmd.copyBufferToImage(
            staging.handle(), in.linear_depth.handle(), vk::ImageLayout::eTransferDstOptimal,
            vk::BufferImageCopy(
                0, 0, 0, vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, 0, 0, 1),
                {0, 0, 0}, vk::Extent3D(extent, 1)));
        vk_core::transition(cmd, in.linear_depth, vk::ImageLayout::eTransferDstOptimal,
                            vk::ImageLayout::eShaderReadOnlyOptimal, Stage::eCopy,
                            Access::eTransferWrite, Stage::eComputeShader,
                            Access::eShaderSampledRead);
    });
    // The render graph's executor starts the image from this layout.
    in.linear_depth.set_initial_layout(vk::ImageLayout::eShaderReadOnlyOptimal);
    return in;
}

struct Pixel {
    int x;
    int y;
};

// The pixel that sees world point X (nearest: the one whose footprint holds the projection).
Pixel project(const glm::dmat4& view_proj, glm::dvec3 X, vk::Extent2D area) {
    const glm::dvec4 c = view_proj * glm::dvec4(X, 1.0);
    return {static_cast<int>(std::floor((c.x / c.w * 0.5 + 0.5) * area.width)),
            static_cast<int>(std::floor((c.y / c.w * 0.5 + 0.5) * area.height))};
}

// At this small resolution the 13-tap filter spreads the corner's occlusion over a few pixels
// either side of the crease; HBAO+'s own scale, 2 / (1 - bias), rounded up, keeps it clearly
// visible after the filter. The default parameters are checked for the same ordering below.
passes::SsaoParams test_params() {
    passes::SsaoParams params;
    params.strength = 2.5f;
    return params;
}

bool inside(Pixel p, vk::Extent2D area) {
    return p.x >= 0 && p.y >= 0 && p.x < static_cast<int>(area.width) &&
           p.y < static_cast<int>(area.height);
}

// A view's SSAO images and the linear depth it reads, as the plan's resources of `view`.
void bind_view(GraphHarness& harness, plan::ViewId view, const SsaoImages& ssao,
               const vk_core::Image& linear_depth) {
    plan::PlanResources& r = harness.resources();
    harness.bind(r.image(view, ImageRole::kLinearDepth), linear_depth);
    harness.bind(r.image(view, ImageRole::kAo), ssao.ao());
    std::vector<vk_core::ImageRange> scratch;
    for (const vk_core::Image* image : ssao.scratch()) scratch.push_back(image->range());
    harness.bind(r.image(view, ImageRole::kAoScratch), std::move(scratch));
}

// Bindings of `pass` pointed at a view's images.
std::unique_ptr<SsaoBindings> bindings_of(const SsaoPass& pass, const vk_core::Buffer& constants,
                                          const vk_core::Image& linear_depth,
                                          const SsaoImages& images) {
    std::unique_ptr<SsaoBindings> bindings = pass.make_bindings();
    pass.bind(*bindings, {&constants, &linear_depth, &images.ao(), images.scratch()});
    return bindings;
}

// The AO image (a transfer source in the read-back step) into the view's host-visible buffer.
void copy_ao(const vk::raii::CommandBuffer& cmd, const SsaoImages& images) {
    cmd.copyImageToBuffer(
        images.ao().handle(), vk::ImageLayout::eTransferSrcOptimal, images.readback().handle(),
        vk::BufferImageCopy(0, 0, 0,
                            vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, 0, 0, 1),
                            {0, 0, 0}, vk::Extent3D(images.extent(), 1)));
}

struct AoPair {
    std::array<std::vector<float>, 2> ao;  // per eye, extent-sized
    vk::Extent2D extent;
    float at(int eye, Pixel p) const {
        return ao[eye][static_cast<std::size_t>(p.y) * extent.width + p.x];
    }
};

class SsaoPassTest : public testing::GpuTest {
  protected:
    void SetUp() override {
        GpuTest::SetUp();
        if (HasFatalFailure()) return;
        for (int e = 0; e < 2; ++e) eyes_[e] = make_eye(ctx(), e, kArea, kArea);
    }

    AoPair run(const std::array<EyeInputs, 2>& eyes, vk::Extent2D extent, SsaoVariant variant,
               const passes::SsaoParams& params = test_params(),
               float skip_beyond = SsaoPass::kEveryPixel) {
        const SsaoPass pass(ctx());
        const std::array<SsaoImages, 2> images = {SsaoImages(ctx(), extent),
                                                  SsaoImages(ctx(), extent)};
        std::array<std::unique_ptr<SsaoBindings>, 2> bindings;
        for (int e = 0; e < 2; ++e) {
            bindings[e] = bindings_of(pass, eyes[e].constants, eyes[e].linear_depth, images[e]);
        }
        GraphHarness harness;
        plan::PlanResources& r = harness.resources();
        for (int e = 0; e < 2; ++e) harness.input(plan::eye_view(e), ImageRole::kLinearDepth);
        // The unit's steps for the eyes' SSAO less its applies.
        std::vector<passes::ssao::Step> table =
            passes::ssao::eye_steps(variant == SsaoVariant::kStereoConsistent);
        std::erase_if(table, [](const passes::ssao::Step& s) {
            return s.dispatch == passes::ssao::Dispatch::kApply;
        });
        harness.add_pass(
            plan::PassKind::kSsao, "ssao", passes::ssao::declared_steps(r, table, false),
            [&](const vk::raii::CommandBuffer& cmd, passes::StepSync& sync) {
                for (const passes::ssao::Step& step : table) {
                    sync.next(cmd, step.name);
                    pass.dispatch(cmd, step.dispatch, *bindings[plan::eye_index(step.self)],
                                  *bindings[plan::eye_index(step.other)], kArea, params,
                                  skip_beyond);
                }
            });
        std::vector<std::pair<graph::ImageHandle, graph::BufferHandle>> copies;
        for (int e = 0; e < 2; ++e) {
            const plan::ViewId eye = plan::eye_view(e);
            copies.emplace_back(r.image(eye, ImageRole::kAo),
                                r.buffer(eye, plan::BufferRole::kAoReadback));
        }
        harness.add_readback(copies, [&](const vk::raii::CommandBuffer& cmd, passes::StepSync&) {
            for (const SsaoImages& eye : images) copy_ao(cmd, eye);
        });
        const SsaoImages* left = &images[0];
        const SsaoImages* right = &images[1];
        bind_view(harness, plan::ViewId::kLeft, *left, eyes[0].linear_depth);
        bind_view(harness, plan::ViewId::kRight, *right, eyes[1].linear_depth);
        ctx().submit_and_wait([&](const vk::raii::CommandBuffer& cmd) { harness.record(cmd); });
        AoPair result{{left->ao_values(), right->ao_values()}, extent};
        EXPECT_EQ(result.ao[0].size(), std::size_t{extent.width} * extent.height);
        EXPECT_EQ(result.ao[1].size(), result.ao[0].size());
        return result;
    }

    std::array<EyeInputs, 2> eyes_;
};

// World points on the floor, well away from the wall and the box.
const std::array<glm::dvec3, 3> kOpenFloor = {glm::dvec3(-0.9, kFloorY, -1.15),
                                              glm::dvec3(-0.6, kFloorY, -1.1),
                                              glm::dvec3(-1.1, kFloorY, -1.25)};
// World points on the floor 5 cm in front of the wall, away from the box.
const std::array<glm::dvec3, 3> kCorner = {glm::dvec3(-0.6, kFloorY, kWallZ + 0.05),
                                           glm::dvec3(-0.3, kFloorY, kWallZ + 0.05),
                                           glm::dvec3(0.0, kFloorY, kWallZ + 0.05)};

void expect_plausible(const AoPair& pair, const std::array<EyeInputs, 2>& eyes,
                      float corner_max = 0.8f, float margin = 0.15f) {
    for (int e = 0; e < 2; ++e) {
        SCOPED_TRACE(e == 0 ? "left" : "right");
        int sky = 0;
        for (std::uint32_t j = 0; j < kArea.height; ++j) {
            for (std::uint32_t i = 0; i < kArea.width; ++i) {
                const float ao = pair.ao[e][j * pair.extent.width + i];
                ASSERT_TRUE(ao >= 0.0f && ao <= 1.0f) << i << "," << j << ": " << ao;
                if (eyes[e].depth[j * pair.extent.width + i] == kSky) {
                    ++sky;
                    ASSERT_EQ(ao, 1.0f) << "sky pixel " << i << "," << j;
                }
            }
        }
        EXPECT_GT(sky, 500);  // the set-up sees sky above the wall
        float open_min = 1.0f;
        for (const glm::dvec3& x : kOpenFloor) {
            const float ao = pair.at(e, project(eyes[e].view_proj, x, kArea));
            EXPECT_GT(ao, 0.95f) << "open floor at " << x.x << "," << x.z;
            open_min = std::min(open_min, ao);
        }
        for (const glm::dvec3& x : kCorner) {
            const float ao = pair.at(e, project(eyes[e].view_proj, x, kArea));
            std::printf("%s corner %.3f (open floor >= %.3f)\n", e == 0 ? "left" : "right", ao,
                        open_min);
            EXPECT_LT(ao, corner_max) << "corner at " << x.x << "," << x.z;
            EXPECT_LT(ao, open_min - margin) << "corner at " << x.x << "," << x.z;
        }
    }
}

TEST_F(SsaoPassTest, PerViewDarkensTheConcaveCornerOnly) {
    const AoPair pair = run(eyes_, kArea, SsaoVariant::kPerView);
    expect_plausible(pair, eyes_);
}

TEST_F(SsaoPassTest, StereoConsistentDarkensTheConcaveCornerOnly) {
    const AoPair pair = run(eyes_, kArea, SsaoVariant::kStereoConsistent);
    expect_plausible(pair, eyes_);
}

// The default strength, 1.5: the raw estimate at the crease is about 0.7 (O is about 0.18 there:
// only the half of the directions that meet the wall contribute), about 0.85 after the filter.
TEST_F(SsaoPassTest, DefaultParametersDarkenTheCornerLess) {
    for (SsaoVariant variant : {SsaoVariant::kPerView, SsaoVariant::kStereoConsistent}) {
        SCOPED_TRACE(passes::ssao_variant_name(variant));
        expect_plausible(run(eyes_, kArea, variant, passes::SsaoParams{}), eyes_, 0.9f, 0.1f);
    }
}

// The inconsistency of papers/002 Sect. 4.1 at points both eyes see: |A^l(p) - A^r(p*)|.
TEST_F(SsaoPassTest, StereoConsistentAgreesBetterAcrossTheEyes) {
    const AoPair per_view = run(eyes_, kArea, SsaoVariant::kPerView);
    const AoPair stereo = run(eyes_, kArea, SsaoVariant::kStereoConsistent);

    // Known points on the floor near the corner and around the box's foot.
    std::vector<glm::dvec3> points;
    for (double x = -1.0; x <= 0.41; x += 0.2) {
        for (double dz : {0.03, 0.1, 0.2, 0.35}) points.emplace_back(x, kFloorY, kWallZ + dz);
    }
    for (double x = 0.4; x <= 1.01; x += 0.1) points.emplace_back(x, kFloorY, kBoxMax.z + 0.08);
    for (double z = -1.5; z <= -1.09; z += 0.1) points.emplace_back(kBoxMin.x - 0.08, kFloorY, z);
    double per_view_points = 0.0;
    double stereo_points = 0.0;
    int counted = 0;
    for (const glm::dvec3& x : points) {
        const Pixel l = project(eyes_[0].view_proj, x, kArea);
        const Pixel r = project(eyes_[1].view_proj, x, kArea);
        if (!inside(l, kArea) || !inside(r, kArea)) continue;
        per_view_points += std::abs(per_view.at(0, l) - per_view.at(1, r));
        stereo_points += std::abs(stereo.at(0, l) - stereo.at(1, r));
        ++counted;
    }
    // And over every left pixel whose surface point the right eye sees (ray-cast here), all of
    // them and those where some result shows occlusion.
    double per_view_all = 0.0;
    double stereo_all = 0.0;
    double per_view_shaded = 0.0;
    double stereo_shaded = 0.0;
    int both = 0;
    int shaded = 0;
    for (std::uint32_t j = 0; j < kArea.height; ++j) {
        for (std::uint32_t i = 0; i < kArea.width; ++i) {
            const glm::dvec3 dir = pixel_ray(i, j, kArea);
            const std::optional<double> t = cast_ray(eye_position(0), dir);
            if (!t) continue;
            const glm::dvec3 x = eye_position(0) + *t * dir;
            const Pixel r = project(eyes_[1].view_proj, x, kArea);
            if (!inside(r, kArea)) continue;
            const std::optional<double> seen = cast_ray(eye_position(1), x - eye_position(1));
            if (!seen || std::abs(*seen - 1.0) > 1e-6) continue;  // hidden from the right eye
            const Pixel l{static_cast<int>(i), static_cast<int>(j)};
            const double per_view_error = std::abs(per_view.at(0, l) - per_view.at(1, r));
            const double stereo_error = std::abs(stereo.at(0, l) - stereo.at(1, r));
            per_view_all += per_view_error;
            stereo_all += stereo_error;
            ++both;
            if (std::min({per_view.at(0, l), per_view.at(1, r), stereo.at(0, l), stereo.at(1, r)}) <
                0.97f) {
                per_view_shaded += per_view_error;
                stereo_shaded += stereo_error;
                ++shaded;
            }
        }
    }
    ASSERT_GT(counted, 30);
    ASSERT_GT(both, 5000);
    ASSERT_GT(shaded, 500);
    std::printf(
        "mean |AO_l - AO_r|, per-view vs stereo: %d points %.4f %.4f; %d pixels seen by "
        "both %.4f %.4f; %d of them shaded %.4f %.4f\n",
        counted, per_view_points / counted, stereo_points / counted, both, per_view_all / both,
        stereo_all / both, shaded, per_view_shaded / shaded, stereo_shaded / shaded);
    EXPECT_LE(stereo_points, per_view_points);
    EXPECT_LE(stereo_all, per_view_all);
    EXPECT_LE(stereo_shaded, per_view_shaded);
}

// C's case: the area is the top-left part of a larger allocation. Pixels outside it hold a near
// surface that would occlude everything if the pass read them; inside, the result is the same
// as with images of exactly the area's size.
TEST_F(SsaoPassTest, AreaInsideALargerImageReadsOnlyTheArea) {
    const vk::Extent2D extent{kArea.width + 16, kArea.height + 12};
    std::array<EyeInputs, 2> padded = {make_eye(ctx(), 0, extent, kArea),
                                       make_eye(ctx(), 1, extent, kArea)};
    for (SsaoVariant variant : {SsaoVariant::kPerView, SsaoVariant::kStereoConsistent}) {
        SCOPED_TRACE(passes::ssao_variant_name(variant));
        const AoPair exact = run(eyes_, kArea, variant);
        const AoPair inside = run(padded, extent, variant);
        int differing = 0;
        for (int e = 0; e < 2; ++e) {
            for (std::uint32_t j = 0; j < kArea.height; ++j) {
                for (std::uint32_t i = 0; i < kArea.width; ++i) {
                    const Pixel p{static_cast<int>(i), static_cast<int>(j)};
                    if (std::abs(exact.at(e, p) - inside.at(e, p)) > 1e-6f) ++differing;
                }
            }
        }
        EXPECT_EQ(differing, 0);
    }
}

// Reads an R16G16B16A16_SFLOAT image back as floats: from eColorAttachmentOptimal, where the
// render graph left it after the apply, into eTransferSrcOptimal.
std::vector<float> read_hdr(const vk_core::Context& ctx, const vk_core::Image& hdr) {
    const vk::Extent2D extent = hdr.desc().extent;
    const vk_core::Buffer buffer(ctx, vk::DeviceSize{extent.width} * extent.height * 8,
                                 vk::BufferUsageFlagBits::eTransferDst,
                                 vk_core::MemoryUse::kHostVisible);
    ctx.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
        vk_core::transition(cmd, hdr, vk::ImageLayout::eColorAttachmentOptimal,
                            vk::ImageLayout::eTransferSrcOptimal, Stage::eColorAttachmentOutput,
                            Access::eColorAttachmentWrite, Stage::eCopy, Access::eTransferRead);
        cmd.copyImageToBuffer(
            hdr.handle(), vk::ImageLayout::eTransferSrcOptimal, buffer.handle(),
            vk::BufferImageCopy(
                0, 0, 0, vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, 0, 0, 1),
                {0, 0, 0}, vk::Extent3D(extent, 1)));
        const vk::MemoryBarrier2 to_host(Stage::eCopy, Access::eTransferWrite, Stage::eHost,
                                         Access::eHostRead);
        cmd.pipelineBarrier2(vk::DependencyInfo({}, to_host));
    });
    std::vector<std::uint16_t> halves(std::size_t{extent.width} * extent.height * 4);
    std::memcpy(halves.data(), buffer.mapped(), halves.size() * sizeof(std::uint16_t));
    std::vector<float> values(halves.size());
    std::transform(halves.begin(), halves.end(), values.begin(),
                   [](std::uint16_t h) { return glm::unpackHalf1x16(h); });
    return values;
}

// An HDR target filled with `color`, left a colour attachment (the apply blends into it).
vk_core::Image make_hdr(const vk_core::Context& ctx, const std::array<float, 4>& color) {
    vk_core::Image hdr(
        ctx, {kArea, passes::ForwardPass::kHdrFormat,
              vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eTransferSrc |
                  vk::ImageUsageFlagBits::eTransferDst});
    vk_core::initialise_image(ctx, hdr, vk::ImageLayout::eColorAttachmentOptimal,
                              vk::ClearColorValue(color));
    return hdr;
}

// Near content in the left `near_width` columns (reversed-Z 0.5), the cleared far value 0
// elsewhere; left a depth attachment.
vk_core::Image make_near_depth(const vk_core::Context& ctx, std::uint32_t near_width) {
    vk_core::Image depth(ctx, {kArea, passes::ForwardPass::kDepthFormat,
                               vk::ImageUsageFlagBits::eDepthStencilAttachment});
    ctx.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
        vk_core::transition(cmd, depth, vk::ImageLayout::eUndefined,
                            vk::ImageLayout::eDepthAttachmentOptimal, Stage::eNone, Access::eNone,
                            Stage::eEarlyFragmentTests | Stage::eLateFragmentTests,
                            Access::eDepthStencilAttachmentWrite);
        const std::array<std::pair<std::uint32_t, float>, 2> clears = {
            {{kArea.width, 0.0f}, {near_width, 0.5f}}};
        for (const auto& [width, value] : clears) {
            const vk::RenderingAttachmentInfo clear(
                depth.view(), vk::ImageLayout::eDepthAttachmentOptimal, {}, {}, {},
                vk::AttachmentLoadOp::eClear, vk::AttachmentStoreOp::eStore,
                vk::ClearDepthStencilValue(value, 0));
            cmd.beginRendering(vk::RenderingInfo()
                                   .setRenderArea(vk::Rect2D({0, 0}, {width, kArea.height}))
                                   .setLayerCount(1)
                                   .setPDepthAttachment(&clear));
            cmd.endRendering();
            const vk::MemoryBarrier2 cleared(
                Stage::eEarlyFragmentTests | Stage::eLateFragmentTests,
                Access::eDepthStencilAttachmentWrite,
                Stage::eEarlyFragmentTests | Stage::eLateFragmentTests,
                Access::eDepthStencilAttachmentRead | Access::eDepthStencilAttachmentWrite);
            cmd.pipelineBarrier2(vk::DependencyInfo({}, cleared));
        }
    });
    // The render graph's executor starts the image from this layout.
    depth.set_initial_layout(vk::ImageLayout::eDepthAttachmentOptimal);
    return depth;
}

// C's SSAO (the unit's mono_steps: the estimate, the filters, an apply into `everywhere`), then
// an apply depth-tested against `depth` into `near_only`, then the AO's read-back, under the
// render graph. The plan's keys only label the images here: left.hdr and left.depth stand for
// the second target and its near content, applied with the uses of the eyes' near-only apply.
void record_ssao_and_applies(const vk_core::Context& ctx, const SsaoPass& pass,
                             const SsaoImages& images, const SsaoBindings& view,
                             const vk_core::Image& linear_depth, const vk_core::Image& everywhere,
                             const vk_core::Image& near_only, const vk_core::Image& depth) {
    using plan::ViewId;
    GraphHarness harness;
    plan::PlanResources& r = harness.resources();
    harness.input(ViewId::kMono, ImageRole::kLinearDepth);
    harness.input(ViewId::kMono, ImageRole::kHdr);
    harness.input(ViewId::kLeft, ImageRole::kHdr);
    harness.input(ViewId::kLeft, ImageRole::kDepth);
    const std::vector<passes::ssao::Step> table = passes::ssao::mono_steps();
    std::vector<graph::Step> steps = passes::ssao::declared_steps(r, table, false);
    graph::Step& near = steps.emplace_back();
    near.name = "left.apply";
    graph::StepBuilder(near)
        .use(r.image(ViewId::kMono, ImageRole::kAo), graph::Use::kSampledFragment)
        .use(r.image(ViewId::kLeft, ImageRole::kHdr), graph::Use::kColorBlend)
        .use(r.image(ViewId::kLeft, ImageRole::kDepth), graph::Use::kDepthTest);
    const passes::SsaoParams params;
    harness.add_pass(plan::PassKind::kSsao, "mono.ssao", std::move(steps),
                     [&](const vk::raii::CommandBuffer& cmd, passes::StepSync& sync) {
                         for (const passes::ssao::Step& step : table) {
                             sync.next(cmd, step.name);
                             if (step.dispatch == passes::ssao::Dispatch::kApply) {
                                 pass.apply(cmd, view, everywhere, kArea);
                             } else {
                                 pass.dispatch(cmd, step.dispatch, view, view, kArea, params);
                             }
                         }
                         sync.next(cmd, "left.apply");
                         pass.apply(cmd, view, near_only, kArea, &depth);
                     });
    harness.add_readback(
        {{r.image(ViewId::kMono, ImageRole::kAo),
          r.buffer(ViewId::kMono, plan::BufferRole::kAoReadback)}},
        [&](const vk::raii::CommandBuffer& cmd, passes::StepSync&) { copy_ao(cmd, images); });
    bind_view(harness, ViewId::kMono, images, linear_depth);
    harness.bind(r.image(ViewId::kMono, ImageRole::kHdr), everywhere);
    harness.bind(r.image(ViewId::kLeft, ImageRole::kHdr), near_only);
    harness.bind(r.image(ViewId::kLeft, ImageRole::kDepth), depth);
    ctx.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) { harness.record(cmd); });
}

TEST_F(SsaoPassTest, ApplyMultipliesTheHdrByTheAoOverNearContentOnlyWhenAsked) {
    const SsaoPass pass(ctx());
    const SsaoImages images(ctx(), kArea);
    const std::unique_ptr<SsaoBindings> view =
        bindings_of(pass, eyes_[0].constants, eyes_[0].linear_depth, images);
    const std::array<float, 4> color = {0.5f, 1.0f, 2.0f, 0.75f};  // exact in half floats
    const vk_core::Image everywhere = make_hdr(ctx(), color);
    const vk_core::Image near_only = make_hdr(ctx(), color);
    const std::uint32_t near_width = kArea.width / 2;
    const vk_core::Image depth = make_near_depth(ctx(), near_width);
    record_ssao_and_applies(ctx(), pass, images, *view, eyes_[0].linear_depth, everywhere,
                            near_only, depth);
    const std::vector<float> ao = images.ao_values();
    ASSERT_EQ(ao.size(), std::size_t{kArea.width} * kArea.height);
    const std::vector<float> all = read_hdr(ctx(), everywhere);
    const std::vector<float> near = read_hdr(ctx(), near_only);
    int darkened = 0;
    int mismatched = 0;
    for (std::uint32_t j = 0; j < kArea.height; ++j) {
        for (std::uint32_t i = 0; i < kArea.width; ++i) {
            const std::size_t p = j * kArea.width + i;
            const float a = ao[p];
            if (a < 0.9f) ++darkened;
            for (int c = 0; c < 4; ++c) {
                // Half floats carry 11 significant bits.
                const float expected = c < 3 ? color[c] * a : color[c];
                const float tolerance = 2e-3f * color[c];
                if (std::abs(all[p * 4 + c] - expected) > tolerance) ++mismatched;
                const float expected_near = i < near_width ? expected : color[c];
                if (std::abs(near[p * 4 + c] - expected_near) > tolerance) ++mismatched;
            }
            // Untouched beyond the near content: bit-exact.
            if (i >= near_width) {
                for (int c = 0; c < 4; ++c) ASSERT_EQ(near[p * 4 + c], color[c]);
            }
        }
    }
    EXPECT_GT(darkened, 20);  // there is something to multiply
    EXPECT_EQ(mismatched, 0);
}

TEST(SsaoVariant, NamesRoundTrip) {
    for (SsaoVariant v : {SsaoVariant::kPerView, SsaoVariant::kStereoConsistent}) {
        EXPECT_EQ(passes::parse_ssao_variant(passes::ssao_variant_name(v)), v);
    }
    EXPECT_EQ(passes::parse_ssao_variant("per-eye"), SsaoVariant::kPerView);
    EXPECT_EQ(passes::parse_ssao_variant("stereo"), SsaoVariant::kStereoConsistent);
    EXPECT_FALSE(passes::parse_ssao_variant("mono").has_value());
}

// Hybrid's eyes skip the estimate beyond m + skip_margin() (their AO there is C's): pixels a
// margin beyond the limit read 1, and every pixel nearer than the limit less the margin keeps the
// AO it has when every pixel is computed, in both variants.
TEST_F(SsaoPassTest, SkippingFarPixelsLeavesTheNearAoUnchanged) {
    passes::SsaoParams params = test_params();
    params.sigma_max = 0.05f;  // a margin of 0.3 m, small against the set-up's 1-2 m of depth
    const float margin = SsaoPass::skip_margin(params);
    EXPECT_FLOAT_EQ(margin, 6.0f * params.sigma_max);
    const float limit = 1.6f;
    for (SsaoVariant variant : {SsaoVariant::kPerView, SsaoVariant::kStereoConsistent}) {
        SCOPED_TRACE(passes::ssao_variant_name(variant));
        const AoPair every = run(eyes_, kArea, variant, params);
        const AoPair skipped = run(eyes_, kArea, variant, params, limit);
        for (int e = 0; e < 2; ++e) {
            int beyond = 0;
            int near = 0;
            for (std::size_t i = 0; i < eyes_[e].depth.size(); ++i) {
                const float depth = eyes_[e].depth[i];
                if (depth == kSky) continue;
                if (depth > limit + margin) {
                    // Skipped, and so are the pixels the filter weighs in: 1 up to rounding.
                    ++beyond;
                    ASSERT_NEAR(skipped.ao[e][i], 1.0f, 1e-6f) << "pixel " << i;
                } else if (depth < limit - margin) {
                    ++near;
                    ASSERT_NEAR(skipped.ao[e][i], every.ao[e][i], 1e-4f) << "pixel " << i;
                }
            }
            EXPECT_GT(beyond, 1000) << "eye " << e;
            EXPECT_GT(near, 1000) << "eye " << e;
        }
    }
}

}  // namespace
}  // namespace monoplane
