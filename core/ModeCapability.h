// Which modes a device's channels can feed, and if not why: the one place
// each mode's channel needs are written. The live-session controller asks
// before it builds a processor or starts a recording, and the processors
// pick their channels through modeChannels(), so the answer and the
// processor cannot disagree.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/Vocabulary.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tactiscope::core {

// The channels `mode` reads, in the order its processor wants them, or
// nothing when the device lacks one:
//   panel-scan: the first two strain channels (cantilevers A and B);
//   palpation:  the first two channels that are not a position (the stiff
//               and the soft beam, in the device's order), then the first
//               position channel (the displacement);
//   capacitive: the first capacitance channel.
std::optional<std::vector<std::size_t>> modeChannels(Mode mode, std::span<const ChannelDescriptor> channels);

// Nothing when `mode` can run on `channels`; else one sentence naming the
// channels it needs and those the device has.
std::optional<std::string> modeRefusal(Mode mode, std::span<const ChannelDescriptor> channels);

// The modes that can run on `channels`, in kModes order.
std::vector<Mode> runnableModes(std::span<const ChannelDescriptor> channels);

}  // namespace tactiscope::core
