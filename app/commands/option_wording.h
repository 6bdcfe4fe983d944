// The command line's words for what the libraries refuse. A library says what is wrong in its
// own terms (the output, forcing, session 2, the same-person rule); the commands' users give
// options, so the commands word the same refusals with the options' names (--out, --force,
// --session 2, --codes same-person). All of that wording is here, in one place.
#pragma once

#include <filesystem>
#include <vector>

#include "analysis/dataset.h"
#include "common/result.h"
#include "study/export.h"
#include "study/output_file.h"
#include "study/request_names.h"

namespace monoplane::app {

// An output refusal as an Error that names --out and --force: what is wrong, which option to
// change, and that nothing was written.
Error output_option_error(const study::OutputProblem& problem);

// study::output_problem for a command's --out (`force` is its --force), worded by
// output_option_error.
Result<void> check_output_option(const std::filesystem::path& out, const study::OutputKind& kind,
                                 const std::vector<std::filesystem::path>& inputs, bool force);

// An export of `format` as `study export --format` names it: "export of --format csv".
study::OutputKind export_option_kind(study::ExportFormat format);

// A session request's inputs as `study run` takes them: --session 2, --participant-number 3
// (--participant-number for the option itself), --var age=17.
const study::RequestNames& study_run_option_names();

// `analyze --codes same-person` / `--codes per-database`, and "run it again with one of".
const analysis::SharedCodesNames& codes_option_names();

}  // namespace monoplane::app
