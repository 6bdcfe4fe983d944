#include "study/frame_queue.h"

#include <string>

namespace monoplane::study {

using sqlite::Statement;

void FrameQueue::add(std::int64_t session_id, const FrameRecord& frame) {
    rows_.push_back({session_id, frame});
}

void FrameQueue::add_gpu_ms(std::int64_t session_id, std::int64_t frame, double gpu_ms,
                            std::optional<double> mono_plane) {
    gpu_.push_back({session_id, frame, gpu_ms, mono_plane});
}

void FrameQueue::clear() {
    rows_.clear();
    gpu_.clear();
}

Result<void> FrameQueue::write(const sqlite::Connection& db) const {
    if (empty()) return Ok{};
    Result<Statement> insert = Statement::prepare(
        db,
        "INSERT OR REPLACE INTO frames (session_id, frame, trial_index, shown, display_time_ns, "
        "cpu_ms, gpu_ms, missed, head_x, head_y, head_z, head_qw, head_qx, head_qy, head_qz, "
        "pipelines_created, driver_compiles, gaze_valid, gaze_dir_x, gaze_dir_y, gaze_dir_z, "
        "gaze_error_arcmin, gaze_depth_m, gaze_mono_plane_m) "
        "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    MONOPLANE_TRY(insert);
    for (const Row& row : rows_) {
        const FrameRecord& f = row.frame;
        Statement& s = insert.value();
        s.reset();
        s.bind(1, row.session_id).bind(2, f.frame).bind(3, f.trial_index).bind(4, f.shown);
        s.bind(5, f.display_time_ns).bind(6, f.cpu_ms).bind(7, f.gpu_ms).bind(8, f.missed ? 1 : 0);
        for (std::size_t i = 0; i < 7; ++i) {
            s.bind(9 + static_cast<int>(i),
                   f.head ? std::optional<double>((*f.head)[i]) : std::nullopt);
        }
        s.bind(16, f.pipelines_created).bind(17, f.driver_compiles);
        s.bind(18, f.gaze ? std::optional<std::int64_t>(f.gaze->valid ? 1 : 0) : std::nullopt);
        for (std::size_t i = 0; i < 3; ++i) {
            // A direction only where the sample was valid.
            s.bind(19 + static_cast<int>(i), f.gaze && f.gaze->valid
                                                 ? std::optional<double>(f.gaze->direction[i])
                                                 : std::nullopt);
        }
        const std::optional<GazePointRecord>& point = f.gaze_point;
        s.bind(22, point ? std::optional<double>(point->error_arcmin) : std::nullopt);
        s.bind(23, point ? point->depth_m : std::nullopt);
        s.bind(24, point ? std::optional<double>(point->mono_plane_m) : std::nullopt);
        const std::string what = "logging frame " + std::to_string(f.frame) + " of session " +
                                 std::to_string(row.session_id);
        MONOPLANE_TRY(s.run(what));
    }
    Result<Statement> update =
        Statement::prepare(db,
                           "UPDATE frames SET gpu_ms = ?, mono_plane = ? WHERE session_id = ? AND "
                           "frame = ?");
    MONOPLANE_TRY(update);
    for (const GpuTime& g : gpu_) {
        update.value().reset();
        update.value()
            .bind(1, g.gpu_ms)
            .bind(2, g.mono_plane)
            .bind(3, g.session_id)
            .bind(4, g.frame);
        MONOPLANE_TRY(update.value().run("logging a frame's GPU time"));
    }
    return Ok{};
}

Result<std::int64_t> next_frame_number(const sqlite::Connection& db, std::int64_t session_id) {
    Result<Statement> stmt = Statement::prepare(
        db,
        "SELECT max(coalesce((SELECT max(frame) FROM frames WHERE session_id = ?1), -1), "
        "coalesce((SELECT max(frame) FROM events WHERE session_id = ?1), -1)) + 1");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, session_id);
    MONOPLANE_TRY(stmt.value().step("reading the session's last frame number"));
    return stmt.value().int64(0);
}

Result<std::vector<FrameRecord>> read_frames(const sqlite::Connection& db,
                                             std::int64_t session_id) {
    Result<Statement> stmt = Statement::prepare(
        db,
        "SELECT frame, trial_index, shown, display_time_ns, cpu_ms, gpu_ms, missed, head_x, "
        "head_y, head_z, head_qw, head_qx, head_qy, head_qz, mono_plane, pipelines_created, "
        "driver_compiles, gaze_valid, gaze_dir_x, gaze_dir_y, gaze_dir_z, gaze_error_arcmin, "
        "gaze_depth_m, gaze_mono_plane_m "
        "FROM frames WHERE "
        "session_id = ? "
        "ORDER BY frame");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, session_id);
    std::vector<FrameRecord> frames;
    for (;;) {
        Result<bool> row = stmt.value().step("reading the frame log");
        MONOPLANE_TRY(row);
        if (!*row) break;
        const Statement& s = stmt.value();
        FrameRecord f;
        f.frame = s.int64(0);
        if (!s.is_null(1)) f.trial_index = s.int32(1);
        f.shown = s.text(2);
        f.display_time_ns = s.int64(3);
        f.cpu_ms = s.real(4);
        if (!s.is_null(5)) f.gpu_ms = s.real(5);
        f.missed = s.int64(6) != 0;
        if (!s.is_null(7)) {
            std::array<double, 7> head{};
            for (int i = 0; i < 7; ++i) head[static_cast<std::size_t>(i)] = s.real(7 + i);
            f.head = head;
        }
        if (!s.is_null(14)) f.mono_plane = s.real(14);
        if (!s.is_null(15)) f.pipelines_created = s.int64(15);
        if (!s.is_null(16)) f.driver_compiles = s.int64(16);
        if (!s.is_null(17)) {
            GazeRecord gaze;
            gaze.valid = s.int64(17) != 0;
            if (gaze.valid && !s.is_null(18)) {
                for (int i = 0; i < 3; ++i) {
                    gaze.direction[static_cast<std::size_t>(i)] = s.real(18 + i);
                }
            }
            f.gaze = gaze;
        }
        if (!s.is_null(21)) {
            GazePointRecord point{.error_arcmin = s.real(21), .mono_plane_m = s.real(23)};
            if (!s.is_null(22)) point.depth_m = s.real(22);
            f.gaze_point = point;
        }
        frames.push_back(std::move(f));
    }
    return frames;
}

}  // namespace monoplane::study
