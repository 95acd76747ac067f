// A mode as one unit: what each layer asks about a sensor type instead of
// switching on it. One definition per mode names its record word and title,
// the channel roles its processor reads (in that order), the profile it
// takes, what its analysis stores, whether it has a zero to take, and the
// review's and export's quantities of a stored session. Each built-in mode
// defines itself in its own file beside this one (PanelScanMode.cpp, …);
// the registry (ModeRegistry.cpp) lists them. Each upper layer keeps its
// part of a mode in one table of its own (docs/conventions.md, "A new
// mode"). Like sigrok's decoders declaring their channels, a mode declares
// roles, and any device whose channels can play them feeds it.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/Vocabulary.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>

namespace tactiscope::core::storage {
class ComputedColumns;
class SessionSource;
struct SessionSummary;
}  // namespace tactiscope::core::storage
namespace tactiscope::core::derived {
struct LaneOptions;
struct ModeLanes;
}  // namespace tactiscope::core::derived

namespace tactiscope::core {

// The sensor profile a mode's processor reads through (core/sensors).
enum class ProfileType { None, CompliancePair, CapacitiveBeam };

struct ModeDefinition {
    Mode mode;
    std::string_view name;   // the record's word: "panel-scan"
    std::string_view title;  // as the user reads it, untranslated: "Panel scan"
    // What its channels are, for the sentence that refuses a device:
    // "two strain cantilevers (A and B)".
    std::string_view needs{};
    std::span<const ChannelRole> roles{};  // in the order its processor reads them
    // Roles it uses when a channel plays them, on this device or another
    // device of the session, and does without otherwise: the capacitive
    // beam's reference force, for a calibration against a load cell.
    std::span<const ChannelRole> optionalRoles{};
    ProfileType profile = ProfileType::None;
    // Stores the detector's defects and decides the automatic verdict.
    bool detectsDefects = false;
    // The shortest recording its automatic verdict judges, as the rule its
    // live unit applies, in words; a shorter one is "too short to judge"
    // and gets none. Empty for a mode without an automatic verdict.
    std::string_view shortestJudged{};
    // What its analysis stores as readings, if anything.
    std::optional<ReadingKind> readings{};
    // Why it has no zero to take; empty when it has one.
    std::string_view noZero{};
    // The review's lanes and the export's columns of its quantities, from
    // the stored samples, profile and calibrations; null: the stored
    // channels as they are. Both throw std::invalid_argument saying why a
    // session has none (e.g. a palpation session without a profile).
    derived::ModeLanes (*lanes)(storage::SessionSource& store, const storage::SessionSummary& session,
                                const derived::LaneOptions& options) = nullptr;
    std::unique_ptr<storage::ComputedColumns> (*computedColumns)(storage::SessionSource& store,
                                                                 std::int64_t session) = nullptr;
};

// Every mode: the built-in ones in kModes order (general last), then any
// registered.
std::span<const ModeDefinition> modeDefinitions();
// Throws std::out_of_range for a mode nobody defined.
const ModeDefinition& definitionOf(Mode mode);
// Adds a mode (a test's, a plugin's) to the registry, before anything asks
// it from another thread. Throws std::invalid_argument when its value or
// its name is taken. A mode recorded into a store also needs its word in
// the store's CHECK list (core/storage/Schema.cpp, by a migration).
void registerMode(const ModeDefinition& definition);
// Takes a registered mode out again (a test's, a plugin unloaded); the
// built-in ones stay.
void unregisterMode(Mode mode);

// The built-in modes' definitions, each in its own file.
const ModeDefinition& panelScanMode();
const ModeDefinition& palpationMode();
const ModeDefinition& capacitiveMode();
const ModeDefinition& generalMode();

// Whether a channel's values are what `role` reads, whether it was given
// the role or is matched by its kind: cantilevers read a strain, the
// palpation beams a strain, a force or ADC counts (through the probe's
// converter or a profile's scale), the displacement a length, the
// capacitance a capacitance (or counts given the role, by a capacitive
// profile's scale), the reference force a force. A plain number (no unit)
// plays none of them: it is recorded as it is.
bool canPlay(const ChannelDescriptor& channel, ChannelRole role);
// What `role` reads, with units it takes: "a strain (strain, µε)".
std::string_view quantityFor(ChannelRole role);

}  // namespace tactiscope::core
