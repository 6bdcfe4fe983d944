#include "app/commands/study_scenes.h"

#include <iostream>
#include <system_error>
#include <utility>

#include "app/commands/scene_source.h"

namespace monoplane::app {
namespace {

// The loader's list of files, each digested. Paths are made absolute (the loader reports them
// as it opened them) so that the record names the file wherever the experimenter resumes from.
Result<std::vector<study::SceneFileRecord>> digest_files_read(
    const std::string& scene, const std::vector<std::filesystem::path>& files_read) {
    std::vector<study::SceneFileRecord> records;
    for (const std::filesystem::path& file : files_read) {
        std::error_code ignored;
        const std::filesystem::path absolute = std::filesystem::absolute(file, ignored);
        Result<study::FileDigest> digest = study::digest_file(absolute);
        MONOPLANE_TRY(digest);
        records.push_back(
            {scene, static_cast<int>(records.size()), absolute.lexically_normal(), *digest});
    }
    return records;
}

Result<ImportedStudyScene> load_one(const std::string& scene, const std::filesystem::path& path) {
    SceneSource source;
    source.file = path;
    source.label = scene;
    scenes::GltfLoadReport report;
    // Detail and seed apply to procedural scenes only.
    Result<scenes::Scene> loaded =
        load_scene(source, scenes::Detail::Low, scenes::kDefaultSeed, &report);
    MONOPLANE_TRY(loaded);
    Result<std::vector<study::SceneFileRecord>> files = digest_files_read(scene, report.files_read);
    MONOPLANE_TRY(files);
    return ImportedStudyScene{std::move(loaded).value(), std::move(files).value()};
}

std::string count_of(std::size_t count, const std::string& noun) {
    return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

void print_loaded(const std::string& scene, const ImportedStudyScene& imported) {
    std::cerr << "scene '" << scene << "': " << describe_size(imported.scene) << ", read from "
              << count_of(imported.files.size(), "file") << " (SHA-256 digests taken)\n";
}

}  // namespace

Result<ImportedStudyScenes> load_imported_scenes(
    const std::map<std::string, std::filesystem::path>& paths, const std::string& protocol) {
    ImportedStudyScenes scenes;
    std::string problems;
    for (const auto& [scene, path] : paths) {
        Result<ImportedStudyScene> imported = load_one(scene, path);
        if (!imported) {
            problems += (problems.empty() ? "" : "\n") + std::string("protocol '") + protocol +
                        "': scenes entry '" + scene +
                        "' cannot be used: " + imported.error().message;
            continue;
        }
        print_loaded(scene, *imported);
        scenes.emplace(scene, std::move(imported).value());
    }
    if (!problems.empty()) return Error{problems};
    return scenes;
}

std::string describe_size(const scenes::Scene& scene) {
    return count_of(scene.triangle_count(), "triangle") + " in " +
           count_of(scene.chunks.size(), "chunk");
}

std::vector<study::SceneFileRecord> scene_file_records(const ImportedStudyScenes& scenes) {
    std::vector<study::SceneFileRecord> records;
    for (const auto& [scene, imported] : scenes) {
        records.insert(records.end(), imported.files.begin(), imported.files.end());
    }
    return records;
}

void check_scene_files_before_resume(study::StudyStore& store, const study::SessionInfo& session,
                                     bool accept_changes) {
    const std::vector<study::SceneFileChange> changes =
        study::changed_scene_files(session.scene_files);
    const std::string name = "session " + std::to_string(session.id);
    if (changes.empty()) {
        if (!session.scene_files.empty()) {
            std::cerr << name << ": all " << session.scene_files.size()
                      << " scene files as recorded when it began (SHA-256)\n";
        }
        return;
    }
    std::string lines;
    for (const study::SceneFileChange& change : changes) lines += "\n  " + study::describe(change);
    if (!accept_changes) {
        throw UserError(name + " is not resumed: scene files changed since it began, so its " +
                        "remaining trials would show other scenes than its first:" + lines +
                        "\nRestore the files, or resume with --accept-changed-scenes (the " +
                        "session's notes will record it).");
    }
    store
        .add_session_note(session.id, "study resume --accept-changed-scenes: scene files " +
                                          std::string("changed since the session began:") + lines)
        .value_or_throw();
    std::cerr << "warning: " << name << " resumes with changed scene files (recorded in its "
              << "notes):" << lines << "\n";
}

}  // namespace monoplane::app
