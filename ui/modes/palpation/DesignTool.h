// The compliance probe's design tool (seed 001, section 2.2.3, Figs 5–7):
// for a pair of beams from the palpation profiles and several beam lengths,
// how the force ratio Q, its sensitivity dQ/dk_o, the root-strain ratio
// ε_l/ε_h and the tip-deflection ratio Δ_l/Δ_h run over a range of object
// stiffness k_o — the curves the paper weighs to pick 50 mm (higher
// sensitivity against less crosstalk). Numbers from core::sensors'
// CompliancePair; this view only draws them.
#pragma once

#include "ui/profiles/ProfileLibrary.h"

#include <QDialog>
#include <QPointF>
#include <QString>

#include <vector>

class QComboBox;
class QCPLegend;
class QCustomPlot;
class QLabel;
class QLineEdit;

namespace tactiscope::ui {

class QuantityEdit;

class DesignTool : public QDialog {
    Q_OBJECT

public:
    enum class Curve { ForceRatio, Sensitivity, StrainRatio, DeflectionRatio };

    explicit DesignTool(const QString& libraryDirectory, QWidget* parent = nullptr);

    // Beam lengths in mm, as "40, 50, 60"; false (and the reason shown) for
    // anything else.
    bool setLengths(const QString& lengths_mm);
    // The points of one curve for the i-th length: (k_o in N/m, value).
    std::vector<QPointF> curvePoints(Curve curve, std::size_t length) const;

private:
    void redraw();

    std::vector<ProfileEntry> m_probes;
    QComboBox* m_probeBox;
    QLineEdit* m_lengths;
    QuantityEdit* m_from;
    QuantityEdit* m_to;
    QLabel* m_problem;
    QCustomPlot* m_plot;
    QCPLegend* m_legend = nullptr;
};

}  // namespace tactiscope::ui
