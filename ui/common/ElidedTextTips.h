// The full text of whatever Qt shows cut short ("Emulator (serial path, no
// hardwa…", "capacitanc…"), as a tooltip where the pointer rests: one event
// filter on the application for every item view's cells and every combo
// box, so no window has to remember it. A cell or combo that already has
// a tooltip of its own keeps it.
#pragma once

#include <QObject>

class QEvent;

namespace tactiscope::ui {

class ElidedTextTips : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    // Installs one filter on the running application (again: no effect).
    static void install();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
};

}  // namespace tactiscope::ui
