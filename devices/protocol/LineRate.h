// The sample rate of a text board, which sends no rate of its own:
//   - from the board's clock, when its lines carry one (a labelled t,
//     time, millis or micros value, Teleplot's timestamp): the lines over
//     the time they span by it, a unit the label does not give found from
//     the arrivals (seconds, milliseconds or microseconds: whichever power
//     of 1000 the board's time runs nearest the host's at);
//   - else from the host's arrival times, by the clock mapping the probes
//     use (core/timing/ClockAlignment): line i is stamped i periods of a
//     provisional rate, and the mapping's drift corrects that rate; its
//     uncertainty is the mapping's (400 lines and more). Lines read in the
//     first kBacklog_s may have waited in the port: they are not timed,
//     nor are those of a board catching up on what it could not send
//     while nobody read, which the mapping sets aside (their lags fall a
//     period per period): the rate settles on lines that came on time.
//     On fewer lines, a least-squares line through the arrivals (after
//     those held up far above the mapping's floor) gives the rate and its
//     standard error.
//   Either way from the arrivals, the ± holds an allowance for the host:
//   its scheduler delays lines by an amount whose level wanders over
//   seconds (power states, other work), which a fit over a window of a
//   few seconds cannot tell from a rate (kHostWander_s).
// Settled once the lines it is timed on span kWindow_s and kPeriods of
// their own periods (a board printing once a second is timed over 8 s,
// after the first line, which may have waited in the port), and the rate
// is known to kSettledU of itself (every time in a recording rests on it:
// 100 ppm is 0.36 s in an hour), or they span kLongestWindow_s (a link
// too uneven for that: the rate is then stated with the ± it has).
#pragma once

#include "devices/protocol/TextLine.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace tactiscope::devices::protocol {

struct LineRateEstimate {
    double rate_hz = 0.0;
    std::optional<double> u_hz;  // standard uncertainty; none while the mapping states none
    std::size_t lines = 0;
    double span_s = 0.0;
    bool boardClock = false;
    double boardSecondsPerUnit = 1.0;  // with a board clock: its unit, given or found
};

class LineRate {
public:
    static constexpr double kWindow_s = 2.0;
    static constexpr double kPeriods = 8.0;
    // Timing by arrivals begins this long after the first line.
    static constexpr double kBacklog_s = 0.5;
    static constexpr double kSettledU = 1e-4;
    static constexpr double kLongestWindow_s = 5.0;
    // The standard uncertainty of the host's delay level at each end of
    // the window, a type B allowance: Python boards on this workstation's
    // ptys, timed on 2.2 s windows 0.3 s apart over 120 s, were off by
    // 37 µs (30, 100 Hz) and 22 µs (500, 1000 Hz) root-mean-square over
    // the span on an idle host, where the fits stated 9 µs; beside other
    // recordings, more (docs/protocol.md, "Text").
    static constexpr double kHostWander_s = 35e-6;

    // One line (a sample, or a hole: it was sent too), when it arrived and
    // the board's time on it.
    void add(double arrival_s, const std::optional<BoardTime>& boardTime);
    std::optional<LineRateEstimate> estimate() const;
    // Fits the lines again only once they have grown by a tenth since the
    // last look, so that a fast board timed for seconds costs little.
    bool settled();

private:
    std::optional<LineRateEstimate> fromBoardClock() const;
    std::optional<LineRateEstimate> fromArrivals() const;

    std::vector<double> m_arrivals;
    std::vector<BoardTime> m_boardTimes;  // while every line carries one
    bool m_everyLineTimed = true;
    std::size_t m_linesLookedAt = 0;
};

}  // namespace tactiscope::devices::protocol
