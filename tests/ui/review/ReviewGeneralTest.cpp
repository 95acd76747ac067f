// A general recording in the review window: a maker's board with a
// temperature and a load cell, stored as they came with an operator's
// marker. It opens on its stored channels by name, with no mode panel and
// no verdict, its readout names each channel's unit, and it exports as CSV
// and as a report with its channels.
#include "core/SampleBlock.h"
#include "core/storage/SessionStore.h"
#include "support/PdfText.h"
#include "support/Screenshot.h"
#include "support/TextFiles.h"
#include "ui/review/ReviewPlot.h"
#include "ui/review/ReviewWindow.h"

#include <QAction>
#include <QTemporaryDir>
#include <QTreeWidget>

#include <gtest/gtest.h>

#include <cmath>

using namespace tactiscope;

TEST(ReviewGeneral, AGeneralRecordingIsReviewedAndExportedByItsChannels)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("maker.tactiscope");
    {
        core::storage::SessionStore store(db.toStdString());
        core::storage::SessionMetadata metadata;
        metadata.mode = core::Mode::General;
        metadata.subject = "board-1";
        const std::vector<core::ChannelDescriptor> channels{{"temp", "K", core::ChannelKind::Other},
                                                            {"load", "N", core::ChannelKind::Force}};
        const auto id = store.beginSession(metadata, channels, 50.0);
        core::SampleBlock block(2, 500, 0.0, 0.02, 0);
        for (std::size_t s = 0; s < 500; ++s) {
            block.channel(0)[s] = 296.0 + 0.5 * std::sin(0.02 * static_cast<double>(s));
            block.channel(1)[s] = s > 200 && s < 300 ? 1.5 : 0.0;
        }
        store.appendBlocks(id, std::vector{block});
        store.addEvents(
            id, std::vector<core::storage::SessionEvent>{{0, "live", core::EventKind::Marker, 4.0, 4.0, 0, std::nullopt,
                                                          std::nullopt, std::nullopt, "weight on"}});
        store.endSession(id, core::SessionStatus::Complete);
    }
    QString error;
    std::unique_ptr<ui::ReviewWindow> window(ui::ReviewWindow::open(db, 1, nullptr, error));
    ASSERT_NE(window, nullptr) << error.toStdString();
    window->resize(1366, 768);
    window->show();
    window->plot()->reload();
    EXPECT_EQ(window->account(), nullptr);  // the list of records alone
    EXPECT_FALSE(window->plot()->showsDerived());
    EXPECT_EQ(window->plot()->laneNames(), (std::vector<std::string>{"temp", "load"}));
    EXPECT_EQ(window->findChild<QAction*>(QStringLiteral("verdictAction")), nullptr);  // no verdict to give
    EXPECT_EQ(window->recordList()->topLevelItemCount(), 1);                           // the marker
    const QString readout = window->plot()->readoutAt(5.0);
    EXPECT_TRUE(readout.contains(QStringLiteral("load")) && readout.contains(QStringLiteral("N")))
        << readout.toStdString();
    tactiscope::testing::saveScreenshot(*window, QStringLiteral("review-general"));

    const QString csv = dir.filePath("board-1.csv");
    ASSERT_EQ(window->exportCsv(csv, false), QString());
    const QStringList lines =
        QString::fromUtf8(tactiscope::testing::readBytes(csv)).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 501);
    EXPECT_EQ(lines.front().trimmed(), QStringLiteral("t [s],temp [K],load [N]"));

    if (*tactiscope::testing::pdfTextMissing()) GTEST_SKIP() << tactiscope::testing::pdfTextMissing();
    const QString pdf = dir.filePath("board-1.pdf");
    ASSERT_EQ(window->exportReport(pdf), QString());
    const QString text = tactiscope::testing::pdfText(pdf).simplified();
    EXPECT_TRUE(text.contains(QStringLiteral("Mode general"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("weight on"))) << text.toStdString();
}
