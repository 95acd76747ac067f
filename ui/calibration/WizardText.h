// Small text helpers the calibration wizards share: a word-wrapped label
// and a measured number to a given count of significant digits.
#pragma once

#include "ui/common/NumberText.h"

#include <QLabel>

namespace tactiscope::ui {

inline QLabel* wrappedLabel(const QString& text, QWidget* parent)
{
    auto* label = new QLabel(text, parent);
    label->setWordWrap(true);
    return label;
}

inline QString significant(double value, int digits = 4)
{
    return significantText(value, digits);
}

}  // namespace tactiscope::ui
