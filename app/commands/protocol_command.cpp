// `monoplane protocol check FILE`: validates a study protocol before anyone
// sits down for a session, printing every problem with file, line and key, or, if it is valid, a
// summary of what a session will contain so the experimenter can check the design itself. Scene
// files (glTF) are loaded as a session would load them.
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <memory>
#include <string>

#include "app/commands/commands.h"
#include "app/commands/study_scenes.h"
#include "app/headset/response_device.h"
#include "common/result.h"
#include "study/protocol.h"

namespace monoplane::app {
namespace {

// Shortest round-trip text, as the protocol file would write it: "1.6", "39.5", "8".
std::string number(double value) {
    char buffer[32];
    const auto result = std::to_chars(std::begin(buffer), std::end(buffer), value);
    return std::string(buffer, result.ptr);
}

std::string hex(std::uint64_t value) {
    char buffer[17];
    std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(value));
    return buffer;
}

// The procedure's line: constant, or the staircase rule with its trials and stopping rule.
std::string procedure_summary(const study::Protocol& p) {
    if (p.procedure == study::Procedure::Constant) {
        return p.day.repetitions == 1 ? "constant (every scene x distance once)"
                                      : "constant (every scene x distance " +
                                            std::to_string(p.day.repetitions) + " times)";
    }
    const study::StaircaseSettings& s = p.staircase;
    std::string text = "staircase, " + std::string(study::staircase_rule_name(s.rule)) +
                       ", up to " + std::to_string(s.trials_per_scene) + " trials per scene";
    if (s.stop_sd_log10) {
        text += ", stopping at a posterior SD of log10 threshold <= " + number(*s.stop_sd_log10) +
                " after " + std::to_string(s.min_trials_per_scene);
    }
    return text;
}

// The study day: sessions, blocking, the participant's screens and variables.
void print_study_day(const study::Protocol& p) {
    const study::StudyDaySettings& d = p.day;
    std::cout << "  sessions:      " << d.sessions << " per participant"
              << (d.sessions > 1 ? " (the scene order rotates across them)" : "") << ", blocking "
              << study::blocking_name(d.blocking) << "\n";
    std::cout << "  screens:       " << d.instructions.size() << " instruction page(s)"
              << (d.ready ? ", a ready screen" : "") << (d.end ? ", an end screen" : "")
              << "; text " << number(d.text_height_deg) << " degrees high\n";
    std::cout << "  font:          " << d.font << "\n";  // [text] font, every character checked
    if (d.breaks) {
        std::cout << "  breaks:        ";
        if (d.breaks->every_trials > 0)
            std::cout << "every " << d.breaks->every_trials << " data trials";
        if (d.breaks->every_trials > 0 && d.breaks->between_blocks) std::cout << " and ";
        if (d.breaks->between_blocks) std::cout << "between scene blocks";
        std::cout << ", at least " << number(d.breaks->min_s) << " s\n";
    }
    for (const study::ParticipantVariable& v : d.variables) {
        std::cout << "  variable:      " << v.name << " (" << study::variable_type_name(v.type)
                  << (v.required ? ", required" : "") << ")"
                  << (v.help.empty() ? "" : ": " + v.help) << "\n";
    }
}

void print_summary(const study::Protocol& p) {
    std::string scenes;
    for (const std::string& scene : p.scenes) scenes += (scenes.empty() ? "" : ", ") + scene;
    std::string distances;
    for (double m : p.mono_planes) distances += (distances.empty() ? "" : ", ") + number(m);
    std::cout << "protocol '" << p.name << "' (" << p.source << ", hash " << hex(p.text_hash)
              << ") is valid\n"
              << "  scenes:        " << scenes << "\n"
              << "  mono planes:   " << distances << " m\n"
              << "  alternatives:  " << study::render_mode_name(p.alternatives[0])
              << " (reference) vs " << study::render_mode_name(p.alternatives[1]) << "\n"
              << "  procedure:     " << procedure_summary(p) << "\n"
              << "  trials:        " << (p.procedure == study::Procedure::Staircase ? "up to " : "")
              << p.trials_per_session() << " per session (" << p.scenes.size() << " scenes x "
              << (p.procedure == study::Procedure::Staircase
                      ? std::to_string(p.staircase.trials_per_scene) + " trials"
                      : std::to_string(p.mono_planes.size()) + " distances" +
                            (p.day.repetitions > 1
                                 ? " x " + std::to_string(p.day.repetitions) + " repetitions"
                                 : std::string()))
              << "), plus " << p.practice_trials << " practice\n"
              << "  order:         " << study::trial_order_name(p.order) << ", first scene "
              << study::first_scene_name(p.first_scene)
              << (p.require_both_viewed ? ", both alternatives must be viewed"
                                        : ", confirming without viewing both is allowed")
              << "\n"
              << "  clip range:    near " << number(p.near) << " m, far " << number(p.far) << " m\n"
              << "  questionnaire: " << p.questionnaire.items.size() << " items on a "
              << p.questionnaire.scale_points << "-point scale\n"
              << "  render:        anti-aliasing " << p.render.anti_aliasing << ", SSAO "
              << p.render.ssao << ", detail " << p.render.detail << "\n"
              << "  frame log:     trials flagged above "
              << number(100.0 * p.missed_frame_threshold) << " % missed frames\n";
    print_study_day(p);
}

// Who answers: the controller, and the [responses] keys. A device that cannot be read now is
// said here already (it may still be plugged in before the session, which refuses it otherwise).
void print_responses(const study::Protocol& p) {
    std::cout << "  answers:       controller"
              << (p.responses.enabled ? "; " + study::describe_responses(p.responses) : "") << "\n";
    if (!p.responses.enabled || p.responses.device.empty()) return;
    if (const auto device = headset::ResponseDevice::open(p.responses.device); !device) {
        std::cout << "  warning:       " << device.error().message << "\n";
    }
}

// What each imported scene holds and every file it was read from, digests as `sha256sum`
// prints them, so the experimenter can compare them with the files they meant to use.
void print_imported(const ImportedStudyScenes& imported) {
    for (const auto& [scene, entry] : imported) {
        std::cout << "  scene file:    " << scene << ": " << describe_size(entry.scene) << "\n";
        for (const study::SceneFileRecord& file : entry.files) {
            std::cout << "                 " << file.digest.sha256 << "  " << file.path.string()
                      << " (" << file.digest.size_bytes << " bytes)\n";
        }
    }
}

// Loads every scene file too: a broken one is reported now, not when a session begins.
void run_check(const std::string& file) {
    const study::Protocol protocol = study::load_protocol(file).value_or_throw();
    const ImportedStudyScenes imported =
        load_imported_scenes(protocol.scene_files, protocol.source).value_or_throw();
    print_summary(protocol);
    print_responses(protocol);
    std::cout << "  eye gaze:      " << study::describe_gaze(protocol.gaze) << "\n";
    print_imported(imported);
}

}  // namespace

void add_protocol_command(CLI::App& root, const GlobalOptions& /*global: no GPU involved*/) {
    CLI::App* cmd =
        root.add_subcommand("protocol", "Study protocol files (TOML; examples in protocols/)");
    cmd->require_subcommand(1);
    auto file = std::make_shared<std::string>();
    CLI::App* check = cmd->add_subcommand(
        "check", "Validate a protocol; print every problem with file, line and key, or a summary");
    check->add_option("FILE", *file, "Protocol TOML file, e.g. protocols/fink2019.toml")
        ->required();
    check->callback([file] { run_check(*file); });
}

}  // namespace monoplane::app
