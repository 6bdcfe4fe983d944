#include "app/commands/option_wording.h"

#include <string>

namespace monoplane::app {

Error output_option_error(const study::OutputProblem& problem) {
    using study::OutputRefusal;
    const std::string& what = problem.what;
    const std::string nothing = " Nothing was written.";
    switch (problem.refusal) {
        case OutputRefusal::NoName:
            return Error{"the output file name (--out) is empty"};
        case OutputRefusal::IsAnInput:
            return Error{what + "; choose another --out (--force never allows this)." + nothing};
        case OutputRefusal::IsADatabase:
            return Error{what + ", also with --force; choose another --out." + nothing};
        case OutputRefusal::NotAFile:
            return Error{what + "; --out must name a file." + nothing};
        case OutputRefusal::NotAnEarlierOutput:
        case OutputRefusal::OtherSource:
            return Error{what + ". Give --force to replace it, or choose another --out." + nothing};
        case OutputRefusal::NoFolder:
            return Error{what + "; create it first or choose another --out." + nothing};
        case OutputRefusal::Unreadable:
        case OutputRefusal::FolderIsNoFolder:
            break;
    }
    return Error{what + "; choose another --out." + nothing};
}

Result<void> check_output_option(const std::filesystem::path& out, const study::OutputKind& kind,
                                 const std::vector<std::filesystem::path>& inputs, bool force) {
    if (std::optional<study::OutputProblem> problem =
            study::output_problem(out, kind, inputs, force))
        return output_option_error(*problem);
    return Ok{};
}

study::OutputKind export_option_kind(study::ExportFormat format) {
    study::OutputKind kind = study::export_output_kind(format);
    kind.name = "export of --format " + std::string(study::export_format_name(format));
    return kind;
}

const study::RequestNames& study_run_option_names() {
    static const study::RequestNames names{
        [](std::string_view number) { return "--session " + std::string(number); },
        [](std::string_view number) {
            return number.empty() ? std::string("--participant-number")
                                  : "--participant-number " + std::string(number);
        },
        [](std::string_view assignment) { return "--var " + std::string(assignment); },
    };
    return names;
}

const analysis::SharedCodesNames& codes_option_names() {
    static const analysis::SharedCodesNames names{
        [](analysis::SharedCodes rule) {
            return "--codes " + std::string(analysis::shared_codes_name(rule));
        },
        "analyze does not merge participants from different files without being told who they "
        "are; run it again with one of:"};
    return names;
}

}  // namespace monoplane::app
