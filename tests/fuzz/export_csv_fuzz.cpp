// Fuzz target: the CSV import of `monoplane analyze --csv` (analysis/dataset.h read_export_csv,
// analysis/csv.h), which reads exports that pandas, R or a spreadsheet may have written back.
// read_export_csv takes a path: the input is read from the file the runner writes.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/dataset.h"
#include "tests/fuzz/fuzz_runner.h"
#include "tests/fuzz/mutator.h"

namespace monoplane {
namespace {

TEST(Fuzz, ExportCsv) {
    const fuzz::FuzzTarget target{
        .name = "export_csv",
        .seeds = {fuzz::source_path("tests/fixtures/analysis"), fuzz::corpus_path("export_csv")},
        .dictionary = fuzz::split_words(R"(participant session trial_index block scene
            mono_plane label1_mode label2_mode chosen_mode valid switches decision_time_s
            practice decided protocol NA TRUE FALSE True False true false stereo hybrid
            hybrid-farfield 2.0)"),
        .file_extension = ".csv",
        .iterations = 15000,
        .run = [](const fuzz::FuzzInput& input) {
            const Result<analysis::Dataset> dataset = analysis::read_export_csv(input.file);
            if (!dataset) return fuzz::rejected(dataset.error(), input);
            for (const analysis::TrialRow& trial : dataset->trials) {
                if (!std::isfinite(trial.mono_plane) ||
                    (trial.decided && !std::isfinite(trial.decision_time_s)))
                    return fuzz::violation("accepted a number that is not finite");
                if (trial.source != input.file.string())
                    return fuzz::violation("a trial without its source");
            }
            return fuzz::accepted();
        }};
    fuzz::expect_clean(fuzz::run_fuzz_target(target));
}

}  // namespace
}  // namespace monoplane
