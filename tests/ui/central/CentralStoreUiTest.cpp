// The GUI on a site's central store, on a real PostgreSQL server started
// for the suite: the session browser lists two stations' synced sessions
// with their station names, and one opens for review from the server; the
// background push of Session ▸ Central store… sends a station's sessions,
// says none wait afterwards, and says why when the server cannot be
// reached; a browser, a review and the status bar live through the server
// being killed and started again.
#include "core/storage/StoreWorker.h"
#include "core/storage/central/CentralSync.h"
#include "ui/MainWindow.h"
#include "ui/central/CentralStoreDialog.h"
#include "ui/central/CentralStoreLink.h"
#include "ui/central/CentralSyncController.h"
#include "ui/review/ReviewPlot.h"
#include "ui/review/ReviewWindow.h"
#include "ui/review/ReviewWindows.h"
#include "ui/review/SessionBrowser.h"
#include "ui/review/SessionTableModel.h"

#include "support/MainWindowHelpers.h"
#include "support/PostgresServer.h"
#include "support/Screenshot.h"
#include "support/StationStore.h"
#include "support/TempDirectory.h"
#include "support/WaitFor.h"

#include <QAction>
#include <QComboBox>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSettings>
#include <QTableView>

#include <gtest/gtest.h>

#include <set>

using namespace tactiscope;
using core::storage::central::PgConnection;
using tactiscope::testing::child;
using tactiscope::testing::PostgresServer;
using tactiscope::testing::waitFor;

namespace {

class CentralStoreUi : public tactiscope::testing::TempDirectoryTest {
protected:
    static void SetUpTestSuite()
    {
        s_server = tactiscope::testing::centralStoreServer(
            {{"press_a", "tactiscope_station"}, {"press_b", "tactiscope_station"}, {"quality", "tactiscope_reviewer"}});
    }
    static void TearDownTestSuite() { s_server.reset(); }

    void TearDown() override
    {
        // Each test starts with nothing sent and no server set.
        PgConnection(s_server->conninfo()).run("DELETE FROM sessions; DELETE FROM calibrations;");
        QSettings().remove(QStringLiteral("central"));
        TempDirectoryTest::TearDown();
    }

    // A station's store with its three sessions, sent as `station`.
    std::string stationStore(const std::string& station, int seed)
    {
        const std::string path = file(station + ".tactiscope");
        tactiscope::testing::StationStoreOptions options;
        options.seed = seed;
        options.subjectPrefix = station;
        tactiscope::testing::writeStationStore(path, options);
        return path;
    }
    static void sync(const std::string& path, const std::string& station)
    {
        core::storage::SessionStore local(path, core::storage::Database::Access::ReadOnly);
        core::storage::central::CentralStore central(s_server->conninfo(station));
        ASSERT_EQ(core::storage::central::syncToCentral(local, central).sent, 3);
    }

    // Opens the panel scan "press_a-17" listed in `browser` for review, and
    // returns its window (null when none opened).
    static ui::ReviewWindow* reviewThePanelScan(ui::SessionBrowser& browser, const QWidget& owner)
    {
        const QAbstractItemModel* model = browser.table()->model();
        for (int row = 0; row < model->rowCount(); ++row)
            if (model->index(row, ui::SessionTableModel::Subject).data().toString() == "press_a-17")
                browser.table()->selectRow(row);
        browser.openSelected();
        ui::ReviewWindow* review = nullptr;
        waitFor([&] { return (review = owner.findChild<ui::ReviewWindow*>()) != nullptr; }, 10000);
        return review;
    }

    static inline std::unique_ptr<PostgresServer> s_server;
};

}  // namespace

TEST_F(CentralStoreUi, TheBrowserListsBothStationsAndASessionOpensFromTheServer)
{
    sync(stationStore("press_a", 1), "press_a");
    sync(stationStore("press_b", 2), "press_b");
    QWidget owner;
    ui::ReviewWindows reviews(&owner);
    const QString conninfo = QString::fromStdString(s_server->conninfo("quality"));
    ui::SessionBrowser* browser = reviews.showCentralBrowser(conninfo);
    ASSERT_NE(browser, nullptr);
    QTableView* table = browser->table();
    // Read off the window's thread: the rows come when the server answers.
    ASSERT_TRUE(waitFor([&] { return table->model()->rowCount() == 6; }, 10000));
    EXPECT_FALSE(table->isColumnHidden(ui::SessionTableModel::Station));
    std::multiset<QString> stations;
    for (int row = 0; row < 6; ++row)
        stations.insert(table->model()->index(row, ui::SessionTableModel::Station).data().toString());
    EXPECT_EQ(stations.count("press_a"), 3U);
    EXPECT_EQ(stations.count("press_b"), 3U);
    EXPECT_EQ(child<QLabel>(*browser, "countText")->text(), "6 of 6 sessions");
    // The server keeps the newest first and stops at a limit, as a station's store does.
    core::storage::central::CentralStore central(s_server->conninfo("quality"));
    core::storage::SessionFilter newest;
    newest.limit = 2;
    const auto two = central.sessions(newest);
    ASSERT_EQ(two.size(), 2U);
    EXPECT_EQ(two[0].station, "press_b");
    EXPECT_EQ(two[0].metadata.subject, "beam-2");
    EXPECT_TRUE(browser->windowTitle().contains("central store"));
    tactiscope::testing::saveScreenshot(*browser, "central-store-browser");

    // A station asked for by name, of those the server holds.
    auto* station = child<QComboBox>(*browser, "stationFilter");
    EXPECT_FALSE(station->isHidden());
    QStringList offered;
    for (int i = 0; i < station->count(); ++i) offered << station->itemText(i);
    EXPECT_EQ(offered, (QStringList{"Any station", "press_a", "press_b"}));
    station->setCurrentIndex(1);
    ASSERT_TRUE(waitFor([&] { return table->model()->rowCount() == 3; }, 10000));
    for (int row = 0; row < 3; ++row)
        EXPECT_EQ(table->model()->index(row, ui::SessionTableModel::Station).data().toString(), "press_a");
    EXPECT_EQ(child<QLabel>(*browser, "countText")->text(), "3 of 6 sessions");

    // Review straight from the server: the panel scan, with its samples.
    ui::ReviewWindow* review = reviewThePanelScan(*browser, owner);
    ASSERT_NE(review, nullptr);
    EXPECT_EQ(review->storePath(), conninfo);
    EXPECT_EQ(review->store().sampleCount(review->sessionId()), 6000U);
    EXPECT_EQ(review->store().events(review->sessionId()).size(), 1U);
    review->resize(1200, 700);
    tactiscope::testing::saveScreenshot(*review, "central-store-review");
}

TEST_F(CentralStoreUi, TheBackgroundPushSendsTheStationsSessionsAndSaysNoneWait)
{
    const std::string path = stationStore("press_a", 3);
    ui::CentralSyncController controller;
    controller.setStorePath(QString::fromStdString(path));
    EXPECT_FALSE(controller.state().running);  // nothing set: nothing sent
    ui::CentralStoreDialog dialog(&controller);
    dialog.show();
    EXPECT_EQ(child<QLabel>(dialog, "waitingText")->text(), "nothing is sent: no server is set");
    const int width = dialog.width();  // as wide whatever it says (it went from 640 to 515 px)

    controller.setServer(QString::fromStdString(s_server->conninfo("press_a")), {});
    // Save and send now, pressed while setting the server started a send:
    // that one sends all three, the press's finds them there. Before, the
    // dialog then said "synced 0 sessions, 3 already there" to the press.
    ASSERT_TRUE(controller.state().running);
    controller.syncNow();
    // (The press's send starts as the first ends: running until both are done.)
    ASSERT_TRUE(
        waitFor([&] { return !controller.state().running && controller.state().lastAttempt.isValid(); }, 30000));
    EXPECT_EQ(controller.state().lastError, "");
    // Values sent, counted from the station store: the panel scan's 2 × (6000 − 500 lost), the
    // palpation's 2 × 1500 and the capacitive session's 700.
    EXPECT_EQ(controller.state().lastOutcome,
              QStringLiteral("synced 3 sessions (%1 samples), 0 already there").arg(QLocale().toString(14700)));
    ASSERT_TRUE(controller.state().waiting);
    EXPECT_EQ(*controller.state().waiting, 0);
    EXPECT_EQ(child<QLabel>(dialog, "waitingText")->text(), "none");
    EXPECT_EQ(dialog.width(), width);
    EXPECT_EQ(PgConnection(s_server->conninfo()).query("SELECT count(*) FROM sessions").text(0, 0), "3");
    tactiscope::testing::saveScreenshot(dialog, "central-store-dialog");
}

TEST_F(CentralStoreUi, AnUnreachableServerIsShownWithItsReasonAndTheSessionsWait)
{
    const std::string path = stationStore("press_a", 4);
    ui::MainWindow window;
    window.show();
    auto* link = window.findChild<ui::CentralStoreLink*>();
    ASSERT_NE(link, nullptr);
    ui::CentralStoreDialog* dialog = link->showDialog();
    link->controller()->setStorePath(QString::fromStdString(path));
    link->controller()->setServer(
        QStringLiteral("host=%1 dbname=site user=press_a").arg(QString::fromStdString(file("none"))), {});
    ASSERT_TRUE(waitFor([&] { return link->controller()->state().lastAttempt.isValid(); }, 30000));
    const QString error = child<QLabel>(*dialog, "lastErrorText")->text();
    EXPECT_TRUE(error.contains("cannot reach the central store")) << error.toStdString();
    EXPECT_EQ(child<QLabel>(*dialog, "waitingText")->text(), "not counted yet (the server has not been reached)");
    auto* field = child<QLabel>(window, "centralStoreLabel");
    EXPECT_TRUE(field->isVisible());
    EXPECT_TRUE(field->text().contains("server unreachable")) << field->text().toStdString();
    EXPECT_TRUE(field->toolTip().contains("cannot reach")) << field->toolTip().toStdString();
    tactiscope::testing::saveScreenshot(*dialog, "central-store-dialog-offline");
}

// PostgreSQL killed and started again under an open browser, a review and
// the main window's status bar (issue 37). Before: both windows kept saying
// "no connection to the server" until reopened, Refresh emptied the list,
// and the status bar said "up to date" throughout.
TEST_F(CentralStoreUi, ABrowserAReviewAndTheStatusBarLiveThroughAServerRestart)
{
    const std::string station = stationStore("press_a", 5);
    sync(station, "press_a");
    ui::MainWindow window;
    window.show();
    auto* link = window.findChild<ui::CentralStoreLink*>();
    ASSERT_NE(link, nullptr);
    link->controller()->setStorePath(QString::fromStdString(station));
    link->controller()->setServer(QString::fromStdString(s_server->conninfo("press_a")), {});
    auto* field = child<QLabel>(window, "centralStoreLabel");
    ASSERT_TRUE(waitFor([&] { return field->text().contains("up to date"); }, 30000)) << field->text().toStdString();

    ui::ReviewWindows reviews(&window);
    ui::SessionBrowser* browser = reviews.showCentralBrowser(QString::fromStdString(s_server->conninfo("quality")));
    QTableView* table = browser->table();
    ASSERT_TRUE(waitFor([&] { return table->model()->rowCount() == 3; }, 10000));
    ui::ReviewWindow* review = reviewThePanelScan(*browser, window);
    ASSERT_NE(review, nullptr);
    auto* reviewProblem = child<QLabel>(*review, "problemText");
    auto* browserProblem = child<QLabel>(*browser, "problemText");
    auto* count = child<QLabel>(*browser, "countText");

    s_server->crash();
    browser->reload();
    ASSERT_TRUE(waitFor([&] { return browserProblem->isVisible(); }, 20000));
    EXPECT_EQ(table->model()->rowCount(), 3) << "the rows as last read stay";
    EXPECT_TRUE(count->text().contains("as last read")) << count->text().toStdString();
    review->plot()->reload();
    EXPECT_TRUE(reviewProblem->isVisible());
    EXPECT_TRUE(reviewProblem->text().contains("read again when you move or zoom"))
        << reviewProblem->text().toStdString();
    link->controller()->syncNow();
    ASSERT_TRUE(waitFor([&] { return field->text().contains("server unreachable"); }, 20000))
        << field->text().toStdString();

    s_server->start();
    browser->reload();
    ASSERT_TRUE(waitFor([&] { return count->text() == "3 of 3 sessions"; }, 20000)) << count->text().toStdString();
    EXPECT_FALSE(browserProblem->isVisible());
    review->plot()->reload();
    EXPECT_FALSE(reviewProblem->isVisible()) << reviewProblem->text().toStdString();
    EXPECT_EQ(review->store().sampleCount(review->sessionId()), 6000U);
    link->controller()->syncNow();
    ASSERT_TRUE(waitFor([&] { return field->text().contains("up to date"); }, 20000)) << field->text().toStdString();
    EXPECT_TRUE(field->toolTip().contains("last answered")) << field->toolTip().toStdString();
}

// What a login may not do is disabled, with the reason, before the server
// refuses it (issue 37). Before, Delete… was enabled for a station's login,
// said "removed for good" and then failed with "permission denied".
TEST_F(CentralStoreUi, ActionsTheLoginMayNotTakeAreDisabledWithTheReason)
{
    sync(stationStore("press_a", 6), "press_a");
    QWidget owner;
    ui::ReviewWindows reviews(&owner);
    for (const char* login : {"press_a", "quality"}) {
        ui::SessionBrowser* browser = reviews.showCentralBrowser(QString::fromStdString(s_server->conninfo(login)));
        ASSERT_TRUE(waitFor([&] { return browser->table()->model()->rowCount() == 3; }, 10000)) << login;
        auto* remove = child<QPushButton>(*browser, "deleteButton");
        EXPECT_FALSE(remove->isEnabled()) << login;
        EXPECT_TRUE(remove->toolTip().contains("may not delete sessions")) << remove->toolTip().toStdString();

        ui::ReviewWindow* review = reviewThePanelScan(*browser, owner);
        ASSERT_NE(review, nullptr) << login;
        auto* verdict = review->findChild<QAction*>(QStringLiteral("verdictAction"));
        ASSERT_NE(verdict, nullptr);
        const bool reviewer = std::string(login) == "quality";
        EXPECT_EQ(verdict->isEnabled(), reviewer) << login;
        if (!reviewer) {
            EXPECT_TRUE(verdict->toolTip().contains("not a reviewer's")) << verdict->toolTip().toStdString();
        }
        EXPECT_TRUE(review->findChild<QAction*>(QStringLiteral("addNoteAction"))->isEnabled()) << login;
        auto* save = review->findChild<QPushButton*>(QStringLiteral("saveAnalysisButton"));
        ASSERT_NE(save, nullptr);
        EXPECT_TRUE(save->toolTip().contains("may not save analyses")) << save->toolTip().toStdString();
        delete review;
        browser->close();
        QCoreApplication::processEvents();
    }
}
