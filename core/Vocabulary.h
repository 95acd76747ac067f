// The words a session is recorded in: its mode, its status, its verdict,
// and the kinds of its events and readings. Each word's text exists here
// once; the store's columns, the files, the command line and the settings
// all go through toString() and the *FromString() parsers. The schema's
// CHECK lists (core/storage/Schema.cpp, frozen migrations) hold the same
// texts, and VocabularyTest checks the schema accepts each and refuses others.
//
// A mode's word and everything else about it is its definition's
// (core/modes/ModeDefinition.h); docs/conventions.md says where a new
// mode's parts go.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace tactiscope::core {

// What a session inspects, and so which processor reads the probe.
enum class Mode {
    PanelScan,   // seed 000: surface-deflection detector on two strain cantilevers
    Palpation,   // seed 001: object stiffness from two beams of different stiffness
    Capacitive,  // seed 002: force and deflection of the capacitive beam
    General,     // any device, any channels: recorded and reviewed as they come
};
inline constexpr std::array kModes{Mode::PanelScan, Mode::Palpation, Mode::Capacitive, Mode::General};
std::string_view toString(Mode mode);  // "panel-scan", "palpation", "capacitive", "general"
std::optional<Mode> modeFromString(std::string_view text);
// "panel-scan, palpation, capacitive or general", for usage lines.
std::string modeChoices();

enum class SessionStatus { Recording, Complete, Interrupted };
inline constexpr std::array kSessionStatuses{SessionStatus::Recording, SessionStatus::Complete,
                                             SessionStatus::Interrupted};
std::string_view toString(SessionStatus status);  // "recording", "complete", "interrupted"
std::optional<SessionStatus> sessionStatusFromString(std::string_view text);

// A panel's verdict, stored untranslated: filters and reports read it.
enum class Verdict { Pass, DefectsFound };
inline constexpr std::array kVerdicts{Verdict::Pass, Verdict::DefectsFound};
std::string_view toString(Verdict verdict);  // "pass", "defects found"
std::optional<Verdict> verdictFromString(std::string_view text);
std::string_view verdictText(std::optional<Verdict> verdict);  // "" when there is none
// The detector's verdict on a panel: it passes when no defect was found.
Verdict automaticVerdict(std::size_t defects);

// Who decided a verdict: the detector, the operator at the stop, a reviewer later.
enum class VerdictRole { Automatic, Operator, Reviewer };
inline constexpr std::array kVerdictRoles{VerdictRole::Automatic, VerdictRole::Operator, VerdictRole::Reviewer};
std::string_view toString(VerdictRole role);  // "automatic", "operator", "reviewer"
std::optional<VerdictRole> verdictRoleFromString(std::string_view text);

// Trigger: the instant a triggered recording's start condition began (its
// note, the condition).
enum class EventKind { Defect, Contact, Press, Alarm, Marker, Trigger };
inline constexpr std::array kEventKinds{EventKind::Defect, EventKind::Contact, EventKind::Press,
                                        EventKind::Alarm,  EventKind::Marker,  EventKind::Trigger};
std::string_view toString(EventKind kind);  // "defect", "contact", "press", "alarm", "marker", "trigger"
std::optional<EventKind> eventKindFromString(std::string_view text);

enum class ReadingKind { Compliance, Capacitive };
inline constexpr std::array kReadingKinds{ReadingKind::Compliance, ReadingKind::Capacitive};
std::string_view toString(ReadingKind kind);  // "compliance", "capacitive"
std::optional<ReadingKind> readingKindFromString(std::string_view text);

}  // namespace tactiscope::core
