// A desktop window of the app: GLFW + Dear ImGui on the app's Vulkan device, with its swapchain,
// present and screenshot. It draws whatever Dear ImGui was given between begin_frame() and
// end_frame(); the experimenter window (experimenter_window.h) and the launcher of `monoplane lab`
// (app/lab/launcher_window.h) are built on it.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "common/result.h"
#include "renderer/vk/context.h"

namespace monoplane::window {

struct DesktopWindowOptions {
    int width = 1280;
    int height = 800;
    std::string title = "monoplane";
    // What the window is called in error messages ("cannot open the experimenter window: ...").
    std::string what = "window";
    // Dear ImGui's font size in pixels (its built-in font is drawn for 13).
    float font_pixels = 13.0f;
    // Multiplies the font size and Dear ImGui's spacing by the monitor's content scale
    // (glfwGetWindowContentScale), so that text keeps its physical size on a dense display.
    bool scale_with_monitor = false;
    // A key pressed and released between two frames is released one frame later, so that Dear
    // ImGui 1.86 (which samples key states once a frame) sees the tap: scripted input (xdotool,
    // XTest) sends both at once. Off keeps GLFW's events as they come.
    bool hold_taps = false;
};

// A key press GLFW reported (GLFW_KEY_*, GLFW_MOD_* bits).
struct KeyPress {
    int key = 0;
    int mods = 0;
};

class DesktopWindow {
  public:
    // May be called once the Context exists, created with required_instance_extensions() and
    // required_device_extensions(); one window per process at a time
    // (Dear ImGui's backends are global). Must be destroyed before the Context.
    static Result<std::unique_ptr<DesktopWindow>> create(const vk_core::Context& ctx,
                                                         const DesktopWindowOptions& options);
    DesktopWindow(const DesktopWindow&) = delete;
    DesktopWindow& operator=(const DesktopWindow&) = delete;
    ~DesktopWindow();

    // Polls input and starts a Dear ImGui frame; the caller then draws with ImGui:: calls and
    // ends with end_frame(). Once per frame, on the thread that created the window.
    void begin_frame() {
        poll_events();
        new_frame();
    }
    // begin_frame() in two halves, for a caller that reads the input state Dear ImGui left from
    // the last frame before the next one starts (the experimenter window's key commands).
    void poll_events();
    void new_frame();
    // Renders the frame's draw lists into the next swapchain image and presents it (nothing while
    // minimised). After begin_frame(), once per frame, with the app's own frame commands (same
    // queue) submitted and waited for.
    void end_frame();
    // The key presses since the last call, in order (key repeats are not presses). Any time.
    std::vector<KeyPress> take_key_presses();

    // Whether the user closed the window (the app decides what that means). Any time.
    bool close_requested() const;
    // Writes what the window shows (the last frame's draw lists, drawn again) to a PNG file.
    // After end_frame(); fails while minimised or when the surface cannot be read back.
    Result<void> save_screenshot(const std::filesystem::path& png);
    // The drawable size in pixels (0 x 0 while minimised). Any time.
    vk::Extent2D extent() const;
    // Asks the desktop for another window size; it takes effect within a few frames.
    void request_size(int width, int height);
    // The monitor's content scale (1 on a plain display, 2 on a doubled one). Any time.
    float content_scale() const;

    // For windows that draw their own textures through Dear ImGui's backend (the experimenter
    // window's mirror): the descriptor pool Dear ImGui's sets come from, and the command buffer
    // being recorded while a draw-list callback runs (null otherwise).
    vk::DescriptorPool descriptor_pool() const;
    VkCommandBuffer recording() const;
    const vk_core::Context& context() const;

  private:
    struct Impl;
    explicit DesktopWindow(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// Instance extensions the Context must be created with so that a window can present on its
// device. May be called at any time; fails with a message a user can act on when there is no
// display (GLFW cannot initialise) or no Vulkan window-system support.
Result<std::vector<std::string>> required_instance_extensions();
// Device extensions likewise: VK_KHR_swapchain.
std::vector<std::string> required_device_extensions();

}  // namespace monoplane::window
