// `monoplane study probe` (docs/lab.md, "Session settings") end to end: the executable probes a
// protocol it is given, with validation on, and prints each preset's options, eye size, estimate,
// conditions and verdict as JSON; presets are compared by fragment counts, never by time.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/e2e/child_process.h"
#include "tests/e2e/test_files.h"

namespace monoplane {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// One scene at the smallest detail: the whole probe takes a second or two on llvmpipe.
fs::path write_protocol() {
    const fs::path dir = test_folder();
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path file = dir / "probe.toml";
    std::ofstream(file) << R"(name = "probe"
scenes = ["spheres"]
mono_planes = [3, 8]
alternatives = ["stereo", "hybrid"]
[render]
anti_aliasing = "taa"
detail = "test"
)";
    return file;
}

TEST(StudyProbeCli, PrintsEachPresetsEstimateAndVerdict) {
    const fs::path protocol = write_protocol();
    std::string out;
    // 128 x 144: the Vive's aspect; a budget that lets every condition complete.
    const int status =
        run_to_end({MONOPLANE_EXE, "--validation", "study", "probe", "--protocol",
                    protocol.string(), "--width", "128", "--height", "144", "--preset", "minimal",
                    "--preset", "fast", "--budget-s", "600", "--refresh-hz", "90"},
                   &out);
    ASSERT_EQ(status, 0) << out;
    const json j = json::parse(out);
    EXPECT_EQ(j["recommended_width"], 128);
    EXPECT_FALSE(j["device"].get<std::string>().empty());
    const json& presets = j["presets"];
    ASSERT_EQ(presets.size(), 2u);
    const json& minimal = presets[0];
    const json& fast = presets[1];
    EXPECT_EQ(minimal["name"], "minimal");
    EXPECT_EQ(fast["name"], "fast");
    // The protocol's detail is "test" already: minimal only scales the eyes, to 32 x 36.
    EXPECT_EQ(minimal["study_run_arguments"], json({"--resolution-scale", "0.25"}));
    EXPECT_EQ(minimal["eye_width"], 32);
    EXPECT_EQ(minimal["eye_height"], 36);
    EXPECT_EQ(fast["study_run_arguments"], json({"--resolution-scale", "0.5"}));
    EXPECT_EQ(fast["eye_width"], 64);
    EXPECT_EQ(fast["anti_aliasing"], "taa");
    for (const json& p : presets) {
        SCOPED_TRACE(p["name"].get<std::string>());
        EXPECT_GT(p["frame_ms"].get<double>(), 0.0);
        EXPECT_TRUE(p["complete"].get<bool>());
        ASSERT_EQ(p["conditions"].size(), 2u);
        EXPECT_EQ(p["conditions"][0]["mono_plane"], 3.0);
        EXPECT_EQ(p["conditions"][0]["frames"], 3);
        // The verdict is worded against 90 Hz's 11.1 ms, whichever way it goes.
        const std::string text = p["verdict"]["text"];
        EXPECT_NE(text.find("90 Hz: about "), std::string::npos) << text;
        EXPECT_NEAR(p["verdict"]["ratio"].get<double>(),
                    p["frame_ms"].get<double>() / (1000.0 / 90), 1e-6);
    }
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_LT(minimal["conditions"][i]["fragments"].get<std::uint64_t>(),
                  fast["conditions"][i]["fragments"].get<std::uint64_t>());
    }
}

TEST(StudyProbeCli, RefusesAnUnknownPreset) {
    const fs::path protocol = write_protocol();
    std::string out;
    const int status = run_to_end(
        {MONOPLANE_EXE, "study", "probe", "--protocol", protocol.string(), "--preset", "ultra"},
        &out, test_folder().string());
    EXPECT_NE(status, 0);
    EXPECT_NE(out.find("ultra"), std::string::npos) << out;
}

}  // namespace
}  // namespace monoplane
