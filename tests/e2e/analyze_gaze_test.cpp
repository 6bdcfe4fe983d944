// `monoplane analyze` on a headset session that recorded eye gaze (issue 45, part 4): one short
// session on simxr (one scene, m = 3 and 8, no practice, 5 frames a second) whose eyes rest 10
// degrees left of and 15 degrees above the head's view axis, the head still at the seat. The
// report gains its gaze section and the scene's gaze density figure, and summary.json its "gaze"
// object. Where the density peaks follows by hand: the gaze direction is
// (-sin 10 cos 15, sin 15, -cos 10 cos 15), so at infinity the seat's left eye sees it at
// tan_x = -tan 10 = -0.1763 and tan_y = tan 15 / cos 10 = 0.2721; a gaze point at depth z moves
// tan_x right by at most 0.032 / z, within the one and a half bins (0.062) allowed here for
// z > 0.6 m.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/e2e/test_files.h"

namespace monoplane {
namespace {

namespace fs = std::filesystem;

int run(const std::string& command, std::string* output) {
    const std::string log = (test_folder() / "command.log").string();
    const int status = std::system((command + " > " + log + " 2>&1").c_str());
    *output = read_file(log);
    return WEXITSTATUS(status);
}

TEST(AnalyzeGaze, TheReportShowsWhereTheParticipantLooked) {
    const fs::path dir = test_folder();
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "gaze.toml")
        << "name = \"gaze-report\"\nscenes = [\"spheres\"]\nmono_planes = [3, 8]\n"
           "alternatives = [\"stereo\", \"hybrid\"]\npractice_trials = 0\n"
           "[gaze]\nrecord = true\n";
    std::ofstream(dir / "script.toml")
        << "hmd = \"vive\"\ndisplay_rate_hz = 5\n[gaze]\nblink_every_s = 1000\n"
           "[[fixation]]\nt = 0\nduration = 1000\nyaw_pitch_deg = [10, 15]\n";
    const std::string db = (dir / "gaze.sqlite").string();
    std::string output;
    ASSERT_EQ(run(std::string(MONOPLANE_EXE) + " study run --protocol " +
                      (dir / "gaze.toml").string() + " --participant G --db " + db +
                      " --headset simulated --observer default --sim-script " +
                      (dir / "script.toml").string() +
                      " --window off --detail test --resolution-scale 0.1 --seed 5",
                  &output),
              0)
        << output;
    const fs::path out = dir / "report";
    ASSERT_EQ(
        run(std::string(MONOPLANE_EXE) + " analyze --db " + db + " --out " + out.string(), &output),
        0)
        << output;

    const std::string html = read_file(out / "report.html");
    EXPECT_NE(html.find("<h2 id=\"gaze\">Where participants looked</h2>"), std::string::npos);
    EXPECT_NE(html.find("id=\"figure-gaze_density_spheres\""), std::string::npos);
    // Two trials from one participant: the regression says why it has no estimate.
    EXPECT_NE(html.find("<b>Not estimable</b> on these data: logistic regression: 2 analysable "
                        "trials with a gaze error are too few for 2 coefficients"),
              std::string::npos);
    EXPECT_TRUE(fs::is_regular_file(out / "figures" / "gaze_density_spheres.svg"));
    EXPECT_TRUE(fs::is_regular_file(out / "figures" / "gaze_density_spheres.png"));

    const nlohmann::json summary = nlohmann::json::parse(read_file(out / "summary.json"));
    ASSERT_TRUE(summary.contains("logistic"));  // the existing keys stay
    const nlohmann::json& gaze = summary.at("gaze");
    EXPECT_TRUE(gaze.at("recorded").get<bool>());
    EXPECT_EQ(gaze.at("trials_with_gaze").get<int>(), 2);
    EXPECT_GT(gaze.at("samples").get<int>(), 10);
    ASSERT_EQ(gaze.at("by_scene").size(), 1u);
    EXPECT_EQ(gaze.at("by_scene")[0].at("scene"), "spheres");
    EXPECT_FALSE(gaze.at("regression").at("estimable").get<bool>());
    ASSERT_EQ(gaze.at("densities").size(), 1u);
    const nlohmann::json& density = gaze.at("densities")[0];
    EXPECT_EQ(density.at("inside").get<int>(), density.at("samples").get<int>());
    const double bin = 2.639346 / 64.0;  // the Vive's left eye across 64 bins
    EXPECT_NEAR(density.at("peak_tan_x").get<double>(), -std::tan(10.0 * M_PI / 180.0), 1.5 * bin);
    EXPECT_NEAR(density.at("peak_tan_y").get<double>(),
                std::tan(15.0 * M_PI / 180.0) / std::cos(10.0 * M_PI / 180.0), 1.5 * bin);
    // lavapipe is on every test machine: the scene is rendered under the density.
    EXPECT_TRUE(density.at("scene_picture").get<bool>()) << output;
    EXPECT_NE(read_file(out / "figures" / "gaze_density_spheres.svg")
                  .find("href=\"data:image/png;base64,"),
              std::string::npos);
}

}  // namespace
}  // namespace monoplane
