// SessionStore: the chunks of a session that gained channels while it was
// recorded (a board printing lines that began to print another value).
// Every chunk keeps all the session's channels: those stored before get
// the new ones as holes (NaN), so each reader, here and on the central
// store, reads a chunk as it always has; the new channels' pyramids hold
// those holes too.
#include "core/storage/SessionStore.h"

#include "core/storage/ChunkCodec.h"

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

namespace tactiscope::core::storage {

void SessionStore::padChunks(std::int64_t session, std::size_t from, std::size_t added)
{
    // Channel-major: a chunk's new channels follow its others.
    std::uint8_t hole[4];
    putBinary32(std::numeric_limits<float>::quiet_NaN(), hole);
    std::vector<std::pair<std::int64_t, std::vector<std::uint8_t>>> padded;
    auto chunks = m_db.prepare("SELECT first_index, count, samples FROM chunks WHERE session_id = ?");
    chunks.bind(1, session);
    while (chunks.step()) {
        const auto blob = chunks.blob(2);
        std::vector<std::uint8_t> bytes(blob.begin(), blob.end());
        const auto holes = static_cast<std::size_t>(chunks.int64(1)) * added;
        bytes.reserve(bytes.size() + sizeof hole * holes);
        for (std::size_t i = 0; i < holes; ++i) bytes.insert(bytes.end(), hole, hole + sizeof hole);
        padded.emplace_back(chunks.int64(0), std::move(bytes));
    }
    auto update = m_db.prepare("UPDATE chunks SET samples = ? WHERE session_id = ? AND first_index = ?");
    for (const auto& [first, bytes] : padded) update.bindBlob(1, bytes).bind(2, session).bind(3, first).run();
    // Holes up to the end, lost samples included: a channel no sample of
    // which had come yet.
    const std::uint64_t end = sampleCount(session);
    const std::vector<float> holes(static_cast<std::size_t>(std::min<std::uint64_t>(end, 1 << 16)),
                                   std::numeric_limits<float>::quiet_NaN());
    for (std::size_t c = from; c < from + added; ++c) {
        lod::LodBuilder builder;
        for (std::uint64_t at = 0; at < end; at += holes.size())
            builder.add(
                std::span(holes).first(static_cast<std::size_t>(std::min<std::uint64_t>(holes.size(), end - at))));
        pyramid(session, c).write(builder.takeChangedRows());
    }
}

}  // namespace tactiscope::core::storage
