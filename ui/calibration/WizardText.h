// Small text helpers the calibration wizards share: a word-wrapped label
// and a number in the user's locale with a given count of significant
// digits.
#pragma once

#include <QLabel>
#include <QLocale>

namespace tactiscope::ui {

inline QLabel* wrappedLabel(const QString& text, QWidget* parent)
{
    auto* label = new QLabel(text, parent);
    label->setWordWrap(true);
    return label;
}

inline QString significant(double value, int digits = 4)
{
    return QLocale().toString(value, 'g', digits);
}

}  // namespace tactiscope::ui
