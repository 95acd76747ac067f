// The settable limits a calibration fit must meet before it can be stored
// (fewest points, lowest R², how far off the line a point may be), and the
// reasons a fit fails them, in words that say what to do about it.
#pragma once

#include "core/calibration/FitCredibility.h"

#include <QGroupBox>
#include <QStringList>

#include <functional>

class QDoubleSpinBox;
class QSpinBox;

namespace tactiscope::ui {

class FitLimitsBox : public QGroupBox {
    Q_OBJECT

public:
    FitLimitsBox(const core::calibration::CredibilityLimits& defaults, QWidget* parent = nullptr);

    core::calibration::CredibilityLimits limits() const;
    void setLimits(const core::calibration::CredibilityLimits& limits);

    // Why the fit cannot be stored; empty when it can. pointName(i) names
    // the i-th fitted point ("the zero", "load 3 (100 g)").
    static QStringList problems(const core::calibration::FitCredibility& credibility,
                                const core::calibration::CredibilityLimits& limits,
                                const std::function<QString(std::size_t)>& pointName);

signals:
    void changed();

private:
    QSpinBox* m_points;
    QDoubleSpinBox* m_rSquared;
    QDoubleSpinBox* m_offLine;
};

}  // namespace tactiscope::ui
