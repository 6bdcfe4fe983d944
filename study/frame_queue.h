// The frame log's rows not yet in the database (StudyStore::queue_frame). A headset session shows
// 15-90 frames a second; a transaction per frame would cost a sync each, so rows wait in memory
// and are written inside the transaction of the store's next durable write (an event, an outcome,
// a status) or of an explicit flush: every committed event carries the frames queued before it.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "common/result.h"
#include "study/frame_record.h"
#include "study/store_sqlite.h"

namespace monoplane::study {

class FrameQueue {
  public:
    void add(std::int64_t session_id, const FrameRecord& frame);
    // The GPU time (and mono plane, hybrid modes) of a frame queued (or written) earlier.
    void add_gpu_ms(std::int64_t session_id, std::int64_t frame, double gpu_ms,
                    std::optional<double> mono_plane = std::nullopt);
    bool empty() const { return rows_.empty() && gpu_.empty(); }
    // Writes every queued row, then the GPU times, inside the caller's open transaction (a row
    // written again replaces the old one). Keeps the queue: clear() it once the transaction has
    // committed, so a failed commit loses nothing.
    Result<void> write(const sqlite::Connection& db) const;
    void clear();

  private:
    struct Row {
        std::int64_t session_id;
        FrameRecord frame;
    };
    struct GpuTime {
        std::int64_t session_id;
        std::int64_t frame;
        double gpu_ms;
        std::optional<double> mono_plane;
    };
    std::vector<Row> rows_;
    std::vector<GpuTime> gpu_;
};

// A session's frame log, in frame order.
Result<std::vector<FrameRecord>> read_frames(const sqlite::Connection& db, std::int64_t session_id);
// One past the highest frame number the session's frame log or events use (0 for none).
Result<std::int64_t> next_frame_number(const sqlite::Connection& db, std::int64_t session_id);

}  // namespace monoplane::study
