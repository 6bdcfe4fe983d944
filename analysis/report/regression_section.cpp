#include "analysis/report/regression_section.h"

#include "analysis/report/html_format.h"
#include "analysis/report/text_output.h"
#include "charts/svg_writer.h"

namespace monoplane::analysis::report {
namespace {

using charts::xml_escaped;

std::string distance_description(const LogisticOptions& options) {
    return options.log2_distance ? "log<sub>2</sub> of the mono-plane distance m (metres)"
                                 : "the mono-plane distance m (metres)";
}

// An odds ratio's 95 % interval, "[0.9812, 1.2034]".
std::string odds_ratio_ci(double lower, double upper) {
    return "[" + fixed(lower, 4) + ", " + fixed(upper, 4) + "]";
}

std::string term_cell(const Coefficient& c, const LogisticFit& f) {
    const std::string name = "<code>" + xml_escaped(c.name) + "</code>";
    return c.name == f.distance_term ? "<b>" + name + "</b>" : name;
}

Table cr2_table(const LogisticFit& f) {
    Table t;
    t.header = {"term",       "estimate (log-odds)",      "CR2 SE", "t", "df", "p",
                "odds ratio", "95&nbsp;% CI (odds ratio)"};
    t.numeric = {false, true, true, true, true, true, true, true};
    for (const Coefficient& c : f.coefficients) {
        t.rows.push_back({term_cell(c, f), fixed(c.estimate, 4), fixed(c.std_error_cr2, 4),
                          fixed(c.t_cr2, 3), fixed(c.df_cr2, 2), p_value(c.p_cr2),
                          fixed(c.odds_ratio, 4), odds_ratio_ci(c.ci_lower_cr2, c.ci_upper_cr2)});
    }
    return t;
}

Table cr1_table(const LogisticFit& f) {
    Table t;
    t.header = {"term", "CR1 SE", "z", "p (normal)", "95&nbsp;% CI (odds ratio)"};
    t.numeric = {false, true, true, true, true};
    for (const Coefficient& c : f.coefficients) {
        t.rows.push_back({term_cell(c, f), fixed(c.std_error, 4), fixed(c.z, 3), p_value(c.p),
                          odds_ratio_ci(c.ci_lower, c.ci_upper)});
    }
    return t;
}

std::string fit_html(const AnalysisResults& r, const LogisticFit& f) {
    std::string h = cr2_table(f).html();
    h += "<p class=\"note\">n = " + std::to_string(f.n) + " decisions in " +
         std::to_string(f.clusters) + " clusters (participants); " + std::to_string(f.iterations) +
         " Newton iterations, " + (f.converged ? "converged" : "<b>not converged</b>") +
         "; log-likelihood " + fixed(f.log_likelihood, 3) + ". The distance term is <code>" +
         xml_escaped(f.distance_term) + "</code>.</p>\n";
    for (const Coefficient& c : f.coefficients) {
        if (c.name != f.distance_term) continue;
        h += "<p class=\"key\">Distance effect: odds ratio " + fixed(c.odds_ratio, 4) + " per " +
             (r.logistic_options.log2_distance ? "doubling of m" : "metre of m") +
             " (95&nbsp;% CI " + odds_ratio_ci(c.ci_lower_cr2, c.ci_upper_cr2) + "), t(" +
             fixed(c.df_cr2, 1) + ") = " + fixed(c.t_cr2, 2) + ", " + p_statement(c.p_cr2) +
             " (CR2).</p>\n";
    }
    h += "<h3>For comparison: CR1 with normal p-values</h3>\n";
    h += "<p class=\"note\">The sandwich of Stata's <code>vce(cluster)</code> and statsmodels' "
         "<code>cov_type=\"cluster\"</code>, with z tests. With few participants it rejects a true "
         "null more often than alpha (about 8&ndash;9&nbsp;% at alpha = 5&nbsp;% with 6&ndash;10 "
         "participants in simulations, docs/analysis.md); read these p-values as optimistic.</p>\n";
    return h + cr1_table(f).html();
}

}  // namespace

std::string regression_section_html(const AnalysisResults& r) {
    const std::string test = xml_escaped(r.test_mode);
    std::string h =
        "<h2 id=\"regression\">Logistic regression with participant-clustered standard "
        "errors</h2>\n";
    h += "<p>Why: pooled chi-square and binomial tests count " + std::to_string(r.exclusions.kept) +
         " decisions as independent, but they come from " +
         std::to_string(r.analysed_participants) +
         " participants who each made many of them (repeated measures), so they are not valid "
         "inference. The model is a logistic regression of the decision (" +
         test + " chosen = 1) on " + distance_description(r.logistic_options) +
         (r.logistic_options.scene_terms ? " and the scene (indicator terms against the first "
                                           "scene)"
                                         : "") +
         ", with cluster-robust (sandwich) standard errors clustered by participant, which stay "
         "valid however a participant's decisions are correlated. Tests use the small-sample "
         "correction CR2 (Bell &amp; McCaffrey 2002; Pustejovsky &amp; Tipton 2018) with "
         "Student's t on Satterthwaite degrees of freedom, which keeps the false-positive rate "
         "near alpha even with 6 participants.</p>\n";
    if (r.logistic) return h + fit_html(r, *r.logistic);
    return h + "<p class=\"warn\"><b>Not estimable</b> on these data: " +
           xml_escaped(r.logistic_error) + "</p>\n";
}

void logistic_json(JsonWriter& json, const AnalysisResults& r) {
    json.begin_object("logistic")
        .value("estimable", r.logistic.has_value())
        .value("log2_distance", r.logistic_options.log2_distance)
        .value("scene_terms", r.logistic_options.scene_terms)
        .value("distance_term", r.logistic                         ? r.logistic->distance_term
                                : r.logistic_options.log2_distance ? "log2_mono_plane_m"
                                                                   : "mono_plane_m");
    if (!r.logistic) {
        json.value("error", r.logistic_error).end_object();
        return;
    }
    const LogisticFit& f = *r.logistic;
    json.value("n", f.n)
        .value("clusters", f.clusters)
        .value("iterations", f.iterations)
        .value("converged", f.converged)
        .value("log_likelihood", f.log_likelihood)
        .value("small_sample_method", "CR2 with Satterthwaite t");
    coefficients_json(json, f);
    json.end_object();
}

void coefficients_json(JsonWriter& json, const LogisticFit& f) {
    json.begin_array("coefficients");
    for (const Coefficient& c : f.coefficients) {
        json.begin_object()
            .value("name", c.name)
            .value("estimate", c.estimate)
            .value("std_error", c.std_error)
            .value("z", c.z)
            .value("p", c.p)
            .value("odds_ratio", c.odds_ratio)
            .value("ci_lower", c.ci_lower)
            .value("ci_upper", c.ci_upper)
            .value("std_error_cr2", c.std_error_cr2)
            .value("t_cr2", c.t_cr2)
            .value("df_cr2", c.df_cr2)
            .value("p_cr2", c.p_cr2)
            .value("ci_lower_cr2", c.ci_lower_cr2)
            .value("ci_upper_cr2", c.ci_upper_cr2)
            .end_object();
    }
    json.end_array();
}

std::string logistic_csv(const AnalysisResults& r) {
    // The CR1 columns first, in their original places; the CR2 columns were added at the end.
    std::string out = csv_line({"term", "estimate", "std_error", "z", "p", "odds_ratio", "ci_lower",
                                "ci_upper", "n", "clusters", "converged", "std_error_cr2", "t_cr2",
                                "df_cr2", "p_cr2", "ci_lower_cr2", "ci_upper_cr2"});
    if (!r.logistic) return out;
    const LogisticFit& f = *r.logistic;
    for (const Coefficient& c : f.coefficients) {
        out +=
            csv_line({c.name, number_text(c.estimate), number_text(c.std_error), number_text(c.z),
                      number_text(c.p), number_text(c.odds_ratio), number_text(c.ci_lower),
                      number_text(c.ci_upper), std::to_string(f.n), std::to_string(f.clusters),
                      f.converged ? "TRUE" : "FALSE", number_text(c.std_error_cr2),
                      number_text(c.t_cr2), number_text(c.df_cr2), number_text(c.p_cr2),
                      number_text(c.ci_lower_cr2), number_text(c.ci_upper_cr2)});
    }
    return out;
}

}  // namespace monoplane::analysis::report
