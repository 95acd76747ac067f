// The Help menu's windows: the user guide found beside the built GUI (the
// build copies docs/ there) and rendered with its text, and the keyboard
// shortcuts listed from the window's own menus.
#include "ui/HelpWindows.h"
#include "support/Screenshot.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"

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

TEST(HelpWindows, TheShortcutsAreTheMenusOwn)
{
    ui::MainWindow window;
    ui::showKeyboardShortcuts(*window.menuBar(), &window);
    auto* table = window.findChild<QTableWidget*>(QStringLiteral("shortcutTable"));
    ASSERT_NE(table, nullptr);
    QStringList rows;
    for (int r = 0; r < table->rowCount(); ++r) rows << table->item(r, 0)->text() + " = " + table->item(r, 1)->text();
    const QString all = rows.join('\n');
    EXPECT_TRUE(all.contains(QStringLiteral("Session › Start / stop recording = Ctrl+R"))) << all.toStdString();
    EXPECT_TRUE(all.contains(QStringLiteral("Session › Mark event = Ctrl+M"))) << all.toStdString();
    EXPECT_TRUE(all.contains(QStringLiteral("View › Pause display = Ctrl+Space"))) << all.toStdString();
}
