#include "study/store_schema.h"

#include <array>

namespace monoplane::study {
namespace {

// Version 1 (the first release). docs/data.md describes every table and column; keep the two in
// step.
// - Integer nanoseconds of the monotonic clock for durations and event times.
// - Render modes and event kinds as their stable text names, so the file reads without the code.
// - 64-bit unsigned values (seed, protocol hash) as text: SQLite integers are signed.
// - CHECK constraints make a wrong value a refused write rather than a silent bad row.
constexpr std::string_view kVersion1 = R"sql(
CREATE TABLE participants (
    id                INTEGER PRIMARY KEY,
    code              TEXT NOT NULL UNIQUE
                      CHECK (length(code) BETWEEN 1 AND 64 AND code NOT GLOB '*[^A-Za-z0-9_-]*'),
    participant_index INTEGER NOT NULL UNIQUE CHECK (participant_index >= 0),
    created_utc       TEXT NOT NULL
);
CREATE TABLE sessions (
    id               INTEGER PRIMARY KEY,
    participant_id   INTEGER NOT NULL REFERENCES participants(id),
    protocol_name    TEXT NOT NULL,
    protocol_hash    TEXT NOT NULL,
    protocol_text    TEXT NOT NULL,
    seed             TEXT NOT NULL,
    block_order      TEXT NOT NULL,
    software_version TEXT NOT NULL,
    hmd              TEXT NOT NULL,
    runtime          TEXT NOT NULL,
    device           TEXT NOT NULL,
    observer         TEXT NOT NULL,
    started_utc      TEXT NOT NULL,
    ended_utc        TEXT,
    status           TEXT NOT NULL
                     CHECK (status IN ('running', 'paused', 'completed', 'aborted'))
);
CREATE TABLE trials (
    session_id         INTEGER NOT NULL REFERENCES sessions(id),
    trial_index        INTEGER NOT NULL CHECK (trial_index >= 0),
    practice           INTEGER NOT NULL CHECK (practice IN (0, 1)),
    block              INTEGER NOT NULL CHECK (block >= -1),
    scene              TEXT NOT NULL,
    mono_plane         REAL NOT NULL,
    label1_alternative INTEGER NOT NULL CHECK (label1_alternative IN (0, 1)),
    label1_mode        TEXT NOT NULL,
    label2_mode        TEXT NOT NULL,
    decided            INTEGER NOT NULL DEFAULT 0 CHECK (decided IN (0, 1)),
    choice             INTEGER CHECK (choice IN (1, 2)),
    chosen_mode        TEXT,
    valid              INTEGER CHECK (valid IN (0, 1)),
    switches           INTEGER CHECK (switches >= 0),
    time_label1_ns     INTEGER CHECK (time_label1_ns >= 0),
    time_label2_ns     INTEGER CHECK (time_label2_ns >= 0),
    decision_time_ns   INTEGER CHECK (decision_time_ns >= 0),
    decided_utc        TEXT,
    PRIMARY KEY (session_id, trial_index),
    CHECK (decided = (choice IS NOT NULL))
);
CREATE TABLE events (
    id          INTEGER PRIMARY KEY,
    session_id  INTEGER NOT NULL,
    trial_index INTEGER NOT NULL,
    kind        TEXT NOT NULL
                CHECK (kind IN ('shown', 'switched', 'confirmed', 'refused', 'paused', 'resumed',
                                'aborted')),
    label       INTEGER NOT NULL CHECK (label IN (0, 1, 2)),
    time_ns     INTEGER NOT NULL,
    frame       INTEGER NOT NULL CHECK (frame >= -1),
    FOREIGN KEY (session_id, trial_index) REFERENCES trials(session_id, trial_index)
);
CREATE INDEX events_by_session ON events(session_id, id);
CREATE TABLE answers (
    session_id   INTEGER NOT NULL REFERENCES sessions(id),
    item         INTEGER NOT NULL CHECK (item >= 0),
    text         TEXT NOT NULL,
    answer       INTEGER NOT NULL CHECK (answer >= 1),
    answered_utc TEXT NOT NULL,
    PRIMARY KEY (session_id, item)
);
)sql";

// Version 2 (issue 17): the render configuration each session used (the protocol's [render]
// table, with --detail's override), and the frame and head log of headset sessions. Version 1
// sessions rendered without anti-aliasing or SSAO; their detail was not recorded (NULL: NA).
constexpr std::string_view kVersion2 = R"sql(
ALTER TABLE sessions ADD COLUMN render_anti_aliasing TEXT NOT NULL DEFAULT 'none';
ALTER TABLE sessions ADD COLUMN render_ssao TEXT NOT NULL DEFAULT 'off';
ALTER TABLE sessions ADD COLUMN render_detail TEXT;
CREATE TABLE frames (
    session_id      INTEGER NOT NULL REFERENCES sessions(id),
    frame           INTEGER NOT NULL CHECK (frame >= 0),
    trial_index     INTEGER CHECK (trial_index >= 0),
    shown           TEXT NOT NULL
                    CHECK (shown IN ('label1', 'label2', 'neutral', 'paused', 'questionnaire',
                                     'finished')),
    display_time_ns INTEGER NOT NULL,
    cpu_ms          REAL NOT NULL CHECK (cpu_ms >= 0),
    gpu_ms          REAL CHECK (gpu_ms >= 0),
    missed          INTEGER NOT NULL CHECK (missed IN (0, 1)),
    head_x          REAL, head_y REAL, head_z REAL,
    head_qw         REAL, head_qx REAL, head_qy REAL, head_qz REAL,
    PRIMARY KEY (session_id, frame)
);
)sql";

// Version 3 (issue 19): imported (glTF) scenes. Every file each imported scene of a session was
// read from when the session began, with its size and SHA-256 as `sha256sum` prints it, so a
// reviewer can check which bytes the participants saw and `study resume` can refuse changed
// files; and notes for the reviewer, such as a resume that accepted changed files. Sessions
// of versions 1 and 2 showed built-in scenes only: they have no rows here.
constexpr std::string_view kVersion3 = R"sql(
CREATE TABLE scene_files (
    session_id INTEGER NOT NULL REFERENCES sessions(id),
    scene      TEXT NOT NULL CHECK (length(scene) > 0),
    file_index INTEGER NOT NULL CHECK (file_index >= 0),
    path       TEXT NOT NULL CHECK (substr(path, 1, 1) = '/'),
    size_bytes INTEGER NOT NULL CHECK (size_bytes >= 0),
    sha256     TEXT NOT NULL CHECK (length(sha256) = 64 AND sha256 NOT GLOB '*[^0-9a-f]*'),
    PRIMARY KEY (session_id, scene, file_index)
);
CREATE TABLE session_notes (
    id         INTEGER PRIMARY KEY,
    session_id INTEGER NOT NULL REFERENCES sessions(id),
    noted_utc  TEXT NOT NULL,
    note       TEXT NOT NULL CHECK (length(note) > 0)
);
)sql";

// Version 4 (issue 20): each frame's mono plane (hybrid modes; with hybrid-auto the renderer
// chooses it every frame). Earlier sessions' frames have NULL: their m is the trial's.
constexpr std::string_view kVersion4 = R"sql(
ALTER TABLE frames ADD COLUMN mono_plane REAL CHECK (mono_plane > 0);
)sql";

// Version 5 (issue 21): adaptive procedures. A staircase session's data trials are slots whose
// mono plane is chosen only as each starts; their seeded order, scenes and blind labels are
// stored before the first trial in planned_trials, and a slot gets its row in `trials` (with the
// chosen m) when it starts. Sessions record their procedure; earlier ones were all constant.
constexpr std::string_view kVersion5 = R"sql(
ALTER TABLE sessions ADD COLUMN procedure TEXT NOT NULL DEFAULT 'constant'
    CHECK (procedure IN ('constant', 'staircase'));
CREATE TABLE planned_trials (
    session_id         INTEGER NOT NULL REFERENCES sessions(id),
    trial_index        INTEGER NOT NULL CHECK (trial_index >= 0),
    block              INTEGER NOT NULL CHECK (block >= 0),
    scene              TEXT NOT NULL,
    label1_alternative INTEGER NOT NULL CHECK (label1_alternative IN (0, 1)),
    label1_mode        TEXT NOT NULL,
    label2_mode        TEXT NOT NULL,
    PRIMARY KEY (session_id, trial_index)
);
)sql";

// Version 6 (issue 29): what each frame made the renderer build: pipelines monoplane created and
// shader modules the driver compiled (NULL where the driver's compiles cannot be counted). After
// warm-up both are 0; a driver compiling variants while the head turns stalls those frames.
constexpr std::string_view kVersion6 = R"sql(
ALTER TABLE frames ADD COLUMN pipelines_created INTEGER CHECK (pipelines_created >= 0);
ALTER TABLE frames ADD COLUMN driver_compiles INTEGER CHECK (driver_compiles >= 0);
)sql";

// Version 7 (issue 30): a study day. A participant may come back for further sessions, each with
// its number; the participant's study-wide number (which picks the Latin-square row, so sites
// and lab PCs can share one rotation) and variables are kept with the participant; a constant
// session shows each condition `repetitions` times; experimenter notes say who wrote them and
// when in the session; the participant's screens (instructions, ready, breaks, end) are events
// and frames of their own. Rows written before version 7 read as: participant number = the
// participant's index, session 1, repetition 1, notes from the software.
// SQLite cannot change a CHECK constraint or drop a NOT NULL, so events and frames are rebuilt:
// a new table, the rows copied, the old one dropped and the new one renamed, its index recreated;
// all in the migration's transaction, so a failure leaves the version-6 file as it was.
constexpr std::string_view kVersion7 = R"sql(
ALTER TABLE participants ADD COLUMN participant_number INTEGER NOT NULL DEFAULT 0
    CHECK (participant_number >= 0);
UPDATE participants SET participant_number = participant_index;
CREATE UNIQUE INDEX participants_by_number ON participants(participant_number);
CREATE TABLE participant_variables (
    participant_id INTEGER NOT NULL REFERENCES participants(id),
    name           TEXT NOT NULL
                   CHECK (length(name) BETWEEN 1 AND 32 AND name GLOB '[a-z]*'
                          AND name NOT GLOB '*[^a-z0-9_]*'),
    type           TEXT NOT NULL CHECK (type IN ('integer', 'number', 'choice', 'text')),
    value          TEXT NOT NULL,
    PRIMARY KEY (participant_id, name)
);
ALTER TABLE sessions ADD COLUMN session_number INTEGER NOT NULL DEFAULT 1
    CHECK (session_number >= 1);
CREATE UNIQUE INDEX sessions_by_participant ON sessions(participant_id, session_number);
ALTER TABLE trials ADD COLUMN repetition INTEGER NOT NULL DEFAULT 1 CHECK (repetition >= 1);
ALTER TABLE session_notes ADD COLUMN source TEXT NOT NULL DEFAULT 'software'
    CHECK (source IN ('software', 'window', 'command'));
ALTER TABLE session_notes ADD COLUMN runtime_time_ns INTEGER CHECK (runtime_time_ns >= 0);
ALTER TABLE session_notes ADD COLUMN trial_index INTEGER CHECK (trial_index >= 0);

CREATE TABLE events_v7 (
    id          INTEGER PRIMARY KEY,
    session_id  INTEGER NOT NULL REFERENCES sessions(id),
    trial_index INTEGER,
    kind        TEXT NOT NULL
                CHECK (kind IN ('shown', 'switched', 'confirmed', 'refused', 'paused', 'resumed',
                                'aborted', 'instructions_shown', 'instructions_confirmed',
                                'ready_shown', 'ready_confirmed', 'break_started', 'break_ended',
                                'end_shown')),
    label       INTEGER NOT NULL CHECK (label IN (0, 1, 2)),
    time_ns     INTEGER NOT NULL,
    frame       INTEGER NOT NULL CHECK (frame >= -1),
    page        INTEGER CHECK (page >= 0),
    FOREIGN KEY (session_id, trial_index) REFERENCES trials(session_id, trial_index),
    -- A screen is no trial; a trial's event always names its trial.
    CHECK ((trial_index IS NULL) = (kind IN ('instructions_shown', 'instructions_confirmed',
                                             'ready_shown', 'ready_confirmed', 'break_started',
                                             'break_ended', 'end_shown'))),
    CHECK ((page IS NOT NULL) = (kind IN ('instructions_shown', 'instructions_confirmed')))
);
INSERT INTO events_v7 (id, session_id, trial_index, kind, label, time_ns, frame)
    SELECT id, session_id, trial_index, kind, label, time_ns, frame FROM events;
DROP TABLE events;
ALTER TABLE events_v7 RENAME TO events;
CREATE INDEX events_by_session ON events(session_id, id);

CREATE TABLE frames_v7 (
    session_id        INTEGER NOT NULL REFERENCES sessions(id),
    frame             INTEGER NOT NULL CHECK (frame >= 0),
    trial_index       INTEGER CHECK (trial_index >= 0),
    shown             TEXT NOT NULL
                      CHECK (shown IN ('label1', 'label2', 'neutral', 'paused', 'questionnaire',
                                       'finished', 'instructions', 'ready', 'break', 'end')),
    display_time_ns   INTEGER NOT NULL,
    cpu_ms            REAL NOT NULL CHECK (cpu_ms >= 0),
    gpu_ms            REAL CHECK (gpu_ms >= 0),
    missed            INTEGER NOT NULL CHECK (missed IN (0, 1)),
    head_x            REAL, head_y REAL, head_z REAL,
    head_qw           REAL, head_qx REAL, head_qy REAL, head_qz REAL,
    mono_plane        REAL CHECK (mono_plane > 0),
    pipelines_created INTEGER CHECK (pipelines_created >= 0),
    driver_compiles   INTEGER CHECK (driver_compiles >= 0),
    PRIMARY KEY (session_id, frame)
);
INSERT INTO frames_v7 SELECT session_id, frame, trial_index, shown, display_time_ns, cpu_ms,
    gpu_ms, missed, head_x, head_y, head_z, head_qw, head_qx, head_qy, head_qz, mono_plane,
    pipelines_created, driver_compiles FROM frames;
DROP TABLE frames;
ALTER TABLE frames_v7 RENAME TO frames;
)sql";

// Version 8 (issue 42): integrity across files, runs and decisions about sessions.
// - sessions.session_uuid: made when a session starts (a random, version-4 UUID), so the same
//   session found in two files (a copy, a backup) is known as one. Sessions written before
//   version 8 get one derived from what identifies them (store_open.cpp: derive_session_uuids),
//   the same in every copy and every read, whether the file was migrated or only read.
// - session_runs: each run of a session (its start and every resume): when, where, which
//   runtime, the frame it started at, and the offset that puts its runtime's clock on the
//   session's time axis (a restarted runtime starts its clock again).
// - trials.runs: how many runs a trial spanned (1 + the interruptions during it).
// - events: kinds for decisions about a session (session_abandoned, protocol_changed,
//   protocol_text_changed, run_started), with their reason in `detail`; rebuilt as in version 7.
constexpr std::string_view kVersion8 = R"sql(
ALTER TABLE sessions ADD COLUMN session_uuid TEXT
    CHECK (length(session_uuid) = 36 AND session_uuid NOT GLOB '*[^0-9a-f-]*');
CREATE TABLE session_runs (
    session_id      INTEGER NOT NULL REFERENCES sessions(id),
    run             INTEGER NOT NULL CHECK (run >= 1),
    started_utc     TEXT NOT NULL,
    host            TEXT NOT NULL,
    pid             INTEGER NOT NULL CHECK (pid >= 0),
    runtime         TEXT NOT NULL,
    first_frame     INTEGER NOT NULL CHECK (first_frame >= 0),
    clock_offset_ns INTEGER NOT NULL,
    PRIMARY KEY (session_id, run)
);
ALTER TABLE trials ADD COLUMN runs INTEGER NOT NULL DEFAULT 1 CHECK (runs >= 1);

CREATE TABLE events_v8 (
    id          INTEGER PRIMARY KEY,
    session_id  INTEGER NOT NULL REFERENCES sessions(id),
    trial_index INTEGER,
    kind        TEXT NOT NULL
                CHECK (kind IN ('shown', 'switched', 'confirmed', 'refused', 'paused', 'resumed',
                                'aborted', 'instructions_shown', 'instructions_confirmed',
                                'ready_shown', 'ready_confirmed', 'break_started', 'break_ended',
                                'end_shown', 'session_abandoned', 'protocol_changed',
                                'protocol_text_changed', 'run_started')),
    label       INTEGER NOT NULL CHECK (label IN (0, 1, 2)),
    time_ns     INTEGER NOT NULL,
    frame       INTEGER NOT NULL CHECK (frame >= -1),
    page        INTEGER CHECK (page >= 0),
    detail      TEXT,
    FOREIGN KEY (session_id, trial_index) REFERENCES trials(session_id, trial_index),
    -- A screen or a decision about the session is no trial; a trial's event names its trial.
    CHECK ((trial_index IS NULL) = (kind NOT IN ('shown', 'switched', 'confirmed', 'refused',
                                                 'paused', 'resumed', 'aborted'))),
    CHECK ((page IS NOT NULL) = (kind IN ('instructions_shown', 'instructions_confirmed'))),
    CHECK ((detail IS NOT NULL) = (kind IN ('session_abandoned', 'protocol_changed',
                                            'protocol_text_changed')))
);
INSERT INTO events_v8 (id, session_id, trial_index, kind, label, time_ns, frame, page)
    SELECT id, session_id, trial_index, kind, label, time_ns, frame, page FROM events;
DROP TABLE events;
ALTER TABLE events_v8 RENAME TO events;
CREATE INDEX events_by_session ON events(session_id, id);
)sql";

// Version 9 (issue 43, answers from keys): every press of the participant's answer channels, the
// controller's buttons and the [responses] keys (from the experimenter window or an evdev
// device), with its source, whatever it changed. A table of its own rather than event kinds:
// presses are input, not changes of what was shown, and the events keep their meaning for every
// reader that replays them. Older sessions have no rows.
constexpr std::string_view kVersion9 = R"sql(
CREATE TABLE presses (
    id          INTEGER PRIMARY KEY,
    session_id  INTEGER NOT NULL REFERENCES sessions(id),
    trial_index INTEGER,
    source      TEXT NOT NULL CHECK (source IN ('controller', 'keyboard', 'device')),
    action      TEXT NOT NULL CHECK (action IN ('switch', 'confirm', 'pause')),
    key         TEXT,
    screen      TEXT NOT NULL,
    time_ns     INTEGER NOT NULL,
    FOREIGN KEY (session_id, trial_index) REFERENCES trials(session_id, trial_index),
    CHECK ((key IS NULL) = (source = 'controller'))
);
CREATE INDEX presses_by_session ON presses(session_id, id);
)sql";

// Version 10 (issue 45, eye gaze): per frame, the eye tracker's sample when the protocol asked
// for gaze ([gaze] record) and the runtime tracks the eyes, and the hybrid error at the gaze
// point where it is derived, with the depth of the point (NULL: the ray met nothing, the sky) and
// the mono plane the error is for. NULL everywhere else, and in every older session. The partial
// index answers "does this session hold gaze" (study list, the export) without reading a frame
// log that holds none.
constexpr std::string_view kVersion10 = R"sql(
ALTER TABLE frames ADD COLUMN gaze_valid INTEGER CHECK (gaze_valid IN (0, 1));
ALTER TABLE frames ADD COLUMN gaze_dir_x REAL;
ALTER TABLE frames ADD COLUMN gaze_dir_y REAL;
ALTER TABLE frames ADD COLUMN gaze_dir_z REAL;
ALTER TABLE frames ADD COLUMN gaze_error_arcmin REAL;
ALTER TABLE frames ADD COLUMN gaze_depth_m REAL;
ALTER TABLE frames ADD COLUMN gaze_mono_plane_m REAL;
CREATE INDEX frames_with_gaze ON frames(session_id) WHERE gaze_valid IS NOT NULL;
)sql";

constexpr std::array<std::string_view, 10> kMigrations = {
    kVersion1, kVersion2, kVersion3, kVersion4, kVersion5,
    kVersion6, kVersion7, kVersion8, kVersion9, kVersion10};

}  // namespace

std::span<const std::string_view> store_migrations() {
    return kMigrations;
}

}  // namespace monoplane::study
