#include "analysis/report/psychometric_section.h"

#include <cmath>

#include "analysis/report/html_format.h"
#include "analysis/report/text_output.h"
#include "charts/svg_writer.h"

namespace monoplane::analysis::report {
namespace {

using charts::xml_escaped;

// A threshold interval for people: "[4.40, 9.30]", with "&lt; 1.6" / "&gt; 39.5" for an end the
// data do not bound.
std::string interval_text(const PsychometricFit& f) {
    const std::string lower = f.threshold_lower ? fixed(*f.threshold_lower, 2)
                                                : "&lt;&nbsp;" + metres(f.levels.front().m);
    const std::string upper =
        f.threshold_upper ? fixed(*f.threshold_upper, 2) : "&gt;&nbsp;" + metres(f.levels.back().m);
    return "[" + lower + ", " + upper + "]";
}

std::string method_text(const PsychometricFit& f) {
    if (f.interval_method == "participant bootstrap") {
        return "bootstrap over participants (" + std::to_string(f.bootstrap_replicates) + ")";
    }
    return xml_escaped(f.interval_method);
}

Table fits_table(const std::vector<PsychometricFit>& fits) {
    Table t;
    t.header = {
        "participant", "scene", "trials",         "threshold T (m)", "95&nbsp;% interval (m)",
        "slope B",     "lapse", "interval / note"};
    t.numeric = {false, false, true, true, true, true, true, false};
    for (const PsychometricFit& f : fits) {
        const std::string who = f.participant == "all"
                                    ? "<b>all (" + std::to_string(f.participants) + ")</b>"
                                    : xml_escaped(f.participant);
        if (!f.estimable) {
            t.rows.push_back({who, scene_name(f.scene), std::to_string(f.n), "&ndash;", "&ndash;",
                              "&ndash;", "&ndash;", "not estimable: " + xml_escaped(f.reason)});
            continue;
        }
        t.rows.push_back({who, scene_name(f.scene), std::to_string(f.n),
                          fixed(f.parameters.threshold, 2), interval_text(f),
                          fixed(f.parameters.slope, 2), fixed(f.parameters.lapse, 3),
                          method_text(f)});
    }
    return t;
}

double or_nan(const std::optional<double>& value) {
    return value.value_or(NAN);
}

}  // namespace

std::string psychometric_section_html(const AnalysisResults& r,
                                      const std::vector<Figure>& figures) {
    const std::string reference = xml_escaped(r.reference_mode);
    std::string h = "<h2 id=\"psychometric\">Psychometric functions: the threshold</h2>\n";
    h += "<p>Where does m become indistinguishable from " + reference +
         "? Per participant and scene, and per scene for all participants pooled, a "
         "psychometric function of the probability of choosing " +
         reference +
         " over the mono-plane distance m is fitted by maximum likelihood: P = 0.5 + (0.5 &minus; "
         "&lambda;) / (1 + (m / T)<sup>B</sup>). Near the eyes the difference is seen and " +
         reference +
         " is chosen with probability 1 &minus; &lambda; (&lambda;, the lapse rate, at most 0.1); "
         "far beyond the threshold T the two look alike and the choice is a coin flip. At m = T, " +
         reference +
         " is chosen halfway between (75&nbsp;% without lapses); B is the slope over log m. "
         "Participants' intervals are profile-likelihood intervals; the group's come from "
         "resampling whole participants (a bootstrap), as one participant's decisions are "
         "correlated. An interval end written &lt; or &gt; lies beyond the distances tested: the "
         "data do not bound the threshold on that side.</p>\n";
    if (r.psychometric.empty()) {
        return h + "<p class=\"warn\">No analysable trials to fit.</p>\n";
    }
    for (const Figure& f : figures) {
        if (f.name.rfind("psychometric_", 0) != 0) continue;
        h += "<figure id=\"figure-" + xml_escaped(f.name) + "\">\n" + inline_svg(f.svg) +
             "<figcaption>" + xml_escaped(f.caption) + " (also figures/" + xml_escaped(f.name) +
             ".svg and .png)</figcaption>\n</figure>\n";
    }
    h += fits_table(r.psychometric).html();
    h += "<p class=\"note\">Every fit with its data per distance is in summary.json "
         "(<code>psychometric</code>); the table is psychometric.csv.</p>\n";
    return h;
}

void psychometric_json(JsonWriter& json, const AnalysisResults& r) {
    json.begin_array("psychometric");
    for (const PsychometricFit& f : r.psychometric) {
        const bool e = f.estimable;
        json.begin_object()
            .value("participant", f.participant)
            .value("scene", f.scene)
            .value("threshold_m", e ? f.parameters.threshold : NAN)
            .begin_array("threshold_ci")
            .value("", e ? or_nan(f.threshold_lower) : NAN)
            .value("", e ? or_nan(f.threshold_upper) : NAN)
            .end_array()
            .value("slope", e ? f.parameters.slope : NAN)
            .value("n", f.n)
            .value("lapse", e ? f.parameters.lapse : NAN)
            .value("estimable", e)
            .value("reason", f.reason)
            .value("interval_method", f.interval_method)
            .value("participants", f.participants)
            .value("log_likelihood", e ? f.log_likelihood : NAN)
            .value("bootstrap_replicates", f.bootstrap_replicates)
            .begin_array("levels");
        for (const StimulusLevel& level : f.levels) {
            json.begin_object()
                .value("m", level.m)
                .value("reference", level.reference)
                .value("trials", level.trials)
                .end_object();
        }
        json.end_array().end_object();
    }
    json.end_array();
}

std::string psychometric_csv(const AnalysisResults& r) {
    std::string out = csv_line({"participant", "scene", "n", "participants", "estimable",
                                "threshold_m", "threshold_ci_lower", "threshold_ci_upper", "slope",
                                "lapse", "log_likelihood", "interval_method", "reason"});
    for (const PsychometricFit& f : r.psychometric) {
        const bool e = f.estimable;
        out += csv_line(
            {f.participant, f.scene, std::to_string(f.n), std::to_string(f.participants),
             e ? "TRUE" : "FALSE", e ? number_text(f.parameters.threshold) : "",
             e ? number_text(or_nan(f.threshold_lower)) : "",
             e ? number_text(or_nan(f.threshold_upper)) : "",
             e ? number_text(f.parameters.slope) : "", e ? number_text(f.parameters.lapse) : "",
             e ? number_text(f.log_likelihood) : "", f.interval_method, f.reason});
    }
    return out;
}

}  // namespace monoplane::analysis::report
