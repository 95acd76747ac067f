// A main window as an operator leaves it before pressing Record: its store
// chosen, a live simulator connected, shown, and the operator's name typed
// (a recording asks for one).
#pragma once

#include "support/MainWindowHelpers.h"
#include "ui/MainWindow.h"
#include "ui/live/LiveStation.h"

#include <QLineEdit>
#include <QString>
#include <QTest>

#include <string>

namespace tactiscope::testing {

inline void readyToRecord(ui::MainWindow& window, const QString& store, const std::string& scenario = "panel-scan")
{
    window.setStorePath(store);
    window.station().connectSource(liveSimulator(scenario));
    window.show();
    QTest::keyClicks(child<QLineEdit>(window, "operatorEdit"), QStringLiteral("Ada"));
}

}  // namespace tactiscope::testing
