// Pages in the participant's language as the headset shows them (issue 43, items 6 and 7): a
// German page (protocols/fink2019-de.toml, the default font) and a Chinese one
// (tests/fixtures/text/demo-zh.toml, a CJK font) through the simulated OpenXR runtime, the
// Khronos validation layer on. The runtime's dumped eye image is cut where the page's panel is
// and compared, pixel for pixel, with FreeType's rasterisation of the page's lines done here
// (tests/text/freetype_reference.h), blended ink over background. MONOPLANE_WRITE_DOCS=1 writes
// the pages into docs/images/headset-page-de.png and headset-page-zh.png.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <stb/stb_image.h>

#include "app/headset/text_panel.h"
#include "hmd/profile.h"
#include "study/protocol.h"
#include "tests/e2e/test_files.h"
#include "tests/text/freetype_reference.h"
#include "tests/unit/png_bytes.h"

namespace monoplane {
namespace {

namespace fs = std::filesystem;

fs::path source_dir() {
    const char* dir = std::getenv("MONOPLANE_SOURCE_DIR");
    return dir ? fs::path(dir) : fs::path(".");
}

struct Image {
    int width = 0;
    int height = 0;
    std::vector<unsigned char> rgba;
    const unsigned char* at(int x, int y) const { return &rgba[(std::size_t(y) * width + x) * 4]; }
};

Image load_png(const fs::path& path) {
    Image image;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 4);
    if (data != nullptr) {
        image.rgba.assign(data, data + std::size_t(image.width) * image.height * 4);
        stbi_image_free(data);
    }
    return image;
}

// The panel: the bounding box of the pixels in its background colour (the scene behind a page
// is a lighter grey, the text lighter still).
struct Box {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
};

Box panel_box(const Image& image, const headset::Rgba8& background) {
    Box box;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const unsigned char* p = image.at(x, y);
            if (p[0] != background[0] || p[1] != background[1] || p[2] != background[2]) continue;
            box.x0 = std::min(box.x0, x);
            box.y0 = std::min(box.y0, y);
            box.x1 = std::max(box.x1, x + 1);
            box.y1 = std::max(box.y1, y + 1);
        }
    }
    return box;
}

struct Page {
    const char* name;
    fs::path protocol;
    const char* font;
    // The headset's prompt under the first of its pages, as the protocol words it
    // ([text.prompts]): written out here, not taken from the program.
    std::vector<std::string> footer;
};

class HeadsetPageLanguage : public ::testing::TestWithParam<Page> {};

// The first page of the protocol, seen by the simulated runtime's left eye (Vive, head still).
Image first_page_frame(const Page& page, const fs::path& dir) {
    fs::remove_all(dir);
    fs::create_directories(dir / "frames");
    const fs::path script = dir / "still.toml";
    std::ofstream(script) << "hmd = \"vive\"\ndisplay_rate_hz = 30\nhead_motion = \"still\"\n"
                          << "exit_after_s = 0.15\ndump_dir = \"" << (dir / "frames").string()
                          << "\"\n";
    const std::string command =
        std::string(MONOPLANE_EXE) + " --validation study run --protocol " +
        page.protocol.string() + " --participant P --db " + (dir / "s.sqlite").string() +
        " --headset simulated --observer none --sim-script " + script.string() +
        " --window off --detail test --seed 3 > " + (dir / "run.log").string() + " 2>&1";
    std::system(command.c_str());
    return load_png(dir / "frames" / "frame_000003_left.png");
}

TEST_P(HeadsetPageLanguage, ThePageIsFreeTypesGlyphsInTheEye) {
    const Page& page = GetParam();
    if (!fs::exists(page.font)) GTEST_SKIP() << page.font << " not installed";
    const fs::path dir = test_folder();
    const Image eye = first_page_frame(page, dir);
    ASSERT_GT(eye.width, 0) << read_file(dir / "run.log");
    // The Vulkan and OpenXR validation layers said nothing (their messages name a VUID).
    EXPECT_EQ(read_file(dir / "run.log").find("VUID"), std::string::npos)
        << read_file(dir / "run.log");
    // The page as the headset lays it out for the Vive's eyes at the protocol's text height.
    const study::Protocol protocol = study::load_protocol(page.protocol).value_or_throw();
    const hmd::HmdProfile vive = hmd::load_hmd_profile("vive").value_or_throw();
    headset::TextPanelOptions options;
    options.text_height_deg = protocol.day.text_height_deg;
    options.font = protocol.day.font;
    const headset::TextPanel panel = headset::layout_text_panel(
        protocol.day.instructions.at(0).text, page.footer, {vive.left, vive.right},
        vk::Extent2D(static_cast<std::uint32_t>(vive.width),
                     static_cast<std::uint32_t>(vive.height)),
        options);
    testing::FreeTypeReference reference(page.font);
    ASSERT_TRUE(reference.ok());
    const testing::FreeTypeReference::Image expected = reference.render(
        panel.lines, panel.style.capital_px / reference.cap_height_em(), panel.style.padding_px);
    const Box box = panel_box(eye, panel.style.background);
    ASSERT_EQ(box.x1 - box.x0, expected.width);
    ASSERT_EQ(box.y1 - box.y0, expected.height);
    std::size_t differing = 0;
    for (int y = 0; y < expected.height; ++y) {
        for (int x = 0; x < expected.width; ++x) {
            const double c = expected.coverage[std::size_t(y) * expected.width + x] / 255.0;
            for (int k = 0; k < 3; ++k) {
                const double from = panel.style.background[k];
                const auto want =
                    static_cast<int>(std::lround(from + (panel.style.ink[k] - from) * c));
                differing += eye.at(box.x0 + x, box.y0 + y)[k] != want;
            }
        }
    }
    EXPECT_EQ(differing, 0u) << page.name;
    if (std::getenv("MONOPLANE_WRITE_DOCS") != nullptr) {
        // The panel with a margin of the eye around it, as the participant sees it.
        const int margin = 24;
        const int x0 = std::max(0, box.x0 - margin), y0 = std::max(0, box.y0 - margin);
        const int x1 = std::min(eye.width, box.x1 + margin),
                  y1 = std::min(eye.height, box.y1 + margin);
        std::vector<unsigned char> crop;
        for (int y = y0; y < y1; ++y)
            crop.insert(crop.end(), eye.at(x0, y), eye.at(x0, y) + (x1 - x0) * 4);
        monoplane::testing::write_png(
            source_dir() / "docs" / "images" / ("headset-page-" + std::string(page.name) + ".png"),
            x1 - x0, y1 - y0, crop);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Pages, HeadsetPageLanguage,
    ::testing::Values(Page{"de",
                           source_dir() / "protocols" / "fink2019-de.toml",
                           testing::kDejaVuSans,
                           {"Seite 1 von 3 - CONFIRM: weiter"}},
                      Page{"zh",
                           source_dir() / "tests" / "fixtures" / "text" / "demo-zh.toml",
                           testing::kWqyMicroHei,
                           {"\u6309 CONFIRM \u952e\u5f00\u59cb"}}),
    [](const ::testing::TestParamInfo<Page>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace monoplane
