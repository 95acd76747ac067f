// The review window's commands as actions, with their texts, shortcuts and
// tips, made apart from any window: a review window connects and places
// them, and Help ▸ Keyboard shortcuts lists them from the actions
// themselves, whether or not a review is open.
#pragma once

#include "ui/common/HelpWindows.h"

#include <QList>
#include <QObject>
#include <QPair>
#include <QString>

class QAction;

namespace tactiscope::ui {

class ReviewActions : public QObject {
    Q_OBJECT

public:
    explicit ReviewActions(QObject* parent);

    // The Export menu.
    QAction* report;
    QAction* print;
    QAction* plotImage;
    QAction* csvWhole;
    QAction* csvShown;
    QAction* close;
    // The tool bar.
    QAction* wholeSession;
    QAction* zoomIn;
    QAction* zoomOut;
    QAction* play;
    QAction* addNote;
    QAction* undoDelete;
    QAction* verdict;  // null in a window whose mode has no verdict
    // The list of events and notes (its own shortcut: Del there only).
    QAction* deleteNote;

    // Every action with a shortcut, by where it is found ("Export ›
    // Inspection report (PDF)…", "Undo delete"), in the window's order.
    QList<QPair<QString, QAction*>> withShortcuts() const;
    // The review window's shortcuts for Help: these actions' and the
    // re-analysis panel's.
    static QList<ShortcutRow> helpRows();
};

}  // namespace tactiscope::ui
