// What a decoder has seen, for the troubleshooting view and the record
// summary. All counters only grow until reset.
#pragma once

#include <cstdint>

namespace tactiscope::devices::protocol {

struct DecoderCounters {
    std::uint64_t bytes = 0;
    std::uint64_t frames = 0;  // good frames (binary) or good lines (text)
    std::uint64_t crcErrors = 0;
    std::uint64_t resyncs = 0;            // times bytes had to be skipped to find the next frame
    std::uint64_t malformedPayloads = 0;  // CRC fine, payload not (a firmware bug)
    std::uint64_t linesSkipped = 0;       // text lines that did not parse
    std::uint64_t valueHoles = 0;         // text values that were no number ("nan", "inf"): a hole in one channel
    std::uint64_t samplesLost = 0;        // gaps the sequence and the clock agree on, and restarts
    std::uint64_t sequenceFaults = 0;     // frames whose sequence number the device clock contradicted
    std::uint64_t deviceRestarts = 0;     // times the device clock began again

    // Sums counts over several connections to one device.
    DecoderCounters& operator+=(const DecoderCounters& other)
    {
        bytes += other.bytes;
        frames += other.frames;
        crcErrors += other.crcErrors;
        resyncs += other.resyncs;
        malformedPayloads += other.malformedPayloads;
        linesSkipped += other.linesSkipped;
        valueHoles += other.valueHoles;
        samplesLost += other.samplesLost;
        sequenceFaults += other.sequenceFaults;
        deviceRestarts += other.deviceRestarts;
        return *this;
    }
};

}  // namespace tactiscope::devices::protocol
