// The design tool against the paper's equations worked here by hand: k from
// eqs 3–4, Q from eq. 1, dQ/dk_o from eq. 5, the strain and deflection
// ratios from eqs 8 and 11; and the trends of Figs 5–6 (longer beams: higher
// Q, lower strain ratio).
#include "ui/modes/palpation/DesignTool.h"

#include "support/MainWindowHelpers.h"
#include "support/Screenshot.h"

#include <QLabel>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

using namespace tactiscope;
using Curve = ui::DesignTool::Curve;

namespace {

// The paper's Perspex pair (3 GPa, 10 mm wide, 3 and 1 mm thick) at length L.
double stiffness(double thickness_m, double length_m)
{
    return 3e9 * 0.01 * std::pow(thickness_m, 3) / (4.0 * std::pow(length_m, 3));
}

}  // namespace

TEST(DesignTool, CurvesFollowThePapersEquationsForEachLength)
{
    QTemporaryDir library;  // empty: the built-in probe only
    ui::DesignTool tool(library.path());
    const std::vector<double> lengths{0.040, 0.050, 0.060};
    for (std::size_t l = 0; l < lengths.size(); ++l) {
        const double kh = stiffness(0.003, lengths[l]), kl = stiffness(0.001, lengths[l]);
        const auto q = tool.curvePoints(Curve::ForceRatio, l);
        const auto dq = tool.curvePoints(Curve::Sensitivity, l);
        const auto strain = tool.curvePoints(Curve::StrainRatio, l);
        const auto deflection = tool.curvePoints(Curve::DeflectionRatio, l);
        ASSERT_GE(q.size(), 100u);
        ASSERT_EQ(dq.size(), q.size());
        EXPECT_DOUBLE_EQ(q.front().x(), 0.0);
        EXPECT_DOUBLE_EQ(q.back().x(), 1000.0);
        for (std::size_t i = 0; i < q.size(); ++i) {
            const double ko = q[i].x();
            const double expectedQ = kh * (ko + kl) / (kl * (ko + kh));
            EXPECT_NEAR(q[i].y(), expectedQ, 1e-9 * expectedQ);
            EXPECT_NEAR(dq[i].y(), 1e3 * kh * (kh - kl) / (kl * std::pow(ko + kh, 2)), 1e-9 * dq[i].y());
            EXPECT_NEAR(strain[i].y(), 9.0 / expectedQ, 1e-9);       // (t_h/t_l)² / Q
            EXPECT_NEAR(deflection[i].y(), 27.0 / expectedQ, 1e-9);  // (t_h/t_l)³ / Q
        }
    }
    // Fig. 5: Q grows with L; Fig. 6: the strain ratio falls with it.
    const std::size_t middle = tool.curvePoints(Curve::ForceRatio, 0).size() / 2;
    EXPECT_LT(tool.curvePoints(Curve::ForceRatio, 0)[middle].y(), tool.curvePoints(Curve::ForceRatio, 2)[middle].y());
    EXPECT_GT(tool.curvePoints(Curve::StrainRatio, 0)[middle].y(), tool.curvePoints(Curve::StrainRatio, 2)[middle].y());
    tool.show();
    tactiscope::testing::saveScreenshot(tool, QStringLiteral("design-tool"));
}

TEST(DesignTool, LengthsThatAreNotLengthsAreRefusedWithTheReason)
{
    QTemporaryDir library;
    ui::DesignTool tool(library.path());
    EXPECT_FALSE(tool.setLengths(QStringLiteral("40, forty")));
    EXPECT_TRUE(tactiscope::testing::child<QLabel>(tool, "problemLabel")->text().contains(QStringLiteral("forty")));
    EXPECT_TRUE(tool.curvePoints(Curve::ForceRatio, 0).empty());
    EXPECT_TRUE(tool.setLengths(QStringLiteral("45")));
    EXPECT_FALSE(tool.curvePoints(Curve::ForceRatio, 0).empty());
    EXPECT_TRUE(tool.curvePoints(Curve::ForceRatio, 1).empty());
}
