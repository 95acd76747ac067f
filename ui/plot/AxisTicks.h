// How many value ticks a lane gets: the most (up to what its height asks)
// whose labels stand a label's height apart, and never fewer than two
// labels inside the range when any count gives two: a live lane of 1.7 mN
// with "about two ticks" got steps of 2 and one lonely "0". The live view,
// the review and the reports' lanes ask the same rule. And every label of
// an axis with the same decimals, those of its step: 0.0190, 0.0195,
// 0.0200 mN, not 0.019, 0.0195, 0.02.
#pragma once

#include <qcustomplot.h>

namespace tactiscope::ui {

// Labels in fixed notation with the decimals the tick step needs (0.0005:
// four; 2.5: one; 2: none). Beyond a million or below a hundred-millionth
// it leaves the labels to QCustomPlot's own notation.
class EvenDecimalsTicker : public QCPAxisTicker {
protected:
    QVector<QString> createLabelVector(const QVector<double>& ticks, const QLocale& locale, QChar formatChar,
                                       int precision) override;
};

// Gives `axis` an EvenDecimalsTicker with its present tick count.
void useEvenDecimals(QCPAxis& axis);

// Sets the tick count of `axis` (its ticker and range as they are now)
// for a lane `height_px` tall whose labels are `line_px` high, at most
// `most` ticks where two or more fit. Named levels (a text ticker) are left
// alone. Returns whether the count changed.
bool fitTickCount(QCPAxis& axis, int height_px, double line_px, int most);

}  // namespace tactiscope::ui
