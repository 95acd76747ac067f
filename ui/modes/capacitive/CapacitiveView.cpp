// CapacitiveView: lanes, large readouts, baseline and calibration lines.
#include "ui/modes/capacitive/CapacitiveView.h"

#include "devices/session/modes/CapacitiveUnit.h"

#include "devices/session/LiveSession.h"
#include "ui/calibration/CalibrationText.h"
#include "ui/common/NumberText.h"
#include "ui/plot/LivePlotWidget.h"
#include "ui/profiles/ActiveProfiles.h"

#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

namespace tactiscope::ui {

CapacitiveView::CapacitiveView(QWidget* parent)
    : LiveModeView(parent),
      m_lanes(new LivePlotWidget(this)),
      m_readoutPanel(new QWidget(this)),
      m_baseline(new QLabel(this)),
      m_calibration(new QLabel(this)),
      m_tare(new QPushButton(tr("Tare C0 (Ctrl+T)"), this))
{
    auto* grid = new QGridLayout(m_readoutPanel);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setHorizontalSpacing(24);
    m_capacitance = addReadout(tr("Capacitance"), "capacitanceReadout");
    m_deltaC = addReadout(tr("ΔC"), "deltaCReadout");
    m_relative = addReadout(tr("ΔC/C0"), "relativeReadout");
    m_force = addReadout(tr("Force"), "forceReadout");
    m_displacement = addReadout(tr("Tip deflection"), "displacementReadout");
    m_baseline->setObjectName(QStringLiteral("baselineLabel"));
    m_calibration->setObjectName(QStringLiteral("calibrationLabel"));
    m_tare->setObjectName(QStringLiteral("tareButton"));
    m_tare->setMinimumHeight(40);
    m_tare->setToolTip(tr(
        "With the signal settled: the last half second's mean becomes the baseline C0 (refused while a load changes)"));
    m_calibration->setWordWrap(true);
    m_calibration->setStyleSheet(QStringLiteral("color: palette(window-text);"));
    m_calibration->setTextFormat(Qt::RichText);
    connect(m_calibration, &QLabel::linkActivated, this, &CapacitiveView::profilesRequested);

    auto* side = new QVBoxLayout;
    side->addWidget(m_readoutPanel);
    side->addStretch(1);
    auto* baselineRow = new QHBoxLayout;
    baselineRow->addWidget(m_baseline, 1);
    baselineRow->addWidget(m_tare);
    side->addLayout(baselineRow);
    side->addWidget(m_calibration);

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 6, 0);
    layout->addWidget(m_lanes, 3);
    layout->addLayout(side, 2);
    connect(m_tare, &QPushButton::clicked, this, &CapacitiveView::tareRequested);
}

QLabel* CapacitiveView::addReadout(const QString& caption, const char* objectName)
{
    auto* grid = static_cast<QGridLayout*>(m_readoutPanel->layout());
    const int index = grid->count() / 2;
    auto* title = new QLabel(caption, m_readoutPanel);
    // Full contrast, in any theme: a caption must be read at arm's length.
    title->setStyleSheet(QStringLiteral("color: palette(window-text); font-weight: 600;"));
    auto* value = new QLabel(QStringLiteral("—"), m_readoutPanel);
    value->setObjectName(QString::fromLatin1(objectName));
    QFont big = value->font();
    big.setPointSizeF(big.pointSizeF() * 2.0);
    big.setBold(true);
    value->setFont(big);
    // Two readouts per row: the caption above its value.
    grid->addWidget(title, index / 2 * 2, index % 2);
    grid->addWidget(value, index / 2 * 2 + 1, index % 2);
    return value;
}

void CapacitiveView::bind(const devices::session::LiveSession* session)
{
    const auto* unit = session ? session->unitAs<devices::session::CapacitiveUnit>() : nullptr;
    m_capacitive = unit ? unit->capacitive() : nullptr;
    const auto* profile = session ? session->profile(core::Mode::Capacitive) : nullptr;
    const QString probe = profile ? QString::fromStdString(core::sensors::profileName(*profile)) : QString();
    QString calibration = session ? calibrationsText(session->calibrations(core::Mode::Capacitive)) : QString();
    if (calibration.isEmpty()) calibration = tr("none — the beam model (uncalibrated); drift tracking off");
    m_tare->setEnabled(m_capacitive != nullptr);
    m_calibration->setText(
        probe.isEmpty() ? QString() : tr("%1<br>Calibration: %2").arg(probeLine(probe), calibration.toHtmlEscaped()));
    if (!m_capacitive) {
        m_lanes->clearSource();
        return;
    }
    // µN and mm: the scale of this beam (seed 002).
    m_lanes->setSource(m_capacitive->output(), core::capacitive::LiveCapacitive::outputChannels(),
                       session->source().nominalSampleRate_hz(),
                       {{1e6, tr("µN"), tr("Force")}, {1e3, tr("mm"), tr("Deflection")}});
    updateReadouts();
}

void CapacitiveView::update(devices::session::LiveSession&)
{
    updateReadouts();
}

void CapacitiveView::updateReadouts()
{
    const auto reading = m_capacitive ? m_capacitive->latest() : std::nullopt;
    if (!reading) {
        for (QLabel* label : {m_capacitance, m_deltaC, m_relative, m_force, m_displacement})
            label->setText(QStringLiteral("—"));
        m_baseline->clear();
        return;
    }
    const QLocale locale;
    m_capacitance->setText(tr("%1 pF").arg(fixedText(reading->capacitance_f * 1e12, 3)));
    m_deltaC->setText(tr("%1 pF").arg(fixedText(reading->deltaC_f * 1e12, 3)));
    m_relative->setText(tr("%1 %").arg(fixedText(reading->relativeChange * 1e2, 3)));
    m_force->setText(tr("%1 µN").arg(fixedText(reading->force_n * 1e6, 1)));
    m_displacement->setText(tr("%1 mm").arg(fixedText(reading->displacement_m * 1e3, 3)));
    m_baseline->setText(tr("C0 = %1 pF%2")
                            .arg(fixedText(reading->c0_f * 1e12, 3),
                                 reading->unloaded ? tr(" (unloaded: following drift)") : QString()));
}

}  // namespace tactiscope::ui
