// SpectrumView: the controls, the log–log plot and the peaks' line.
#include "ui/signal/SpectrumView.h"

#include "core/NumberRanges.h"
#include "ui/common/NumberText.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace tactiscope::ui {
namespace {

// Peaks listed under the plot.
constexpr std::size_t kPeaksShown = 3;

}  // namespace

SpectrumView::SpectrumView(QWidget* parent)
    : QWidget(parent),
      m_channel(new QComboBox(this)),
      m_window(new QComboBox(this)),
      m_averages(new QSpinBox(this)),
      m_plot(new QCustomPlot(this)),
      m_peaks(new QLabel(this))
{
    m_channel->setObjectName(QStringLiteral("spectrumChannel"));
    m_window->setObjectName(QStringLiteral("spectrumWindow"));
    m_averages->setObjectName(QStringLiteral("spectrumAverages"));
    m_peaks->setObjectName(QStringLiteral("spectrumPeaks"));
    m_plot->setObjectName(QStringLiteral("spectrumPlot"));
    m_window->addItem(tr("Hann"), static_cast<int>(core::dsp::SpectralWindow::Hann));
    m_window->addItem(tr("Flat-top"), static_cast<int>(core::dsp::SpectralWindow::FlatTop));
    m_window->setToolTip(tr("Hann: the density's shape; flat-top: lines' amplitudes true to 0.1 %. The peaks below "
                            "are read through a flat-top window either way."));
    m_averages->setRange(1, 1024);
    m_averages->setValue(8);
    m_averages->setToolTip(tr("Segments averaged, at least: more averages, a smoother density and a coarser "
                              "resolution."));
    m_peaks->setWordWrap(true);
    m_peaks->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* controls = new QHBoxLayout;
    const auto label = [this](const QString& text, QWidget* buddy) {
        auto* l = new QLabel(text, this);
        l->setBuddy(buddy);
        return l;
    };
    controls->addWidget(label(tr("&Channel"), m_channel));
    controls->addWidget(m_channel, 1);
    controls->addWidget(label(tr("&Window"), m_window));
    controls->addWidget(m_window);
    controls->addWidget(label(tr("&Averages"), m_averages));
    controls->addWidget(m_averages);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(controls);
    layout->addWidget(m_plot, 1);
    layout->addWidget(m_peaks);

    m_plot->addGraph();
    m_plot->graph(0)->setPen(QPen(QColor(0x1f, 0x77, 0xb4), 1.2));
    for (QCPAxis* axis : {m_plot->xAxis, m_plot->yAxis}) {
        axis->setScaleType(QCPAxis::stLogarithmic);
        axis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
        axis->setNumberFormat(QStringLiteral("eb"));
        axis->setNumberPrecision(0);
    }
    m_plot->xAxis->setNumberFormat(QStringLiteral("g"));  // 10, 100 Hz
    m_plot->xAxis->setNumberPrecision(6);
    m_plot->xAxis->setLabel(tr("Frequency (Hz)"));
    m_plot->setMinimumHeight(160);

    connect(m_channel, &QComboBox::currentIndexChanged, this, &SpectrumView::settingsChanged);
    connect(m_window, &QComboBox::currentIndexChanged, this, &SpectrumView::settingsChanged);
    connect(m_averages, &QSpinBox::valueChanged, this, &SpectrumView::settingsChanged);
    clear(tr("No channel yet."));
}

void SpectrumView::setChannels(const std::vector<core::ChannelDescriptor>& channels)
{
    const QString chosen = m_channel->currentText();
    m_channels = channels;
    const QSignalBlocker quiet(m_channel);
    m_channel->clear();
    for (const auto& c : channels) m_channel->addItem(QString::fromStdString(c.name));
    const int again = m_channel->findText(chosen);
    m_channel->setCurrentIndex(again >= 0 ? again : 0);
}

int SpectrumView::channel() const
{
    return m_channel->currentIndex();
}

core::dsp::SpectrumSettings SpectrumView::settings() const
{
    return {static_cast<core::dsp::SpectralWindow>(m_window->currentData().toInt()),
            static_cast<std::size_t>(m_averages->value())};
}

void SpectrumView::show(std::span<const double> values, double rate_hz, const QString& span)
{
    const int c = channel();
    if (c < 0 || static_cast<std::size_t>(c) >= m_channels.size()) return clear(tr("No channel."));
    m_spectrum = core::dsp::welchSpectrum(values, rate_hz, settings(), m_accumulator);
    if (m_spectrum.averages == 0) return clear(tr("Too few samples between gaps for a spectrum (%1).").arg(span));
    m_unit = displayUnitFor(m_channels[static_cast<std::size_t>(c)]);
    const auto asd = m_spectrum.asd();
    QVector<double> f, y;
    for (std::size_t k = 1; k < asd.size(); ++k) {  // no DC on a log axis
        if (!(asd[k] > 0.0) || !std::isfinite(asd[k])) continue;
        f.push_back(m_spectrum.frequency_hz[k]);
        y.push_back(asd[k] * m_unit.scale);
    }
    m_plot->graph(0)->setData(f, y, true);
    const QString symbol = m_unit.symbol.isEmpty() ? QStringLiteral("1") : m_unit.symbol;
    m_plot->yAxis->setLabel(tr("%1/√Hz").arg(symbol));
    if (!f.isEmpty()) {
        m_plot->xAxis->setRange(f.front(), f.back());
        const auto [low, high] = std::minmax_element(y.begin(), y.end());
        m_plot->yAxis->setRange(*low / 2.0, *high * 2.0);
    }
    m_plot->replot(QCustomPlot::rpQueuedReplot);
    QString said = tr("%1: %2 averages of %3 points, resolution %4 Hz")
                       .arg(span)
                       .arg(m_spectrum.averages)
                       .arg(m_spectrum.segmentLength)
                       .arg(significantText(m_spectrum.resolution_hz(), 3));
    if (m_spectrum.stretches > 1 || m_spectrum.stretchesTooShort > 0)
        said += tr("; in %n gap-free stretch(es), never across a gap", nullptr, static_cast<int>(m_spectrum.stretches));
    m_peaks->setText(said + QStringLiteral(". ") + peaksText());
}

void SpectrumView::clear(const QString& why)
{
    m_spectrum = {};
    m_plot->graph(0)->data()->clear();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
    m_peaks->setText(why);
}

QString SpectrumView::peaksText() const
{
    if (m_spectrum.peaks.empty()) return tr("No line stands out.");
    QStringList lines;
    for (std::size_t p = 0; p < std::min(kPeaksShown, m_spectrum.peaks.size()); ++p) {
        const auto& peak = m_spectrum.peaks[p];
        const QString amplitude = significantText(peak.amplitude * m_unit.scale, 3);
        lines << tr("%1 Hz: %2%3")
                     .arg(significantText(peak.frequency_hz, 4), amplitude,
                          m_unit.symbol.isEmpty() ? QString() : QStringLiteral(" ") + m_unit.symbol);
    }
    return tr("Lines: %1").arg(lines.join(QStringLiteral(", ")));
}

}  // namespace tactiscope::ui
