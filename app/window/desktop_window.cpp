#include "app/window/desktop_window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <thread>

#include "app/window/screenshot.h"
#include "app/window/swapchain.h"
#include "app/window/text_fonts.h"
#include "renderer/vk/buffer.h"

namespace monoplane::window {
namespace {

// GLFW reports errors through a callback; the last one goes into our error messages.
std::string& last_glfw_error() {
    static std::string text;
    return text;
}

void on_glfw_error(int code, const char* description) {
    last_glfw_error() = std::to_string(code) + ": " + (description ? description : "?");
}

// A few tries a moment apart: an X server may refuse a new connection for a moment (one failure
// in a loaded test run opened no experimenter window, where the same display served the
// launcher before and after), and a session that starts without its window runs to its end
// without the experimenter's view and controls. A display that is not there fails each try
// within a second in all.
bool init_glfw() {
    glfwSetErrorCallback(&on_glfw_error);
    constexpr int kTries = 5;
    for (int attempt = 1; attempt < kTries; ++attempt) {
        if (glfwInit() == GLFW_TRUE) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
    return glfwInit() == GLFW_TRUE;
}

void on_imgui_vulkan_result(VkResult result) {
    if (result < 0) std::fprintf(stderr, "Dear ImGui's Vulkan backend: VkResult %d\n", result);
}

bool window_exists = false;  // Dear ImGui's backends keep global state: one window at a time

}  // namespace

Result<std::vector<std::string>> required_instance_extensions() {
    if (!init_glfw()) {
        return Error{"cannot open the experimenter window: GLFW failed to initialise (" +
                     last_glfw_error() +
                     "). Is there a display? Set DISPLAY, run under xvfb-run, or run without "
                     "the window"};
    }
    if (glfwVulkanSupported() != GLFW_TRUE) {
        return Error{
            "cannot open the experimenter window: GLFW finds no Vulkan loader with "
            "window-system support (install libvulkan1 and a Vulkan driver)"};
    }
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (names == nullptr) {
        return Error{
            "cannot open the experimenter window: Vulkan cannot present to this "
            "display (" +
            last_glfw_error() + ")"};
    }
    return std::vector<std::string>(names, names + count);
}

std::vector<std::string> required_device_extensions() {
    return {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
}

struct DesktopWindow::Impl {
    explicit Impl(const vk_core::Context& context) : ctx(context) {}
    ~Impl();

    const vk_core::Context& ctx;
    DesktopWindowOptions options;
    GLFWwindow* window = nullptr;
    bool glfw_ready = false, imgui_context = false, imgui_glfw = false, imgui_vulkan = false;
    vk::raii::SurfaceKHR surface{nullptr};
    SwapchainConfig config;
    vk::raii::RenderPass present_pass{nullptr};
    vk::raii::RenderPass capture_pass{nullptr};  // same pass, ends in TRANSFER_SRC
    vk::raii::DescriptorPool descriptor_pool{nullptr};
    vk::raii::CommandPool command_pool{nullptr};
    vk::raii::CommandBuffer cmd{nullptr};
    vk::raii::Fence frame_done{nullptr};
    vk::raii::Semaphore image_available{nullptr};
    std::unique_ptr<Swapchain> swapchain;
    bool swapchain_stale = false;
    VkCommandBuffer recording = VK_NULL_HANDLE;  // for draw-list callbacks
    std::vector<KeyPress> pressed_keys;
    // hold_taps: keys pressed since the last frame began, and releases held back for the next.
    std::vector<int> down_this_frame;
    std::vector<std::pair<int, int>> held_releases;  // key, mods

    static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void on_key_holding_taps(GLFWwindow* window, int key, int scancode, int action,
                                    int mods);

    Result<void> init(const DesktopWindowOptions& options);
    Result<void> init_surface();
    void init_imgui();
    // Builds the swapchain for the current framebuffer size; false while minimised.
    bool ensure_swapchain();
    // Draws `draw_data` into the next swapchain image and presents it; with `capture`, also reads
    // the image back (tightly packed RGBA8). False when nothing was presented.
    bool render(ImDrawData* draw_data, std::vector<std::uint8_t>* capture);
    void record_readback(std::uint32_t index, const vk_core::Buffer& readback);
    void copy_capture(const vk_core::Buffer& readback, std::vector<std::uint8_t>& capture) const;
};

void DesktopWindow::Impl::on_key(GLFWwindow* window, int key, int /*scancode*/, int action,
                                 int mods) {
    // Dear ImGui chains to this callback (it was installed first); key repeats are not presses.
    auto* self = static_cast<Impl*>(glfwGetWindowUserPointer(window));
    if (self != nullptr && action == GLFW_PRESS) self->pressed_keys.push_back({key, mods});
}

void DesktopWindow::Impl::on_key_holding_taps(GLFWwindow* window, int key, int scancode, int action,
                                              int mods) {
    // Installed over Dear ImGui's callback, which it calls (and which chains to on_key).
    auto* self = static_cast<Impl*>(glfwGetWindowUserPointer(window));
    if (self != nullptr && action == GLFW_RELEASE &&
        std::find(self->down_this_frame.begin(), self->down_this_frame.end(), key) !=
            self->down_this_frame.end()) {
        self->held_releases.emplace_back(key, mods);
        return;
    }
    if (self != nullptr && action == GLFW_PRESS) self->down_this_frame.push_back(key);
    ImGui_ImplGlfw_KeyCallback(window, key, scancode, action, mods);
}

DesktopWindow::Impl::~Impl() {
    // Nothing may go while the GPU uses it; a destructor must not throw, so the result (only a
    // lost device can fail here) is left to the driver's teardown.
    if (*ctx.device()) {
        static_cast<void>(ctx.device().getDispatcher()->vkDeviceWaitIdle(*ctx.device()));
    }
    if (imgui_vulkan) ImGui_ImplVulkan_Shutdown();
    if (imgui_glfw) ImGui_ImplGlfw_Shutdown();
    if (imgui_context) ImGui::DestroyContext();
    // Vulkan objects of the window before its surface, the surface before the window.
    swapchain.reset();
    surface.clear();
    if (window != nullptr) glfwDestroyWindow(window);
    if (glfw_ready) glfwTerminate();
    window_exists = false;
}

Result<void> DesktopWindow::Impl::init(const DesktopWindowOptions& window_options) {
    options = window_options;
    if (!ctx.has_device_extension(VK_KHR_SWAPCHAIN_EXTENSION_NAME)) {
        return Error{
            "the Vulkan device was created without VK_KHR_swapchain; create the Context "
            "with window::required_device_extensions()"};
    }
    glfw_ready = init_glfw();
    if (!glfw_ready) {
        return Error{"cannot open the " + options.what + ": GLFW failed to initialise (" +
                     last_glfw_error() + "). Is there a display?"};
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    window =
        glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
    if (window == nullptr) {
        return Error{"cannot open the " + options.what + " (" + last_glfw_error() + ")"};
    }
    MONOPLANE_TRY(init_surface());
    // Dear ImGui's font set and the users' sets (the experimenter window's mirror).
    const vk::DescriptorPoolSize pool_size(vk::DescriptorType::eCombinedImageSampler, 4);
    descriptor_pool = vk::raii::DescriptorPool(
        ctx.device(), vk::DescriptorPoolCreateInfo(
                          vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 4, pool_size));
    command_pool = vk::raii::CommandPool(
        ctx.device(), vk::CommandPoolCreateInfo(vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                                ctx.queue_family()));
    cmd = std::move(vk::raii::CommandBuffers(
                        ctx.device(), vk::CommandBufferAllocateInfo(
                                          *command_pool, vk::CommandBufferLevel::ePrimary, 1))
                        .front());
    frame_done =
        vk::raii::Fence(ctx.device(), vk::FenceCreateInfo(vk::FenceCreateFlagBits::eSignaled));
    image_available = vk::raii::Semaphore(ctx.device(), vk::SemaphoreCreateInfo());
    init_imgui();
    ensure_swapchain();
    return Ok{};
}

Result<void> DesktopWindow::Impl::init_surface() {
    VkSurfaceKHR raw_surface = VK_NULL_HANDLE;
    if (glfwCreateWindowSurface(*ctx.instance(), window, nullptr, &raw_surface) != VK_SUCCESS) {
        return Error{"cannot create a Vulkan surface for the " + options.what + " (" +
                     last_glfw_error() +
                     "); create the Context with window::required_instance_extensions()"};
    }
    surface = vk::raii::SurfaceKHR(ctx.instance(), raw_surface);
    if (!ctx.physical_device().getSurfaceSupportKHR(ctx.queue_family(), *surface)) {
        return Error{"the Vulkan device '" + ctx.device_info().name +
                     "' cannot present to this display; choose another with --device"};
    }
    config = choose_swapchain_config(ctx.physical_device(), *surface);
    present_pass =
        make_ui_render_pass(ctx.device(), config.format.format, vk::ImageLayout::ePresentSrcKHR);
    if (config.transfer_src) {
        capture_pass = make_ui_render_pass(ctx.device(), config.format.format,
                                           vk::ImageLayout::eTransferSrcOptimal);
    }
    return Ok{};
}

void DesktopWindow::Impl::init_imgui() {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    imgui_context = true;
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // nothing written to the working directory
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0.0f;
    float scale = 1.0f;
    if (options.scale_with_monitor) {
        float x = 1.0f, y = 1.0f;
        glfwGetWindowContentScale(window, &x, &y);
        scale = std::max(1.0f, std::max(x, y));
        ImGui::GetStyle().ScaleAllSizes(scale);
    }
    ImFontConfig font;
    font.SizePixels = options.font_pixels * scale;
    io.Fonts->AddFontDefault(&font);
    merge_text_fonts(*io.Fonts, font.SizePixels);  // pages in the participant's language

    // Installed before Dear ImGui's, which then chains to it.
    glfwSetWindowUserPointer(window, this);
    glfwSetKeyCallback(window, &Impl::on_key);
    imgui_glfw = ImGui_ImplGlfw_InitForVulkan(window, true);
    if (options.hold_taps) glfwSetKeyCallback(window, &Impl::on_key_holding_taps);

    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = *ctx.instance();
    info.PhysicalDevice = *ctx.physical_device();
    info.Device = *ctx.device();
    info.QueueFamily = ctx.queue_family();
    info.Queue = *ctx.queue();
    info.DescriptorPool = *descriptor_pool;
    info.Subpass = 0;
    // The backend rotates its vertex buffers over ImageCount frames; one frame is in flight here,
    // so two never overlap whatever the swapchain's image count.
    info.MinImageCount = 2;
    info.ImageCount = 2;
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = &on_imgui_vulkan_result;
    imgui_vulkan = ImGui_ImplVulkan_Init(&info, *present_pass);
    ctx.submit_and_wait([](const vk::raii::CommandBuffer& upload) {
        ImGui_ImplVulkan_CreateFontsTexture(*upload);
    });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

bool DesktopWindow::Impl::ensure_swapchain() {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    if (width <= 0 || height <= 0) return false;  // minimised
    const bool fits = swapchain && swapchain->extent().width == static_cast<std::uint32_t>(width) &&
                      swapchain->extent().height == static_cast<std::uint32_t>(height);
    if (fits && !swapchain_stale) return true;
    const auto caps = ctx.physical_device().getSurfaceCapabilitiesKHR(*surface);
    const vk::Extent2D extent = swapchain_extent(caps, width, height);
    if (extent.width == 0 || extent.height == 0) return false;
    // The old swapchain's last frame must be done before its images and views go.
    static_cast<void>(ctx.device().waitForFences(*frame_done, VK_TRUE,
                                                 std::numeric_limits<std::uint64_t>::max()));
    ctx.queue().waitIdle();
    auto next = std::make_unique<Swapchain>(ctx, *surface, config, *present_pass, extent,
                                            swapchain ? *swapchain->handle() : vk::SwapchainKHR());
    swapchain = std::move(next);
    swapchain_stale = false;
    return true;
}

void DesktopWindow::Impl::record_readback(std::uint32_t index, const vk_core::Buffer& readback) {
    const vk::Extent2D extent = swapchain->extent();
    const vk::BufferImageCopy region(
        0, 0, 0, vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, 0, 0, 1), {0, 0, 0},
        vk::Extent3D(extent, 1));
    cmd.copyImageToBuffer(swapchain->image(index), vk::ImageLayout::eTransferSrcOptimal,
                          readback.handle(), region);
    const vk::ImageMemoryBarrier2 to_present(
        vk::PipelineStageFlagBits2::eCopy, {}, vk::PipelineStageFlagBits2::eNone, {},
        vk::ImageLayout::eTransferSrcOptimal, vk::ImageLayout::ePresentSrcKHR,
        VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, swapchain->image(index),
        vk::ImageSubresourceRange(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1));
    const vk::BufferMemoryBarrier2 to_host(
        vk::PipelineStageFlagBits2::eCopy, vk::AccessFlagBits2::eTransferWrite,
        vk::PipelineStageFlagBits2::eHost, vk::AccessFlagBits2::eHostRead, VK_QUEUE_FAMILY_IGNORED,
        VK_QUEUE_FAMILY_IGNORED, readback.handle(), 0, VK_WHOLE_SIZE);
    cmd.pipelineBarrier2(vk::DependencyInfo({}, {}, to_host, to_present));
}

void DesktopWindow::Impl::copy_capture(const vk_core::Buffer& readback,
                                       std::vector<std::uint8_t>& capture) const {
    const vk::Extent2D extent = swapchain->extent();
    const auto* pixels = reinterpret_cast<const std::uint8_t*>(readback.mapped());
    const std::size_t count = std::size_t{extent.width} * extent.height;
    const bool bgra = config.format.format == vk::Format::eB8G8R8A8Unorm ||
                      config.format.format == vk::Format::eB8G8R8A8Srgb;
    capture.resize(count * 4);
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint8_t* p = pixels + i * 4;
        std::uint8_t* q = capture.data() + i * 4;
        q[0] = bgra ? p[2] : p[0];
        q[1] = p[1];
        q[2] = bgra ? p[0] : p[2];
        q[3] = 255;  // the window is opaque, whatever alpha the UI left behind
    }
}

bool DesktopWindow::Impl::render(ImDrawData* draw_data, std::vector<std::uint8_t>* capture) {
    if (!ensure_swapchain()) return false;
    const auto forever = std::numeric_limits<std::uint64_t>::max();
    static_cast<void>(ctx.device().waitForFences(*frame_done, VK_TRUE, forever));

    std::uint32_t index = 0;
    try {
        const auto [result, acquired] =
            swapchain->handle().acquireNextImage(forever, *image_available);
        if (result == vk::Result::eSuboptimalKHR) swapchain_stale = true;
        index = acquired;
    } catch (const vk::OutOfDateKHRError&) {
        swapchain_stale = true;  // resized between the size check and the acquire
        return false;
    }
    ctx.device().resetFences(*frame_done);

    const vk::Extent2D extent = swapchain->extent();
    std::unique_ptr<vk_core::Buffer> readback;
    if (capture != nullptr) {
        readback = std::make_unique<vk_core::Buffer>(
            ctx, vk::DeviceSize{extent.width} * extent.height * 4,
            vk::BufferUsageFlagBits::eTransferDst, vk_core::MemoryUse::kHostVisible);
    }
    cmd.reset();
    cmd.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    const vk::ClearValue clear(vk::ClearColorValue(std::array{0.08f, 0.08f, 0.09f, 1.0f}));
    cmd.beginRenderPass(
        vk::RenderPassBeginInfo(capture ? *capture_pass : *present_pass,
                                swapchain->framebuffer(index), vk::Rect2D({0, 0}, extent), clear),
        vk::SubpassContents::eInline);
    recording = *cmd;
    ImGui_ImplVulkan_RenderDrawData(draw_data, *cmd);
    recording = VK_NULL_HANDLE;
    cmd.endRenderPass();
    if (capture != nullptr) record_readback(index, *readback);
    cmd.end();

    const vk::PipelineStageFlags wait_stage = vk::PipelineStageFlagBits::eColorAttachmentOutput;
    const vk::Semaphore finished = swapchain->render_finished(index);
    ctx.queue().submit(vk::SubmitInfo(*image_available, wait_stage, *cmd, finished), *frame_done);
    try {
        const vk::SwapchainKHR handle = *swapchain->handle();
        if (ctx.queue().presentKHR(vk::PresentInfoKHR(finished, handle, index)) ==
            vk::Result::eSuboptimalKHR) {
            swapchain_stale = true;
        }
    } catch (const vk::OutOfDateKHRError&) {
        swapchain_stale = true;
    }
    if (capture != nullptr) {
        static_cast<void>(ctx.device().waitForFences(*frame_done, VK_TRUE, forever));
        copy_capture(*readback, *capture);
    }
    return true;
}

DesktopWindow::DesktopWindow(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
DesktopWindow::~DesktopWindow() = default;

Result<std::unique_ptr<DesktopWindow>> DesktopWindow::create(const vk_core::Context& ctx,
                                                             const DesktopWindowOptions& options) {
    if (window_exists) return Error{"only one " + options.what + " can be open at a time"};
    window_exists = true;
    auto impl = std::make_unique<Impl>(ctx);
    try {
        MONOPLANE_TRY(impl->init(options));
    } catch (const vk::SystemError& e) {
        return Error{"cannot set up the " + options.what + ": " + e.what()};
    }
    return std::unique_ptr<DesktopWindow>(new DesktopWindow(std::move(impl)));
}

void DesktopWindow::poll_events() {
    Impl& s = *impl_;
    if (s.options.hold_taps) {
        // The taps of the last poll are released now, after Dear ImGui saw them down for a frame.
        s.down_this_frame.clear();
        for (const auto& [key, mods] : s.held_releases) {
            ImGui_ImplGlfw_KeyCallback(s.window, key, 0, GLFW_RELEASE, mods);
        }
        s.held_releases.clear();
    }
    glfwPollEvents();
}

void DesktopWindow::new_frame() {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void DesktopWindow::end_frame() {
    ImGui::Render();
    impl_->render(ImGui::GetDrawData(), nullptr);
}

std::vector<KeyPress> DesktopWindow::take_key_presses() {
    std::vector<KeyPress> keys = std::move(impl_->pressed_keys);
    impl_->pressed_keys.clear();
    return keys;
}

bool DesktopWindow::close_requested() const {
    return glfwWindowShouldClose(impl_->window) == GLFW_TRUE;
}

Result<void> DesktopWindow::save_screenshot(const std::filesystem::path& png) {
    Impl& s = *impl_;
    ImDrawData* draw_data = ImGui::GetDrawData();
    if (draw_data == nullptr || !draw_data->Valid) {
        return Error{"no " + s.options.what + " frame to save yet (call frame() first)"};
    }
    if (!s.config.transfer_src) {
        return Error{"this display's swapchain images cannot be read back; no screenshot"};
    }
    std::vector<std::uint8_t> rgba;
    if (!s.render(draw_data, &rgba)) {
        return Error{"the " + s.options.what + " is minimised or being resized; no screenshot"};
    }
    const vk::Extent2D extent = s.swapchain->extent();
    return write_rgba_png(png, extent.width, extent.height, rgba);
}

vk::Extent2D DesktopWindow::extent() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(impl_->window, &width, &height);
    return vk::Extent2D(static_cast<std::uint32_t>(std::max(width, 0)),
                        static_cast<std::uint32_t>(std::max(height, 0)));
}

void DesktopWindow::request_size(int width, int height) {
    glfwSetWindowSize(impl_->window, width, height);
}

float DesktopWindow::content_scale() const {
    float x = 1.0f, y = 1.0f;
    glfwGetWindowContentScale(impl_->window, &x, &y);
    return std::max(1.0f, std::max(x, y));
}

vk::DescriptorPool DesktopWindow::descriptor_pool() const {
    return *impl_->descriptor_pool;
}

VkCommandBuffer DesktopWindow::recording() const {
    return impl_->recording;
}

const vk_core::Context& DesktopWindow::context() const {
    return impl_->ctx;
}

}  // namespace monoplane::window
