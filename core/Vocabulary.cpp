// Vocabulary: the one table of each word's text.
#include "core/Vocabulary.h"

#include "core/modes/ModeDefinition.h"

#include <algorithm>
#include <utility>

namespace tactiscope::core {
namespace {

template <typename Enum, std::size_t N>
using Words = std::array<std::pair<Enum, std::string_view>, N>;

constexpr Words<SessionStatus, 3> kStatusWords{{
    {SessionStatus::Recording, "recording"},
    {SessionStatus::Complete, "complete"},
    {SessionStatus::Interrupted, "interrupted"},
}};
constexpr Words<Verdict, 2> kVerdictWords{{
    {Verdict::Pass, "pass"},
    {Verdict::DefectsFound, "defects found"},
}};
constexpr Words<VerdictRole, 3> kVerdictRoleWords{{
    {VerdictRole::Automatic, "automatic"},
    {VerdictRole::Operator, "operator"},
    {VerdictRole::Reviewer, "reviewer"},
}};
constexpr Words<EventKind, 6> kEventWords{{
    {EventKind::Defect, "defect"},
    {EventKind::Contact, "contact"},
    {EventKind::Press, "press"},
    {EventKind::Alarm, "alarm"},
    {EventKind::Marker, "marker"},
    {EventKind::Trigger, "trigger"},
}};
constexpr Words<ReadingKind, 2> kReadingWords{{
    {ReadingKind::Compliance, "compliance"},
    {ReadingKind::Capacitive, "capacitive"},
}};

template <typename Enum, std::size_t N>
std::string_view wordOf(const Words<Enum, N>& words, Enum value)
{
    return std::ranges::find(words, value, &std::pair<Enum, std::string_view>::first)->second;
}

template <typename Enum, std::size_t N>
std::optional<Enum> valueOf(const Words<Enum, N>& words, std::string_view text)
{
    const auto found = std::ranges::find(words, text, &std::pair<Enum, std::string_view>::second);
    if (found == words.end()) return std::nullopt;
    return found->first;
}

}  // namespace

std::string_view toString(Mode mode)
{
    return definitionOf(mode).name;
}

std::optional<Mode> modeFromString(std::string_view text)
{
    for (const auto& definition : modeDefinitions())
        if (definition.name == text) return definition.mode;
    return std::nullopt;
}

std::string modeChoices()
{
    const auto definitions = modeDefinitions();
    std::string text;
    for (std::size_t i = 0; i < definitions.size(); ++i) {
        if (i > 0) text += i + 1 == definitions.size() ? " or " : ", ";
        text += definitions[i].name;
    }
    return text;
}

std::string_view toString(SessionStatus status)
{
    return wordOf(kStatusWords, status);
}

std::optional<SessionStatus> sessionStatusFromString(std::string_view text)
{
    return valueOf(kStatusWords, text);
}

std::string_view toString(Verdict verdict)
{
    return wordOf(kVerdictWords, verdict);
}

std::optional<Verdict> verdictFromString(std::string_view text)
{
    return valueOf(kVerdictWords, text);
}

std::string_view verdictText(std::optional<Verdict> verdict)
{
    return verdict ? toString(*verdict) : std::string_view();
}

Verdict automaticVerdict(std::size_t defects)
{
    return defects == 0 ? Verdict::Pass : Verdict::DefectsFound;
}

std::string_view toString(VerdictRole role)
{
    return wordOf(kVerdictRoleWords, role);
}

std::optional<VerdictRole> verdictRoleFromString(std::string_view text)
{
    return valueOf(kVerdictRoleWords, text);
}

std::string_view toString(EventKind kind)
{
    return wordOf(kEventWords, kind);
}

std::optional<EventKind> eventKindFromString(std::string_view text)
{
    return valueOf(kEventWords, text);
}

std::string_view toString(ReadingKind kind)
{
    return wordOf(kReadingWords, kind);
}

std::optional<ReadingKind> readingKindFromString(std::string_view text)
{
    return valueOf(kReadingWords, text);
}

}  // namespace tactiscope::core
