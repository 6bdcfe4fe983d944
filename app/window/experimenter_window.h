// The experimenter window: a desktop window (GLFW + Dear ImGui on the app's Vulkan device) that
// the experimenter watches while a participant in the headset runs a 2AFC session. It mirrors the
// participant's view and shows the session, progress, the blinded trial state, controls, the log
// tail and, at the end, the questionnaire form. It keeps no study state: the study loop fills an
// ExperimenterView every frame and acts on the Commands it gets back.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/window/desktop_window.h"
#include "app/window/experimenter_view.h"
#include "app/window/key_commands.h"
#include "app/window/mirror_texture.h"
#include "app/window/response_key_input.h"
#include "common/result.h"
#include "renderer/vk/context.h"

struct GLFWwindow;
struct ImDrawList;
struct ImDrawCmd;

namespace monoplane::window {

struct WindowOptions {
    int width = 1280;
    int height = 800;
    std::string title = "monoplane: experimenter";
};

// required_instance_extensions() and required_device_extensions(): desktop_window.h.

class ExperimenterWindow {
  public:
    // May be called once the Context exists, created with the extensions above; one window per
    // process at a time (Dear ImGui's backends are global). The window must be destroyed before
    // the Context. `mirror_extent`: the size of the mirror texture (e.g. one eye's aspect).
    static Result<std::unique_ptr<ExperimenterWindow>> create(const vk_core::Context& ctx,
                                                              const WindowOptions& options,
                                                              vk::Extent2D mirror_extent);

    ExperimenterWindow(const ExperimenterWindow&) = delete;
    ExperimenterWindow& operator=(const ExperimenterWindow&) = delete;
    ~ExperimenterWindow();

    // Records into the caller's command buffer a scaled copy (blit, aspect kept) of `source` (an
    // image the caller owns, in `source_layout`, with TRANSFER_SRC usage) into the mirror texture,
    // leaving `source` in `source_layout` again. Barriers included. Called inside the app's frame
    // commands, on the Context's queue.
    void record_mirror(const vk::raii::CommandBuffer& cmd, vk::Image source,
                       vk::ImageLayout source_layout, vk::Extent2D source_extent);

    // Polls input, draws the panels for `view`, presents; returns the experimenter's commands
    // since the last call (keys first, then panel buttons). Call once per app frame, after the
    // app's frame commands were submitted and waited for (same queue, single-threaded). While
    // minimised it draws nothing but still returns commands.
    std::vector<Command> frame(const ExperimenterView& view);

    // The participant's answer keys ([responses]): from then on a press of one of them is a
    // Switch or Confirm carrying the key's name, in any phase (the session decides what it
    // changes), instead of the experimenter's own command for that key. Like every key, they are
    // not read while a text field has the focus. Any time.
    void set_response_keys(std::vector<ResponseKeyBinding> bindings);

    // Whether the experimenter closed the window (the app decides what that means).
    bool close_requested() const;

    // Writes what the window shows (the last frame's panels, drawn again) to a PNG file. May be
    // called after frame(); fails while minimised or when the surface cannot be read back.
    Result<void> save_screenshot(const std::filesystem::path& png);

    // Writes what the last frame showed as JSON, for tests and for checking a session's window
    // afterwards: the frame's index and phase, where the mirror was drawn and the gaze marker
    // ({"frame_index", "phase", "mirror": {x, y, width, height}, "gaze": {"tracked", "uv":
    // [u, v] or null, "shown": none|point|outside|lost, "radius", "marker": [x, y] or null}},
    // window pixels). May be called after frame().
    Result<void> save_state(const std::filesystem::path& json) const;

    // The window's drawable size in pixels (0 x 0 while minimised).
    vk::Extent2D extent() const;
    // Asks the desktop for another window size (tests, scripted dry runs); it takes effect within
    // a few frames, and the swapchain follows.
    void request_size(int width, int height);
    // Where the mirror was drawn in the last frame, in window pixels (for tests and layout).
    FitRect mirror_rect() const;

  private:
    struct Impl;
    explicit ExperimenterWindow(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace monoplane::window
