// The session browser on a real store of 60 sessions: the table lists them
// all, the mode, status, verdict, search and date filters narrow them to the
// sessions counted while the store was written, the columns sort as numbers
// and dates (not as text), interrupted sessions are marked, and delete asks
// first and then removes exactly the selected sessions.
#include "ui/review/SessionBrowser.h"

#include "core/SampleBlock.h"
#include "core/storage/SessionStore.h"
#include "core/storage/StoreWorker.h"
#include "ui/review/SessionTableModel.h"

#include "support/MainWindowHelpers.h"
#include "support/Screenshot.h"
#include "support/TempDirectory.h"
#include "support/WaitFor.h"

#include <QCalendarWidget>
#include <QComboBox>
#include <QDateEdit>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableView>
#include <QTest>

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <map>

using namespace tactiscope;
using namespace tactiscope::core::storage;
using tactiscope::testing::child;
using tactiscope::testing::waitFor;

namespace {

constexpr int kSessions = 60;

// Session i (from 0): mode i % 3, i + 1 seconds at 10 Hz, i % 5 events,
// interrupted when i % 7 == 3, verdict "defects found" for panel scans with
// events, else "pass" for panel scans; subject "door-<i>" or "phantom-<i>".
struct Expected {
    std::map<tactiscope::core::Mode, int> perMode;
    int interrupted = 0;
    int defectVerdicts = 0;
};

class SessionBrowserTest : public tactiscope::testing::TempDirectoryTest {
protected:
    void SetUp() override
    {
        TempDirectoryTest::SetUp();
        m_path = QString::fromStdString(file("many.tactiscope"));
        SessionStore store(m_path.toStdString());
        const std::vector<core::ChannelDescriptor> channels{{"a", "", core::ChannelKind::Strain}};
        for (int i = 0; i < kSessions; ++i) {
            SessionMetadata metadata;
            metadata.mode = tactiscope::core::kModes[static_cast<std::size_t>(i % 3)];
            metadata.subject = (i % 3 == 0 ? "door-" : "phantom-") + std::to_string(i);
            metadata.operatorName = i % 2 ? "Ada" : "Grace";
            const auto id = store.beginSession(metadata, channels, 10.0);
            core::SampleBlock block(1, static_cast<std::size_t>(10 * (i + 1)), 0.0, 0.1, 0);
            store.appendBlocks(id, std::vector{block});
            std::vector<SessionEvent> events(static_cast<std::size_t>(i % 5));
            for (auto& e : events) e.kind = tactiscope::core::EventKind::Marker;
            store.addEvents(id, events);
            const bool interrupted = i % 7 == 3;
            store.endSession(id, interrupted ? tactiscope::core::SessionStatus::Interrupted
                                             : tactiscope::core::SessionStatus::Complete);
            m_expected.perMode[metadata.mode] += 1;
            m_expected.interrupted += interrupted ? 1 : 0;
            if (i % 3 == 0) {
                store.setVerdict(id, i % 5 ? tactiscope::core::Verdict::DefectsFound : tactiscope::core::Verdict::Pass);
                m_expected.defectVerdicts += i % 5 ? 1 : 0;
            }
            m_ids.push_back(id);
        }
    }

    QString m_path;
    Expected m_expected;
    std::vector<std::int64_t> m_ids;
};

int rows(const ui::SessionBrowser& browser)
{
    return browser.table()->model()->rowCount();
}

QVariant cell(const ui::SessionBrowser& browser, int row, int column, int role = Qt::DisplayRole)
{
    const auto* model = browser.table()->model();
    return model->data(model->index(row, column), role);
}

}  // namespace

TEST_F(SessionBrowserTest, ListsEverySessionAndFiltersAsCountedWhenWritten)
{
    ui::SessionBrowser browser(std::make_shared<core::storage::StoreWorker>(m_path.toStdString()));
    browser.show();
    EXPECT_EQ(rows(browser), kSessions);
    EXPECT_EQ(child<QLabel>(browser, "countText")->text(), QStringLiteral("60 of 60 sessions"));

    // A station's own store holds its own sessions only: no station to choose.
    EXPECT_TRUE(child<QComboBox>(browser, "stationFilter")->isHidden());
    auto* mode = child<QComboBox>(browser, "modeFilter");
    mode->setCurrentText(QStringLiteral("palpation"));
    EXPECT_EQ(rows(browser), m_expected.perMode[tactiscope::core::Mode::Palpation]);
    for (int r = 0; r < rows(browser); ++r)
        EXPECT_EQ(cell(browser, r, ui::SessionTableModel::Mode).toString(), QStringLiteral("palpation"));
    mode->setCurrentIndex(0);

    auto* status = child<QComboBox>(browser, "statusFilter");
    status->setCurrentText(QStringLiteral("interrupted"));
    EXPECT_EQ(rows(browser), m_expected.interrupted);
    // Marked: a warning icon in the status column, and the row coloured.
    EXPECT_FALSE(cell(browser, 0, ui::SessionTableModel::Status, Qt::DecorationRole).isNull());
    EXPECT_TRUE(cell(browser, 0, ui::SessionTableModel::Subject, Qt::ForegroundRole).isValid());
    status->setCurrentIndex(0);

    auto* verdict = child<QComboBox>(browser, "verdictFilter");
    ASSERT_EQ(verdict->count(), 3);  // any, defect, pass: what the store holds
    verdict->setCurrentText(QStringLiteral("defects found"));
    EXPECT_EQ(rows(browser), m_expected.defectVerdicts);
    verdict->setCurrentIndex(0);

    // Search: any case, in subject, operator, site, notes, verdict, serial.
    auto* search = child<QLineEdit>(browser, "searchEdit");
    QTest::keyClicks(search, QStringLiteral("DOOR-1"));
    ASSERT_TRUE(waitFor([&] { return rows(browser) != kSessions; }, 5000));
    // door-12, door-15, door-18 (subjects of i % 3 == 0 starting "door-1").
    EXPECT_EQ(rows(browser), 3);
    search->clear();
    ASSERT_TRUE(waitFor([&] { return rows(browser) == kSessions; }, 5000));

    // Dates: all were started today (local time); none before today.
    auto* to = child<QDateEdit>(browser, "toDate");
    to->setDate(QDate::currentDate().addDays(-1));
    EXPECT_EQ(rows(browser), 0);
    to->setDate(to->minimumDate());
    child<QDateEdit>(browser, "fromDate")->setDate(QDate::currentDate());
    EXPECT_EQ(rows(browser), kSessions);
    tactiscope::testing::saveScreenshot(browser, QStringLiteral("session-browser"));
}

TEST_F(SessionBrowserTest, ColumnsSortAsNumbersAndDates)
{
    ui::SessionBrowser browser(std::make_shared<core::storage::StoreWorker>(m_path.toStdString()));
    browser.show();
    QHeaderView* header = browser.table()->horizontalHeader();
    // Newest first by default: the last written session on top.
    EXPECT_EQ(cell(browser, 0, 0, ui::SessionTableModel::kIdRole).toLongLong(), m_ids.back());

    browser.table()->sortByColumn(ui::SessionTableModel::Duration, Qt::AscendingOrder);
    // 1 s, 2 s, …, 60 s: as text "10.0 s" would come before "2.0 s".
    for (int r = 0; r < rows(browser); ++r)
        EXPECT_EQ(cell(browser, r, 0, ui::SessionTableModel::kIdRole).toLongLong(), m_ids[static_cast<std::size_t>(r)])
            << r;
    EXPECT_EQ(cell(browser, 9, ui::SessionTableModel::Duration).toString(), QStringLiteral("10.0 s"));
    EXPECT_EQ(cell(browser, 59, ui::SessionTableModel::Duration).toString(), QStringLiteral("1 min 00 s"));

    QTest::mouseClick(header->viewport(), Qt::LeftButton, {},
                      QPoint(header->sectionViewportPosition(ui::SessionTableModel::Events) + 5, 5));
    std::vector<int> events;
    for (int r = 0; r < rows(browser); ++r) events.push_back(cell(browser, r, ui::SessionTableModel::Events).toInt());
    if (header->sortIndicatorOrder() == Qt::AscendingOrder)
        EXPECT_TRUE(std::ranges::is_sorted(events));
    else
        EXPECT_TRUE(std::ranges::is_sorted(events, std::greater<>()));
    EXPECT_EQ(events.front() + events.back(), 4);  // 0 at one end, 4 at the other
}

TEST_F(SessionBrowserTest, DeleteAsksFirstAndRemovesExactlyTheSelected)
{
    ui::SessionBrowser browser(std::make_shared<core::storage::StoreWorker>(m_path.toStdString()));
    browser.show();
    QSignalSpy deleted(&browser, &ui::SessionBrowser::sessionsDeleted);
    browser.table()->selectRow(0);  // the newest two
    browser.table()->selectionModel()->select(browser.table()->model()->index(1, 0),
                                              QItemSelectionModel::Select | QItemSelectionModel::Rows);
    const auto chosen = browser.selectedSessions();
    ASSERT_EQ(chosen, (std::vector<std::int64_t>{m_ids[59], m_ids[58]}));

    // Cancel deletes nothing.
    browser.deleteSelected();
    auto* box = browser.findChild<QMessageBox*>(QStringLiteral("deleteConfirmBox"));
    ASSERT_NE(box, nullptr);
    EXPECT_TRUE(box->informativeText().contains(QStringLiteral("phantom-59")));
    box->button(QMessageBox::Cancel)->click();
    ASSERT_TRUE(waitFor([&] { return !browser.findChild<QMessageBox*>(QStringLiteral("deleteConfirmBox")); }, 5000));
    EXPECT_EQ(rows(browser), kSessions);

    browser.deleteSelected();
    box = browser.findChild<QMessageBox*>(QStringLiteral("deleteConfirmBox"));
    ASSERT_NE(box, nullptr);
    tactiscope::testing::saveScreenshot(*box, QStringLiteral("session-browser-delete"));
    child<QPushButton>(*box, "confirmDeleteButton")->click();
    ASSERT_TRUE(waitFor([&] { return deleted.count() == 1; }, 10000));
    EXPECT_EQ(rows(browser), kSessions - 2);

    SessionStore store(m_path.toStdString(), Database::Access::ReadOnly);
    EXPECT_FALSE(store.session(m_ids[59]).has_value());
    EXPECT_FALSE(store.session(m_ids[58]).has_value());
    EXPECT_EQ(store.sessions().size(), static_cast<std::size_t>(kSessions - 2));
}

// Issue 37: the browser opens ready to use. Before, the first row had a
// focus frame but no selection (Enter did nothing), and the date filter's
// calendar opened on January 2000.
TEST_F(SessionBrowserTest, OpensWithTheNewestSelectedAndTheCalendarOnToday)
{
    ui::SessionBrowser browser(std::make_shared<core::storage::StoreWorker>(m_path.toStdString()));
    browser.show();
    std::vector<std::vector<std::int64_t>> opened;
    QObject::connect(&browser, &ui::SessionBrowser::openSessions,
                     [&](const std::vector<std::int64_t>& ids) { opened.push_back(ids); });
    ASSERT_EQ(browser.selectedSessions(), std::vector<std::int64_t>{m_ids.back()});  // newest first
    QTest::keyClick(browser.table(), Qt::Key_Return);
    ASSERT_EQ(opened.size(), 1U);
    EXPECT_EQ(opened.front(), std::vector<std::int64_t>{m_ids.back()});

    // A reload (as after a verdict changed in a review) keeps the selection.
    browser.table()->selectRow(5);
    const auto chosen = browser.selectedSessions();
    browser.reload();
    EXPECT_EQ(browser.selectedSessions(), chosen);

    auto* from = child<QDateEdit>(browser, "fromDate");
    QCalendarWidget* calendar = from->calendarWidget();
    QTest::mouseClick(from, Qt::LeftButton, {}, QPoint(from->width() - 6, from->height() / 2));  // its arrow
    ASSERT_TRUE(calendar->isVisible());
    EXPECT_EQ(calendar->yearShown(), QDate::currentDate().year());
    EXPECT_EQ(calendar->monthShown(), QDate::currentDate().month());
    calendar->window()->hide();
    EXPECT_EQ(from->date(), from->minimumDate()) << "showing the calendar chose no date";
}
