// The seeded, recorded order of a session (Session -> Block -> Trial):
// practice trials first and apart from the data, then one block per scene whose order is
// counterbalanced across participants, distances within a block in random order, and per trial
// a random assignment of the two alternatives to the blind labels 1 and 2. With a staircase
// procedure the data trials are slots of the scenes' staircases, interleaved in rounds, whose
// mono planes are chosen when they start (study/staircases.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "study/protocol.h"

namespace monoplane::study {

struct ScheduledTrial {
    int index = 0;  // position in the session, 0-based, practice trials first
    bool practice = false;
    int block = -1;  // -1 for practice; else the block's position (0 = first scene block)
    std::string scene;
    // Metres. For an adaptive trial: NaN until its staircase chooses it as the trial starts.
    double mono_plane = 0.0;
    // Which alternative each blind label shows: label1_mode = alternatives[label1_alternative].
    int label1_alternative = 0;  // 0 or 1
    RenderMode label1_mode = RenderMode::Stereo;
    RenderMode label2_mode = RenderMode::Hybrid;
    // A staircase's slot (procedure = "staircase", data trials only): its scene's staircase
    // chooses mono_plane when the trial starts, or skips the slot once it has stopped.
    bool adaptive = false;
    // 1-based: which showing of its scene x distance condition this is (protocol
    // `repetitions`); 1 for practice and staircase trials.
    int repetition = 1;
};

struct Schedule {
    std::uint64_t seed = 0;
    // 0-based: the participant's number in the whole study (`--participant-number`; by default
    // the participant's index in the database), which selects the Latin square row.
    int participant_index = 0;
    int session_number = 1;                // 1-based: the participant's session
    std::vector<std::string> block_order;  // scenes in block order
    std::vector<ScheduledTrial> trials;    // practice trials, then the data trials

    int practice_count() const;
};

// Deterministic: the same protocol, seed, participant number and session number give the same
// schedule. The constant procedure shows each scene x distance protocol.day.repetitions times:
// with blocking = "scene" within the scene's block, the copies shuffled together (order =
// "randomized") or listed distance by distance, repetition after repetition ("fixed"); with
// blocking = "none" every data trial in one block (block 0), all shuffled or listed. A
// participant's session s shows the Latin-square (or random, or fixed) block order rotated left by
// s - 1 places, so over a participant's sessions each scene comes first in turn. With the
// staircase procedure the data trials come in staircase.trials_per_scene rounds of one slot per
// scene: the first round in the counterbalanced block order (so first_scene balances the first
// scene seen), each later round shuffled with the seed (order = "randomized") or in block order
// too ("fixed"). A slot's block is its scene's position in the block order.
Schedule make_schedule(const Protocol& protocol, std::uint64_t seed, int participant_index,
                       int session_number = 1);

// Row `row` of a balanced Latin square of order n (Williams design: n rows for even n, 2n for
// odd n), as a permutation of 0..n-1. Over consecutive rows every item is first equally often and
// every ordered pair of items is adjacent equally often.
std::vector<int> balanced_latin_square_row(int n, int row);
int balanced_latin_square_rows(int n);

}  // namespace monoplane::study
