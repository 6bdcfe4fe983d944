// The report where researchers read it (issue 21, item 7): `monoplane analyze` on a small CSV
// export (tests/fixtures/analysis/psychometric.csv: 4 participants, 2 scenes, 640 trials), then
// report.html in Debian's headless Chromium, one run that writes a screenshot of the whole page
// and dumps the DOM it built, with the browser's log on stderr. Checked: the page logs no console
// message (it has no scripts; a message means something broke), the DOM holds every figure as an
// <svg> with drawn lines, the psychometric figures among them, and the screenshot is not blank:
// enough ink, many colours, and the psychometric figures' green group curves and threshold marks
// (#009E73, used by no other figure of a two-scene report) in two separate places, one per scene.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <stb/stb_image.h>

namespace monoplane {
namespace {

namespace fs = std::filesystem;

const fs::path kFolder = fs::temp_directory_path() / "monoplane_e2e_report_browser";
// Wide enough for the report's 1000-pixel column, tall enough for the whole page (about 7500
// pixels for this fixture).
constexpr int kWidth = 1100, kHeight = 9000;

std::string read(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Runs `command` with stdout and stderr to files in kFolder; returns the exit status.
int run(const std::string& command, const std::string& name) {
    const std::string redirect = " > " + (kFolder / (name + ".out")).string() + " 2> " +
                                 (kFolder / (name + ".err")).string();
    const int status = std::system((command + redirect).c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

struct Screenshot {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
    const unsigned char* at(int x, int y) const { return &rgb[(std::size_t(y) * width + x) * 3]; }
};

Screenshot load(const fs::path& path) {
    Screenshot s;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &s.width, &s.height, &channels, 3);
    if (data) {
        s.rgb.assign(data, data + std::size_t(s.width) * s.height * 3);
        stbi_image_free(data);
    }
    return s;
}

bool near_colour(const unsigned char* p, int r, int g, int b, int tolerance) {
    return std::abs(p[0] - r) <= tolerance && std::abs(p[1] - g) <= tolerance &&
           std::abs(p[2] - b) <= tolerance;
}

void expect_no_console_message() {
    // Chromium's own complaints (no D-Bus in a container, no GPU) are not the page's; console
    // messages are logged as "...:CONSOLE:<line>] ...".
    std::istringstream log(read(kFolder / "chromium.err"));
    for (std::string line; std::getline(log, line);) {
        EXPECT_EQ(line.find(":CONSOLE"), std::string::npos) << line;
    }
}

void expect_every_figure_in_the_dom() {
    const std::string dom = read(kFolder / "chromium.out");
    ASSERT_NE(dom.find("<h1>monoplane study analysis</h1>"), std::string::npos)
        << dom.substr(0, 500);
    // choices, the two psychometric figures, decision times, switches.
    for (const char* id :
         {"choices", "psychometric_beams", "psychometric_spheres", "decision_times", "switches"}) {
        const auto at = dom.find("<figure id=\"figure-" + std::string(id) + "\">");
        ASSERT_NE(at, std::string::npos) << id;
        const std::string figure = dom.substr(at, dom.find("</figure>", at) - at);
        EXPECT_NE(figure.find("<svg"), std::string::npos) << id;
        EXPECT_NE(figure.find("</svg>"), std::string::npos) << id;
        if (std::string(id).rfind("psychometric", 0) == 0) {
            // The group's curve and threshold marks, and the participants' curves.
            EXPECT_NE(figure.find("stroke=\"#009E73\""), std::string::npos) << id;
            EXPECT_NE(figure.find("stroke=\"#B8B8B8\""), std::string::npos) << id;
        }
    }
    std::size_t svgs = 0;
    for (auto at = dom.find("<svg"); at != std::string::npos; at = dom.find("<svg", at + 1)) ++svgs;
    EXPECT_EQ(svgs, 5u);
}

void expect_figures_in_the_screenshot() {
    const Screenshot s = load(kFolder / "page.png");
    ASSERT_EQ(s.width, kWidth);
    ASSERT_EQ(s.height, kHeight);
    std::size_t ink = 0;
    std::set<int> colours;
    std::vector<int> green_rows;  // rows holding the psychometric figures' green
    for (int y = 0; y < s.height; ++y) {
        int green = 0;
        for (int x = 0; x < s.width; ++x) {
            const unsigned char* p = s.at(x, y);
            if (p[0] < 245 || p[1] < 245 || p[2] < 245) ++ink;
            colours.insert(p[0] << 16 | p[1] << 8 | p[2]);
            green += near_colour(p, 0x00, 0x9E, 0x73, 24) ? 1 : 0;
        }
        if (green > 0) green_rows.push_back(y);
    }
    // Text, tables and five figures: a few percent of the page is ink, in many colours.
    EXPECT_GT(double(ink) / (double(s.width) * s.height), 0.02);
    EXPECT_GT(colours.size(), 200u);
    // Two clusters of green rows (BEAMS, SPHERES), each about a figure's plot high.
    ASSERT_FALSE(green_rows.empty());
    std::vector<std::pair<int, int>> clusters{{green_rows.front(), green_rows.front()}};
    for (int y : green_rows) {
        if (y - clusters.back().second > 60) clusters.push_back({y, y});
        clusters.back().second = y;
    }
    ASSERT_EQ(clusters.size(), 2u);
    for (const auto& [top, bottom] : clusters) {
        EXPECT_GT(bottom - top, 100) << "green from row " << top << " to " << bottom;
        EXPECT_LT(bottom - top, 460) << "green from row " << top << " to " << bottom;
    }
}

// One test, so ctest (one process per test) runs analyze and Chromium once.
TEST(ReportInBrowser, ShowsEveryFigureAndLogsNoError) {
    fs::remove_all(kFolder);
    fs::create_directories(kFolder / "profile");
    const char* source = std::getenv("MONOPLANE_SOURCE_DIR");
    ASSERT_NE(source, nullptr);
    ASSERT_EQ(
        run(std::string(MONOPLANE_EXE) + " analyze --csv " + source +
                "/tests/fixtures/analysis/psychometric.csv --out " + (kFolder / "report").string(),
            "analyze"),
        0)
        << read(kFolder / "analyze.err");
    // Flags: no sandbox (ctest may run as root), no GPU, nothing from the network, a fresh
    // profile; the log on stderr carries the page's console messages.
    const std::string chromium =
        "timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic "
        "--no-first-run --disable-background-networking --disable-component-update "
        "--disable-sync --user-data-dir=" +
        (kFolder / "profile").string() +
        " --enable-logging=stderr --v=0 --window-size=" + std::to_string(kWidth) + "," +
        std::to_string(kHeight) +
        " --hide-scrollbars --screenshot=" + (kFolder / "page.png").string() +
        " --dump-dom file://" + (kFolder / "report" / "report.html").string();
    ASSERT_EQ(run(chromium, "chromium"), 0) << read(kFolder / "chromium.err");
    {
        SCOPED_TRACE("console");
        expect_no_console_message();
    }
    {
        SCOPED_TRACE("DOM");
        expect_every_figure_in_the_dom();
    }
    {
        SCOPED_TRACE("screenshot");
        expect_figures_in_the_screenshot();
    }
    fs::remove_all(kFolder / "profile");
}

}  // namespace
}  // namespace monoplane
