// The Help menu's windows: the user guide (docs/user-guide.md, rendered
// with its screenshots) and the keyboard shortcuts of every window, each
// listed from that window's own actions.
#pragma once

#include <QKeySequence>
#include <QList>
#include <QString>

class QAction;
class QMenuBar;
class QWidget;

namespace tactiscope::ui {

// The user guide's path: installed, <prefix>/share/doc/tactiscope/; in a
// build tree, doc/ beside the executable. Empty when neither has it.
QString userGuidePath(const QString& executableDirectory);

// Opens the guide found from `executableDirectory` in a window of its own,
// or says where it is missing.
void showUserGuide(QWidget* parent, const QString& executableDirectory);

// One command's keys, where it is found ("Session › Record").
struct ShortcutRow {
    QString command;
    QString keys;  // every sequence that triggers it, as the platform writes them
};
struct ShortcutGroup {
    QString window;
    QList<ShortcutRow> rows;
};

QString keysText(const QList<QKeySequence>& keys);
// Every action of `menus` with a shortcut, by its menu path.
QList<ShortcutRow> menuShortcuts(const QMenuBar& menus);

// The table of every group's shortcuts, window by window.
void showKeyboardShortcuts(const QList<ShortcutGroup>& groups, QWidget* parent);

}  // namespace tactiscope::ui
