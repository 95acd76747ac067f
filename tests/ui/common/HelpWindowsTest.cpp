// The Help menu's windows: the user guide found beside the built GUI (the
// build copies docs/ there) and rendered with its text, and the keyboard
// shortcuts of every window, listed from the windows' own actions.
#include "ui/common/HelpWindows.h"
#include "support/Screenshot.h"
#include "support/StationStore.h"
#include "support/TempPath.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/review/ReviewWindow.h"

#include <QAction>

#include <algorithm>
#include <filesystem>
#include <map>

#include <QDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QTableWidget>
#include <QTextBrowser>

#include <gtest/gtest.h>

using namespace tactiscope;

TEST(HelpWindows, TheUserGuideIsFoundBesideTheProgramAndRendered)
{
    const QString programDirectory = QFileInfo(QStringLiteral(TACTISCOPE_GUI)).absolutePath();
    const QString guide = ui::userGuidePath(programDirectory);
    ASSERT_FALSE(guide.isEmpty()) << "the build copies docs/ beside the GUI";
    EXPECT_TRUE(guide.endsWith("user-guide.md"));
    EXPECT_TRUE(ui::userGuidePath(QStringLiteral("/nonexistent")).isEmpty());

    QWidget parent;
    ui::showUserGuide(&parent, programDirectory);
    auto* dialog = parent.findChild<QDialog*>(QStringLiteral("userGuide"));
    ASSERT_NE(dialog, nullptr);
    auto* text = dialog->findChild<QTextBrowser*>(QStringLiteral("userGuideText"));
    ASSERT_NE(text, nullptr);
    // Rendered Markdown: the headings' words without their '#'.
    EXPECT_TRUE(text->toPlainText().contains(QStringLiteral("Palpation")))
        << text->toPlainText().left(200).toStdString();
    EXPECT_FALSE(text->toPlainText().startsWith(QLatin1Char('#')));
    tactiscope::testing::saveScreenshot(*dialog, QStringLiteral("help-user-guide"));
}

// Help ▸ Keyboard shortcuts lists every window's shortcuts from the
// windows' own actions (issue 37: before, only the main window's 11): every
// action with a shortcut in a review window that is open, with its keys,
// under "Review window"; the session browser's keys; the main window's menus.
TEST(HelpWindows, TheShortcutsAreEveryWindowsOwn)
{
    const std::string store = tactiscope::testing::uniqueTempPath("help.tactiscope");
    tactiscope::testing::writeStationStore(store);
    ui::MainWindow window;
    QAction* help = nullptr;
    for (QAction* action : window.findChildren<QAction*>())
        if (action->text() == QStringLiteral("&Keyboard shortcuts")) help = action;
    ASSERT_NE(help, nullptr);
    help->trigger();
    auto* table = window.findChild<QTableWidget*>(QStringLiteral("shortcutTable"));
    ASSERT_NE(table, nullptr);
    std::map<QString, QStringList> byWindow;  // window → "command = keys"
    QString group;
    for (int r = 0; r < table->rowCount(); ++r) {
        if (table->item(r, 0)->data(Qt::UserRole).toString() == QStringLiteral("window")) {
            group = table->item(r, 0)->text();
            continue;
        }
        byWindow[group] << table->item(r, 0)->text().trimmed() + " = " + table->item(r, 1)->text();
    }
    const QString main = byWindow["Main window"].join('\n');
    EXPECT_TRUE(main.contains(QStringLiteral("Session › Start / stop recording = Ctrl+R"))) << main.toStdString();
    EXPECT_TRUE(main.contains(QStringLiteral("View › Pause display = Ctrl+Space"))) << main.toStdString();
    const QString browser = byWindow["Session browser"].join('\n');
    EXPECT_TRUE(browser.contains(QStringLiteral("Refresh = F5"))) << browser.toStdString();
    EXPECT_TRUE(browser.contains(QStringLiteral("Delete the selected sessions = Del"))) << browser.toStdString();

    // Every shortcut of a review window as it is, listed with its keys.
    QString error;
    ui::ReviewWindow* review = ui::ReviewWindow::open(QString::fromStdString(store), 1, &window, error);
    ASSERT_NE(review, nullptr) << error.toStdString();
    const QStringList listed = byWindow["Review window"];
    int shortcuts = 0;
    for (const QAction* action : review->findChildren<QAction*>()) {
        if (action->shortcuts().isEmpty()) continue;
        ++shortcuts;
        const QString text = QString(action->text()).remove('&');
        const QString keys = ui::keysText(action->shortcuts());
        EXPECT_TRUE(std::ranges::any_of(listed, [&](const QString& row) { return row.endsWith(text + " = " + keys); }))
            << text.toStdString() << " (" << keys.toStdString() << ") is not listed:\n"
            << listed.join('\n').toStdString();
    }
    EXPECT_GE(shortcuts, 10);
    EXPECT_TRUE(listed.join('\n').contains(QStringLiteral("Re-analysis › Run = Ctrl+Return")));
    auto* dialog = window.findChild<QDialog*>(QStringLiteral("keyboardShortcuts"));
    ASSERT_NE(dialog, nullptr);
    tactiscope::testing::saveScreenshot(*dialog, QStringLiteral("help-keyboard-shortcuts"));
    delete review;
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(store + suffix);
}
