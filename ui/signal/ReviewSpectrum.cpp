// ReviewSpectrum: the range in samples, the channel read, the view drawn.
#include "ui/signal/ReviewSpectrum.h"

#include "core/signal/SignalColumns.h"
#include "ui/common/NumberText.h"
#include "ui/signal/SpectrumView.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace tactiscope::ui {

ReviewSpectrum::ReviewSpectrum(core::storage::SessionSource& store, const core::storage::SessionSummary& session,
                               double from_s, double to_s, QWidget* parent)
    : QDialog(parent),
      m_store(store),
      m_session(session),
      m_view(new SpectrumView(this))
{
    setWindowTitle(tr("Spectrum — session %1").arg(session.id));
    setObjectName(QStringLiteral("reviewSpectrum"));
    const auto stored = store.channels(session.id);
    std::vector<core::ChannelDescriptor> channels;
    for (const auto& c : stored) channels.push_back(c.descriptor);
    m_stored = channels.size();
    m_rate_hz = stored.empty() ? 0.0 : stored.front().sampleRate_hz;
    std::string problem;
    m_signal = core::signal::withRecordedSignal(store, session.id, nullptr, problem);
    if (m_signal) {
        const auto more = m_signal->channels();
        channels.insert(channels.end(), more.begin(), more.end());
    }
    m_view->setChannels(channels);
    m_first = static_cast<std::uint64_t>(std::max(0.0, std::floor(from_s * m_rate_hz)));
    const auto end = std::min(session.sampleCount, static_cast<std::uint64_t>(std::ceil(to_s * m_rate_hz)) + 1);
    m_count = end > m_first ? std::min(end - m_first, kMostSamples) : 0;
    const double shownTo_s = static_cast<double>(m_first + m_count) / m_rate_hz;
    m_span = tr("%1–%2 s").arg(fixedText(from_s, 2), fixedText(shownTo_s, 2));
    if (end - m_first > kMostSamples) m_span += tr(" (the range's first %1 samples)").arg(kMostSamples);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::accept);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_view, 1);
    if (!problem.empty()) {
        auto* left = new QLabel(QString::fromStdString(problem), this);
        left->setWordWrap(true);
        layout->addWidget(left);
    }
    layout->addWidget(buttons);
    connect(m_view, &SpectrumView::settingsChanged, this, &ReviewSpectrum::draw);
    resize(720, 480);
    draw();
}

ReviewSpectrum::~ReviewSpectrum() = default;

void ReviewSpectrum::draw()
{
    const int chosen = m_view->channel();
    if (chosen < 0 || m_count == 0) return m_view->clear(tr("Nothing in the range shown."));
    const auto channel = static_cast<std::size_t>(chosen);
    std::vector<double> values;
    try {
        if (channel < m_stored) {
            values = m_store.readChannel(m_session.id, channel, m_first, m_count);
        } else {
            auto columns = m_signal->read(m_first, m_count);
            values = std::move(columns.at(channel - m_stored));
        }
    } catch (const std::exception& e) {  // a store that went, a damaged chunk
        return m_view->clear(tr("The samples could not be read: %1").arg(QString::fromStdString(e.what())));
    }
    m_view->show(values, m_rate_hz, m_span);
}

}  // namespace tactiscope::ui
