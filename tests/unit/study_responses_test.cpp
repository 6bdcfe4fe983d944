// Answers from a keyboard or response box: the key names, the protocol's [responses] table, the
// --keys and --response-device options, and the presses the session logs with their source.
#include <linux/input-event-codes.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "study/export.h"
#include "study/live_session.h"
#include "study/protocol.h"
#include "study/response_keys.h"
#include "study/schedule.h"
#include "study/study_store.h"

namespace monoplane::study {
namespace {

constexpr std::string_view kBase = R"(name = "keys"
scenes = ["spheres"]
mono_planes = [3]
alternatives = ["stereo", "hybrid"]
practice_trials = 0
)";

Result<Protocol> parse(const std::string& responses) {
    return parse_protocol(std::string(kBase) + responses, "keys.toml");
}

std::string problems(const std::string& responses) {
    const Result<Protocol> protocol = parse(responses);
    return protocol ? std::string() : protocol.error().message;
}

TEST(ResponseKeys, NamesMapToTheEvdevCodesOfTheirKeys) {
    EXPECT_EQ(find_response_key("Left")->evdev_code, KEY_LEFT);
    EXPECT_EQ(find_response_key("Right")->evdev_code, KEY_RIGHT);
    EXPECT_EQ(find_response_key("Return")->evdev_code, KEY_ENTER);
    EXPECT_EQ(find_response_key("KP_Enter")->evdev_code, KEY_KPENTER);
    EXPECT_EQ(find_response_key("space")->evdev_code, KEY_SPACE);
    EXPECT_EQ(find_response_key("a")->evdev_code, KEY_A);
    EXPECT_EQ(find_response_key("z")->evdev_code, KEY_Z);
    EXPECT_EQ(find_response_key("0")->evdev_code, KEY_0);
    EXPECT_EQ(find_response_key("KP_7")->evdev_code, KEY_KP7);
    EXPECT_EQ(find_response_key("F12")->evdev_code, KEY_F12);
    EXPECT_EQ(response_key_name(KEY_ENTER), "Return");
    EXPECT_EQ(response_key_name(KEY_B), "b");
    EXPECT_FALSE(response_key_name(KEY_ESC));  // the window's text fields keep Escape
    EXPECT_FALSE(find_response_key("Escape"));
    EXPECT_FALSE(find_response_key("return"));  // X names are case-sensitive
}

TEST(ResponseKeys, NamesAndCodesAreEachUsedOnce) {
    for (const ResponseKey& a : response_keys()) {
        int names = 0, codes = 0;
        for (const ResponseKey& b : response_keys()) {
            names += a.name == b.name;
            codes += a.evdev_code == b.evdev_code;
        }
        EXPECT_EQ(names, 1) << a.name;
        EXPECT_EQ(codes, 1) << a.name;
    }
}

TEST(ResponseKeys, AMisspeltNameSuggestsTheKey) {
    EXPECT_EQ(closest_response_key("return"), "Return");
    EXPECT_EQ(closest_response_key("LEFT"), "Left");
    EXPECT_EQ(closest_response_key("Retrun"), "Return");
    EXPECT_EQ(closest_response_key("Enter"), "");  // nothing near: no guess
}

// [gaze] (study/protocol_gaze.h): off unless asked; a wrong value or key is named.
TEST(ProtocolGaze, GazeIsRecordedOnlyWhenTheProtocolAsks) {
    const Result<Protocol> without = parse("");
    ASSERT_TRUE(without.ok()) << without.error().message;
    EXPECT_FALSE(without->gaze.record);
    EXPECT_EQ(describe_gaze(without->gaze), "not recorded");
    const Result<Protocol> with = parse("[gaze]\nrecord = true\n");
    ASSERT_TRUE(with.ok()) << with.error().message;
    EXPECT_TRUE(with->gaze.record);
    EXPECT_NE(describe_gaze(with->gaze).find("XR_EXT_eye_gaze_interaction"), std::string::npos);
    const std::string wrong = problems("[gaze]\nrecord = \"yes\"\neyes = 2\n");
    EXPECT_NE(wrong.find("gaze.record"), std::string::npos) << wrong;
    EXPECT_NE(wrong.find("a boolean"), std::string::npos) << wrong;
    EXPECT_NE(wrong.find("gaze.eyes"), std::string::npos) << wrong;
    EXPECT_NE(problems("gaze = true\n").find("a table"), std::string::npos);
}

TEST(ProtocolResponses, WithoutTheTableNoKeysAnswer) {
    const Result<Protocol> protocol = parse("");
    ASSERT_TRUE(protocol) << protocol.error().message;
    EXPECT_FALSE(protocol->responses.enabled);
}

TEST(ProtocolResponses, TheTableAloneEnablesTheDefaultKeys) {
    const Result<Protocol> protocol = parse("[responses]\n");
    ASSERT_TRUE(protocol) << protocol.error().message;
    EXPECT_TRUE(protocol->responses.enabled);
    EXPECT_EQ(protocol->responses.switch_keys, (std::vector<std::string>{"Left", "Right"}));
    EXPECT_EQ(protocol->responses.confirm_keys, (std::vector<std::string>{"Return"}));
    EXPECT_EQ(protocol->responses.device, "");
}

TEST(ProtocolResponses, KeysAndDeviceAsWritten) {
    const Result<Protocol> protocol = parse(
        "[responses]\nkeys = { switch = [\"a\", \"b\"], confirm = \"KP_Enter\" }\n"
        "device = \"/dev/input/by-id/usb-box-event-kbd\"\n");
    ASSERT_TRUE(protocol) << protocol.error().message;
    EXPECT_EQ(protocol->responses.switch_keys, (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(protocol->responses.confirm_keys, (std::vector<std::string>{"KP_Enter"}));
    EXPECT_EQ(protocol->responses.device, "/dev/input/by-id/usb-box-event-kbd");
    EXPECT_EQ(protocol->responses.action_of("b"), ResponseAction::Switch);
    EXPECT_EQ(protocol->responses.action_of("KP_Enter"), ResponseAction::Confirm);
    EXPECT_EQ(protocol->responses.action_of("Left"), std::nullopt);
}

TEST(ProtocolResponses, AnActionLeftOutKeepsItsDefault) {
    const Result<Protocol> protocol = parse("[responses]\nkeys = { confirm = \"c\" }\n");
    ASSERT_TRUE(protocol) << protocol.error().message;
    EXPECT_EQ(protocol->responses.switch_keys, (std::vector<std::string>{"Left", "Right"}));
    EXPECT_EQ(protocol->responses.confirm_keys, (std::vector<std::string>{"c"}));
}

TEST(ProtocolResponses, AnUnknownKeyNameIsRefusedWithASuggestion) {
    const std::string error = problems("[responses]\nkeys = { switch = \"left\" }\n");
    EXPECT_NE(error.find("keys.toml:7:8: key 'responses.keys': 'left' is no key name monoplane "
                         "knows (did you mean 'Left'?)"),
              std::string::npos)
        << error;
}

TEST(ProtocolResponses, OneKeyForBothActionsIsRefused) {
    const std::string error =
        problems("[responses]\nkeys = { switch = \"a\", confirm = [\"b\", \"a\"] }\n");
    EXPECT_NE(error.find("'a' both switches and confirms; give each action its own key"),
              std::string::npos)
        << error;
}

TEST(ProtocolResponses, AKeyTheWindowKeepsForAnotherCommandIsRefused) {
    // p pauses; Return confirms and space switches in the window: they may not do otherwise.
    EXPECT_NE(problems("[responses]\nkeys = { switch = \"p\" }\n")
                  .find("'p' is the experimenter window's pause/resume key and cannot also "
                        "switch; choose another key, or read the keys from a device"),
              std::string::npos);
    EXPECT_NE(problems("[responses]\nkeys = { switch = \"Return\", confirm = \"a\" }\n")
                  .find("'Return' is the experimenter window's confirm key and cannot also "
                        "switch"),
              std::string::npos);
    EXPECT_NE(problems("[responses]\nkeys = { confirm = \"space\", switch = \"a\" }\n")
                  .find("'space' is the experimenter window's switch key"),
              std::string::npos);
    // Doing what the window's command does is no clash; from a device nothing is the window's.
    EXPECT_EQ(problems("[responses]\nkeys = { switch = \"space\", confirm = \"KP_Enter\" }\n"), "");
    EXPECT_EQ(problems("[responses]\nkeys = { switch = \"p\", confirm = \"space\" }\n"
                       "device = \"/dev/input/event3\"\n"),
              "");
}

TEST(ProtocolResponses, WrongTypesAndKeysAreLocated) {
    EXPECT_NE(problems("[responses]\nkeys = \"Left\"\n")
                  .find("keys.toml:7:8: key 'responses.keys': must be a table such as"),
              std::string::npos)
        << problems("[responses]\nkeys = \"Left\"\n");
    EXPECT_NE(problems("[responses]\nkeys = { switch = [] }\n")
                  .find("key 'responses.keys.switch': must name at least one key"),
              std::string::npos);
    EXPECT_NE(problems("[responses]\nkeys = { swich = \"a\" }\n")
                  .find("keys.toml:7:10: key 'responses.keys.swich': unknown key (did you mean "
                        "'responses.keys.switch'?)"),
              std::string::npos)
        << problems("[responses]\nkeys = { swich = \"a\" }\n");
    EXPECT_NE(problems("[responses]\ndevice = \"event3\"\n")
                  .find("key 'responses.device': must be an absolute path"),
              std::string::npos);
    EXPECT_NE(problems("[responses]\nkey = 1\n")
                  .find("key 'responses.key': unknown key (did you mean 'responses.keys'?)"),
              std::string::npos)
        << problems("[responses]\nkey = 1\n");
}

TEST(KeysOption, DefaultNoneAndActionKeyPairs) {
    const ResponseSettings protocol;  // no [responses]
    EXPECT_EQ(*parse_keys_option("default", protocol), default_responses());
    EXPECT_FALSE(parse_keys_option("none", default_responses())->enabled);
    const Result<ResponseSettings> keys =
        parse_keys_option("switch=Left,switch=Up,confirm=KP_Enter", protocol);
    ASSERT_TRUE(keys) << keys.error().message;
    EXPECT_EQ(keys->switch_keys, (std::vector<std::string>{"Left", "Up"}));
    EXPECT_EQ(keys->confirm_keys, (std::vector<std::string>{"KP_Enter"}));
    // An action not named keeps its default keys; the protocol's device stays.
    ResponseSettings with_device = default_responses();
    with_device.device = "/dev/input/event3";
    const Result<ResponseSettings> confirm = parse_keys_option("confirm=c", with_device);
    ASSERT_TRUE(confirm) << confirm.error().message;
    EXPECT_EQ(confirm->switch_keys, (std::vector<std::string>{"Left", "Right"}));
    EXPECT_EQ(confirm->device, "/dev/input/event3");
}

TEST(KeysOption, MistakesNameTheOption) {
    EXPECT_EQ(parse_keys_option("switch:Left", {}).error().message,
              "--keys switch:Left: 'switch:Left' is not ACTION=KEY; write e.g. --keys "
              "switch=Left,confirm=Return, --keys default or --keys none");
    EXPECT_EQ(parse_keys_option("switch=Left,confirm=Left", {}).error().message,
              "--keys switch=Left,confirm=Left: 'Left' both switches and confirms; give each "
              "action its own key");
    EXPECT_NE(parse_keys_option("confirm=p", {}).error().message.find("pause/resume key"),
              std::string::npos);
    EXPECT_NE(parse_keys_option("confirm=Enter", {}).error().message.find("'Enter' is no key"),
              std::string::npos);
}

TEST(ResponseDeviceOption, EnablesTheKeysAndNeedsAnAbsolutePath) {
    const Result<ResponseSettings> device = with_response_device("/dev/input/event7", {});
    ASSERT_TRUE(device) << device.error().message;
    EXPECT_TRUE(device->enabled);
    EXPECT_EQ(device->switch_keys, (std::vector<std::string>{"Left", "Right"}));
    EXPECT_EQ(device->device, "/dev/input/event7");
    EXPECT_NE(with_response_device("event7", {}).error().message.find("absolute path"),
              std::string::npos);
    EXPECT_EQ(describe_responses(*device),
              "keys Left, Right switch; Return confirm (device /dev/input/event7)");
    EXPECT_EQ(describe_responses({}), "no keys");
}

// The store logs each press with its source, key, screen and trial, durable at once.
TEST(ResponsePresses, TheStoreKeepsEachPressWithItsSource) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "monoplane_study_responses_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::filesystem::path db = dir / "presses.sqlite";
    const Result<Protocol> protocol = parse("[responses]\n");
    ASSERT_TRUE(protocol) << protocol.error().message;
    auto store = StudyStore::open(db);
    ASSERT_TRUE(store) << store.error().message;
    SessionInfo info;
    info.participant_code = "P1";
    info.protocol_name = protocol->name;
    info.protocol_hash = protocol->text_hash;
    info.protocol_text = protocol->text;
    info.seed = 3;
    info.software_version = "test";
    info.hmd = "vive";
    info.runtime = "simulated";
    info.device = "test";
    const Result<std::int64_t> id_or =
        (*store)->begin_session(info, make_schedule(*protocol, 3, 0));
    ASSERT_TRUE(id_or) << id_or.error().message;
    const std::int64_t id = *id_or;
    LiveOptions options;
    options.neutral_ns = 1'000'000'000;
    auto live = LiveSession::open(**store, id, *protocol, options);
    ASSERT_TRUE(live) << live.error().message;
    ASSERT_TRUE((*live)->record_press(PressSource::Keyboard, PressAction::Switch, "Left", 100));
    ASSERT_TRUE((*live)->frame_presented(0, 1'000));          // the neutral screen starts
    ASSERT_TRUE((*live)->frame_presented(1, 1'100'000'000));  // its second is over: the trial
    ASSERT_TRUE((*live)->frame_presented(2, 1'200'000'000));  // shows
    ASSERT_TRUE((*live)->record_press(PressSource::Device, PressAction::Confirm, "Return", 2200));
    ASSERT_TRUE((*live)->record_press(PressSource::Controller, PressAction::Pause, "", 2300));
    EXPECT_FALSE((*live)->record_press(PressSource::Controller, PressAction::Switch, "a", 2400));
    EXPECT_FALSE((*live)->record_press(PressSource::Keyboard, PressAction::Switch, "", 2400));
    const auto presses = (*store)->presses(id);
    ASSERT_TRUE(presses) << presses.error().message;
    ASSERT_EQ(presses->size(), 3u);
    EXPECT_EQ((*presses)[0].source, PressSource::Keyboard);
    EXPECT_EQ((*presses)[0].key, "Left");
    EXPECT_EQ((*presses)[0].screen, "neutral");
    EXPECT_EQ((*presses)[0].trial_index, -1);
    EXPECT_EQ((*presses)[0].time_ns, 100);
    EXPECT_EQ((*presses)[1].source, PressSource::Device);
    EXPECT_EQ((*presses)[1].action, PressAction::Confirm);
    EXPECT_EQ((*presses)[1].screen, "trial");
    EXPECT_EQ((*presses)[1].trial_index, 0);
    EXPECT_EQ((*presses)[2].source, PressSource::Controller);
    EXPECT_EQ((*presses)[2].action, PressAction::Pause);
    EXPECT_EQ((*presses)[2].key, "");
}

TEST(PressesExport, OneRowPerPressWithItsSource) {
    EXPECT_EQ(*parse_export_format("presses-csv"), ExportFormat::PressesCsv);
    EXPECT_EQ(export_format_name(ExportFormat::PressesCsv), "presses-csv");
    EXPECT_NE(parse_export_format("press").error().message.find("presses-csv"), std::string::npos);
    ExportData data;
    SessionInfo info;
    info.participant_code = "P7";
    info.session_number = 2;
    data.sessions.emplace(4, info);
    data.presses[4] = {{PressSource::Controller, PressAction::Switch, "", "neutral", -1, 5},
                       {PressSource::Keyboard, PressAction::Confirm, "Return", "trial", 3, 70},
                       {PressSource::Device, PressAction::Switch, "Left", "trial", 3, 90}};
    std::ostringstream out;
    write_presses_csv(data, out);
    EXPECT_EQ(out.str(),
              "participant,session,trial,screen,source,action,key,time_ns\n"
              "P7,2,NA,neutral,controller,switch,NA,5\n"
              "P7,2,3,trial,keyboard,confirm,Return,70\n"
              "P7,2,3,trial,device,switch,Left,90\n");
    // An earlier presses export is recognised by its header.
    EXPECT_TRUE(
        export_output_kind(ExportFormat::PressesCsv)
            .is_earlier_output("participant,session,trial,screen,source,action,key,time_ns\n"));
}

}  // namespace
}  // namespace monoplane::study
