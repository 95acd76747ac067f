// The Help menu's windows: the user guide (docs/user-guide.md, rendered
// with its screenshots) and the keyboard shortcuts of the window's menus.
#pragma once

#include <QString>

class QMenuBar;
class QWidget;

namespace tactiscope::ui {

// The user guide's path: installed, <prefix>/share/doc/tactiscope/; in a
// build tree, doc/ beside the executable. Empty when neither has it.
QString userGuidePath(const QString& executableDirectory);

// Opens the guide found from `executableDirectory` in a window of its own,
// or says where it is missing.
void showUserGuide(QWidget* parent, const QString& executableDirectory);

// Lists every action of `menus` that has a shortcut, menu by menu.
void showKeyboardShortcuts(const QMenuBar& menus, QWidget* parent);

}  // namespace tactiscope::ui
