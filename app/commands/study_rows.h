// The study library's records as the analysis's plain rows (analysis/dataset.h): the app is where
// study/ and analysis/ meet (docs/architecture.md). Also the observer's error model, shared by
// `study run|resume` (the trial's stimulus strength) and `simulate` (power analysis).
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "analysis/dataset.h"
#include "common/result.h"
#include "hmd/profile.h"
#include "study/protocol.h"
#include "study/schedule.h"
#include "study/study_store.h"

namespace monoplane::app {

// The observer's stimulus strength: the rig's largest projection error (pixels) for the trial's
// hybrid alternative at its mono plane (papers/000 Fig. 2, right); 0 when both alternatives are
// stereo-like. Memoised per mono plane: a power analysis asks for the same few distances
// millions of times.
std::function<double(const study::ScheduledTrial&)> trial_error_model(
    const hmd::HmdProfile& hmd, const study::Protocol& protocol);

// One analysis row of a trial record. `reference_mode` is the protocol's first alternative ("" if
// unknown: derive_session_fields() then decides); chose_test and first_scene are left to
// derive_session_fields().
analysis::TrialRow trial_row(const study::TrialRecord& record, const study::SessionInfo& session,
                             const std::string& source, const std::string& reference_mode);

// Every trial and questionnaire answer of a study database, labelled with `path` as their
// source, with derive_session_fields() applied. Opens the database for reading only in effect
// (nothing is written). Errors: the file does not exist or is not a study database, or it holds
// no sessions.
Result<analysis::Dataset> read_study_database(const std::filesystem::path& path);

}  // namespace monoplane::app
