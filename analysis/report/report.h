// The analysis report of `monoplane analyze` (docs/analysis.md): every statistic of papers/000
// section 6.2, computed with analysis/, plus what a repeated-measures design needs on top (a
// participant-clustered logistic regression), gathered in one value (AnalysisResults), then
// written as a self-contained report.html (figures inline as SVG), summary.json and CSV tables.
// No Vulkan, no study library: the input is analysis::Dataset, whatever file it came from.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/choice_rates.h"
#include "analysis/contingency.h"
#include "analysis/dataset.h"
#include "analysis/exclusions.h"
#include "analysis/frame_timing.h"
#include "analysis/logistic_regression.h"
#include "analysis/psychometric_fits.h"
#include "analysis/report/gaze_results.h"
#include "analysis/report/inputs_section.h"
#include "analysis/report/study_day_section.h"
#include "analysis/summaries.h"
#include "common/result.h"

namespace monoplane::analysis::report {

struct ReportOptions {
    LogisticOptions logistic;
    PsychometricOptions psychometric;
    std::string title = "monoplane study analysis";
    // The view the gaze densities are drawn in: the seat's left eye of this HMD profile.
    SeatEye gaze_eye;
    std::string gaze_hmd = "vive";
};

// What one input file contributed.
struct SourceCounts {
    std::string source;
    int sessions = 0;      // (source, session id) pairs
    int participants = 0;  // distinct codes within this source
    int trials = 0;        // every trial row, practice and undecided included
    int practice = 0;
    int data_trials = 0;  // trials - practice
    int analysed = 0;     // decided, valid, not practice
    int answers = 0;      // questionnaire answers
};

struct FirstSceneRate {
    ChoiceRate rate;  // rate.scene: the scene of the first block
    int sessions = 0;
};

// A chi-square test, or why there is none (e.g. a single distance).
struct ChiSquareResult {
    std::string scene;  // "" for all scenes pooled
    std::optional<ChiSquareTest> test;
    std::string error;
};

struct AnalysisResults {
    std::string title;
    std::vector<SourceCounts> sources;
    int sessions = 0;
    int participants = 0;           // distinct codes over all sources
    int analysed_participants = 0;  // with at least one analysed trial: the regression's clusters
    int trials = 0;
    int data_trials = 0;
    Exclusions exclusions;
    std::string reference_mode;  // e.g. "stereo"; modes joined by "/" if sessions differ
    std::string test_mode;       // e.g. "hybrid"
    ChoiceRate overall;
    std::vector<ChoiceRate> by_scene;
    std::vector<ChoiceRate> by_distance;
    std::vector<ChoiceRate> by_scene_distance;
    std::vector<FirstSceneRate> by_first_scene;
    ChiSquareResult chi_square;  // all scenes
    std::vector<ChiSquareResult> chi_square_by_scene;
    LogisticOptions logistic_options;
    std::optional<LogisticFit> logistic;  // unset: not estimable, see logistic_error
    std::string logistic_error;
    std::vector<PsychometricFit> psychometric;  // per scene: the group's, then participants'
    std::vector<GroupSummary> decision_times;   // seconds, per scene
    std::vector<GroupSummary> switches;         // per scene
    std::vector<ItemSummary> questionnaire;
    FrameTimingSummary frame_timing;  // headset sessions' frame logs
    // Participants with their sessions and variables, notes, counterbalancing.
    StudyDay day;
    // The protocol versions the sessions ran and the sessions several files held.
    InputRecords inputs;
    // Eye gaze, where sessions recorded it (gaze_results.h).
    GazeResults gaze;
};

// Runs every statistic. Never fails: a test that cannot be computed on these data (too few
// trials, one distance, separation) is recorded with its reason and the report says so.
AnalysisResults analyse(const Dataset& data, const ReportOptions& options = {});

struct Figure {
    std::string name;     // file stem under figures/, e.g. "choices"
    std::string caption;  // one sentence for the report
    std::string svg;      // a self-contained SVG document
};

// choices (Fig. 7), decision_times, switches, psychometric_<scene> per scene fitted, then
// gaze_density_<scene> per scene with gaze samples.
std::vector<Figure> report_figures(const AnalysisResults& results);

// The figure `name` of `figures` with its caption, as report.html shows it; "" when there is no
// such figure.
std::string figure_html(const std::vector<Figure>& figures, const std::string& name);

// The HTML page: no external resources (CSS inline, figures inline SVG without namespace URLs).
std::string report_html(const AnalysisResults& results, const std::vector<Figure>& figures);
// summary.json: stable keys documented in docs/analysis.md.
std::string summary_json(const AnalysisResults& results);

// scene,mono_plane,test_chosen,n,rate,wilson_lower,wilson_upper,cp_lower,cp_upper,binomial_p
// (scene empty: all scenes; mono_plane empty: all distances).
std::string rates_csv(const std::vector<ChoiceRate>& rates);
// term,estimate,std_error,z,p,odds_ratio,ci_lower,ci_upper,n,clusters,converged (header only
// when the model was not estimable).
std::string logistic_csv(const AnalysisResults& results);
// item,text,scale_points,n,mean,sd,median,q1,q3,min,max,count_1..count_K
std::string questionnaire_csv(const std::vector<ItemSummary>& items);

struct WrittenReport {
    std::filesystem::path html;
    std::filesystem::path json;
    std::vector<std::filesystem::path> tables;
    std::vector<std::filesystem::path> figures;  // the SVG files
};

// Writes report.html, summary.json, rates_by_scene.csv, rates_by_distance.csv,
// rates_by_scene_distance.csv, rates_by_first_scene.csv, logistic.csv, psychometric.csv,
// questionnaire.csv and
// figures/<name>.svg into `dir` (which must exist). The error names the file.
Result<WrittenReport> write_report(const AnalysisResults& results,
                                   const std::vector<Figure>& figures,
                                   const std::filesystem::path& dir);

// Writes `text` to `path`, replacing it; the error names the file.
Result<void> write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace monoplane::analysis::report
