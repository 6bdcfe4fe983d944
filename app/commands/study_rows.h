// The study library's records as the analysis's plain rows (analysis/dataset.h): the app is where
// study/ and analysis/ meet (docs/architecture.md). Also the observer's error model, shared by
// `study run|resume` (the trial's stimulus strength) and `simulate` (power analysis).
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "analysis/dataset.h"
#include "analysis/protocol_versions.h"
#include "common/result.h"
#include "hmd/profile.h"
#include "study/export.h"
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

// What a trial's frame log holds for its frame timing (analysis/frame_timing.h): the frames it
// showed (label1 or label2 on screen; screens between trials are not the trial's) and how many of
// them missed their display slot.
struct TrialFrameCounts {
    int shown = 0;
    int missed = 0;
};

// A session's frame log counted per trial index, as `analyze` counts it. Any time.
std::map<int, TrialFrameCounts> trial_frame_counts(const std::vector<study::FrameRecord>& frames);

// The threshold above which a trial's missed-frame share is flagged: the protocol's
// missed_frame_threshold as the session ran it, or the protocol default when its stored text no
// longer parses. Any time.
double missed_frame_threshold(const study::SessionInfo& session);

// The study library's rule for whether two protocol texts are one experiment
// (study/protocol_design.h), for analysis::check_protocol_versions: each text is parsed once.
// Any time.
analysis::DesignComparison protocol_design_comparison();

// Every trial and questionnaire answer of a study database, labelled with `path` as their
// source, with derive_session_fields() applied: `data` is study::collect_export of `store`, which
// the caller opened read-only (its frames and answers are read here). Errors: it holds no
// sessions.
Result<analysis::Dataset> read_study_database(const std::filesystem::path& path,
                                              const study::StudyStore& store,
                                              const study::ExportData& data);

}  // namespace monoplane::app
