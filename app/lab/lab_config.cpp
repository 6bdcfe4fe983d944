#include "app/lab/lab_config.h"

#include <cstdlib>
#include <fstream>
#include <system_error>

#include <toml++/toml.h>

namespace monoplane::lab {

namespace fs = std::filesystem;

fs::path lab_config_file() {
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
        return fs::path(xdg) / "monoplane" / "lab.toml";
    if (const char* home = std::getenv("HOME"); home && *home)
        return fs::path(home) / ".config" / "monoplane" / "lab.toml";
    return {};
}

Result<LabConfig> read_lab_config(const fs::path& file) {
    LabConfig config;
    std::error_code ec;
    if (file.empty() || !fs::exists(file, ec)) return config;
    try {
        const toml::table table = toml::parse_file(file.string());
        config.db = table["db"].value_or(std::string());
        config.protocols = table["protocols"].value_or(std::string());
    } catch (const toml::parse_error& e) {
        return Error{"the launcher's settings '" + file.string() +
                     "': " + std::string(e.description())};
    }
    return config;
}

Result<void> write_lab_config(const fs::path& file, const LabConfig& config) {
    if (file.empty()) return Error{"no settings folder: neither XDG_CONFIG_HOME nor HOME is set"};
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    toml::table table;
    if (!config.db.empty()) table.insert("db", fs::absolute(config.db, ec).string());
    if (!config.protocols.empty())
        table.insert("protocols", fs::absolute(config.protocols, ec).string());
    const fs::path temporary = fs::path(file).concat(".tmp");
    {
        std::ofstream out(temporary, std::ios::trunc);
        out << "# monoplane lab: the last study database and protocols folder\n" << table << "\n";
        if (!out.flush()) return Error{"cannot write '" + temporary.string() + "'"};
    }
    fs::rename(temporary, file, ec);
    if (ec) return Error{"cannot replace '" + file.string() + "': " + ec.message()};
    return Ok{};
}

}  // namespace monoplane::lab
