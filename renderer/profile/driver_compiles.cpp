#include "renderer/profile/driver_compiles.h"

#include <dlfcn.h>
#include <link.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

// LLVM's C API handles, opaque here: monoplane does not link LLVM, it only passes them on.
using Opaque = void*;
using RunPasses = Opaque (*)(Opaque module, const char* passes, Opaque machine, Opaque options);
using PointerToGlobal = void* (*)(Opaque engine, Opaque global);

std::atomic<std::uint64_t> compiled_modules{0};
std::atomic<std::uint64_t> compile_nanoseconds{0};
std::atomic<Opaque> last_module{nullptr};

// The path of the libLLVM loaded into the process, or "" when none is.
std::string loaded_llvm() {
    std::string path;
    dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void* out) {
            if (info->dlpi_name == nullptr || std::strstr(info->dlpi_name, "libLLVM") == nullptr) {
                return 0;
            }
            *static_cast<std::string*>(out) = info->dlpi_name;
            return 1;
        },
        &path);
    return path;
}

// The definition the driver meant: the one in the libLLVM it loaded (which is not in the global
// scope, so RTLD_NEXT would not find it).
void* real_llvm_symbol(const char* name) {
    const std::string path = loaded_llvm();
    void* library = path.empty() ? nullptr : dlopen(path.c_str(), RTLD_LAZY | RTLD_NOLOAD);
    void* symbol = library != nullptr ? dlsym(library, name) : nullptr;
    if (symbol == nullptr) {
        // Only a libLLVM calls these names; one that lacks them cannot have called.
        std::fprintf(stderr, "monoplane: cannot find LLVM's %s for the driver\n", name);
        std::abort();
    }
    return symbol;
}

class CompileTimer {
  public:
    CompileTimer() : start_(std::chrono::steady_clock::now()) {}
    CompileTimer(const CompileTimer&) = delete;
    CompileTimer& operator=(const CompileTimer&) = delete;
    ~CompileTimer() {
        const auto elapsed = std::chrono::steady_clock::now() - start_;
        compile_nanoseconds.fetch_add(
            static_cast<std::uint64_t>(
                std::chrono::duration_cast<std::chrono::nanoseconds>(elapsed).count()),
            std::memory_order_relaxed);
    }

  private:
    std::chrono::steady_clock::time_point start_;
};

}  // namespace

// The interposed entry points (exported from the executable: monoplane_profile's link options).
extern "C" {

__attribute__((visibility("default"))) Opaque LLVMRunPasses(Opaque module, const char* passes,
                                                            Opaque machine, Opaque options) {
    static const auto real = reinterpret_cast<RunPasses>(real_llvm_symbol("LLVMRunPasses"));
    // gallivm runs more than one pipeline over a module: a module is one compile.
    if (last_module.exchange(module) != module) {
        compiled_modules.fetch_add(1, std::memory_order_relaxed);
    }
    const CompileTimer timer;
    return real(module, passes, machine, options);
}

__attribute__((visibility("default"))) void* LLVMGetPointerToGlobal(Opaque engine, Opaque global) {
    static const auto real =
        reinterpret_cast<PointerToGlobal>(real_llvm_symbol("LLVMGetPointerToGlobal"));
    // MCJIT generates the machine code of the whole module on the first look-up.
    const CompileTimer timer;
    return real(engine, global);
}

}  // extern "C"

namespace monoplane::profile {

DriverCompiles driver_compiles() {
    DriverCompiles now;
    now.modules = compiled_modules.load(std::memory_order_relaxed);
    // A driver that ever compiled through these entry points compiles through LLVM; lavapipe
    // does so for every pipeline it creates, so by the first frame the count is live.
    now.measurable = now.modules > 0;
    now.seconds = static_cast<double>(compile_nanoseconds.load(std::memory_order_relaxed)) * 1e-9;
    return now;
}

DriverCompiles compiles_between(const DriverCompiles& earlier, const DriverCompiles& later) {
    return DriverCompiles{later.measurable, later.modules - earlier.modules,
                          later.seconds - earlier.seconds};
}

}  // namespace monoplane::profile
