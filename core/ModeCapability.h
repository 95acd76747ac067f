// Which modes a device's channels can feed, and if not why. Each mode
// declares the roles it reads (core/modes/ModeDefinition.h); a channel
// plays a role when it was given that role, or, given none, when its kind
// can play it. The live-session controller asks before it builds a
// processor or starts a recording, and the processors pick their channels
// through modeChannels(), so the answer and the processor cannot disagree.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/Vocabulary.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tactiscope::core {

// The channels `mode` reads, one per role of its definition in that order,
// or nothing when a role has no channel. A role goes to the channel given
// it; when none was, to the first channel with no role whose kind can play
// it and that no earlier role took (panel scan: the first two strain
// channels are A and B; palpation: the first two non-position channels are
// the stiff and the soft beam, the first position the displacement).
std::optional<std::vector<std::size_t>> modeChannels(Mode mode, std::span<const ChannelDescriptor> channels);

// Nothing when `mode` can run on `channels`; else one sentence naming the
// roles missing and the channels the device has. Each front end adds how
// roles are given there (the command line's --roles, the device panel).
std::optional<std::string> modeRefusal(Mode mode, std::span<const ChannelDescriptor> channels);
// The channels given a role of `mode` whose values it cannot read (no unit,
// or another quantity's): the refusal's first part. Each front end adds
// how units are given there.
std::vector<std::string> channelsWithoutFittingUnit(Mode mode, std::span<const ChannelDescriptor> channels);
// The roles `mode` reads given to the device's channels in order, as the
// front ends show how to give them: "a=cantilever-a,b=cantilever-b"
// ("NAME=…" where the device has fewer channels).
std::string roleExample(Mode mode, std::span<const ChannelDescriptor> channels);

// The modes that can run on `channels`, in the registry's order (general
// is the last built-in one: it runs on any device).
std::vector<Mode> runnableModes(std::span<const ChannelDescriptor> channels);

}  // namespace tactiscope::core
