// Review reached from the main window: the interrupted-sessions report's
// Review button opens the cut-short session; the session browser opens
// several sessions at once, raises a window already open instead of opening
// it twice, and a deleted session's review window closes.
#include "core/SampleBlock.h"
#include "core/storage/SessionStore.h"
#include "ui/MainWindow.h"
#include "ui/review/ReviewWindow.h"
#include "ui/review/SessionBrowser.h"

#include "support/MainWindowHelpers.h"
#include "support/WaitFor.h"

#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTableView>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::testing::child;
using tactiscope::testing::waitFor;

namespace {

// Three palpation sessions of 2.5 s; the last never ended (a crash).
QString storeWithACrash(const QTemporaryDir& dir)
{
    const QString path = dir.filePath("review.tactiscope");
    core::storage::SessionStore store(path.toStdString());
    const std::vector<core::ChannelDescriptor> channels{{"a", "", core::ChannelKind::Strain}};
    for (int i = 0; i < 3; ++i) {
        core::storage::SessionMetadata metadata;
        metadata.mode = tactiscope::core::Mode::Palpation;
        metadata.subject = "phantom-" + std::to_string(i);
        const auto id = store.beginSession(metadata, channels, 100.0);
        core::SampleBlock block(1, 250, 0.0, 0.01, 0);
        store.appendBlocks(id, std::span(&block, 1));
        if (i < 2) store.endSession(id, tactiscope::core::SessionStatus::Complete);
    }
    return path;
}

std::vector<std::int64_t> reviewed(const ui::MainWindow& window)
{
    std::vector<std::int64_t> ids;
    for (const auto* review : window.findChildren<ui::ReviewWindow*>()) ids.push_back(review->sessionId());
    std::ranges::sort(ids);
    return ids;
}

}  // namespace

TEST(SessionReviewFromMainWindow, TheInterruptedReportOffersReview)
{
    QTemporaryDir dir;
    ui::MainWindow window;
    window.setStorePath(storeWithACrash(dir));
    window.show();
    window.checkStore();
    QMessageBox* box = nullptr;
    ASSERT_TRUE(
        waitFor([&] { return (box = window.findChild<QMessageBox*>(QStringLiteral("interruptedBox"))); }, 10000));
    child<QPushButton>(*box, "reviewInterruptedButton")->click();
    ASSERT_EQ(reviewed(window), (std::vector<std::int64_t>{3}));
    const auto* review = window.findChild<ui::ReviewWindow*>();
    EXPECT_TRUE(child<QLabel>(*review, "sessionHeader")->text().contains(QStringLiteral("interrupted")));
}

TEST(SessionReviewFromMainWindow, TheBrowserOpensSeveralOnceEachAndDeletingClosesTheirReview)
{
    QTemporaryDir dir;
    ui::MainWindow window;
    window.setStorePath(storeWithACrash(dir));
    window.show();
    ui::SessionBrowser* browser = window.showSessionBrowser();
    ASSERT_EQ(browser->table()->model()->rowCount(), 3);
    browser->table()->selectAll();
    browser->openSelected();
    EXPECT_EQ(reviewed(window), (std::vector<std::int64_t>{1, 2, 3}));
    browser->openSelected();  // raised, not opened again
    EXPECT_EQ(reviewed(window), (std::vector<std::int64_t>{1, 2, 3}));

    browser->table()->selectRow(2);  // newest first: session 1
    ASSERT_EQ(browser->selectedSessions(), (std::vector<std::int64_t>{1}));
    browser->deleteSelected();
    auto* confirm = browser->findChild<QMessageBox*>(QStringLiteral("deleteConfirmBox"));
    ASSERT_NE(confirm, nullptr);
    child<QPushButton>(*confirm, "confirmDeleteButton")->click();
    // Its review window closes before its samples go; the list follows the deletion.
    ASSERT_TRUE(waitFor([&] { return reviewed(window) == std::vector<std::int64_t>{2, 3}; }, 5000));
    EXPECT_TRUE(waitFor([&] { return browser->table()->model()->rowCount() == 2; }, 10000));
}
