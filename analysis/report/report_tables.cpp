// The report's CSV tables of rates and questionnaire answers (logistic.csv and psychometric.csv are
// their sections').
#include "analysis/report/report.h"

#include <algorithm>
#include <string>
#include <vector>

#include "analysis/report/text_output.h"

namespace monoplane::analysis::report {
namespace {

std::string rate_fields(const ChoiceRate& r) {
    return csv_line({r.scene, number_text(r.mono_plane), std::to_string(r.test_chosen),
                     std::to_string(r.n), number_text(r.rate), number_text(r.wilson.lower),
                     number_text(r.wilson.upper), number_text(r.clopper_pearson.lower),
                     number_text(r.clopper_pearson.upper), number_text(r.binomial_p)});
}

}  // namespace

std::string rates_csv(const std::vector<ChoiceRate>& rates) {
    std::string out = csv_line({"scene", "mono_plane", "test_chosen", "n", "rate", "wilson_lower",
                                "wilson_upper", "cp_lower", "cp_upper", "binomial_p"});
    for (const ChoiceRate& r : rates) out += rate_fields(r);
    return out;
}

std::string questionnaire_csv(const std::vector<ItemSummary>& items) {
    int points = 0;
    for (const ItemSummary& item : items) {
        points =
            std::max(points, std::max(item.scale_points, static_cast<int>(item.counts.size())));
    }
    std::vector<std::string> header = {"item",   "text", "scale_points", "n",   "mean", "sd",
                                       "median", "q1",   "q3",           "min", "max"};
    for (int k = 1; k <= points; ++k) header.push_back("count_" + std::to_string(k));
    std::string out = csv_line(header);
    for (const ItemSummary& item : items) {
        const Summary& s = item.summary;
        std::vector<std::string> row = {
            std::to_string(item.item), item.text,           std::to_string(item.scale_points),
            std::to_string(s.n),       number_text(s.mean), number_text(s.sd),
            number_text(s.median),     number_text(s.q1),   number_text(s.q3),
            number_text(s.min),        number_text(s.max)};
        for (int k = 0; k < points; ++k) {
            row.push_back(k < static_cast<int>(item.counts.size())
                              ? std::to_string(item.counts[k])
                              : (k < item.scale_points ? "0" : ""));
        }
        out += csv_line(row);
    }
    return out;
}

}  // namespace monoplane::analysis::report
