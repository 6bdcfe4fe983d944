#include "app/commands/output_directory.h"

#include <system_error>

#include "common/result.h"

namespace monoplane::app {

std::filesystem::path prepare_output_directory(const std::string& option, const std::string& path) {
    const std::filesystem::path out(path);
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec || !std::filesystem::is_directory(out)) {
        throw UserError(option + " " + path + ": cannot create the directory (" + ec.message() +
                        ")");
    }
    return out;
}

}  // namespace monoplane::app
