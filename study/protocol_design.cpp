#include "study/protocol_design.h"

#include <sstream>

namespace monoplane::study {
namespace {

std::string text_of(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

std::string text_of(const std::vector<double>& values) {
    std::string text;
    for (double v : values) text += (text.empty() ? "" : ", ") + text_of(v);
    return text;
}

std::string text_of(const std::vector<std::string>& values) {
    std::string text;
    for (const std::string& v : values) text += (text.empty() ? "" : ", ") + v;
    return text;
}

std::string text_of(const std::array<RenderMode, 2>& modes) {
    return std::string(render_mode_name(modes[0])) + ", " + std::string(render_mode_name(modes[1]));
}

std::string text_of(const RenderSettings& r) {
    return r.anti_aliasing + "/" + r.ssao + "/" + r.detail;
}

// Collects "name: a -> b" for each field that differs.
class Differences {
  public:
    template <class T>
    void compare(const char* name, const T& a, const T& b, const std::string& a_text,
                 const std::string& b_text) {
        if (!(a == b)) lines_.push_back(std::string(name) + ": " + a_text + " -> " + b_text);
    }
    void compare(const char* name, int a, int b) {
        compare(name, a, b, std::to_string(a), std::to_string(b));
    }
    void compare(const char* name, double a, double b) {
        compare(name, a, b, text_of(a), text_of(b));
    }
    template <class T>
    void compare(const char* name, const T& a, const T& b) {
        compare(name, a, b, text_of(a), text_of(b));
    }
    std::vector<std::string> take() { return std::move(lines_); }

  private:
    std::vector<std::string> lines_;
};

}  // namespace

std::vector<std::string> design_differences(const Protocol& a, const Protocol& b) {
    Differences d;
    d.compare("scenes", a.scenes, b.scenes);
    d.compare("mono_planes", a.mono_planes, b.mono_planes);
    d.compare("alternatives", a.alternatives, b.alternatives);
    d.compare("procedure", a.procedure, b.procedure, std::string(procedure_name(a.procedure)),
              std::string(procedure_name(b.procedure)));
    if (a.procedure == Procedure::Staircase && b.procedure == Procedure::Staircase)
        d.compare("staircase", a.staircase, b.staircase, "one setting", "another");
    d.compare("order", a.order, b.order, std::string(trial_order_name(a.order)),
              std::string(trial_order_name(b.order)));
    d.compare("first_scene", a.first_scene, b.first_scene,
              std::string(first_scene_name(a.first_scene)),
              std::string(first_scene_name(b.first_scene)));
    d.compare("require_both_viewed", a.require_both_viewed, b.require_both_viewed,
              a.require_both_viewed ? "true" : "false", b.require_both_viewed ? "true" : "false");
    d.compare("practice_trials", a.practice_trials, b.practice_trials);
    d.compare("near", a.near, b.near);
    d.compare("far", a.far, b.far);
    d.compare("render", a.render, b.render);
    d.compare("auto", a.auto_plane, b.auto_plane, "one setting", "another");
    d.compare("sessions", a.day.sessions, b.day.sessions);
    d.compare("repetitions", a.day.repetitions, b.day.repetitions);
    d.compare("blocking", a.day.blocking, b.day.blocking,
              std::string(blocking_name(a.day.blocking)),
              std::string(blocking_name(b.day.blocking)));
    return d.take();
}

std::string describe_differences(const std::vector<std::string>& differences) {
    std::string text;
    for (const std::string& line : differences) text += (text.empty() ? "" : "; ") + line;
    return text;
}

}  // namespace monoplane::study
