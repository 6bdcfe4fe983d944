// The work of `monoplane analyze` as a function, so that the command and the launcher write the
// same report from the same inputs: read and merge study databases and CSV exports, join
// participant codes as asked, analyse, and write report.html, summary.json, the CSV tables and
// the figures as SVG and PNG into one directory (docs/analysis.md).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "analysis/dataset.h"
#include "analysis/report/report.h"
#include "common/result.h"

namespace monoplane::app {

struct AnalyzeRequest {
    std::vector<std::filesystem::path> dbs;   // study databases (`--db`)
    std::vector<std::filesystem::path> csvs;  // CSV exports (`--csv`)
    // The output folder (`--out`): written beside its place and renamed there whole; an existing
    // one only when it holds nothing but an earlier analysis (app/commands/output_folder.h).
    std::filesystem::path out;
    bool force = false;           // `--force`: write among files analyze did not write
    bool log2_distance = false;   // `--log2-distance`
    bool no_scene_terms = false;  // `--no-scene-terms`
    analysis::SharedCodes codes = analysis::SharedCodes::Refuse;  // `--codes`
    // `--pool-protocols`: pool sessions of protocol versions whose designs differ (or cannot be
    // compared) instead of refusing them.
    bool pool_protocols = false;
    // `--drop-duplicates`: count once a session several inputs hold in identical copies instead
    // of refusing them (copies that differ are refused all the same).
    bool drop_duplicates = false;
    // Render each scene with gaze at the seat for the report's gaze densities (a Vulkan device;
    // without one they are drawn alone). `--no-scene-pictures` turns it off.
    bool scene_pictures = true;
    // Told each input as it is read ("read FILE: N trials, ..."); may be empty.
    std::function<void(const std::string&)> on_read;
};

struct AnalysisWritten {
    analysis::report::AnalysisResults results;
    std::filesystem::path out;                // the output directory
    std::filesystem::path html;               // report.html in it, absolute
    analysis::report::WrittenReport written;  // every file write_report wrote
    std::vector<std::filesystem::path> pngs;  // the figures as PNG (figures/NAME.png)
};

// Runs the analysis of `request` and writes its files. May be called at any time, also while a
// session writes to one of the databases (it reads what is committed). The output folder and the
// inputs are checked before anything is written, so a refusal leaves no output folder behind.
// Errors (no input, a file given twice, a missing or unreadable file, a session several inputs
// hold (identical copies without `drop_duplicates`, copies that differ always), sessions of
// protocol designs that differ without `pool_protocols`, a participant code several inputs hold
// without `codes` saying what it means, an output folder that holds files analyze did not write
// without `force`, one that cannot be written) name the option and the file.
Result<AnalysisWritten> run_analysis(const AnalyzeRequest& request);

}  // namespace monoplane::app
