// The report's plot on a real store: PNG at twice the size asked for, SVG
// as vector text, and a file that cannot be written is said.
#include "ui/report/ReportPlot.h"

#include "core/SampleBlock.h"
#include "core/storage/SessionStore.h"

#include <QFile>
#include <QImage>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace tactiscope;

namespace {

core::report::ReportData oneChannelSession(const QTemporaryDir& dir)
{
    core::storage::SessionStore store(dir.filePath(QStringLiteral("p.tactiscope")).toStdString());
    core::storage::SessionMetadata metadata;
    metadata.mode = tactiscope::core::Mode::Capacitive;
    const std::vector<core::ChannelDescriptor> channels{{"C", "F", core::ChannelKind::Capacitance}};
    const auto id = store.beginSession(metadata, channels, 10.0);
    core::SampleBlock block(1, 100, 0.0, 0.1, 0);
    for (std::size_t i = 0; i < 100; ++i) block.channel(0)[i] = 51.44e-12 + 1e-15 * static_cast<double>(i);
    store.appendBlocks(id, std::span(&block, 1));
    store.endSession(id, tactiscope::core::SessionStatus::Complete);
    return core::report::gatherReport(store, id);
}

}  // namespace

TEST(ReportPlot, SavesPngAtTwiceTheSizeAndSvgAsVectors)
{
    QTemporaryDir dir;
    const auto data = oneChannelSession(dir);
    const QString png = dir.filePath(QStringLiteral("plot.png"));
    const QString svg = dir.filePath(QStringLiteral("plot.svg"));
    ui::saveReportPlot(data, QSize(600, 240), png);
    ui::saveReportPlot(data, QSize(600, 240), svg);
    const QImage image(png);
    EXPECT_EQ(image.size(), QSize(1200, 480));
    QFile file(svg);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray text = file.readAll();
    EXPECT_TRUE(text.contains("<svg"));
    EXPECT_TRUE(text.contains("<path") || text.contains("<polyline"));
    EXPECT_TRUE(text.contains("(pF)"));  // the axis title ("C" over its unit) is text, not pixels
    EXPECT_THROW(ui::saveReportPlot(data, QSize(600, 240), dir.filePath(QStringLiteral("no/folder/p.png"))),
                 std::runtime_error);
}

TEST(ReportPlot, AShortDefectIsShadedAtLeastTwoPixelsWide)
{
    // A 10 ms defect on a 10 s axis is 0.6 px of a 600 px plot: before, it
    // was drawn that thin and could not be seen.
    QTemporaryDir dir;
    auto data = oneChannelSession(dir);
    data.events.push_back({0, "live", tactiscope::core::EventKind::Defect, 5.0, 5.01, 1, 0.9, 0.05, 0.3, ""});
    const QImage image = ui::renderReportPlot(data, QSize(600, 240), 1.0);
    // Columns through the lane's middle that the orange shading tints.
    int tinted = 0;
    const int y = image.height() / 2;
    for (int x = 0; x < image.width(); ++x) {
        const QColor pixel = image.pixelColor(x, y);
        tinted += pixel.red() > pixel.green() + 20 && pixel.green() > pixel.blue() + 10;
    }
    EXPECT_GE(tinted, 2);
    EXPECT_LE(tinted, 4);
}
