// The experimenter window on a real (virtual) display: it opens on the validated device, mirrors
// an image the test made, draws its panels and saves what it shows. Run under xvfb-run by ctest.
#include <gtest/gtest.h>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "app/window/experimenter_window.h"
#include "app/window/view_text.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/image.h"

namespace monoplane::window {
namespace {

namespace fs = std::filesystem;
using Rgb = std::array<int, 3>;

constexpr Rgb kLeft{210, 60, 40};    // the mirror source's left half
constexpr Rgb kRight{40, 150, 220};  // and its right half
constexpr vk::Extent2D kSourceExtent{320, 180};
constexpr vk::Extent2D kMirrorExtent{640, 360};

struct Png {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;
    Rgb at(int x, int y) const {
        const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
};

Png load_png(const fs::path& path) {
    Png png;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &png.width, &png.height, &channels, 3);
    if (data == nullptr) return png;
    png.rgb.assign(data, data + static_cast<std::size_t>(png.width) * png.height * 3);
    stbi_image_free(data);
    return png;
}

bool near(const Rgb& a, const Rgb& b, int tolerance = 3) {
    for (int c = 0; c < 3; ++c) {
        if (std::abs(a[c] - b[c]) > tolerance) return false;
    }
    return true;
}

fs::path test_out() {
    const char* out = std::getenv("MONOPLANE_TEST_OUT");
    return out ? fs::path(out) : fs::temp_directory_path();
}

ExperimenterView trial_view() {
    ExperimenterView view;
    view.participant = "P07";
    view.protocol = "fink2019";
    view.headset = "simulated";
    view.hmd = "vive";
    view.device = "llvmpipe";
    view.trial_number = 5;
    view.trial_count = 32;
    view.scene = "spheres";
    view.mono_plane = 8.0;
    view.elapsed_s = 312.4;
    view.trial_elapsed_s = 7.9;
    view.phase = Phase::Trial;
    view.visible_label = 2;
    view.switches = 3;
    view.both_seen = true;
    view.unblinded = false;
    view.label_modes = {"stereo", "hybrid"};
    for (int i = 0; i < 30; ++i) {
        const int tenths = 2500 + i * 21;
        char line[96];
        std::snprintf(line, sizeof(line), "%d:%02d.%d  trial %d  label %d shown (switch %d)",
                      tenths / 600, tenths / 10 % 60, tenths % 10, i / 6 + 1, i % 2 + 1, i % 6);
        view.log_tail.emplace_back(line);
    }
    view.status_line = "Waiting for the participant's choice";
    view.frame_index = 28113;
    view.frame_ms = 11.1;
    return view;
}

class ExperimenterWindowTest : public ::testing::Test {
  protected:
    void SetUp() override {
        auto extensions = required_instance_extensions();
        if (!extensions && std::getenv("DISPLAY") == nullptr) {
            GTEST_SKIP() << "no display and no xvfb-run: " << extensions.error().message;
        }
        ASSERT_TRUE(extensions) << extensions.error().message;
        vk_core::ContextOptions options;
        options.validation = true;
        if (const char* device = std::getenv("MONOPLANE_TEST_DEVICE")) {
            options.device_selector = device;
        }
        options.instance_extensions = *extensions;
        options.device_extensions = required_device_extensions();
        auto ctx = vk_core::Context::create(options);
        ASSERT_TRUE(ctx) << ctx.error().message;
        ctx_ = std::move(ctx).value();
        auto window = ExperimenterWindow::create(*ctx_, WindowOptions{}, kMirrorExtent);
        ASSERT_TRUE(window) << window.error().message;
        window_ = std::move(window).value();
    }

    void TearDown() override {
        if (!ctx_) return;
        window_.reset();  // teardown is validated too
        ctx_->device().waitIdle();
        EXPECT_EQ(ctx_->validation_messages().count(), 0u) << [this] {
            std::string text;
            for (const auto& m : ctx_->validation_messages().first_messages()) text += m + "\n";
            return text;
        }();
    }

    // An sRGB image: left half kLeft, right half kRight, left in SHADER_READ_ONLY as an app's
    // eye image might be.
    vk_core::Image make_source() {
        vk_core::Image image(
            *ctx_, {kSourceExtent, vk::Format::eR8G8B8A8Srgb,
                    vk::ImageUsageFlagBits::eTransferDst | vk::ImageUsageFlagBits::eTransferSrc |
                        vk::ImageUsageFlagBits::eSampled});
        const std::size_t pixels = std::size_t{kSourceExtent.width} * kSourceExtent.height;
        vk_core::Buffer staging(*ctx_, pixels * 4, vk::BufferUsageFlagBits::eTransferSrc,
                                vk_core::MemoryUse::kHostVisible);
        auto* bytes = reinterpret_cast<std::uint8_t*>(staging.mapped());
        for (std::size_t i = 0; i < pixels; ++i) {
            const bool left = i % kSourceExtent.width < kSourceExtent.width / 2;
            const Rgb& colour = left ? kLeft : kRight;
            for (int c = 0; c < 3; ++c) bytes[i * 4 + c] = static_cast<std::uint8_t>(colour[c]);
            bytes[i * 4 + 3] = 255;
        }
        using Stage = vk::PipelineStageFlagBits2;
        using Access = vk::AccessFlagBits2;
        ctx_->submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
            vk_core::transition(cmd, image, vk::ImageLayout::eUndefined,
                                vk::ImageLayout::eTransferDstOptimal, Stage::eNone, {},
                                Stage::eCopy, Access::eTransferWrite);
            cmd.copyBufferToImage(
                staging.handle(), image.handle(), vk::ImageLayout::eTransferDstOptimal,
                vk::BufferImageCopy(
                    0, 0, 0, vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, 0, 0, 1),
                    {0, 0, 0}, vk::Extent3D(kSourceExtent, 1)));
            vk_core::transition(cmd, image, vk::ImageLayout::eTransferDstOptimal,
                                vk::ImageLayout::eShaderReadOnlyOptimal, Stage::eCopy,
                                Access::eTransferWrite, Stage::eFragmentShader,
                                Access::eShaderSampledRead);
        });
        return image;
    }

    void mirror(const vk_core::Image& source) {
        ctx_->submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
            window_->record_mirror(cmd, source.handle(), vk::ImageLayout::eShaderReadOnlyOptimal,
                                   kSourceExtent);
        });
    }

    std::unique_ptr<vk_core::Context> ctx_;
    std::unique_ptr<ExperimenterWindow> window_;
};

TEST_F(ExperimenterWindowTest, ShowsTheMirrorAndThePanels) {
    const vk_core::Image source = make_source();
    const ExperimenterView view = trial_view();
    for (int frame = 0; frame < 6; ++frame) {
        mirror(source);  // as the app does: its frame commands, then the window's frame
        const auto commands = window_->frame(view);
        EXPECT_TRUE(commands.empty());  // nobody pressed anything
    }
    EXPECT_FALSE(window_->close_requested());

    const fs::path png_path = test_out() / "experimenter-window.png";
    fs::remove(png_path);
    const auto saved = window_->save_screenshot(png_path);
    ASSERT_TRUE(saved) << saved.error().message;
    const Png png = load_png(png_path);
    ASSERT_FALSE(png.rgb.empty()) << png_path;
    EXPECT_EQ(png.width, WindowOptions{}.width);
    EXPECT_EQ(png.height, WindowOptions{}.height);

    // Not blank: the panels' widgets give many distinct colours (ImGui's bitmap font is not
    // antialiased, so text adds few), and their text many bright pixels.
    std::set<int> colours;
    std::size_t bright = 0;
    for (std::size_t i = 0; i + 2 < png.rgb.size(); i += 3) {
        colours.insert(png.rgb[i] << 16 | png.rgb[i + 1] << 8 | png.rgb[i + 2]);
        if (png.rgb[i] > 180 && png.rgb[i + 1] > 180 && png.rgb[i + 2] > 180) ++bright;
    }
    EXPECT_GT(colours.size(), 20u);
    EXPECT_GT(bright, 5000u);

    // The mirror: drawn with the source's aspect, its left half kLeft and its right half kRight,
    // each covering about half the mirror's rectangle.
    const FitRect rect = window_->mirror_rect();
    ASSERT_GT(rect.width, 300.0f);
    EXPECT_NEAR(rect.width / rect.height, 16.0 / 9.0, 0.01);
    const int mid_y = static_cast<int>(rect.y + rect.height / 2);
    EXPECT_TRUE(near(png.at(static_cast<int>(rect.x + rect.width * 0.25f), mid_y), kLeft));
    EXPECT_TRUE(near(png.at(static_cast<int>(rect.x + rect.width * 0.75f), mid_y), kRight));
    std::size_t left_pixels = 0, right_pixels = 0, left_outside = 0;
    for (int y = 0; y < png.height; ++y) {
        for (int x = 0; x < png.width; ++x) {
            const Rgb c = png.at(x, y);
            const auto fx = static_cast<float>(x), fy = static_cast<float>(y);
            const bool inside = fx >= rect.x && fx < rect.x + rect.width && fy >= rect.y &&
                                fy < rect.y + rect.height;
            if (near(c, kLeft)) (inside ? left_pixels : left_outside)++;
            if (near(c, kRight) && inside) right_pixels++;
        }
    }
    const double half = rect.width * rect.height / 2.0;
    EXPECT_NEAR(static_cast<double>(left_pixels), half, half * 0.03);
    EXPECT_NEAR(static_cast<double>(right_pixels), half, half * 0.03);
    EXPECT_EQ(left_outside, 0u);

    // The docs' picture, refreshed on request only.
    if (std::getenv("MONOPLANE_UPDATE_DOC_IMAGES") != nullptr) {
        const char* source_dir = std::getenv("MONOPLANE_SOURCE_DIR");
        ASSERT_NE(source_dir, nullptr);
        const fs::path doc = fs::path(source_dir) / "docs/images/experimenter-window.png";
        fs::create_directories(doc.parent_path());
        fs::copy_file(png_path, doc, fs::copy_options::overwrite_existing);
    }
}

TEST_F(ExperimenterWindowTest, FollowsAResizeAndDrawsEveryPhase) {
    const vk_core::Image source = make_source();
    window_->request_size(900, 620);
    ExperimenterView view = trial_view();
    view.questionnaire_items = {"I noticed differences between the two versions",
                                "The two versions looked the same"};
    view.answers = {5, 0};
    // The protocol's pages: mirrored with their text (a long one scrolls in its box).
    view.page_text =
        "You will see two versions of each scene.\n\nPress SWITCH to change "
        "between them, then CONFIRM to choose the one that looked more natural.";
    for (int i = 0; i < 5; ++i) view.page_text += "\nThere are no right or wrong answers.";
    view.page = 1;
    view.page_count = 3;
    view.break_countdown = "0:23";
    view.note_status = "note stored at trial 5";
    for (const Phase phase : {Phase::Starting, Phase::Instructions, Phase::Trial, Phase::Neutral,
                              Phase::Paused, Phase::Ready, Phase::Break, Phase::Questionnaire,
                              Phase::Finished, Phase::End, Phase::Aborted}) {
        view.phase = phase;
        view.unblinded = phase == Phase::Paused;
        for (int i = 0; i < 3; ++i) {
            mirror(source);
            EXPECT_TRUE(window_->frame(view).empty());
        }
        if (phase != Phase::Questionnaire && phase != Phase::Instructions) continue;
        EXPECT_EQ(window_->extent(), vk::Extent2D(900, 620));
        const fs::path png_path =
            test_out() / (std::string("experimenter-window-") + phase_name(phase) + ".png");
        const auto saved = window_->save_screenshot(png_path);
        ASSERT_TRUE(saved) << saved.error().message;
        const Png png = load_png(png_path);
        EXPECT_EQ(png.width, 900);
        EXPECT_EQ(png.height, 620);
    }
}

// The gaze marker over the mirror: a ring and a cross at the view's gaze point, where the state
// dump says; a blink leaves a faded ring where the gaze was last seen; a gaze beyond the mirrored
// eye's field is marked on the mirror's edge; no marker where no gaze is tracked.
TEST_F(ExperimenterWindowTest, MarksTheGazeOverTheMirror) {
    const vk_core::Image source = make_source();
    ExperimenterView view = trial_view();
    view.gaze_tracked = true;
    const auto show = [&](std::optional<std::array<double, 2>> uv, const std::string& name) {
        view.gaze_uv = uv;
        for (int i = 0; i < 3; ++i) {
            mirror(source);
            window_->frame(view);
        }
        const fs::path png_path = test_out() / ("experimenter-window-gaze-" + name + ".png");
        const fs::path json_path = test_out() / ("experimenter-window-gaze-" + name + ".json");
        EXPECT_TRUE(window_->save_screenshot(png_path));
        EXPECT_TRUE(window_->save_state(json_path));
        std::ifstream in(json_path);
        return std::make_pair(load_png(png_path), nlohmann::json::parse(in));
    };

    // A quarter across, half down: inside the mirror's left (kLeft) half.
    auto [png, state] = show(std::array<double, 2>{0.25, 0.5}, "point");
    const FitRect rect = window_->mirror_rect();
    const nlohmann::json gaze = state["gaze"];  // a copy: `state` is read again below
    EXPECT_EQ(state["phase"], "trial");
    EXPECT_EQ(state["mirror"]["width"].get<double>(), rect.width);
    EXPECT_EQ(gaze["tracked"], true);
    EXPECT_EQ(gaze["shown"], "point") << state;
    EXPECT_EQ(gaze["uv"], nlohmann::json::parse("[0.25, 0.5]"));
    const double x = gaze["marker"][0], y = gaze["marker"][1];
    EXPECT_NEAR(x, rect.x + 0.25 * rect.width, 1e-3);
    EXPECT_NEAR(y, rect.y + 0.5 * rect.height, 1e-3);
    const double radius = gaze["radius"];
    EXPECT_GE(radius, 8.0);
    // The ring in the marker's green on the red half; the centre left visible.
    const auto green = [](const Rgb& c) { return c[1] > 180 && c[0] < 160 && c[2] < 190; };
    for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const Rgb ring = png.at(static_cast<int>(std::lround(x + dx * radius)),
                                static_cast<int>(std::lround(y + dy * radius)));
        EXPECT_TRUE(green(ring)) << ring[0] << " " << ring[1] << " " << ring[2];
    }
    EXPECT_TRUE(near(png.at(static_cast<int>(x), static_cast<int>(y)), kLeft));

    // A blink: the ring stays, faded, where the gaze was; no cross, no marker green.
    std::tie(png, state) = show(std::nullopt, "blink");
    EXPECT_EQ(state["gaze"]["shown"], "lost") << state;
    EXPECT_TRUE(state["gaze"]["uv"].is_null());
    EXPECT_EQ(state["gaze"]["marker"], gaze["marker"]);
    const Rgb faded = png.at(static_cast<int>(std::lround(x + radius)), static_cast<int>(y));
    EXPECT_FALSE(green(faded)) << faded[0] << " " << faded[1] << " " << faded[2];
    EXPECT_FALSE(near(faded, kLeft, 10));

    // Beyond the right edge: marked on it, at the gaze's height.
    std::tie(png, state) = show(std::array<double, 2>{1.4, 0.3}, "outside");
    EXPECT_EQ(state["gaze"]["shown"], "outside") << state;
    EXPECT_NEAR(state["gaze"]["marker"][0].get<double>(), rect.x + rect.width, 1e-3);
    EXPECT_NEAR(state["gaze"]["marker"][1].get<double>(), rect.y + 0.3 * rect.height, 1e-3);

    // No eye tracker: nothing.
    view.gaze_tracked = false;
    std::tie(png, state) = show(std::nullopt, "untracked");
    EXPECT_EQ(state["gaze"]["tracked"], false);
    EXPECT_EQ(state["gaze"]["shown"], "none");
    EXPECT_TRUE(state["gaze"]["marker"].is_null());
}

}  // namespace
}  // namespace monoplane::window
