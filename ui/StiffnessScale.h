// The reference scale of the palpation mode: a vertical logarithmic axis of
// stiffness in N/m with the reference tissues (seed 001, §2.1) marked and
// named along it, and the current reading as an arrow, so a clinician sees
// at a glance what the phantom feels like. Labels that would overlap are
// pushed apart and tied to their mark by a leader line.
#pragma once

#include "core/compliance/ReferenceTissues.h"

#include <QWidget>

#include <optional>
#include <vector>

namespace tactiscope::ui {

class StiffnessScale : public QWidget {
    Q_OBJECT

public:
    static constexpr double kLow_n_per_m = 20.0;  // the scale's ends
    static constexpr double kHigh_n_per_m = 1000.0;

    explicit StiffnessScale(QWidget* parent = nullptr);

    void setTissues(std::vector<core::compliance::ReferenceTissue> tissues);
    void setReading(std::optional<double> stiffness_n_per_m);
    std::optional<double> reading() const { return m_reading; }

    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    double yOf(double stiffness_n_per_m) const;

    std::vector<core::compliance::ReferenceTissue> m_tissues;
    std::optional<double> m_reading;
};

// The colour of a stiffness on the same logarithmic range (a perceptually
// even blue → green → yellow map), for the site grid and its legend.
QColor stiffnessColour(double stiffness_n_per_m);
// The map as a Qt style-sheet gradient, low end at the left.
QString stiffnessGradientStyle();

}  // namespace tactiscope::ui
