// LiveHealth: the dock, an accumulator per channel, the table.
#include "ui/signal/LiveHealth.h"

#include "devices/session/LiveSession.h"
#include "ui/common/DateText.h"
#include "ui/common/StoreJobs.h"
#include "ui/live/LiveStation.h"
#include "ui/signal/HealthText.h"

#include <QAction>
#include <QDockWidget>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMainWindow>
#include <QPushButton>
#include <QTableWidget>
#include <QThreadPool>
#include <QVBoxLayout>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tactiscope::ui {
namespace {

// The table at most once a second: the figures move slowly, the eye reads them.
constexpr qint64 kRedraw_ms = 1000;
// The table's column of each of healthCells' (hum, floor, drift, clipped).
constexpr std::array<int, 4> kColumnOf{1, 2, 4, 3};
// A beam's creep is fitted again after this much more of it (at least).
constexpr double kCreepRefit_s = 10.0;
// A gap longer than this is counted as this much missing: the drift's
// clock keeps its intervals; a device silent for minutes is a restart.
constexpr double kLongestGap_s = 10.0;

}  // namespace

LiveHealth::LiveHealth(LiveStation& station, QMainWindow* window)
    : QObject(window),
      m_station(station),
      m_dock(new QDockWidget(tr("Signal health"), window)),
      m_line(new QLabel),
      m_table(new QTableWidget),
      m_creepLine(new QLabel)
{
    m_dock->setObjectName(QStringLiteral("healthDock"));
    auto* panel = new QWidget;
    auto* layout = new QVBoxLayout(panel);
    auto* top = new QHBoxLayout;
    m_line->setObjectName(QStringLiteral("healthSince"));
    m_line->setWordWrap(true);
    auto* restartButton = new QPushButton(tr("Restart"));
    restartButton->setObjectName(QStringLiteral("healthRestart"));
    restartButton->setToolTip(tr("Judge the channels afresh from now on"));
    top->addWidget(m_line, 1);
    top->addWidget(restartButton);
    layout->addLayout(top);
    m_table->setObjectName(QStringLiteral("healthTable"));
    m_table->setColumnCount(5);
    // Short titles for a dock's width, the report's in full as their tips;
    // the drift, the widest, last, where the dock's edge cuts least.
    m_table->setHorizontalHeaderLabels({tr("Channel"), tr("Hum"), tr("Noise floor"), tr("Clipped"), tr("Drift /h")});
    const QStringList full = healthHeaders();
    for (int c = 0; c < full.size(); ++c)
        m_table->horizontalHeaderItem(kColumnOf[static_cast<std::size_t>(c)])->setToolTip(full[c]);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    layout->addWidget(m_table, 1);
    m_creepLine->setObjectName(QStringLiteral("healthCreep"));
    m_creepLine->setWordWrap(true);
    m_creepLine->hide();  // for a beam
    layout->addWidget(m_creepLine);
    auto* note = new QLabel(tr("Hum: the mains line's amplitude (flat-top). Noise floor: the median density above "
                               "1 Hz. Drift: a line through one-second means, ± u (k = 1)."));
    note->setWordWrap(true);
    note->setStyleSheet(QStringLiteral("color: palette(mid)"));
    layout->addWidget(note);
    m_dock->setWidget(panel);
    window->addDockWidget(Qt::LeftDockWidgetArea, m_dock);
    m_dock->hide();  // on request (View menu), a tab beside the device panel

    connect(restartButton, &QPushButton::clicked, this, [this] { restart(tr("since Restart")); });
    connect(&station, &LiveStation::connected, this, [this] { restart(tr("since the device connected")); });
    connect(&station, &LiveStation::disconnecting, this, [this] {
        m_sources.clear();
        m_line->setText(tr("No device."));
    });
    connect(&station, &LiveStation::recordingChanged, this, [this](bool recording) {
        if (recording) restart(tr("since the recording began"));
    });
    connect(&station, &LiveStation::polled, this, &LiveHealth::update);
    connect(m_dock->toggleViewAction(), &QAction::triggered, this, [this](bool on) {
        if (on) m_dock->raise();  // its tab to the front
    });
    connect(m_dock, &QDockWidget::visibilityChanged, this, [this](bool shown) {
        // Samples are read only while it is shown: what it missed is not judged.
        if (shown) restart(tr("since the panel opened"));
    });
    m_line->setText(tr("No device."));
}

// Every channel of the device and of its chain, from now on.
void LiveHealth::restart(const QString& since)
{
    m_sources.clear();
    m_accumulators.clear();
    m_channels.clear();
    m_beamSamples.clear();
    m_samples = 0;
    m_creepFittedAt = 0;
    ++m_generation;
    m_creepFitting = false;
    m_creepLine->hide();
    m_since = since;
    const auto* live = m_station.device();
    // Hidden, it builds nothing (an accumulator plans its FFT): update()
    // starts it once the panel shows, "since" as said here.
    if (!live || !m_dock->isVisible()) return;
    m_rate_hz = live->source().nominalSampleRate_hz();
    const auto chain = live->signalChain();
    m_chainSeen = chain;
    const std::size_t segment = core::dsp::streamSegmentLength(m_rate_hz);
    const auto interval = static_cast<std::uint64_t>(std::max(1.0, std::round(m_rate_hz)));  // a second
    const auto add = [&](std::shared_ptr<const core::LiveBuffer> buffer,
                         const std::vector<core::ChannelDescriptor>& channels) {
        Source source;
        source.buffer = std::move(buffer);
        source.cursor.next = source.buffer->samplesWritten();  // from now on
        for (const auto& channel : channels) {
            if (channel.kind == core::ChannelKind::Decision) {  // a probe's −1/0/+1
                source.rows.push_back(-1);
                continue;
            }
            // A position dwelling at an end stop is not a clipped converter, nor does it drift.
            const bool position = channel.kind == core::ChannelKind::Position;
            source.rows.push_back(static_cast<int>(m_channels.size()));
            m_accumulators.emplace_back(m_rate_hz, segment, interval, !position);
            m_channels.push_back({channel, {}, !position});
            m_channels.back().creepJudged = core::report::isBeamChannel(channel);
            m_beamSamples.emplace_back();
        }
        m_sources.push_back(std::move(source));
    };
    add(live->buffer(), live->channels());
    if (chain) add(chain->output(), chain->outputs());
    m_table->setRowCount(static_cast<int>(m_channels.size()));
    for (std::size_t r = 0; r < m_channels.size(); ++r) {
        m_table->setItem(static_cast<int>(r), 0,
                         new QTableWidgetItem(QString::fromStdString(m_channels[r].channel.name)));
        for (int c = 1; c < m_table->columnCount(); ++c)
            m_table->setItem(static_cast<int>(r), c, new QTableWidgetItem(QString()));
    }
    redraw();
}

void LiveHealth::update()
{
    const auto* live = m_station.device();
    if (!live || !m_dock->isVisible()) return;
    if (live->signalChain() != m_chainSeen.lock()) return restart(tr("since the filters changed"));
    if (m_sources.empty()) return restart(m_since);
    for (Source& source : m_sources) read(source);
    if (!m_sinceRedraw.isValid() || m_sinceRedraw.elapsed() >= kRedraw_ms) redraw();
}

// The new samples of one buffer into its channels' accumulators, each run
// between jumps in time at once; a jump's lost samples as missing ones.
void LiveHealth::read(Source& source)
{
    source.buffer->readNew(source.cursor, source.chunk);
    const auto& chunk = source.chunk;
    const std::size_t n = chunk.sampleCount();
    const auto pushRun = [&](std::size_t from, std::size_t to) {
        for (std::size_t c = 0; c < source.rows.size() && c < chunk.values.size(); ++c) {
            if (source.rows[c] < 0) continue;
            keep(static_cast<std::size_t>(source.rows[c]),
                 std::span<const double>(chunk.values[c]).subspan(from, to - from));
        }
    };
    std::size_t runStart = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = chunk.time_s[i];
        if (source.started) {
            const double lost = std::round((t - source.lastTime_s) * m_rate_hz) - 1.0;
            if (lost >= 1.0) {
                pushRun(runStart, i);
                runStart = i;
                const std::vector<double> missing(static_cast<std::size_t>(std::min(lost, kLongestGap_s * m_rate_hz)),
                                                  std::numeric_limits<double>::quiet_NaN());
                for (const int row : source.rows)
                    if (row >= 0) keep(static_cast<std::size_t>(row), missing);
            }
        }
        source.started = true;
        source.lastTime_s = t;
    }
    pushRun(runStart, n);
    if (&source == &m_sources.front()) m_samples += n;
}

void LiveHealth::keep(std::size_t row, std::span<const double> values)
{
    m_accumulators[row].push(values);
    if (!m_channels[row].creepJudged) return;
    auto& kept = m_beamSamples[row];
    if (kept.size() + values.size() > core::report::kMostCreepSamples) {
        m_channels[row].creepJudged = false;  // too long to hold: no creep read, rather than a stale one
        m_channels[row].creep.reset();
        kept = {};
        return;
    }
    kept.insert(kept.end(), values.begin(), values.end());
}

// Each beam's creep over its samples so far, on a worker thread; its
// result is dropped if a restart came first.
void LiveHealth::fitCreep()
{
    // After 10 s, and again after 10 s more or a tenth more of the record:
    // a long one's fit is long.
    const double due = std::max(kCreepRefit_s * m_rate_hz, 0.1 * static_cast<double>(m_creepFittedAt));
    if (m_creepFitting || static_cast<double>(m_samples - m_creepFittedAt) < due) return;
    std::vector<std::pair<std::size_t, std::vector<double>>> beams;
    for (std::size_t r = 0; r < m_channels.size(); ++r)
        if (m_channels[r].creepJudged) beams.emplace_back(r, m_beamSamples[r]);
    if (beams.empty()) return;
    m_creepFitting = true;
    m_creepFittedAt = m_samples;
    // `self` is only called back while `guard` says it lives (onGuiThread).
    QThreadPool::globalInstance()->start([beams = std::move(beams), rate = m_rate_hz, generation = m_generation,
                                          guard = QPointer<QObject>(this), self = this] {
        std::vector<std::pair<std::size_t, std::optional<core::dsp::StepCreep>>> found;
        for (const auto& [row, values] : beams) found.emplace_back(row, core::dsp::findStepCreep(values, rate));
        detail::onGuiThread(guard, [self, generation, found = std::move(found)] {
            if (self->m_generation != generation) return;
            self->m_creepFitting = false;
            QStringList lines;
            for (const auto& [row, creep] : found) {
                self->m_channels[row].creep = creep;
                lines << tr("Creep after a load step (%1): %2")
                             .arg(QString::fromStdString(self->m_channels[row].channel.name), healthCreepText(creep));
            }
            self->m_creepLine->setText(lines.join(QLatin1Char('\n')));
            self->m_creepLine->show();
        });
    });
}

void LiveHealth::redraw()
{
    m_sinceRedraw.restart();
    if (m_sources.empty()) return;
    m_line->setText(tr("Over %1 %2.").arg(durationText(static_cast<double>(m_samples) / m_rate_hz), m_since));
    for (std::size_t r = 0; r < m_channels.size(); ++r) {
        m_channels[r].health = m_accumulators[r].result();
        const QStringList cells = healthCells(m_channels[r]);
        for (int c = 0; c < cells.size(); ++c)
            m_table->item(static_cast<int>(r), kColumnOf[static_cast<std::size_t>(c)])->setText(cells[c]);
    }
    fitCreep();
}

}  // namespace tactiscope::ui
