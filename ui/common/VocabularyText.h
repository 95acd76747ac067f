// The core vocabulary's words (core/Vocabulary.h) as Qt strings, for labels,
// filters and reports. They are shown as stored: files and filters read them.
#pragma once

#include "core/Vocabulary.h"

#include <QString>

#include <optional>

namespace tactiscope::ui {

template <typename Word>
QString wordText(Word word)
{
    const std::string_view text = core::toString(word);
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

inline QString wordText(std::optional<core::Verdict> verdict)
{
    return verdict ? wordText(*verdict) : QString();
}

// A mode's name in the session bar's words ("Panel scan").
QString modeTitle(core::Mode mode);

// A defect's order in the operator's words: which cantilever met it first
// (direction > 0: "A then B").
QString orderText(int direction);

}  // namespace tactiscope::ui
