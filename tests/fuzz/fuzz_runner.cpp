#include "tests/fuzz/fuzz_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <thread>

#include <unistd.h>

#include "tests/fuzz/mutator.h"

// AddressSanitizer calls the callback given here before it ends the process
// (sanitizer/common_interface_defs.h); weak, so the address is null in a build without it. GCC's
// UBSan is a runtime of its own that does not call it: its reports leave the input file only.
// NOLINTNEXTLINE(bugprone-reserved-identifier): the sanitizers' name
extern "C" void __sanitizer_set_death_callback(void (*callback)()) __attribute__((weak));

namespace monoplane::fuzz {
namespace {

using Clock = std::chrono::steady_clock;

std::uint64_t env_number(const char* name, std::uint64_t fallback) {
    const char* text = std::getenv(name);
    if (text == nullptr || *text == '\0') return fallback;
    char* end = nullptr;
    const unsigned long long value = std::strtoull(text, &end, 0);
    if (*end != '\0') {
        ADD_FAILURE() << name << "=" << text << " is not a number";
        return fallback;
    }
    return value;
}

std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void write_file(const std::filesystem::path& path, std::string_view bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// What a crash handler prints: formatted before each input, so the handler only writes it.
char crash_note[4096] = "";

void print_crash_note() {
    const std::size_t length = std::char_traits<char>::length(crash_note);
    if (::write(STDERR_FILENO, crash_note, length) < 0) return;  // nothing else to do in a crash
}

void on_fatal_signal(int signal) {
    print_crash_note();
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

void install_crash_note() {
    static bool installed = false;
    if (installed) return;
    installed = true;
    if (__sanitizer_set_death_callback != nullptr) {
        __sanitizer_set_death_callback(print_crash_note);
        return;
    }
    // Without a sanitizer: the signals of a crash (the sanitizers handle these themselves).
    for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) {
        std::signal(signal, on_fatal_signal);
    }
}

// Ends the process when one input runs longer than the limit: a parser stuck in a loop would
// otherwise hold the test until ctest's timeout, without saying which input.
class Watchdog {
  public:
    explicit Watchdog(double limit_s) : limit_(std::chrono::duration<double>(limit_s)) {
        thread_ = std::thread([this] { watch(); });
    }
    ~Watchdog() {
        {
            const std::lock_guard lock(mutex_);
            stop_ = true;
        }
        wake_.notify_one();
        thread_.join();
    }
    Watchdog(const Watchdog&) = delete;
    Watchdog& operator=(const Watchdog&) = delete;

    void started() { started_ns_ = Clock::now().time_since_epoch().count(); }
    void finished() { started_ns_ = 0; }

  private:
    void watch() {
        std::unique_lock lock(mutex_);
        while (!wake_.wait_for(lock, std::chrono::milliseconds(100), [this] { return stop_; })) {
            const auto started = started_ns_.load();
            if (started == 0) continue;
            const auto running = Clock::now() - Clock::time_point(Clock::duration(started));
            if (running > limit_) {
                std::fprintf(stderr, "fuzz: an input ran longer than %.1f s (a hang?)\n",
                             limit_.count());
                print_crash_note();
                std::_Exit(3);
            }
        }
    }

    std::chrono::duration<double> limit_;
    std::atomic<Clock::rep> started_ns_{0};
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    std::thread thread_;
};

struct Seed {
    std::filesystem::path path;
    std::string bytes;
    bool regression = false;  // in a folder named regressions: may be rejected
};

std::vector<Seed> load_seeds(const FuzzTarget& target) {
    std::vector<Seed> seeds;
    const auto add = [&](const std::filesystem::path& path) {
        const bool regression = path.parent_path().filename() == "regressions";
        seeds.push_back({path, read_file(path), regression});
    };
    for (const std::filesystem::path& entry : target.seeds) {
        if (!std::filesystem::is_directory(entry)) {
            EXPECT_TRUE(std::filesystem::is_regular_file(entry)) << "no seed file " << entry;
            add(entry);
            continue;
        }
        std::vector<std::filesystem::path> files;
        for (const auto& file : std::filesystem::recursive_directory_iterator(entry)) {
            if (file.is_regular_file() && file.path().extension() == target.file_extension)
                files.push_back(file.path());
        }
        std::ranges::sort(files);
        EXPECT_FALSE(files.empty()) << "no " << target.file_extension << " seeds in " << entry;
        for (const auto& file : files) add(file);
    }
    return seeds;
}

class Session {
  public:
    Session(const FuzzTarget& target, FuzzReport& report, double input_limit_s)
        : target_(target),
          report_(report),
          folder_(work_folder(target.name)),
          input_file_(folder_ / ("input" + target.file_extension)),
          info_file_(folder_ / "input.info"),
          input_limit_s_(input_limit_s),
          watchdog_(input_limit_s) {
        install_crash_note();
    }

    // label: "seed 3 (file)" or "seed 1, iteration 17"; how: the mutations, for messages.
    // Returns whether the parser accepted the input.
    bool run(std::string_view bytes, const std::string& label, const std::string& how,
             const std::string& failure_name) {
        write_file(input_file_, bytes);
        const std::string details = target_.name + ", " + label + " (" + how + ")";
        write_file(info_file_, details + "\n");
        std::snprintf(crash_note, sizeof crash_note,
                      "fuzz: the process ends in %s\n  the input is %s\n  replay it with "
                      "MONOPLANE_FUZZ_REPLAY=%s and this test\n",
                      details.c_str(), input_file_.c_str(), input_file_.c_str());

        Verdict verdict;
        std::string failure;
        const Clock::time_point start = Clock::now();
        watchdog_.started();
        try {
            verdict = target_.run(FuzzInput{bytes, input_file_});
        } catch (const std::exception& error) {
            failure = std::string("exception: ") + error.what();
        } catch (...) {
            failure = "an exception that is no std::exception";
        }
        watchdog_.finished();
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        if (failure.empty() && !verdict.violation.empty()) failure = verdict.violation;
        if (failure.empty() && seconds > input_limit_s_)
            failure = "took " + std::to_string(seconds) + " s";
        if (!failure.empty()) {
            const std::filesystem::path saved =
                folder_ / ("failure-" + failure_name + target_.file_extension);
            write_file(saved, bytes);
            report_.failures.push_back(details + ": " + failure + "\n  input saved as " +
                                       saved.string());
        }
        return failure.empty() && verdict.accepted;
    }

    // A clean end: no input is left behind to be mistaken for a crash's.
    void finish() {
        std::error_code ignored;
        std::filesystem::remove(input_file_, ignored);
        std::filesystem::remove(info_file_, ignored);
        crash_note[0] = '\0';
    }

  private:
    const FuzzTarget& target_;
    FuzzReport& report_;
    std::filesystem::path folder_;
    std::filesystem::path input_file_;
    std::filesystem::path info_file_;
    double input_limit_s_;
    Watchdog watchdog_;
};

constexpr std::size_t kMaxFailures = 10;

}  // namespace

Verdict rejected(const Error& error, const FuzzInput& input) {
    if (error.message.empty()) return violation("an error without a message");
    if (error.message.find(input.file.string()) == std::string::npos)
        return violation("the error does not name the file: " + error.message);
    return {};
}

FuzzReport run_fuzz_target(const FuzzTarget& target) {
    FuzzReport report;
    report.target = target.name;
    report.seed = env_number("MONOPLANE_FUZZ_SEED", 1);
    const std::uint64_t iterations = env_number("MONOPLANE_FUZZ_ITERATIONS", target.iterations);
    const std::uint64_t start = env_number("MONOPLANE_FUZZ_START", 0);
    const auto seconds = static_cast<double>(env_number("MONOPLANE_FUZZ_SECONDS", 15));
    const auto input_limit_s =
        static_cast<double>(env_number("MONOPLANE_FUZZ_INPUT_TIMEOUT_S", 10));
    const Clock::time_point began = Clock::now();
    Session session(target, report, input_limit_s);

    if (const char* replay = std::getenv("MONOPLANE_FUZZ_REPLAY"); replay && *replay != '\0') {
        EXPECT_TRUE(std::filesystem::is_regular_file(replay)) << "no file " << replay;
        const std::string bytes = read_file(replay);
        const bool ok = session.run(bytes, "replay of " + std::string(replay), "as is", "replay");
        std::cout << "fuzz " << target.name << ": replayed " << replay << ", "
                  << (ok ? "accepted" : "rejected") << "\n";
        session.finish();
        return report;
    }

    std::cout << "fuzz " << target.name << ": a crash leaves its input in "
              << (work_folder(target.name) / ("input" + target.file_extension)).string()
              << " (how it was made: input.info)" << std::endl;  // flushed: a crash may follow
    const std::vector<Seed> seeds = load_seeds(target);
    if (seeds.empty()) return report;
    std::vector<std::string> corpus;
    for (std::size_t i = 0; i < seeds.size(); ++i) {
        const Seed& seed = seeds[i];
        const std::size_t failures = report.failures.size();
        const bool ok = session.run(seed.bytes, "seed file " + std::to_string(i),
                                    seed.path.string(), "seed-" + std::to_string(i));
        if (!ok && !seed.regression && report.failures.size() == failures)
            report.seeds_rejected.push_back(seed.path.string());
        if (!seed.regression) corpus.push_back(seed.bytes);
        ++report.seeds_run;
    }

    if (corpus.empty()) {
        ADD_FAILURE() << "fuzz " << target.name << ": no seeds outside regressions/ to mutate";
        return report;
    }
    const Mutator mutator(std::move(corpus), target.dictionary);
    for (std::uint64_t i = start; iterations == 0 || i < start + iterations; ++i) {
        if (report.failures.size() >= kMaxFailures) break;
        if (std::chrono::duration<double>(Clock::now() - began).count() > seconds) {
            report.stopped_by_time = true;
            break;
        }
        const Mutant mutant = mutator.mutant(report.seed, i);
        const std::string label =
            "seed " + std::to_string(report.seed) + ", iteration " + std::to_string(i);
        const std::string name = std::to_string(report.seed) + "-" + std::to_string(i);
        if (session.run(mutant.bytes, label, mutant.history, name)) ++report.mutants_accepted;
        ++report.mutants_run;
    }
    session.finish();
    report.seconds = std::chrono::duration<double>(Clock::now() - began).count();
    std::cout << "fuzz " << target.name << ": " << report.seeds_run << " seeds, "
              << report.mutants_run << " mutants of seed " << report.seed << " from iteration "
              << start << " (" << report.mutants_accepted << " accepted), " << report.seconds
              << " s" << (report.stopped_by_time ? ", stopped by MONOPLANE_FUZZ_SECONDS" : "")
              << "\n";
    return report;
}

void expect_clean(const FuzzReport& report) {
    for (const std::string& failure : report.failures) ADD_FAILURE() << "fuzz " << failure;
    for (const std::string& seed : report.seeds_rejected) {
        ADD_FAILURE() << "fuzz " << report.target << ": the seed " << seed
                      << " is rejected; seeds must be valid (rejected ones belong in "
                         "regressions/)";
    }
}

std::filesystem::path corpus_path(std::string_view name) {
    return std::filesystem::path(MONOPLANE_FUZZ_SOURCE_DIR) / "tests/fuzz/corpus" / name;
}

std::filesystem::path source_path(std::string_view relative) {
    return std::filesystem::path(MONOPLANE_FUZZ_SOURCE_DIR) / relative;
}

std::filesystem::path work_folder(std::string_view target) {
    std::filesystem::path folder = std::filesystem::path(MONOPLANE_FUZZ_WORK_DIR) / target;
    std::filesystem::create_directories(folder);
    return folder;
}

}  // namespace monoplane::fuzz
