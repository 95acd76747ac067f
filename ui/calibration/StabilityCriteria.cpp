// StabilityCriteria: three spin boxes in display units.
#include "ui/calibration/StabilityCriteria.h"

#include "ui/common/DisplayUnits.h"
#include "ui/common/NumberText.h"

#include <QDoubleSpinBox>
#include <QFormLayout>

namespace tactiscope::ui {

StabilityCriteria::StabilityCriteria(const DisplayUnit& unit, QWidget* parent)
    : QWidget(parent),
      m_unit(unit),
      m_window(new QDoubleSpinBox(this)),
      m_maxDrift(new QDoubleSpinBox(this)),
      m_maxNoise(new QDoubleSpinBox(this))
{
    m_window->setRange(0.2, 30.0);
    m_window->setSuffix(tr(" s"));
    for (QDoubleSpinBox* box : {m_maxDrift, m_maxNoise}) {
        box->setRange(0.0001, 1e6);
        box->setDecimals(4);
    }
    m_maxDrift->setSuffix(QLatin1Char(' ') + unit.symbol + tr("/s"));
    m_maxNoise->setSuffix(QLatin1Char(' ') + unit.symbol);
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->addRow(tr("Stable means, over a &window of"), m_window);
    form->addRow(tr("a &drift of at most"), m_maxDrift);
    form->addRow(tr("and a σ about the trend of at most"), m_maxNoise);
    for (QDoubleSpinBox* box : {m_window, m_maxDrift, m_maxNoise}) {
        box->setMaximumWidth(180);
        connect(box, &QDoubleSpinBox::editingFinished, this, &StabilityCriteria::edited);
    }
}

core::calibration::StabilitySettings StabilityCriteria::settings() const
{
    return {m_window->value(), m_maxDrift->value() / m_unit.scale, m_maxNoise->value() / m_unit.scale};
}

void StabilityCriteria::setSettings(const core::calibration::StabilitySettings& settings)
{
    m_window->setValue(settings.window_s);
    // Three significant digits of each limit ("6.55 counts/s", not "6.5536").
    for (const auto& [box, value] : {std::pair{m_maxDrift, settings.maxDrift_per_s * m_unit.scale},
                                     std::pair{m_maxNoise, settings.maxNoise * m_unit.scale}}) {
        box->setDecimals(decimalsForMagnitude(value, 3));
        box->setValue(value);
    }
}

}  // namespace tactiscope::ui
