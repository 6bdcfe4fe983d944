#include "app/lab/launcher_window.h"

#include <algorithm>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>
#include <imgui_stdlib.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <system_error>
#include <thread>

#include "app/lab/launcher_panels.h"

namespace monoplane::lab {

namespace fs = std::filesystem;

Result<void> write_file_atomically(const fs::path& file, const std::string& text) {
    const fs::path temporary = fs::path(file).concat(".tmp");
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << text;
        if (!out.flush()) return Error{"cannot write '" + temporary.string() + "'"};
    }
    std::error_code ec;
    fs::rename(temporary, file, ec);
    if (ec) return Error{"cannot replace '" + file.string() + "': " + ec.message()};
    return Ok{};
}

struct LauncherWindow::Impl {
    Impl(LauncherModel& m, LauncherUi& u, LauncherActions a)
        : model(m), ui(u), panels(m, u, std::move(a)) {}

    LauncherModel& model;
    LauncherUi& ui;
    LauncherPanels panels;
    std::unique_ptr<window::DesktopWindow> desktop;
    std::optional<LauncherStep> shown_step;  // the step of the last frame
    int frames_in_step = 0;
    bool screenshot_taken = false;
    std::chrono::steady_clock::time_point last_check_frame;
    int check_frames_drawn = 0;
    std::chrono::steady_clock::time_point last_rescan;

    void frame();
    // One turn of the headset check: input, and a frame of the check's panel at most every
    // 15 ms (the check's loop may turn faster than the launcher needs to draw).
    CheckAnswer check_turn(const HeadsetCheckTurn& turn);
    void run_check();
    void after_frame();
    void write_state();
    void save_screenshot(const std::string& name);
};

void LauncherWindow::Impl::frame() {
    // A protocol saved (or the folder made) while the window is open is listed within a second.
    const auto now = std::chrono::steady_clock::now();
    if (now - last_rescan >= std::chrono::seconds(1)) {
        last_rescan = now;
        model.rescan_protocols_if_changed();
    }
    desktop->poll_events();
    for (const window::KeyPress& press : desktop->take_key_presses()) panels.key(press);
    desktop->new_frame();
    panels.draw();
    desktop->end_frame();
    after_frame();
}

CheckAnswer LauncherWindow::Impl::check_turn(const HeadsetCheckTurn& turn) {
    desktop->poll_events();
    for (const window::KeyPress& press : desktop->take_key_presses()) panels.check_key(press);
    if (desktop->close_requested()) panels.cancel_check();
    const auto now = std::chrono::steady_clock::now();
    if (now - last_check_frame < std::chrono::milliseconds(15)) return panels.take_check_answer();
    last_check_frame = now;
    desktop->new_frame();
    const CheckAnswer answer = panels.draw_check(turn);
    desktop->end_frame();
    write_state();  // the check's answer warning, while it runs
    // The check as the experimenter sees it, once it shows the runtime's measurements.
    if (++check_frames_drawn == 10) save_screenshot("headset-check");
    return answer;
}

// The check runs its own OpenXR session and Vulkan device beside the window's Context, and the
// window goes on drawing (as the experimenter window does beside a session's headset).
void LauncherWindow::Impl::run_check() {
    check_frames_drawn = 0;
    last_check_frame = {};
    panels.run_check([this](const HeadsetCheckTurn& turn) { return check_turn(turn); });
    // A check that ended before its tenth frame (a loaded machine draws fewer) is shown by its
    // last frame: the panel with the runtime's measurements as it ended.
    if (check_frames_drawn > 0 && check_frames_drawn < 10) save_screenshot("headset-check");
    write_state();
}

void LauncherWindow::Impl::after_frame() {
    write_state();
    if (shown_step != model.step()) {
        shown_step = model.step();
        frames_in_step = 0;
        screenshot_taken = false;
        return;
    }
    // A few frames after a step change the new step is laid out and focused as it stays: that
    // frame is the step's screenshot.
    if (++frames_in_step == 3 && !screenshot_taken) {
        screenshot_taken = true;
        save_screenshot(std::string(step_name(model.step())));
    }
}

void LauncherWindow::Impl::write_state() {
    if (ui.state_file.empty()) return;
    std::string state = model.state_json();
    if (state == ui.last_state) return;
    if (Result<void> written = write_file_atomically(ui.state_file, state); !written) {
        std::fprintf(stderr, "monoplane lab: %s\n", written.error().message.c_str());
    }
    ui.last_state = std::move(state);
}

// NN-<name>.png, numbered across the window's openings.
void LauncherWindow::Impl::save_screenshot(const std::string& name) {
    if (ui.screenshot_dir.empty()) return;
    std::error_code ec;
    fs::create_directories(ui.screenshot_dir, ec);
    char number[16];
    std::snprintf(number, sizeof number, "%02d-", ++ui.screenshots);
    const fs::path png = ui.screenshot_dir / (std::string(number) + name + ".png");
    if (Result<void> saved = desktop->save_screenshot(png); !saved) {
        std::fprintf(stderr, "monoplane lab: no screenshot: %s\n", saved.error().message.c_str());
    }
}

namespace {

// The window's size and text for the primary monitor's work area: three quarters of it (at
// least 1280 x 800 where it is larger, never more than it), and 16-pixel text on a 1080-line
// display, proportionally more on a taller one (a 3840 x 2160 monitor gets 32 pixels), so the
// text keeps its size relative to the screen where the desktop sets no content scale. The
// content scale (DesktopWindow's scale_with_monitor) multiplies the text further on top.
window::DesktopWindowOptions fitted_to_monitor() {
    window::DesktopWindowOptions options;
    options.font_pixels = 16.0f;
    if (glfwInit() != GLFW_TRUE) return options;  // DesktopWindow::create says why
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    if (monitor == nullptr) return options;
    int x = 0, y = 0, width = 0, height = 0;
    glfwGetMonitorWorkarea(monitor, &x, &y, &width, &height);
    if (width <= 0 || height <= 0) return options;
    options.width = std::min(width, std::max(1280, width * 3 / 4));
    options.height = std::min(height, std::max(800, height * 3 / 4));
    float xscale = 1.0f, yscale = 1.0f;
    glfwGetMonitorContentScale(monitor, &xscale, &yscale);
    const float content = std::max(1.0f, std::max(xscale, yscale));
    // Physical pixels per content-scaled pixel: the lines the monitor has at scale 1.
    const float lines = static_cast<float>(height) / content;
    options.font_pixels = 16.0f * std::max(1.0f, lines / 1080.0f);
    return options;
}

}  // namespace

LauncherWindow::LauncherWindow(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
LauncherWindow::~LauncherWindow() = default;

Result<std::unique_ptr<LauncherWindow>> LauncherWindow::create(const vk_core::Context& ctx,
                                                               LauncherModel& model, LauncherUi& ui,
                                                               LauncherActions actions) {
    window::DesktopWindowOptions options = fitted_to_monitor();
    options.title = "monoplane lab";
    options.what = "launcher window";
    options.scale_with_monitor = true;
    options.hold_taps = true;  // keyboard-only use includes scripted keys (xdotool, XTest)
    auto desktop = window::DesktopWindow::create(ctx, options);
    MONOPLANE_TRY(desktop);
    auto impl = std::make_unique<Impl>(model, ui, std::move(actions));
    impl->desktop = std::move(desktop).value();
    // As DesktopWindow scales it: the monitor's size's font, times the content scale.
    const float scale = std::max(1.0f, impl->desktop->content_scale());
    model.set_window_scale(impl->desktop->content_scale(), options.font_pixels * scale);
    // Arrow keys, Space and Enter reach every button, list entry and field.
    ImGui::GetIO().ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard;
    return std::unique_ptr<LauncherWindow>(new LauncherWindow(std::move(impl)));
}

LauncherExit LauncherWindow::run() {
    Impl& s = *impl_;
    while (!s.desktop->close_requested() && !s.panels.quit_requested()) {
        s.frame();
        if (std::optional<LaunchRequest> launch = s.panels.take_launch()) {
            // The Session step as the launcher shows it before it closes, and its state.
            s.save_screenshot("session");
            s.write_state();
            return LauncherExit{std::move(launch)};
        }
        if (s.panels.take_check_request()) s.run_check();
        // The launcher waits for a person: 60 frames a second are plenty, and leave the CPU to
        // whatever else runs on the lab PC.
        std::this_thread::sleep_for(std::chrono::milliseconds(15));
    }
    return LauncherExit{};
}

}  // namespace monoplane::lab
