// monoplane: hybrid mono-stereo rendering for VR perception studies (see README.md).
// Exceptions end here: a user error prints its message and exits 1; a session whose OpenXR
// runtime was lost (app/commands/runtime_lost.h) prints its one message and exits 3.
#include <iostream>

#include <CLI/CLI.hpp>

#include "app/commands/commands.h"
#include "app/commands/runtime_lost.h"
#include "app/version/build_info.h"
#include "common/result.h"
#include "renderer/vk/vulkan.h"

int main(int argc, char** argv) {
    using namespace monoplane::app;
    CLI::App root{
        "monoplane - hybrid mono-stereo rendering (Fink et al. 2019) for VR perception studies"};
    root.require_subcommand(1);
    root.fallthrough();  // --device and --validation may follow the command name too
    GlobalOptions global;
    root.add_option("--device", global.device,
                    "Vulkan device: index or part of its name (default: discrete GPU, else "
                    "llvmpipe); see `monoplane devices`");
    // Which build this is, for a lab's records and bug reports: version, git revision, the
    // database schema it writes, build type.
    root.set_version_flag(
        "--version", [] { return version_text(); },
        "Print the version, git revision, database schema and build type");
    root.add_flag("--validation", global.validation,
                  "Enable the Khronos validation layer, its synchronisation validation "
                  "included; any message is an error");
    add_render_command(root, global);
    add_rig_command(root, global);
    add_devices_command(root, global);
    add_protocol_command(root, global);
    add_study_command(root, global);
    add_bench_command(root, global);
    add_analyze_command(root, global);
    add_simulate_command(root, global);
    add_simulate_threshold_command(root, global);
    add_lab_command(root, global);
    try {
        root.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return root.exit(e);
    } catch (const RuntimeLost& e) {
        std::cerr << "monoplane: " << e.what() << "\n";
        return kExitRuntimeLost;
    } catch (const monoplane::UserError& e) {
        std::cerr << "monoplane: " << e.what() << "\n";
        return 1;
    } catch (const vk::SystemError& e) {
        std::cerr << "monoplane: Vulkan error: " << e.what() << "\n";
        return 2;
    }
    return 0;
}
