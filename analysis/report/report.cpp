// The report's files on disk: the figures, the CSV tables, summary.json, then report.html.
#include "analysis/report/report.h"

#include <fstream>
#include <utility>

#include "analysis/report/psychometric_section.h"

namespace monoplane::analysis::report {

Result<void> write_text_file(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) return Error{"cannot write '" + path.string() + "': cannot open it for writing"};
    out << text;
    out.close();
    if (!out) return Error{"cannot write '" + path.string() + "': write failed (disk full?)"};
    return Ok{};
}

Result<WrittenReport> write_report(const AnalysisResults& r, const std::vector<Figure>& figures,
                                   const std::filesystem::path& dir) {
    WrittenReport written;
    std::error_code ec;
    std::filesystem::create_directories(dir / "figures", ec);
    if (ec) return Error{"cannot create '" + (dir / "figures").string() + "': " + ec.message()};
    for (const Figure& f : figures) {
        const std::filesystem::path path = dir / "figures" / (f.name + ".svg");
        MONOPLANE_TRY(write_text_file(path, f.svg));
        written.figures.push_back(path);
    }
    const std::pair<const char*, std::string> tables[] = {
        {"rates_by_scene.csv", rates_csv(r.by_scene)},
        {"rates_by_distance.csv", rates_csv(r.by_distance)},
        {"rates_by_scene_distance.csv", rates_csv(r.by_scene_distance)},
        {"rates_by_first_scene.csv",
         [&] {
             std::vector<ChoiceRate> rates;
             for (const FirstSceneRate& f : r.by_first_scene) rates.push_back(f.rate);
             return rates_csv(rates);
         }()},
        {"logistic.csv", logistic_csv(r)},
        {"psychometric.csv", psychometric_csv(r)},
        {"questionnaire.csv", questionnaire_csv(r.questionnaire)},
    };
    for (const auto& [name, text] : tables) {
        const std::filesystem::path path = dir / name;
        MONOPLANE_TRY(write_text_file(path, text));
        written.tables.push_back(path);
    }
    written.json = dir / "summary.json";
    MONOPLANE_TRY(write_text_file(written.json, summary_json(r)));
    // Last: a report.html on disk means everything it refers to is there too.
    written.html = dir / "report.html";
    MONOPLANE_TRY(write_text_file(written.html, report_html(r, figures)));
    return written;
}

}  // namespace monoplane::analysis::report
