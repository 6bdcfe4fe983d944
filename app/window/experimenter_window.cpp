#include "app/window/experimenter_window.h"

#include <imgui.h>

#include <fstream>
#include <string>

#include "app/window/imgui_backend_access.h"
#include "app/window/panels.h"
#include "app/window/view_text.h"
#include "common/json_writer.h"

namespace monoplane::window {

// The generic window (GLFW, Dear ImGui, swapchain, screenshot) is a DesktopWindow; this adds the
// mirror texture and the experimenter's panels.
struct ExperimenterWindow::Impl {
    ~Impl();

    std::unique_ptr<DesktopWindow> desktop;
    std::unique_ptr<MirrorTexture> mirror;
    PanelState panels;
    std::vector<ResponseKeyBinding> response_keys;
    // Of the last frame's view, for save_state.
    std::uint64_t frame_index = 0;
    Phase phase = Phase::Starting;
    bool gaze_tracked = false;
    std::optional<std::array<double, 2>> gaze_uv;

    static void bind_mirror(const ImDrawList* list, const ImDrawCmd* command);
};

ExperimenterWindow::Impl::~Impl() {
    // The mirror's set and image may be in use by the last frame; the desktop window waits for
    // the device only when it goes, after the mirror.
    if (desktop) {
        const vk_core::Context& ctx = desktop->context();
        if (*ctx.device()) {
            static_cast<void>(ctx.device().getDispatcher()->vkDeviceWaitIdle(*ctx.device()));
        }
    }
    mirror.reset();
    desktop.reset();
}

void ExperimenterWindow::Impl::bind_mirror(const ImDrawList* /*list*/, const ImDrawCmd* command) {
    auto* self = static_cast<Impl*>(command->UserCallbackData);
    const VkDescriptorSet set = self->mirror->descriptor_set();
    const vk_core::Context& ctx = self->desktop->context();
    ctx.device().getDispatcher()->vkCmdBindDescriptorSets(
        self->desktop->recording(), VK_PIPELINE_BIND_POINT_GRAPHICS, imgui_vulkan_pipeline_layout(),
        0, 1, &set, 0, nullptr);
}

ExperimenterWindow::ExperimenterWindow(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
ExperimenterWindow::~ExperimenterWindow() = default;

Result<std::unique_ptr<ExperimenterWindow>> ExperimenterWindow::create(const vk_core::Context& ctx,
                                                                       const WindowOptions& options,
                                                                       vk::Extent2D mirror_extent) {
    if (mirror_extent.width == 0 || mirror_extent.height == 0) {
        return Error{"the experimenter window's mirror needs a non-empty size"};
    }
    DesktopWindowOptions desktop_options;
    desktop_options.width = options.width;
    desktop_options.height = options.height;
    desktop_options.title = options.title;
    desktop_options.what = "experimenter window";
    auto desktop = DesktopWindow::create(ctx, desktop_options);
    MONOPLANE_TRY(desktop);
    auto impl = std::make_unique<Impl>();
    impl->desktop = std::move(desktop).value();
    try {
        impl->mirror = std::make_unique<MirrorTexture>(
            ctx, mirror_extent, impl->desktop->descriptor_pool(), imgui_vulkan_set_layout());
    } catch (const vk::SystemError& e) {
        return Error{std::string("cannot set up the experimenter window: ") + e.what()};
    }
    return std::unique_ptr<ExperimenterWindow>(new ExperimenterWindow(std::move(impl)));
}

void ExperimenterWindow::record_mirror(const vk::raii::CommandBuffer& cmd, vk::Image source,
                                       vk::ImageLayout source_layout, vk::Extent2D source_extent) {
    impl_->mirror->record_copy(cmd, source, source_layout, source_extent);
}

std::vector<Command> ExperimenterWindow::frame(const ExperimenterView& view) {
    Impl& s = *impl_;
    s.desktop->poll_events();
    std::vector<Command> commands;
    // Keys typed into the note field are text, not the participant's buttons.
    const bool typing = ImGui::GetIO().WantTextInput;
    for (const KeyPress& press : s.desktop->take_key_presses()) {
        if (typing) break;
        if (const ResponseKeyBinding* binding = find_binding(s.response_keys, press.key)) {
            commands.push_back(Command{.kind = binding->kind, .key = binding->name});
            continue;
        }
        if (auto command = command_for_key(press.key, view.phase)) commands.push_back(*command);
    }

    s.desktop->new_frame();
    MirrorImage mirror;
    mirror.width = static_cast<float>(s.mirror->extent().width);
    mirror.height = static_cast<float>(s.mirror->extent().height);
    // Dear ImGui 1.86's Vulkan backend ignores texture ids (the bind callback selects the
    // texture); a distinct id only keeps the image in a draw command of its own.
    mirror.texture = s.mirror.get();
    mirror.bind = &Impl::bind_mirror;
    mirror.bind_data = &s;
    std::vector<Command> clicked = draw_panels(view, mirror, s.panels);
    s.frame_index = view.frame_index;
    s.phase = view.phase;
    s.gaze_tracked = view.gaze_tracked;
    s.gaze_uv = view.gaze_uv;
    commands.insert(commands.end(), clicked.begin(), clicked.end());
    s.desktop->end_frame();
    return commands;
}

void ExperimenterWindow::set_response_keys(std::vector<ResponseKeyBinding> bindings) {
    impl_->response_keys = std::move(bindings);
}

bool ExperimenterWindow::close_requested() const {
    return impl_->desktop->close_requested();
}

Result<void> ExperimenterWindow::save_screenshot(const std::filesystem::path& png) {
    return impl_->desktop->save_screenshot(png);
}

Result<void> ExperimenterWindow::save_state(const std::filesystem::path& json) const {
    const Impl& s = *impl_;
    JsonWriter w(JsonFormat{.indented = true, .significant_digits = 0});
    w.begin_object().value("frame_index", s.frame_index).value("phase", phase_name(s.phase));
    const FitRect& m = s.panels.mirror_rect;
    w.begin_object("mirror")
        .value("x", double{m.x})
        .value("y", double{m.y})
        .value("width", double{m.width})
        .value("height", double{m.height})
        .end_object();
    w.begin_object("gaze").value("tracked", s.gaze_tracked);
    if (s.gaze_uv) {
        w.begin_array("uv").value({}, (*s.gaze_uv)[0]).value({}, (*s.gaze_uv)[1]).end_array();
    } else {
        w.null("uv");
    }
    const GazeMarkerState& marker = s.panels.gaze;
    w.value("shown", gaze_shown_name(marker.shown)).value("radius", double{marker.radius});
    if (marker.centre) {
        w.begin_array("marker")
            .value({}, double{marker.centre->x})
            .value({}, double{marker.centre->y})
            .end_array();
    } else {
        w.null("marker");
    }
    w.end_object().end_object();
    std::ofstream out(json, std::ios::binary);
    out << w.str();
    if (!out.flush()) return Error{"cannot write the window's state to " + json.string()};
    return Ok{};
}

vk::Extent2D ExperimenterWindow::extent() const {
    return impl_->desktop->extent();
}

void ExperimenterWindow::request_size(int width, int height) {
    impl_->desktop->request_size(width, height);
}

FitRect ExperimenterWindow::mirror_rect() const {
    return impl_->panels.mirror_rect;
}

}  // namespace monoplane::window
