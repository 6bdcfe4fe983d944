#include "app/window/experimenter_window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>

#include "app/window/imgui_backend_access.h"
#include "app/window/panels.h"
#include "app/window/screenshot.h"
#include "app/window/swapchain.h"
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

bool init_glfw() {
    glfwSetErrorCallback(&on_glfw_error);
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

struct ExperimenterWindow::Impl {
    explicit Impl(const vk_core::Context& context) : ctx(context) {}
    ~Impl();

    const vk_core::Context& ctx;
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
    std::unique_ptr<MirrorTexture> mirror;
    std::unique_ptr<Swapchain> swapchain;
    bool swapchain_stale = false;
    VkCommandBuffer recording = VK_NULL_HANDLE;  // for the mirror's draw callback
    PanelState panels;
    std::vector<int> pressed_keys;
    bool drawn = false;

    static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void bind_mirror(const ImDrawList* list, const ImDrawCmd* command);

    Result<bool> init(const WindowOptions& options, vk::Extent2D mirror_extent);
    void init_imgui();
    // Builds the swapchain for the current framebuffer size; false while minimised.
    bool ensure_swapchain();
    // Draws `draw_data` into the next swapchain image and presents it; with `capture`, also reads
    // the image back (tightly packed RGBA8). False when nothing was presented.
    bool render(ImDrawData* draw_data, std::vector<std::uint8_t>* capture);
};

void ExperimenterWindow::Impl::on_key(GLFWwindow* window, int key, int /*scancode*/, int action,
                                      int /*mods*/) {
    // Dear ImGui chains to this callback (it was installed first); key repeats are not presses.
    auto* self = static_cast<Impl*>(glfwGetWindowUserPointer(window));
    if (self != nullptr && action == GLFW_PRESS) self->pressed_keys.push_back(key);
}

void ExperimenterWindow::Impl::bind_mirror(const ImDrawList* /*list*/, const ImDrawCmd* command) {
    auto* self = static_cast<Impl*>(command->UserCallbackData);
    const VkDescriptorSet set = self->mirror->descriptor_set();
    self->ctx.device().getDispatcher()->vkCmdBindDescriptorSets(
        self->recording, VK_PIPELINE_BIND_POINT_GRAPHICS, imgui_vulkan_pipeline_layout(), 0, 1,
        &set, 0, nullptr);
}

ExperimenterWindow::Impl::~Impl() {
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
    mirror.reset();
    surface.clear();
    if (window != nullptr) glfwDestroyWindow(window);
    if (glfw_ready) glfwTerminate();
    window_exists = false;
}

Result<bool> ExperimenterWindow::Impl::init(const WindowOptions& options,
                                            vk::Extent2D mirror_extent) {
    if (!ctx.has_device_extension(VK_KHR_SWAPCHAIN_EXTENSION_NAME)) {
        return Error{
            "the Vulkan device was created without VK_KHR_swapchain; create the Context "
            "with window::required_device_extensions()"};
    }
    glfw_ready = init_glfw();
    if (!glfw_ready) {
        return Error{"cannot open the experimenter window: GLFW failed to initialise (" +
                     last_glfw_error() + "). Is there a display?"};
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    window =
        glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
    if (window == nullptr) {
        return Error{"cannot open the experimenter window (" + last_glfw_error() + ")"};
    }
    VkSurfaceKHR raw_surface = VK_NULL_HANDLE;
    if (glfwCreateWindowSurface(*ctx.instance(), window, nullptr, &raw_surface) != VK_SUCCESS) {
        return Error{"cannot create a Vulkan surface for the experimenter window (" +
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
    // Dear ImGui's font set and the mirror's set.
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
    mirror = std::make_unique<MirrorTexture>(ctx, mirror_extent, *descriptor_pool,
                                             imgui_vulkan_set_layout());
    ensure_swapchain();
    return true;
}

void ExperimenterWindow::Impl::init_imgui() {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    imgui_context = true;
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // nothing written to the working directory
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0.0f;

    // Installed before Dear ImGui's, which then chains to it.
    glfwSetWindowUserPointer(window, this);
    glfwSetKeyCallback(window, &Impl::on_key);
    imgui_glfw = ImGui_ImplGlfw_InitForVulkan(window, true);

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

bool ExperimenterWindow::Impl::ensure_swapchain() {
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

bool ExperimenterWindow::Impl::render(ImDrawData* draw_data, std::vector<std::uint8_t>* capture) {
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
    if (capture != nullptr) {
        const vk::BufferImageCopy region(
            0, 0, 0, vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, 0, 0, 1),
            {0, 0, 0}, vk::Extent3D(extent, 1));
        cmd.copyImageToBuffer(swapchain->image(index), vk::ImageLayout::eTransferSrcOptimal,
                              readback->handle(), region);
        const vk::ImageMemoryBarrier2 to_present(
            vk::PipelineStageFlagBits2::eCopy, {}, vk::PipelineStageFlagBits2::eNone, {},
            vk::ImageLayout::eTransferSrcOptimal, vk::ImageLayout::ePresentSrcKHR,
            VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, swapchain->image(index),
            vk::ImageSubresourceRange(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1));
        const vk::BufferMemoryBarrier2 to_host(
            vk::PipelineStageFlagBits2::eCopy, vk::AccessFlagBits2::eTransferWrite,
            vk::PipelineStageFlagBits2::eHost, vk::AccessFlagBits2::eHostRead,
            VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, readback->handle(), 0, VK_WHOLE_SIZE);
        cmd.pipelineBarrier2(vk::DependencyInfo({}, {}, to_host, to_present));
    }
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
        const auto* pixels = reinterpret_cast<const std::uint8_t*>(readback->mapped());
        const std::size_t count = std::size_t{extent.width} * extent.height;
        const bool bgra = config.format.format == vk::Format::eB8G8R8A8Unorm ||
                          config.format.format == vk::Format::eB8G8R8A8Srgb;
        capture->resize(count * 4);
        for (std::size_t i = 0; i < count; ++i) {
            const std::uint8_t* p = pixels + i * 4;
            std::uint8_t* q = capture->data() + i * 4;
            q[0] = bgra ? p[2] : p[0];
            q[1] = p[1];
            q[2] = bgra ? p[0] : p[2];
            q[3] = 255;  // the window is opaque, whatever alpha the UI left behind
        }
    }
    return true;
}

ExperimenterWindow::ExperimenterWindow(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
ExperimenterWindow::~ExperimenterWindow() = default;

Result<std::unique_ptr<ExperimenterWindow>> ExperimenterWindow::create(const vk_core::Context& ctx,
                                                                       const WindowOptions& options,
                                                                       vk::Extent2D mirror_extent) {
    if (window_exists) return Error{"only one experimenter window can be open at a time"};
    if (mirror_extent.width == 0 || mirror_extent.height == 0) {
        return Error{"the experimenter window's mirror needs a non-empty size"};
    }
    window_exists = true;
    auto impl = std::make_unique<Impl>(ctx);
    try {
        Result<bool> ready = impl->init(options, mirror_extent);
        if (!ready) return ready.error();
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
    glfwPollEvents();
    std::vector<Command> commands;
    // Keys typed into the note field are text, not the participant's buttons.
    const bool typing = ImGui::GetIO().WantTextInput;
    for (const int key : s.pressed_keys) {
        if (typing) break;
        if (auto command = command_for_key(key, view.phase)) commands.push_back(*command);
    }
    s.pressed_keys.clear();

    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    MirrorImage mirror;
    mirror.width = static_cast<float>(s.mirror->extent().width);
    mirror.height = static_cast<float>(s.mirror->extent().height);
    // Dear ImGui 1.86's Vulkan backend ignores texture ids (the bind callback selects the
    // texture); a distinct id only keeps the image in a draw command of its own.
    mirror.texture = s.mirror.get();
    mirror.bind = &Impl::bind_mirror;
    mirror.bind_data = &s;
    std::vector<Command> clicked = draw_panels(view, mirror, s.panels);
    commands.insert(commands.end(), clicked.begin(), clicked.end());
    ImGui::Render();
    s.drawn = s.render(ImGui::GetDrawData(), nullptr) || s.drawn;
    return commands;
}

bool ExperimenterWindow::close_requested() const {
    return glfwWindowShouldClose(impl_->window) == GLFW_TRUE;
}

Result<bool> ExperimenterWindow::save_screenshot(const std::filesystem::path& png) {
    Impl& s = *impl_;
    ImDrawData* draw_data = ImGui::GetDrawData();
    if (draw_data == nullptr || !draw_data->Valid) {
        return Error{"no experimenter window frame to save yet (call frame() first)"};
    }
    if (!s.config.transfer_src) {
        return Error{"this display's swapchain images cannot be read back; no screenshot"};
    }
    std::vector<std::uint8_t> rgba;
    if (!s.render(draw_data, &rgba)) {
        return Error{"the experimenter window is minimised or being resized; no screenshot"};
    }
    const vk::Extent2D extent = s.swapchain->extent();
    return write_rgba_png(png, extent.width, extent.height, rgba);
}

vk::Extent2D ExperimenterWindow::extent() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(impl_->window, &width, &height);
    return vk::Extent2D(static_cast<std::uint32_t>(std::max(width, 0)),
                        static_cast<std::uint32_t>(std::max(height, 0)));
}

void ExperimenterWindow::request_size(int width, int height) {
    glfwSetWindowSize(impl_->window, width, height);
}

FitRect ExperimenterWindow::mirror_rect() const {
    return impl_->panels.mirror_rect;
}

}  // namespace monoplane::window
