// Power analysis results (`monoplane simulate`): for each number of participants n, how many of R
// simulated studies detected the distance effect (the distance term of fit_choice_model() with
// p < alpha). The simulation itself lives in the app, which knows the study schedule, the
// observers and the rig; this file holds the grid, the numbers, and their CSV, JSON and figure.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "analysis/proportion.h"

namespace monoplane::analysis::report {

struct PowerPoint {
    int participants = 0;
    int runs = 0;
    int detected = 0;
    int not_estimable = 0;  // fits that failed; counted as not detected
    double power = 0.0;     // detected / runs
    Interval wilson;        // 95 % Wilson interval of the power (simulation uncertainty)
};

// detected, runs and not_estimable as counted; power and its interval from them. runs > 0.
PowerPoint power_point(int participants, int runs, int detected, int not_estimable);

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

// participants,runs,detected,not_estimable,power,ci_lower,ci_upper
std::string power_csv(const PowerStudy& study);
// {"protocol", "observer", "hmd", "alpha", "seed", "runs", "trials_per_participant",
//  "distance_term", "points": [{"participants", "runs", "detected", "not_estimable", "power",
//  "ci_lower", "ci_upper"}, ...]} (docs/analysis.md)
std::string power_json(const PowerStudy& study);
// Power over n with 95 % Wilson error bars and the conventional 0.8 line.
std::string power_svg(const PowerStudy& study);

}  // namespace monoplane::analysis::report
