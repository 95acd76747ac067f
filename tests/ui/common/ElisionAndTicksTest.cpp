// Texts that do not fit and lanes too low for many labels (issue 37): a cut
// cell or combo says its whole text as a tooltip and an uncut one says
// nothing; the tissue scale is tall enough for every name; a lane's value
// axis shows two labels at least, never overlapping.
#include "ui/common/ElidedTextTips.h"
#include "ui/modes/palpation/StiffnessScale.h"
#include "ui/plot/AxisTicks.h"

#include <QApplication>
#include <QComboBox>
#include <QHelpEvent>
#include <QTest>
#include <QToolTip>
#include <QTreeWidget>
#include <qcustomplot.h>

#include <gtest/gtest.h>

#include <algorithm>

using namespace tactiscope;

namespace {

// The tooltip a rest of the pointer at `at` of `widget` brings up, or none.
QString tipAt(QWidget& widget, QPoint at)
{
    QToolTip::hideText();  // the last one fades: gone before this one is asked for
    EXPECT_TRUE(QTest::qWaitFor([] { return !QToolTip::isVisible(); }, 3000));
    QHelpEvent help(QEvent::ToolTip, at, widget.mapToGlobal(at));
    QApplication::sendEvent(&widget, &help);
    return QToolTip::isVisible() ? QToolTip::text() : QString();
}

}  // namespace

TEST(ElidedTextTips, ACutCellOrComboSaysItsWholeTextAndAWholeOneNothing)
{
    ui::ElidedTextTips::install();
    QTreeWidget tree;
    tree.setHeaderHidden(true);
    tree.resize(160, 120);
    const QString longText = QStringLiteral("Emulator (serial path, no hardware)");
    auto* cut = new QTreeWidgetItem(&tree, {longText});
    auto* whole = new QTreeWidgetItem(&tree, {QStringLiteral("Simulator")});
    tree.show();
    EXPECT_EQ(tipAt(*tree.viewport(), tree.visualItemRect(cut).center()), longText);
    EXPECT_EQ(tipAt(*tree.viewport(), tree.visualItemRect(whole).center()), QString());

    QComboBox combo;
    combo.addItem(QStringLiteral("capacitance (capacitive)"));
    combo.setFixedWidth(90);
    combo.show();
    EXPECT_EQ(tipAt(combo, combo.rect().center()), QStringLiteral("capacitance (capacitive)"));
    combo.setFixedWidth(400);
    EXPECT_EQ(tipAt(combo, combo.rect().center()), QString());
}

TEST(StiffnessScale, IsTallEnoughForEveryTissueName)
{
    ui::StiffnessScale scale;
    const auto tissues = ui::builtInTissues();
    scale.setTissues(tissues);
    ASSERT_GE(tissues.size(), 8U);
    EXPECT_GE(scale.minimumSizeHint().height(), static_cast<int>(tissues.size()) * scale.fontMetrics().height());
}

TEST(AxisTicks, ALowLaneShowsTwoLabelsAtLeastAndNoneOverlap)
{
    QCustomPlot plot;
    QCPAxis& axis = *plot.yAxis;
    const double line = 15.0;
    // Ranges a live force lane takes (mN), on lanes 40 to 200 px tall.
    for (const double upper : {0.17, 1.0, 1.5, 1.7, 2.3, 9.5, 17.0, 230.0}) {
        for (const int height : {40, 60, 90, 200}) {
            axis.setRange(-0.05 * upper, upper);
            ui::fitTickCount(axis, height, line, std::clamp(height / 40, 2, 6));
            QVector<double> ticks;
            axis.ticker()->generate(axis.range(), QLocale(), QLatin1Char('g'), 6, ticks, nullptr, nullptr);
            const auto inside =
                std::count_if(ticks.begin(), ticks.end(), [&](double t) { return axis.range().contains(t); });
            EXPECT_GE(inside, 2) << "0…" << upper << " on " << height << " px";
            ASSERT_GE(ticks.size(), 2);
            EXPECT_GE((ticks[1] - ticks[0]) / axis.range().size() * height, line)
                << "0…" << upper << " on " << height << " px";
        }
    }
}

// A range no two labels fit apart on (a palpation's Q lane, 50 px over
// 2.60…2.98: ticks 0.1 apart are 13 px, 0.2 apart leave one inside) still
// shows one label: it showed none.
TEST(AxisTicks, ALaneTooLowForTwoLabelsShowsOne)
{
    QCustomPlot plot;
    QCPAxis& axis = *plot.yAxis;
    axis.setRange(2.60125, 2.97741);
    ui::fitTickCount(axis, 50, 15.0, 2);
    QVector<double> ticks;
    axis.ticker()->generate(axis.range(), QLocale(), QLatin1Char('g'), 6, ticks, nullptr, nullptr);
    const auto inside = std::count_if(ticks.begin(), ticks.end(), [&](double t) { return axis.range().contains(t); });
    EXPECT_EQ(inside, 1);
}

// Issue 52 (fresh eyes): a load cell's lane read 0.019, 0.0195, 0.02,
// 0.0205, 0.021 mN and a beam's 51.44, 51.445, 51.45 pF. Every label of an
// axis has the decimals of its step.
TEST(AxisTicks, EveryLabelOfAnAxisHasTheDecimalsOfItsStep)
{
    QCustomPlot plot;
    QCPAxis& axis = *plot.yAxis;
    ui::useEvenDecimals(axis);
    const auto labels = [&](double lower, double upper, int count) {
        axis.ticker()->setTickCount(count);
        QVector<double> ticks;
        QVector<QString> texts;
        axis.ticker()->generate(QCPRange(lower, upper), QLocale::c(), QLatin1Char('g'), 6, ticks, nullptr, &texts);
        QStringList inside;
        for (int i = 0; i < ticks.size(); ++i)
            if (ticks[i] >= lower && ticks[i] <= upper) inside << texts[i];
        return inside.join(QLatin1Char(' ')).toStdString();
    };
    EXPECT_EQ(labels(0.0189, 0.0211, 5), "0.0190 0.0195 0.0200 0.0205 0.0210");
    EXPECT_EQ(labels(51.4395, 51.4505, 3), "51.4400 51.4425 51.4450 51.4475 51.4500");
    EXPECT_EQ(labels(-1.1, 1.1, 5), "-1.0 -0.5 0.0 0.5 1.0");
    EXPECT_EQ(labels(0.0, 25.0, 3), "0 10 20");
}
