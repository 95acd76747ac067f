// The operator's markers in the recording (Session ▸ Mark event, Ctrl+M;
// with a note, Ctrl+Shift+M): at the window's device's session time, on
// every live plot. A note typed after the recording ended still reaches
// its session, as an annotation at the marker's time, through the store
// worker of the store it was recorded into.
#pragma once

#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <string>

class QWidget;

namespace tactiscope::core::storage {
class StoreWorker;
}

namespace tactiscope::ui {

class LiveStation;
class LiveTraces;

class LiveMarkers : public QObject {
    Q_OBJECT

public:
    struct Hooks {
        std::function<std::shared_ptr<core::storage::StoreWorker>()> store;
        std::function<std::string()> author;       // the session bar's operator
        std::function<void(const QString&)> tell;  // a line in the status bar
    };
    LiveMarkers(LiveStation& station, LiveTraces& traces, Hooks hooks, QWidget* window);

    void mark(const QString& note = {});
    // Takes the time now and asks for the note without blocking.
    void markWithNote();

private:
    void add(double time_s, const QString& note);

    LiveStation& m_station;
    LiveTraces& m_traces;
    Hooks m_hooks;
    QWidget* m_window;
};

}  // namespace tactiscope::ui
