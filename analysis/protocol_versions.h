// Which protocol versions the analysed sessions ran, and whether their designs may be pooled. A
// study whose protocol changed part way (other distances, another scene) would otherwise be
// analysed as one experiment without a word: the distance effect of one design averaged with
// another's. Versions are told apart by the protocol's hash; whether two versions are the same
// experiment is the study library's rule (study/protocol_design.h), which the caller passes in,
// so analysis/ stays free of it. A change of text only (comments, instructions) keeps the
// design: such versions pool silently and are listed.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/dataset.h"
#include "common/result.h"

namespace monoplane::analysis {

// How the design of the protocol text `later` differs from that of `earlier`, one line per
// field (empty: the same design), or nullopt when either text cannot be read as a protocol.
using DesignComparison = std::function<std::optional<std::vector<std::string>>(
    const std::string& earlier, const std::string& later)>;

// Every protocol version of data.sessions, in the order the sessions were read: one per hash
// (per name where the hash is not recorded), with its sessions and files, and its design
// numbered by comparing its text with each earlier design's (a version whose text no input
// holds, or whose text does not read, has design 0: not known). Any time; `compare` is called
// only for versions whose text some session holds.
std::vector<ProtocolVersion> list_protocol_versions(const Dataset& data,
                                                    const DesignComparison& compare);

// True when `versions` cannot be pooled silently: more than one design, or a design not known
// beside another version (a CSV export records only the hash, so a version with another hash
// may be another design: the safe reading).
bool designs_differ(const std::vector<ProtocolVersion>& versions);

// Lists the versions into data.protocol_versions and judges them: designs that differ are an
// error that names every version (name, hash, design and how it differs, sessions, files) and
// the ways on, unless `pool`, which pools them and records data.pooled_protocols.
// `pool_option` is how the caller's user asks for pooling ("--pool-protocols").
Result<void> check_protocol_versions(Dataset& data, const DesignComparison& compare, bool pool,
                                     std::string_view pool_option);

}  // namespace monoplane::analysis
