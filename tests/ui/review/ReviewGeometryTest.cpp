// The review window on a laptop's screen (issue 37): before, it opened
// 1200 × 860 whatever the screen (Run and Save as analysis… off a
// 1366 × 768 one), its lanes squeezed until their tick labels and names
// overlapped, and its splitter collapsed the whole lower panel at once.
// Here, on the offscreen platform's screen (smaller than a laptop's), at
// 1366 × 768 and at 800 × 560: the window opens within the screen, no two
// tick labels of a lane are closer than a label's height, the marker rows
// are a label apart, the panel's buttons can be scrolled into view, and
// neither side of the splitter collapses.
#include "ui/review/ReviewPlot.h"
#include "ui/review/ReviewWindow.h"

#include "support/Screenshot.h"
#include "support/StationStore.h"
#include "support/TempPath.h"

#include <QApplication>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QSplitter>
#include <QTest>
#include <qcustomplot.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

using namespace tactiscope;

namespace {

// The least distance, in pixels, between two tick labels of `axis`.
double closestTicks(QCPAxis& axis)
{
    QVector<double> pixels;
    for (const double tick : axis.tickVector()) pixels << axis.coordToPixel(tick);
    std::sort(pixels.begin(), pixels.end());
    double closest = 1e9;
    for (qsizetype i = 1; i < pixels.size(); ++i) closest = std::min(closest, pixels[i] - pixels[i - 1]);
    return closest;
}

}  // namespace

TEST(ReviewGeometry, ALaptopScreenShowsEveryLabelApartAndEveryControlReachable)
{
    const std::string store = tactiscope::testing::uniqueTempPath("geometry.tactiscope");
    tactiscope::testing::writeStationStore(store);
    QString error;
    std::unique_ptr<ui::ReviewWindow> window(ui::ReviewWindow::open(QString::fromStdString(store), 1, nullptr, error));
    ASSERT_NE(window, nullptr) << error.toStdString();
    const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
    EXPECT_LE(window->width(), screen.width());
    EXPECT_LE(window->height(), screen.height());

    for (const QSize size : {QSize(1366, 768), QSize(800, 560)}) {
        window->resize(size);
        window->show();
        QApplication::processEvents();
        auto* plot = window->findChild<QCustomPlot*>();
        ASSERT_NE(plot, nullptr);
        plot->replot();  // lays the lanes out: their tick counts follow at the next
        QApplication::processEvents();
        plot->replot();
        const int label = QFontMetrics(plot->font()).height();
        ASSERT_GE(plot->axisRects().size(), 4);  // value lanes and the marker lane
        for (QCPAxisRect* rect : plot->axisRects()) {
            QCPAxis* values = rect->axis(QCPAxis::atLeft);
            EXPECT_GE(values->tickVector().size(), 2) << values->label().toStdString() << " has no scale";
            EXPECT_GE(closestTicks(*values), label)
                << size.width() << "×" << size.height() << ": the labels of " << values->label().toStdString()
                << " overlap (lane " << rect->height() << " px high)";
        }

        for (const char* name : {"runButton", "saveAnalysisButton"}) {
            auto* button = window->findChild<QPushButton*>(QString::fromLatin1(name));
            ASSERT_NE(button, nullptr) << name;
            auto* scroll = window->findChild<QScrollArea*>(QStringLiteral("accountScroll"));
            ASSERT_NE(scroll, nullptr);
            scroll->ensureWidgetVisible(button);
            QApplication::processEvents();
            EXPECT_FALSE(button->visibleRegion().isEmpty()) << name << " cannot be reached at " << size.width();
        }
        for (QSplitter* splitter : window->findChildren<QSplitter*>()) {
            EXPECT_FALSE(splitter->childrenCollapsible());
            for (const int part : splitter->sizes()) EXPECT_GT(part, 0);
        }
        tactiscope::testing::saveScreenshot(*window,
                                            QStringLiteral("review-window-%1x%2").arg(size.width()).arg(size.height()));
    }
    window.reset();
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(store + suffix);
}
