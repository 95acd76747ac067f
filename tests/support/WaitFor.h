// Runs the Qt event loop until a condition holds or a time limit passes.
// runEventLoopFor() just lets it run for a while.
// The limit bounds a liveness check ("samples arrive"); it is not a speed
// assertion.
#pragma once

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QThread>

namespace tactiscope::testing {

template <typename Predicate>
bool waitFor(Predicate condition, int timeout_ms)
{
    QDeadlineTimer deadline(timeout_ms);
    while (!condition()) {
        if (deadline.hasExpired()) return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        QThread::msleep(2);
    }
    return true;
}

// Keeps the event loop running for `duration_ms`, e.g. to let live traces fill.
inline void runEventLoopFor(int duration_ms)
{
    waitFor([] { return false; }, duration_ms);
}

}  // namespace tactiscope::testing
