// The protocol's `procedure` key and [staircase] table (issue 21): every value is read, the
// defaults hold, and each mistake is refused with file, line, column and key, as the rest of the
// protocol's are.
#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

#include "study/protocol.h"

namespace monoplane::study {
namespace {

// Line numbers matter: the malformed cases expect them ([staircase] is line 7).
constexpr std::string_view kQuest = R"(name = "threshold"
scenes = ["beams", "spheres"]
mono_planes = [1, 2, 4, 8, 16, 32]
alternatives = ["stereo", "hybrid"]
procedure = "staircase"

[staircase]
rule = "quest+"
trials_per_scene = 30
min_trials_per_scene = 12
stop_sd_log10 = 0.05
threshold_range = [0.5, 64]
threshold_steps = 25
slopes = [1, 3]
lapses = [0, 0.05]
)";

constexpr std::string_view kUpDown = R"(name = "updown"
scenes = ["beams"]
mono_planes = [1.6, 39.5]
alternatives = ["stereo", "hybrid"]
procedure = "staircase"

[staircase]
rule = "weighted-up-down"
trials_per_scene = 50
target = 0.8
step_log10 = 0.1
start_m = 4
skip_reversals = 4
)";

std::string replaced(std::string_view text, std::string_view from, std::string_view to) {
    std::string out(text);
    const std::size_t at = out.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) out.replace(at, from.size(), to);
    return out;
}

TEST(StaircaseProtocol, QuestPlusTableIsReadWithEveryValue) {
    const Result<Protocol> p = parse_protocol(kQuest, "t.toml");
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->procedure, Procedure::Staircase);
    const StaircaseSettings& s = p->staircase;
    EXPECT_EQ(s.rule, StaircaseRule::QuestPlus);
    EXPECT_EQ(s.trials_per_scene, 30);
    EXPECT_EQ(s.min_trials_per_scene, 12);
    EXPECT_EQ(s.stop_sd_log10, 0.05);
    ASSERT_TRUE(s.threshold_range);
    EXPECT_EQ((*s.threshold_range)[0], 0.5);
    EXPECT_EQ((*s.threshold_range)[1], 64.0);
    EXPECT_EQ(s.threshold_steps, 25);
    EXPECT_EQ(s.slopes, (std::vector<double>{1, 3}));
    EXPECT_EQ(s.lapses, (std::vector<double>{0, 0.05}));
    // Two scenes of at most 30 trials each.
    EXPECT_EQ(p->trials_per_session(), 60u);
}

TEST(StaircaseProtocol, UpDownTableIsReadWithEveryValue) {
    const Result<Protocol> p = parse_protocol(kUpDown, "t.toml");
    ASSERT_TRUE(p.ok()) << p.error().message;
    const StaircaseSettings& s = p->staircase;
    EXPECT_EQ(s.rule, StaircaseRule::WeightedUpDown);
    EXPECT_EQ(s.trials_per_scene, 50);
    EXPECT_EQ(s.target, 0.8);
    EXPECT_EQ(s.step_log10, 0.1);
    EXPECT_EQ(s.start_m, 4.0);
    EXPECT_EQ(s.skip_reversals, 4);
    EXPECT_FALSE(s.stop_sd_log10);
}

TEST(StaircaseProtocol, OmittedKeysTakeTheDocumentedDefaults) {
    const std::string text = replaced(kQuest, R"(min_trials_per_scene = 12
stop_sd_log10 = 0.05
threshold_range = [0.5, 64]
threshold_steps = 25
slopes = [1, 3]
lapses = [0, 0.05]
)",
                                      "");
    const Result<Protocol> p = parse_protocol(text, "t.toml");
    ASSERT_TRUE(p.ok()) << p.error().message;
    const StaircaseSettings& s = p->staircase;
    EXPECT_EQ(s.min_trials_per_scene, 10);
    EXPECT_FALSE(s.stop_sd_log10);
    EXPECT_FALSE(s.threshold_range);  // the ends of mono_planes
    EXPECT_EQ(s.threshold_steps, 40);
    EXPECT_EQ(s.slopes, (std::vector<double>{1, 2, 3, 4, 6, 8}));
    EXPECT_EQ(s.lapses, (std::vector<double>{0, 0.02, 0.04}));
    // Without the key the procedure is constant: every scene x distance once.
    const Result<Protocol> constant =
        parse_protocol(kQuest.substr(0, kQuest.find("procedure")), "c.toml");
    ASSERT_TRUE(constant.ok()) << constant.error().message;
    EXPECT_EQ(constant->procedure, Procedure::Constant);
    EXPECT_EQ(constant->trials_per_session(), 12u);
}

struct Malformed {
    std::string_view what;
    std::string_view base;
    std::string_view from;
    std::string_view to;
    std::vector<std::string_view> expected;  // each must occur in the message
};

class MalformedStaircase : public testing::TestWithParam<Malformed> {};

TEST_P(MalformedStaircase, IsRefusedNamingLineAndKey) {
    const Malformed& c = GetParam();
    const Result<Protocol> p = parse_protocol(replaced(c.base, c.from, c.to), "t.toml");
    ASSERT_FALSE(p.ok()) << c.what;
    for (std::string_view expected : c.expected) {
        EXPECT_NE(p.error().message.find(expected), std::string::npos)
            << c.what << ": expected \"" << expected << "\" in:\n"
            << p.error().message;
    }
}

const Malformed kCases[] = {
    {"misspelt procedure",
     kQuest,
     "\"staircase\"\n",
     "\"staircse\"\n",
     {"t.toml:5:13: key 'procedure': unknown value 'staircse'", "did you mean 'staircase'?"}},
    {"staircase without its table",
     kQuest,
     "[staircase]",
     "[render]\n[x]",
     {"t.toml:5:13: key 'procedure': 'staircase' needs a [staircase] table"}},
    {"table without the procedure",
     kQuest,
     "procedure = \"staircase\"",
     "",
     {"key 'staircase': applies to procedure = 'staircase', but the procedure is 'constant'"}},
    {"misspelt rule",
     kQuest,
     "\"quest+\"",
     "\"quest\"",
     {"t.toml:8:8: key 'staircase.rule': unknown value 'quest'", "did you mean 'quest+'?"}},
    {"missing rule",
     kQuest,
     "rule = \"quest+\"\n",
     "",
     {"t.toml:7:1: key 'staircase.rule': required key is missing"}},
    {"missing trial count",
     kQuest,
     "trials_per_scene = 30\n",
     "",
     {"key 'staircase.trials_per_scene': required key is missing"}},
    {"no trials",
     kQuest,
     "trials_per_scene = 30",
     "trials_per_scene = 0",
     {"t.toml:9:20: key 'staircase.trials_per_scene': 0 is outside the allowed range 1..1000"}},
    {"minimum above the maximum",
     kQuest,
     "min_trials_per_scene = 12",
     "min_trials_per_scene = 31",
     {"t.toml:10:24: key 'staircase.min_trials_per_scene': 31 exceeds trials_per_scene = 30"}},
    {"non-positive width",
     kQuest,
     "stop_sd_log10 = 0.05",
     "stop_sd_log10 = 0",
     {"t.toml:11:17: key 'staircase.stop_sd_log10': 0 is not > 0"}},
    {"range backwards",
     kQuest,
     "[0.5, 64]",
     "[64, 0.5]",
     {"t.toml:12:19: key 'staircase.threshold_range': must be two distances"}},
    {"one threshold",
     kQuest,
     "threshold_steps = 25",
     "threshold_steps = 1",
     {"t.toml:13:19: key 'staircase.threshold_steps': 1 is outside the allowed range 2..400"}},
    {"negative slope",
     kQuest,
     "slopes = [1, 3]",
     "slopes = [1, -3]",
     {"t.toml:14:14: key 'staircase.slopes element 2': -3 is not > 0"}},
    {"repeated slope",
     kQuest,
     "slopes = [1, 3]",
     "slopes = [3, 3]",
     {"t.toml:14:14: key 'staircase.slopes': duplicate value 3"}},
    {"lapse of one half",
     kQuest,
     "lapses = [0, 0.05]",
     "lapses = [0, 0.5]",
     {"t.toml:15:14: key 'staircase.lapses element 2': 0.5 is not in [0, 0.5)"}},
    {"a lapse as text",
     kQuest,
     "lapses = [0, 0.05]",
     "lapses = [0, \"low\"]",
     {"key 'staircase.lapses element 2': must be a number in [0, 0.5), but is a string"}},
    {"an up-down key under QUEST+",
     kQuest,
     "lapses = [0, 0.05]",
     "target = 0.75",
     {"t.toml:15:10: key 'staircase.target': applies to rule 'weighted-up-down', but the rule "
      "is 'quest+'"}},
    {"unknown key",
     kQuest,
     "lapses = [0, 0.05]",
     "lapse = [0, 0.05]",
     {"t.toml:15:1: key 'staircase.lapse': unknown key (did you mean 'staircase.lapses'?)"}},
    {"one distance",
     kQuest,
     "[1, 2, 4, 8, 16, 32]",
     "[8]",
     {"key 'procedure': a staircase needs at least two mono_planes"}},
    {"target at chance",
     kUpDown,
     "target = 0.8",
     "target = 0.5",
     {"t.toml:10:10: key 'staircase.target': 0.5 is not in (0.5, 1)"}},
    {"start outside the distances",
     kUpDown,
     "start_m = 4",
     "start_m = 50",
     {"t.toml:12:11: key 'staircase.start_m': 50 is not within the ends of mono_planes [1.6, "
      "39.5] m"}},
    {"zero step",
     kUpDown,
     "step_log10 = 0.1",
     "step_log10 = 0",
     {"t.toml:11:14: key 'staircase.step_log10': 0 is not in (0, 1]"}},
    {"a posterior width for up-down",
     kUpDown,
     "skip_reversals = 4",
     "stop_sd_log10 = 0.1",
     {"t.toml:13:17: key 'staircase.stop_sd_log10': needs a posterior"}},
    {"a QUEST+ key under up-down",
     kUpDown,
     "skip_reversals = 4",
     "slopes = [2]",
     {"t.toml:13:10: key 'staircase.slopes': applies to rule 'quest+'"}},
};

INSTANTIATE_TEST_SUITE_P(Cases, MalformedStaircase, testing::ValuesIn(kCases));

}  // namespace
}  // namespace monoplane::study
