#include <sstream>

#include "app/version/build_info.h"
#include "study/study_store.h"

namespace monoplane::app {

std::string software_version() {
    const BuildInfo& info = build_info();
    return "monoplane " + std::string(info.version) + " (" + std::string(info.git_revision) + ")";
}

std::string version_text() {
    const BuildInfo& info = build_info();
    std::ostringstream out;
    out << "monoplane " << info.version << "\n"
        << "git revision: " << info.git_revision << "\n"
        << "study database schema: " << study::StudyStore::kSchemaVersion << "\n"
        << "build type: " << info.build_type;  // CLI11 ends the line
    return out.str();
}

}  // namespace monoplane::app
