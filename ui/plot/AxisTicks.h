// How many value ticks a lane gets: the most (up to what its height asks)
// whose labels stand a label's height apart, and never fewer than two
// labels inside the range when any count gives two: a live lane of 1.7 mN
// with "about two ticks" got steps of 2 and one lonely "0". The live view,
// the review and the reports' lanes ask the same rule.
#pragma once

class QCPAxis;

namespace tactiscope::ui {

// Sets the tick count of `axis` (its ticker and range as they are now)
// for a lane `height_px` tall whose labels are `line_px` high, at most
// `most` ticks where two or more fit. Named levels (a text ticker) are left
// alone. Returns whether the count changed.
bool fitTickCount(QCPAxis& axis, int height_px, double line_px, int most);

}  // namespace tactiscope::ui
