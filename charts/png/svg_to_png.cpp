#include "charts/png/svg_to_png.h"

#include <cairo.h>
#include <librsvg/rsvg.h>

#include <cmath>
#include <memory>
#include <string>

namespace monoplane::charts {
namespace {

struct GObjectUnref {
    void operator()(void* object) const {
        if (object) g_object_unref(object);
    }
};
struct SurfaceDestroy {
    void operator()(cairo_surface_t* surface) const { cairo_surface_destroy(surface); }
};
struct CairoDestroy {
    void operator()(cairo_t* cr) const { cairo_destroy(cr); }
};
using Surface = std::unique_ptr<cairo_surface_t, SurfaceDestroy>;

std::string take_message(GError* error) {
    std::string message = error && error->message ? error->message : "unknown error";
    if (error) g_error_free(error);
    return message;
}

// The document drawn on a white-backed ARGB surface of its size times `scale`.
Result<Surface> render(std::string_view svg, double scale) {
    if (!(scale > 0.0 && scale <= 16.0)) {
        return Error{"SVG to PNG: scale " + std::to_string(scale) + " is not in (0, 16]"};
    }
    GError* error = nullptr;
    std::unique_ptr<RsvgHandle, GObjectUnref> handle(
        rsvg_handle_new_from_data(reinterpret_cast<const guint8*>(svg.data()), svg.size(), &error));
    if (!handle) return Error{"SVG to PNG: not a readable SVG document: " + take_message(error)};
    rsvg_handle_set_dpi(handle.get(), 96.0);
    gdouble width = 0.0;
    gdouble height = 0.0;
    if (!rsvg_handle_get_intrinsic_size_in_pixels(handle.get(), &width, &height) || width <= 0.0 ||
        height <= 0.0) {
        return Error{"SVG to PNG: the document has no width and height in pixels"};
    }
    const int w = static_cast<int>(std::lround(width * scale));
    const int h = static_cast<int>(std::lround(height * scale));
    if (w < 1 || h < 1 || w > 32768 || h > 32768) {
        return Error{"SVG to PNG: " + std::to_string(w) + " x " + std::to_string(h) +
                     " pixels is not a sensible figure size"};
    }
    Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h));
    if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
        return Error{"SVG to PNG: cannot allocate " + std::to_string(w) + " x " +
                     std::to_string(h) + " pixels"};
    }
    std::unique_ptr<cairo_t, CairoDestroy> cr(cairo_create(surface.get()));
    // The charts paint their own white background; this one covers documents that do not.
    cairo_set_source_rgb(cr.get(), 1.0, 1.0, 1.0);
    cairo_paint(cr.get());
    const RsvgRectangle viewport{0.0, 0.0, static_cast<double>(w), static_cast<double>(h)};
    if (!rsvg_handle_render_document(handle.get(), cr.get(), &viewport, &error)) {
        return Error{"SVG to PNG: rendering failed: " + take_message(error)};
    }
    cairo_surface_flush(surface.get());
    return surface;
}

}  // namespace

Result<RgbaImage> rasterize_svg(std::string_view svg, double scale) {
    Result<Surface> surface = render(svg, scale);
    MONOPLANE_TRY(surface);
    cairo_surface_t* s = surface.value().get();
    RgbaImage image;
    image.width = cairo_image_surface_get_width(s);
    image.height = cairo_image_surface_get_height(s);
    const int stride = cairo_image_surface_get_stride(s);
    const unsigned char* data = cairo_image_surface_get_data(s);
    image.pixels.resize(static_cast<std::size_t>(image.width) * image.height * 4);
    for (int y = 0; y < image.height; ++y) {
        const auto* row = reinterpret_cast<const std::uint32_t*>(data + y * stride);
        for (int x = 0; x < image.width; ++x) {
            // cairo: native-endian premultiplied ARGB in one 32-bit word.
            const std::uint32_t p = row[x];
            const std::uint32_t a = p >> 24;
            auto channel = [a](std::uint32_t c) -> std::uint8_t {
                return static_cast<std::uint8_t>(a == 0 ? 0 : (c * 255 + a / 2) / a);
            };
            std::uint8_t* out = &image.pixels[(static_cast<std::size_t>(y) * image.width + x) * 4];
            out[0] = channel((p >> 16) & 0xFF);
            out[1] = channel((p >> 8) & 0xFF);
            out[2] = channel(p & 0xFF);
            out[3] = static_cast<std::uint8_t>(a);
        }
    }
    return image;
}

Result<void> write_svg_as_png(std::string_view svg, const std::filesystem::path& path,
                              double scale) {
    Result<Surface> surface = render(svg, scale);
    if (!surface) return Error{path.string() + ": " + surface.error().message};
    const cairo_status_t status =
        cairo_surface_write_to_png(surface.value().get(), path.string().c_str());
    if (status != CAIRO_STATUS_SUCCESS) {
        return Error{"cannot write '" + path.string() + "': " + cairo_status_to_string(status)};
    }
    return Ok{};
}

}  // namespace monoplane::charts
