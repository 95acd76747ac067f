// The reference scale of the palpation mode: a vertical logarithmic axis of
// stiffness in N/m with the reference tissues (seed 001, §2.1) marked and
// named along it, and the current reading as an arrow, so a clinician sees
// at a glance what the phantom feels like (a review or report marks each
// site's mean instead, with the site's name beside the arrow). Labels that would overlap are
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
    struct Mark {
        QString label;
        double stiffness_n_per_m = 0.0;
    };
    void setMarks(std::vector<Mark> marks);

    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;
    bool event(QEvent* event) override;  // a cut tissue name's whole text as a tooltip

private:
    double yOf(double stiffness_n_per_m) const;
    struct Tip {
        QRectF area;
        QString text;
    };
    std::vector<Tip> m_tips;  // each tissue's label as last drawn

    std::vector<core::compliance::ReferenceTissue> m_tissues;
    std::optional<double> m_reading;
    std::vector<Mark> m_marks;
};

// The reference tissues shipped inside the program
// (resources/reference-tissues.json).
std::vector<core::compliance::ReferenceTissue> builtInTissues();

// The colour of a stiffness on the same logarithmic range (a perceptually
// even blue → green → yellow map), for the site grid and its legend.
QColor stiffnessColour(double stiffness_n_per_m);
// The map as a Qt style-sheet gradient, low end at the left.
QString stiffnessGradientStyle();

}  // namespace tactiscope::ui
