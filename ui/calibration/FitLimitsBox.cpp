// FitLimitsBox: three limits and the problems text.
#include "ui/calibration/FitLimitsBox.h"

#include "ui/common/NumberText.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLocale>
#include <QSpinBox>

namespace tactiscope::ui {

FitLimitsBox::FitLimitsBox(const core::calibration::CredibilityLimits& defaults, QWidget* parent)
    : QGroupBox(tr("A fit is stored only when"), parent),
      m_points(new QSpinBox(this)),
      m_rSquared(new QDoubleSpinBox(this)),
      m_offLine(new QDoubleSpinBox(this))
{
    m_points->setRange(3, 50);
    m_points->setObjectName(QStringLiteral("minimumPoints"));
    m_rSquared->setRange(0.9, 1.0);
    m_rSquared->setDecimals(5);
    m_rSquared->setSingleStep(0.0001);
    m_rSquared->setObjectName(QStringLiteral("minimumRSquared"));
    m_offLine->setRange(0.1, 50.0);
    m_offLine->setDecimals(1);
    m_offLine->setSuffix(tr(" % of full scale"));
    m_offLine->setObjectName(QStringLiteral("maximumOffLine"));
    for (QWidget* box : {static_cast<QWidget*>(m_points), static_cast<QWidget*>(m_rSquared)}) box->setMaximumWidth(120);
    m_offLine->setMaximumWidth(200);
    auto* form = new QFormLayout(this);
    form->addRow(tr("it has at least (points, zero included)"), m_points);
    form->addRow(tr("R² is at least"), m_rSquared);
    form->addRow(tr("no point is off the line through the others by more than"), m_offLine);
    setLimits(defaults);
    for (auto* box : {static_cast<QAbstractSpinBox*>(m_points), static_cast<QAbstractSpinBox*>(m_rSquared),
                      static_cast<QAbstractSpinBox*>(m_offLine)})
        connect(box, &QAbstractSpinBox::editingFinished, this, &FitLimitsBox::changed);
    connect(m_points, &QSpinBox::valueChanged, this, &FitLimitsBox::changed);
}

core::calibration::CredibilityLimits FitLimitsBox::limits() const
{
    return {static_cast<std::size_t>(m_points->value()), m_rSquared->value(), m_offLine->value() / 100.0};
}

void FitLimitsBox::setLimits(const core::calibration::CredibilityLimits& limits)
{
    m_points->setValue(static_cast<int>(limits.minimumPoints));
    m_rSquared->setValue(limits.minimumRSquared);
    m_offLine->setValue(limits.maximumOffLine * 100.0);
    emit changed();
}

QStringList FitLimitsBox::problems(const core::calibration::FitCredibility& c,
                                   const core::calibration::CredibilityLimits& limits,
                                   const std::function<QString(std::size_t)>& pointName)
{
    const QLocale locale;
    QStringList out;
    if (c.tooFewPoints)
        out << tr("Only %1 points: at least %2 are needed. Add loads.").arg(c.points).arg(limits.minimumPoints);
    if (c.pointOffLine)
        out << tr("%1 is %2 % of full scale off the line through the other points (limit %3 %). Go back, "
                  "select it and retake it.")
                   .arg(pointName(c.farthest->index), fixedText(100.0 * c.farthest->offLine, 1),
                        fixedText(100.0 * limits.maximumOffLine, 1));
    if (c.rSquaredTooLow)
        out << tr("R² = %1 is below the limit %2: the points do not lie on a line.")
                   .arg(fixedText(c.rSquared, 5), fixedText(limits.minimumRSquared, 5));
    return out;
}

}  // namespace tactiscope::ui
