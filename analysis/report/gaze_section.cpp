#include "analysis/report/gaze_section.h"

#include <optional>

#include "analysis/report/figures.h"
#include "analysis/report/gaze_figure.h"
#include "analysis/report/html_format.h"
#include "analysis/report/regression_section.h"
#include "charts/svg_writer.h"

namespace monoplane::analysis::report {
namespace {

using charts::xml_escaped;

std::string optional_fixed(const std::optional<double>& value, int decimals) {
    return value ? fixed(*value, decimals) : "&ndash;";
}

std::string optional_percent(const std::optional<double>& value) {
    return value ? percent(*value) : "&ndash;";
}

std::string scene_table_html(const GazeResults& g, const std::string& test) {
    Table t;
    t.header = {"scene",
                "analysed trials",
                "with gaze",
                "gaze samples",
                "gaze beyond m (mean share per trial)",
                "error at gaze while " + test + " was shown (arcmin, mean per trial)",
                "fixations per trial"};
    t.numeric = {false, true, true, true, true, true, true};
    for (const GazeSceneRow& row : g.by_scene) {
        t.rows.push_back({scene_name(row.scene), std::to_string(row.trials),
                          std::to_string(row.trials_with_gaze), std::to_string(row.samples),
                          optional_percent(row.share_beyond_m),
                          optional_fixed(row.error_test_arcmin, 2),
                          optional_fixed(row.fixations_per_trial, 1)});
    }
    return t.html() +
           "<p class=\"note\">Gaze samples: frames that showed a trial's scene with a valid gaze "
           "sample (databases only; a CSV export holds the per-trial columns alone). Beyond m: "
           "gaze points farther than the trial's mono plane, the sky included, where hybrid shows "
           "the one mono image to both eyes. The error is hybrid's angular error at the point "
           "the gaze met, averaged over the frames of the label that showed " +
           test + ". Fixations: I-DT (1 degree, 100 ms) over the frames that showed a label.</p>\n";
}

// The odds ratio per arcmin in words: which way, and whether the data can tell it from none.
std::string interpretation(const Coefficient& c, const std::string& test) {
    const bool excludes_one = c.ci_lower_cr2 > 1.0 || c.ci_upper_cr2 < 1.0;
    std::string h =
        "<p class=\"key\">Each additional arcmin of hybrid's error where the "
        "participant looked multiplied the odds of choosing " +
        test + " by " + fixed(c.odds_ratio, 3) + " (95&nbsp;% CI " + fixed(c.ci_lower_cr2, 3) +
        "&ndash;" + fixed(c.ci_upper_cr2, 3) + ", " + p_statement(c.p_cr2) + ", CR2). ";
    if (!excludes_one)
        return h +
               "The interval includes 1: these data cannot tell whether the error at gaze "
               "changes the choice.</p>\n";
    return h +
           (c.odds_ratio < 1.0 ? "Larger errors where participants looked made them choose " +
                                     test + " less often."
                               : "Larger errors where participants looked went with " + test +
                                     " being chosen more often.") +
           "</p>\n";
}

std::string regression_html(const GazeResults& g, const std::string& test) {
    std::string h = "<h3>The choice and the error at gaze</h3>\n";
    h += "<p>Logistic regression of the decision (" + test +
         " chosen = 1) on the trial's mean error at gaze while " + test + " was shown (arcmin)" +
         (g.options.scene_terms && g.by_scene.size() > 2 ? " and the scene" : "") +
         ", clustered by participant as the distance model above.</p>\n";
    if (!g.fit)
        return h +
               "<p class=\"warn\"><b>Not estimable</b> on these data: " + xml_escaped(g.fit_error) +
               "</p>\n";
    const LogisticFit& f = *g.fit;
    Table t;
    t.header = {"term",    "odds ratio", "95&nbsp;% CI (CR2)",
                "p (CR2)", "df (CR2)",   "95&nbsp;% CI (CR1)",
                "p (CR1)"};
    t.numeric = {false, true, true, true, true, true, true};
    for (const Coefficient& c : f.coefficients) {
        t.rows.push_back({"<code>" + xml_escaped(c.name) + "</code>", fixed(c.odds_ratio, 4),
                          "[" + fixed(c.ci_lower_cr2, 4) + ", " + fixed(c.ci_upper_cr2, 4) + "]",
                          p_value(c.p_cr2), fixed(c.df_cr2, 2),
                          "[" + fixed(c.ci_lower, 4) + ", " + fixed(c.ci_upper, 4) + "]",
                          p_value(c.p)});
    }
    h += t.html();
    h += "<p class=\"note\">n = " + std::to_string(f.n) + " decisions in " +
         std::to_string(f.clusters) + " clusters (participants); " +
         std::to_string(f.skipped_without_predictor) +
         " analysed trial(s) without an error at gaze left out. Odds ratios of "
         "<code>gaze_error_test_arcmin</code> are per arcmin.</p>\n";
    for (const Coefficient& c : f.coefficients)
        if (c.name == f.distance_term) h += interpretation(c, test);
    return h;
}

// Each density's samples and its peak: the bin and the tangents of its centre in the seat's left
// eye (+x right, +y up), so a reader can check where the gaze concentrated without the figure.
void densities_json(JsonWriter& json, const GazeResults& g) {
    json.begin_array("densities");
    for (const GazeDensity& d : g.densities) {
        const auto [column, row] = d.peak_bin();
        const SeatEye& e = g.eye;
        json.begin_object()
            .value("scene", d.scene)
            .value("samples", d.samples)
            .value("inside", d.inside)
            .value("peak_column", column)
            .value("peak_row", row)
            .value("peak_tan_x",
                   e.tan_left + (column + 0.5) / d.columns * (e.tan_right - e.tan_left))
            .value("peak_tan_y", e.tan_up - (row + 0.5) / d.rows * (e.tan_up - e.tan_down))
            .value("figure", "figures/gaze_density_" + scene_file_stem(d.scene) + ".svg")
            .value("scene_picture", g.images.contains(d.scene))
            .end_object();
    }
    json.end_array();
}

}  // namespace

std::string gaze_section_html(const AnalysisResults& r, const std::vector<Figure>& figures) {
    const GazeResults& g = r.gaze;
    if (!g.recorded) return {};
    const std::string test = xml_escaped(r.test_mode);
    std::string h = "<h2 id=\"gaze\">Where participants looked</h2>\n";
    h += "<p>Sessions that recorded eye gaze (docs/gaze.md) tell where in the scene each "
         "decision was made: how much of the gaze lay beyond the mono plane, and how large " +
         test + "'s error was there.</p>\n";
    h += scene_table_html(g, test);
    h += regression_html(g, test);
    if (!g.densities.empty()) h += "<h3>Gaze density per scene</h3>\n";
    for (const GazeDensity& d : g.densities)
        h += figure_html(figures, "gaze_density_" + scene_file_stem(d.scene));
    return h;
}

void gaze_json(JsonWriter& json, const AnalysisResults& r) {
    const GazeResults& g = r.gaze;
    json.begin_object("gaze").value("recorded", g.recorded);
    if (!g.recorded) {
        json.end_object();
        return;
    }
    const GazeSceneRow& all = g.by_scene.back();
    json.value("trials_with_gaze", all.trials_with_gaze).value("samples", all.samples);
    json.begin_array("by_scene");
    for (const GazeSceneRow& row : g.by_scene) {
        if (row.scene.empty()) continue;
        json.begin_object()
            .value("scene", row.scene)
            .value("trials", row.trials)
            .value("trials_with_gaze", row.trials_with_gaze)
            .value("samples", row.samples);
        row.share_beyond_m ? json.value("share_beyond_m", *row.share_beyond_m)
                           : json.null("share_beyond_m");
        row.error_test_arcmin ? json.value("error_test_arcmin", *row.error_test_arcmin)
                              : json.null("error_test_arcmin");
        row.fixations_per_trial ? json.value("fixations_per_trial", *row.fixations_per_trial)
                                : json.null("fixations_per_trial");
        json.end_object();
    }
    json.end_array();
    json.begin_object("regression").value("estimable", g.fit.has_value());
    if (!g.fit) {
        json.value("error", g.fit_error).end_object();
        densities_json(json, g);
        json.end_object();
        return;
    }
    json.value("n", g.fit->n)
        .value("clusters", g.fit->clusters)
        .value("skipped_without_gaze", g.fit->skipped_without_predictor)
        .value("scene_terms", g.options.scene_terms);
    coefficients_json(json, *g.fit);
    json.end_object();
    densities_json(json, g);
    json.end_object();
}

std::vector<Figure> gaze_figures(const AnalysisResults& r) {
    const GazeResults& g = r.gaze;
    std::vector<Figure> figures;
    for (const GazeDensity& d : g.densities) {
        const auto found = g.images.find(d.scene);
        const std::optional<SceneImage> image =
            found == g.images.end() ? std::nullopt : std::optional<SceneImage>(found->second);
        std::string caption = "Where participants looked in " + upper_case(d.scene) + ": " +
                              std::to_string(d.inside) + " of " + std::to_string(d.samples) +
                              " gaze samples in the left eye's view from the seat (HMD profile " +
                              g.hmd + "), smoothed, ";
        caption += image ? "over the scene as the seat's left eye sees it."
                         : "drawn alone: " + (g.image_note.empty()
                                                  ? std::string("no picture of the scene.")
                                                  : g.image_note);
        figures.push_back({"gaze_density_" + scene_file_stem(d.scene), caption,
                           gaze_density_svg(d, g.eye, image)});
    }
    return figures;
}

}  // namespace monoplane::analysis::report
