// Power analysis results (`monoplane simulate`): for each number of participants n, how many of R
// simulated studies detected the distance effect (the distance term of fit_choice_model() with
// p < alpha), once with the CR1 z test and once with the small-sample CR2 t test. The simulation
// itself lives in the app, which knows the study schedule, the observers and the rig; this file
// holds the grid, the numbers, and their CSV, JSON and figure.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "analysis/proportion.h"

namespace monoplane::analysis::report {

struct PowerPoint {
    int participants = 0;
    int runs = 0;
    int detected = 0;       // CR1 (clustered sandwich, normal z): p < alpha
    int not_estimable = 0;  // fits that failed; counted as not detected by both tests
    double power = 0.0;     // detected / runs
    Interval wilson;        // 95 % Wilson interval of the power (simulation uncertainty)
    int detected_cr2 = 0;   // CR2 with Satterthwaite t: p_cr2 < alpha
    double power_cr2 = 0.0;
    Interval wilson_cr2;
};

// The counts as given; powers and their intervals from them. Requires runs > 0 and every count
// in [0, runs].
PowerPoint power_point(int participants, int runs, int detected, int not_estimable,
                       int detected_cr2);

// The participant counts simulated up to `max_participants`: 2, 4, ..., N for N <= 16, else
// about ten steps from 2 to N (always ending at N). A study of one participant has a single
// cluster, for which clustered standard errors are not defined, so the grid starts at 2
// (N = 1 gives {1}).
std::vector<int> participant_grid(int max_participants);

struct PowerStudy {
    std::string protocol;  // protocol name
    std::string observer;
    std::string hmd;
    std::string distance_term;  // e.g. "mono_plane_m"
    double alpha = 0.05;
    std::uint64_t seed = 0;
    int runs = 0;
    int trials_per_participant = 0;  // data trials
    std::vector<PowerPoint> points;
};

// participants,runs,detected,not_estimable,power,ci_lower,ci_upper,detected_cr2,power_cr2,
// ci_lower_cr2,ci_upper_cr2
std::string power_csv(const PowerStudy& study);
// {"protocol", "observer", "hmd", "alpha", "seed", "runs", "trials_per_participant",
//  "distance_term", "points": [{"participants", "runs", "detected", "not_estimable", "power",
//  "ci_lower", "ci_upper", "detected_cr2", "power_cr2", "ci_lower_cr2", "ci_upper_cr2"}, ...]}
// (docs/analysis.md)
std::string power_json(const PowerStudy& study);
// Power over n of both tests with 95 % Wilson error bars, the conventional 0.8 line and alpha
// (what a null observer such as `chance` should reach).
std::string power_svg(const PowerStudy& study);

}  // namespace monoplane::analysis::report
