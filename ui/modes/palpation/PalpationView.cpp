// PalpationView: layout, the large readout, press rows, scale and grid.
#include "ui/modes/palpation/PalpationView.h"

#include "devices/session/modes/PalpationUnit.h"

#include "core/compliance/ReferenceTissues.h"
#include "ui/calibration/CalibrationText.h"
#include "ui/common/DisplayUnits.h"
#include "ui/common/NumberText.h"
#include "ui/modes/palpation/SiteGridMap.h"
#include "ui/modes/palpation/StiffnessScale.h"
#include "ui/plot/LivePlotWidget.h"
#include "ui/profiles/ActiveProfiles.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QScrollBar>
#include <QStyle>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace tactiscope::ui {
namespace {

QString stiffnessText(double k_n_per_m, double standardError_n_per_m)
{
    const auto [k, se] = valueAndErrorTexts(k_n_per_m, standardError_n_per_m);
    return PalpationView::tr("%1 ± %2 N/m").arg(k, se);
}

// A press's limits of about 95 % (k_o at Q ∓ 2u through the exact map).
QString limitsText(const core::compliance::PressReading& press)
{
    return PalpationView::tr("95 %: %1–%2 N/m")
        .arg(compactText(press.lowerLimit_n_per_m, 3), compactText(press.upperLimit_n_per_m, 3));
}

// Counts become strain through each beam's gauge factor: the calibrated one
// when the beam has a gauge-factor calibration, else the nominal one. The
// line says which, and why k_o hardly cares: k_o needs only F_H/F_L, so
// only the ratio of the two gauge factors enters it.
// A press without a number: why, in the table's words.
QString pressStateText(const core::compliance::PressReading& press)
{
    using core::compliance::PressStatus;
    const QString bound =
        press.bound_n_per_m ? QStringLiteral(" %1").arg(compactText(*press.bound_n_per_m, 3)) : QString();
    switch (press.status) {
    case PressStatus::Clipped:
        return PalpationView::tr("clipped (%1 beam)")
            .arg(press.atLimit.high > 0 ? PalpationView::tr("stiff") : PalpationView::tr("soft"));
    case PressStatus::BelowRange:
        return bound.isEmpty() ? PalpationView::tr("below range") : PalpationView::tr("<%1").arg(bound);
    case PressStatus::AboveRange:
        return bound.isEmpty() ? PalpationView::tr("above range") : PalpationView::tr(">%1").arg(bound);
    case PressStatus::Ok:
        break;
    }
    return {};
}

QString calibrationLine(const core::compliance::LivePalpation& palpation, const QString& calibration)
{
    const auto high = palpation.gaugeFactor(true), low = palpation.gaugeFactor(false);
    if (!high || !low) return PalpationView::tr("Calibration: strain or force as the device sends it");
    const auto factorText = [](double factor) { return compactText(factor, 4); };
    // One line whatever the records: which they are, with their dates and
    // operators, is in the label's tooltip (five lines of it squeezed the
    // tissue scale).
    QString line = PalpationView::tr("Calibration: %1 — gauge factors %2 (stiff) and %3 (soft)")
                       .arg(calibration.isEmpty() ? PalpationView::tr("none, nominal") : PalpationView::tr("stored"),
                            factorText(*high), factorText(*low))
                       .toHtmlEscaped();
    for (const auto& warning : {palpation.mixedCalibrationWarning(), palpation.unjudgedClipping()})
        if (warning)
            line += QStringLiteral("<br><span style='color:#b00020'><b>%1</b></span>")
                        .arg(QString::fromStdString(*warning).toHtmlEscaped());
    return line;
}

}  // namespace

PalpationView::PalpationView(QWidget* parent)
    : LiveModeView(parent),
      m_lanes(new LivePlotWidget(this)),
      m_probe(new QLabel(this)),
      m_stiffness(new QLabel(this)),
      m_status(new QLabel(this)),
      m_tare(new QPushButton(tr("Tare (Ctrl+T)"), this)),
      m_scale(new StiffnessScale(this)),
      m_presses(new QTableWidget(0, 6, this)),
      m_grid(new SiteGridMap(this))
{
    m_stiffness->setObjectName(QStringLiteral("stiffnessLabel"));
    m_status->setObjectName(QStringLiteral("palpationStatus"));
    m_presses->setObjectName(QStringLiteral("pressTable"));
    m_tare->setObjectName(QStringLiteral("tareButton"));
    m_probe->setObjectName(QStringLiteral("probeLabel"));

    // Read from arm's length while the other hand holds the probe: as large
    // as the column allows (resizeEvent), bold.
    QFont big = m_stiffness->font();
    big.setBold(true);
    m_stiffness->setFont(big);
    m_stiffness->setAlignment(Qt::AlignCenter);
    m_status->setAlignment(Qt::AlignCenter);
    m_status->setWordWrap(true);
    m_probe->setWordWrap(true);
    m_probe->setStyleSheet(QStringLiteral("color: palette(placeholder-text);"));
    m_probe->setTextFormat(Qt::RichText);
    connect(m_probe, &QLabel::linkActivated, this, &PalpationView::profilesRequested);
    m_tare->setMinimumHeight(40);
    m_tare->setToolTip(
        tr("With the probe lifted and still: the last half second becomes the zero (refused while pressing)"));
    m_scale->setTissues(builtInTissues());

    m_presses->setHorizontalHeaderLabels(
        {tr("Since connect (s)"), tr("kₒ (N/m)"), tr("± u"), tr("Depth (mm)"), tr("Slope (N/m/mm)"), tr("Site")});
    m_presses->horizontalHeaderItem(4)->setToolTip(
        tr("Change of kₒ per mm pressed, in N/m per mm: near zero when the reading does not depend on the depth"));
    m_presses->verticalHeader()->hide();
    m_presses->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    // The site takes what is left (a stretched last section would keep at
    // least the default 100 px and push the table sideways).
    m_presses->horizontalHeader()->setSectionResizeMode(5, QHeaderView::Stretch);
    // Never sideways: the table is kept as wide as its columns (fitPressColumns).
    m_presses->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    fitPressColumns();
    m_presses->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_presses->setSelectionBehavior(QAbstractItemView::SelectRows);

    auto* readout = new QVBoxLayout;
    readout->addWidget(m_stiffness);
    readout->addWidget(m_status);
    readout->addWidget(m_tare);
    readout->addWidget(m_scale, 1);
    readout->addWidget(m_probe);
    auto* presses = new QVBoxLayout;
    presses->addWidget(m_presses, 1);
    presses->addWidget(m_grid, 1);

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 6, 0);
    layout->addWidget(m_lanes, 3);
    layout->addLayout(readout, 3);
    layout->addLayout(presses, 4);

    connect(m_tare, &QPushButton::clicked, this, &PalpationView::tareRequested);
    startSubject();
}

void PalpationView::bind(const devices::session::LiveSession* session)
{
    const auto* unit = session ? session->unitAs<devices::session::PalpationUnit>() : nullptr;
    m_palpation = unit ? unit->palpation() : nullptr;
    const auto* profile = session ? session->profile(core::Mode::Palpation) : nullptr;
    const QString probeName = profile ? QString::fromStdString(core::sensors::profileName(*profile)) : QString();
    const QString calibration = session ? calibrationsText(session->calibrations(core::Mode::Palpation)) : QString();
    m_probe->setText(probeName.isEmpty() || !m_palpation
                         ? QString()
                         : probeLine(probeName) + QStringLiteral("<br>") + calibrationLine(*m_palpation, calibration));
    m_probe->setToolTip(m_palpation ? tr("%1. kₒ needs only the ratio of the gauge factors.")
                                          .arg(calibration.isEmpty() ? tr("No calibration stored: nominal factors")
                                                                     : tr("Calibrated: %1").arg(calibration))
                                    : QString());
    m_tare->setEnabled(m_palpation != nullptr);
    if (!m_palpation) {
        m_lanes->clearSource();
        return;
    }
    const DisplayUnit force{1e3, tr("mN"), tr("Force")};
    const DisplayUnit ratio{1.0, QString(), tr("Q")};
    m_lanes->setSource(m_palpation->output(), core::compliance::LivePalpation::outputChannels(),
                       session->source().nominalSampleRate_hz(), {force, force, ratio});
    updateReadout();
}

void PalpationView::update(devices::session::LiveSession& session)
{
    auto* unit = session.unitAs<devices::session::PalpationUnit>();
    if (!unit) return updateReadout();
    unit->setSiteGrid(m_grid->grid());
    if (const auto chosen = m_grid->takeChosenSite()) unit->selectSite(*chosen);
    showPresses(unit->presses(), session.lists(), unit->siteGrid());
    updateReadout();
}

void PalpationView::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    // The largest size, up to 2.6× the normal text, at which the widest
    // reading still fits the column.
    QFont font = m_stiffness->font();
    const double normal = QWidget::font().pointSizeF();
    const QString widest = QStringLiteral("1,000.00 ± 10.00 N/m");
    double size = normal * 2.6;
    for (; size > normal; size -= 0.5) {
        font.setPointSizeF(size);
        if (QFontMetrics(font).horizontalAdvance(widest) <= m_stiffness->width()) break;
    }
    font.setPointSizeF(size);
    m_stiffness->setFont(font);
    // The probe's and calibration's lines, wrapped at this width, are part
    // of the view's least height: the splitter above leaves them their room
    // rather than cutting the calibration line off at a 768-pixel screen.
    m_probe->setMinimumHeight(std::max(0, m_probe->heightForWidth(m_probe->width())));  // -1: no text yet
}

void PalpationView::updateReadout()
{
    if (!m_palpation) return;
    const auto state = m_palpation->state();
    const bool stiffAtLimit = state.atLimit.high > 0, softAtLimit = state.atLimit.low > 0;
    m_status->setStyleSheet(state.pressing && (stiffAtLimit || softAtLimit) ? QStringLiteral("color: #b00020;")
                                                                            : QString());
    if (state.pressing && (stiffAtLimit || softAtLimit)) {
        // The press will read no number: say so while the hand can still ease off.
        m_status->setText(tr("%1 at its limit: press less deep")
                              .arg(stiffAtLimit && softAtLimit ? tr("Both beams")
                                   : stiffAtLimit              ? tr("Stiff beam")
                                                               : tr("Soft beam")));
    } else if (state.taring) {
        m_status->setText(tr("Taking the zero: keep the probe lifted and still"));
    } else if (state.pressing && state.current) {
        m_stiffness->setText(stiffnessText(state.current->first, state.current->second));
        m_stiffness->setStyleSheet(QString());
        m_status->setText(tr("Pressing…"));
    } else if (state.pressing) {
        m_status->setText(tr("Pressing: out of the probe's range"));
    } else {
        m_stiffness->setStyleSheet(QStringLiteral("color: palette(mid);"));  // the last press, not a live value
        m_status->setText(m_grid->isActive() ? tr("Press site %1").arg(m_grid->currentSite())
                                             : tr("Ready: press the probe on the subject"));
    }
}

// The press table's minimum width holds every column at its header's or
// its widest value's width, so nothing is clipped and nothing scrolls.
void PalpationView::fitPressColumns()
{
    const QHeaderView* header = m_presses->horizontalHeader();
    const QFontMetrics metrics(m_presses->font());
    // The item delegate's margins: a focus frame and a pixel on each side.
    const int margins_px = 2 * (m_presses->style()->pixelMetric(QStyle::PM_FocusFrameHMargin) + 1);
    int width_px = 2 * m_presses->frameWidth() + m_presses->verticalScrollBar()->sizeHint().width();
    for (int c = 0; c < m_presses->columnCount(); ++c) {
        int column_px = header->sectionSizeHint(c);
        for (int row = 0; row < m_presses->rowCount(); ++row)
            if (const QTableWidgetItem* item = m_presses->item(row, c))
                column_px = std::max(column_px, metrics.horizontalAdvance(item->text()) + margins_px);
        width_px += column_px;
    }
    m_presses->setMinimumWidth(width_px);
}

void PalpationView::showPresses(const std::vector<devices::session::PressRecord>& presses,
                                const devices::session::LiveLists& lists,
                                const std::optional<core::compliance::SiteGrid>& grid)
{
    if (grid) m_grid->showCurrent(grid->current());
    if (lists.generation != m_generation) {
        m_generation = lists.generation;
        startSubject();
    }
    if (lists.clock != m_clock) {
        m_clock = lists.clock;
        m_presses->horizontalHeaderItem(0)->setText(
            lists.clock == devices::session::LiveClock::SinceConnect ? tr("Since connect (s)") : tr("Recording (s)"));
        m_presses->horizontalHeaderItem(0)->setToolTip(
            lists.clock == devices::session::LiveClock::SinceConnect
                ? tr("Seconds since the device connected: these presses are not recorded")
                : tr("Seconds of the recording, as stored in session %1").arg(lists.session));
    }
    if (presses.size() == static_cast<std::size_t>(m_presses->rowCount())) return;
    const QLocale locale;
    for (auto record = presses.begin() + m_presses->rowCount(); record != presses.end(); ++record) {
        const auto& press = record->press;
        const QString site = QString::fromStdString(record->site);
        const bool inRange = press.status == core::compliance::PressStatus::Ok;
        const double k = press.stiffness.objectStiffness_n_per_m;
        const int row = m_presses->rowCount();
        m_presses->insertRow(row);
        const QString outOfRange = pressStateText(press);
        const auto [kText, seText] = valueAndErrorTexts(k, press.uncertainty_n_per_m());
        const QStringList cells{
            fixedText(press.start_s, 1),
            inRange ? kText : outOfRange,
            inRange ? seText : tr("—"),
            tr("%1–%2").arg(fixedText(press.displacementMin_m * 1e3, 2), fixedText(press.displacementMax_m * 1e3, 2)),
            inRange ? fixedText(press.displacementSlope_n_per_m_per_m * 1e-3, 2) : tr("—"),
            site.isEmpty() ? tr("—") : site};
        for (int c = 0; c < cells.size(); ++c) m_presses->setItem(row, c, new QTableWidgetItem(cells[c]));
        if (inRange) {
            m_presses->item(row, 2)->setToolTip(limitsText(press));
            // Near the stiff end a ± is lopsided: the limits say how.
            m_stiffness->setText(
                core::compliance::lopsidedLimits(k, press.lowerLimit_n_per_m, press.upperLimit_n_per_m)
                    ? tr("%1 (%2)").arg(stiffnessText(k, press.uncertainty_n_per_m()), limitsText(press))
                    : stiffnessText(k, press.uncertainty_n_per_m()));
            m_scale->setReading(k);
            // The map holds the recording's readings, where they were taken.
            if (const auto cell = core::compliance::SiteGrid::cellOf(record->site); cell && record->stored)
                m_grid->showReading(*cell, k, press.uncertainty_n_per_m());
        } else {
            m_stiffness->setText(outOfRange);
            m_scale->setReading(std::nullopt);
        }
    }
    fitPressColumns();
    m_presses->scrollToBottom();
}

void PalpationView::startSubject()
{
    m_presses->setRowCount(0);
    m_grid->clearReadings();
    m_stiffness->setText(tr("— N/m"));
    m_scale->setReading(std::nullopt);
}

int PalpationView::readingCount() const
{
    return m_presses->rowCount();
}

}  // namespace tactiscope::ui
