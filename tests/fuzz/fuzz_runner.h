// Fuzzing the parsers of files users write or hand over (issue 19): a target runs one parser over
// its seed corpus and then over deterministic mutants of it (mutator.h). A parser that returns an
// error is doing its job; a failure is a crash, a sanitizer report, an exception, an input that
// runs longer than the per-input limit, or a broken promise the target checks (an error message
// that does not name the file, an accepted value outside the documented range).
//
// Each target is a gtest in its own file, built by monoplane_fuzz_test() in CMakeLists.txt with
// the `unit` label, so scripts/test.sh runs it and scripts/test-sanitizers.sh runs it under
// AddressSanitizer and UndefinedBehaviorSanitizer. The tests are Fuzz.Protocol, Fuzz.HmdProfile,
// Fuzz.ExportCsv and Fuzz.SimxrScript; running them alone:
//   ctest --test-dir build-sanitize -R '^Fuzz[.]' --output-on-failure
//
// Running longer (environment variables, read by every target):
//   MONOPLANE_FUZZ_ITERATIONS=N   mutants per target (default: the target's; 0 = no limit)
//   MONOPLANE_FUZZ_SECONDS=T      stop a target after T seconds (default 15)
//   MONOPLANE_FUZZ_SEED=S         another seed explores other mutants (default 1)
//   MONOPLANE_FUZZ_START=I        first iteration (with ITERATIONS=1: replay one iteration)
//   MONOPLANE_FUZZ_INPUT_TIMEOUT_S=T   an input running longer is a hang (default 10)
// e.g. an hour of a new seed on the protocol parser (one command line):
//   MONOPLANE_FUZZ_ITERATIONS=0 MONOPLANE_FUZZ_SECONDS=3600 MONOPLANE_FUZZ_SEED=$RANDOM
//   build-sanitize/tests/fuzz/fuzz_protocol_test
//
// Reproducing a failure: before each input runs, its bytes are written to
// <build>/tests/fuzz/work/<target>/input<extension> and its seed, iteration and mutations to
// input.info beside it, so a crash leaves the input behind (a clean run removes both); a crash
// under AddressSanitizer, a signal without sanitizers and a hang also print them (a UBSan report
// under GCC, whose runtime is separate, leaves only the files). Exceptions and broken promises are
// reported by the test with the same details, the input saved as
// failure-<seed>-<iteration><extension>.
//   MONOPLANE_FUZZ_REPLAY=FILE build-sanitize/tests/fuzz/fuzz_protocol_test
// runs that file alone through the target (under gdb, or with more logging); so does
//   MONOPLANE_FUZZ_SEED=S MONOPLANE_FUZZ_START=I MONOPLANE_FUZZ_ITERATIONS=1.
// Once fixed, keep the input in corpus/<target>/regressions/ (seeds there may be rejected).
// Runs of one target share its work folder: run one at a time per build folder (ctest never runs
// a test twice at once).
//
// Adding a target (e.g. a glTF loader, which reads a file): a file <name>_fuzz.cpp with
//   TEST(Fuzz, GltfScene) {
//       fuzz::FuzzTarget target{.name = "gltf_scene",
//                               .seeds = {fuzz::corpus_path("gltf_scene")},
//                               .file_extension = ".gltf",
//                               .run = [](const fuzz::FuzzInput& input) {
//                                   const auto scene = load_gltf_scene(input.file, {});
//                                   if (!scene) return fuzz::rejected(scene.error(), input);
//                                   return fuzz::accepted();
//                               }};
//       fuzz::expect_clean(fuzz::run_fuzz_target(target));
//   }
// seed files under corpus/gltf_scene/, and one line in CMakeLists.txt:
//   monoplane_fuzz_test(NAME fuzz_gltf_scene_test SOURCES gltf_scene_fuzz.cpp LIBS <its library>)
// The input file lies in work_folder("gltf_scene"); files it refers to (buffers, images) can be
// copied there first, as simxr_script_fuzz.cpp does with the HMD profile its seeds name.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/result.h"

namespace monoplane::fuzz {

// One input: its bytes, and a file holding exactly those bytes (for parsers that read files).
struct FuzzInput {
    std::string_view bytes;
    std::filesystem::path file;  // <work>/<target>/input<extension>
};

struct Verdict {
    bool accepted = false;  // the parser took the input (counted, to show the mutants get through)
    std::string violation;  // non-empty: a broken promise, a failure
};

inline Verdict accepted() {
    return {.accepted = true, .violation = {}};
}
// A parser's error: fine, as long as it says something and names the file it was given (targets
// pass input.file.string() as the parser's source name).
Verdict rejected(const Error& error, const FuzzInput& input);
// A broken promise: fails the test with the input.
inline Verdict violation(std::string what) {
    return {.accepted = false, .violation = std::move(what)};
}

struct FuzzTarget {
    std::string name;  // names the work folder and the messages; [a-z0-9_]
    // Seed files, and folders whose files ending in file_extension (recursively, sorted) are all
    // seeds. Seeds run first, unmutated. Those in a folder named `regressions` may be rejected and
    // are not mutated; every other seed must be accepted, so that the mutants start from inputs
    // that reach past the syntax check.
    std::vector<std::filesystem::path> seeds;
    std::vector<std::string> dictionary;  // the parser's keys and values, added to the corpus's
    std::string file_extension = ".txt";
    std::uint64_t iterations = 15000;  // mutants in CI; MONOPLANE_FUZZ_ITERATIONS overrides
    std::function<Verdict(const FuzzInput&)> run;
};

struct FuzzReport {
    std::string target;
    std::uint64_t seed = 0;
    std::size_t seeds_run = 0;
    std::vector<std::string> seeds_rejected;  // seeds (outside regressions/) the parser refused
    std::uint64_t mutants_run = 0;
    std::uint64_t mutants_accepted = 0;
    double seconds = 0.0;
    bool stopped_by_time = false;
    std::vector<std::string> failures;  // each with seed, iteration, mutations and the saved input
};

// Runs the seeds, then the mutants (or only MONOPLANE_FUZZ_REPLAY's file), and prints a one-line
// summary to stdout. A crash or a hang ends the process, leaving the input in the work folder.
FuzzReport run_fuzz_target(const FuzzTarget& target);

// gtest expectations on a report: no failures, every seed outside regressions/ accepted.
void expect_clean(const FuzzReport& report);

// tests/fuzz/corpus/<name>, and a path in the source tree ("protocols", "hmd/profiles").
std::filesystem::path corpus_path(std::string_view name);
std::filesystem::path source_path(std::string_view relative);
// <build>/tests/fuzz/work/<target>: the folder a target's input file is written to (created).
std::filesystem::path work_folder(std::string_view target);

}  // namespace monoplane::fuzz
