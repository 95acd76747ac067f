// ReviewFilterDialog: the fields, and the filter or its refusal in words.
#include "ui/signal/ReviewFilterDialog.h"

#include "core/dsp/ChannelFilter.h"
#include "ui/common/NumberText.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <stdexcept>

namespace tactiscope::ui {

ReviewFilterDialog::ReviewFilterDialog(std::vector<Channel> channels, QWidget* parent)
    : QDialog(parent),
      m_channels(std::move(channels)),
      m_channel(new QComboBox),
      m_notch(new QComboBox),
      m_highpass(new QDoubleSpinBox),
      m_lowpass(new QDoubleSpinBox),
      m_order(new QSpinBox),
      m_average(new QDoubleSpinBox),
      m_zeroPhase(new QCheckBox(tr("Zero-phase: forward and backward, no delay"))),
      m_said(new QLabel)
{
    setObjectName(QStringLiteral("reviewFilterDialog"));
    setWindowTitle(tr("Filter a channel in review"));
    for (const Channel& channel : m_channels) m_channel->addItem(QString::fromStdString(channel.name));
    m_channel->setObjectName(QStringLiteral("reviewFilterChannel"));
    m_notch->addItems({tr("off"), tr("50 Hz and harmonics"), tr("60 Hz and harmonics")});
    m_notch->setObjectName(QStringLiteral("reviewFilterNotch"));
    for (QDoubleSpinBox* cutoff : {m_highpass, m_lowpass}) {
        cutoff->setRange(0.0, 1e6);
        cutoff->setDecimals(2);
        cutoff->setSuffix(tr(" Hz"));
        cutoff->setSpecialValueText(tr("off"));
    }
    m_highpass->setObjectName(QStringLiteral("reviewFilterHighpass"));
    m_lowpass->setObjectName(QStringLiteral("reviewFilterLowpass"));
    m_order->setRange(2, 8);
    m_order->setValue(4);
    m_average->setRange(0.0, 60.0);
    m_average->setDecimals(3);
    m_average->setSuffix(tr(" s"));
    m_average->setSpecialValueText(tr("off"));
    m_zeroPhase->setObjectName(QStringLiteral("reviewFilterZeroPhase"));
    m_zeroPhase->setChecked(true);
    m_said->setObjectName(QStringLiteral("reviewFilterSaid"));
    m_said->setWordWrap(true);

    auto* form = new QFormLayout;
    form->addRow(tr("Channel"), m_channel);
    form->addRow(tr("Mains notch"), m_notch);
    form->addRow(tr("High-pass"), m_highpass);
    form->addRow(tr("Low-pass"), m_lowpass);
    form->addRow(tr("Butterworth order"), m_order);
    form->addRow(tr("Moving average"), m_average);
    form->addRow(QString(), m_zeroPhase);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel);
    m_add = buttons->addButton(tr("Add the lane"), QDialogButtonBox::AcceptRole);
    m_add->setObjectName(QStringLiteral("reviewFilterAdd"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_said);
    layout->addWidget(new QLabel(tr("The stored samples are not changed: the filter is a lane of the plot.")));
    layout->addWidget(buttons);

    connect(m_channel, &QComboBox::currentIndexChanged, this, &ReviewFilterDialog::refresh);
    connect(m_notch, &QComboBox::currentIndexChanged, this, &ReviewFilterDialog::refresh);
    for (QDoubleSpinBox* box : {m_highpass, m_lowpass, m_average})
        connect(box, &QDoubleSpinBox::valueChanged, this, &ReviewFilterDialog::refresh);
    connect(m_order, &QSpinBox::valueChanged, this, &ReviewFilterDialog::refresh);
    connect(m_zeroPhase, &QCheckBox::toggled, this, &ReviewFilterDialog::refresh);
    refresh();
}

core::dsp::FilterSettings ReviewFilterDialog::settings() const
{
    core::dsp::FilterSettings s;
    if (m_notch->currentIndex() == 1) s.notch_hz = 50.0;
    if (m_notch->currentIndex() == 2) s.notch_hz = 60.0;
    if (m_highpass->value() > 0.0) s.highpass_hz = m_highpass->value();
    if (m_lowpass->value() > 0.0) s.lowpass_hz = m_lowpass->value();
    s.order = m_order->value();
    s.movingAverage_s = m_average->value();
    s.zeroPhase = m_zeroPhase->isChecked();
    return s;
}

std::optional<core::signal::ReviewFilter> ReviewFilterDialog::filter() const
{
    const int chosen = m_channel->currentIndex();
    if (chosen < 0) return std::nullopt;
    const Channel& channel = m_channels[static_cast<std::size_t>(chosen)];
    const auto s = settings();
    if (s.empty() || core::dsp::filterRefusal(s, channel.rate_hz)) return std::nullopt;
    return core::signal::ReviewFilter{channel.name, s};
}

void ReviewFilterDialog::refresh()
{
    const int chosen = m_channel->currentIndex();
    const auto s = settings();
    QString said;
    bool usable = false;
    if (chosen < 0) {
        said = tr("The session has no channel to filter.");
    } else if (s.empty()) {
        said = tr("Choose a notch, a cut-off or a moving average.");
    } else {
        const double rate = m_channels[static_cast<std::size_t>(chosen)].rate_hz;
        if (const auto refusal = core::dsp::filterRefusal(s, rate)) {
            said = QStringLiteral("<span style='color:#b00020'>%1</span>")
                       .arg(QString::fromStdString(*refusal).toHtmlEscaped());
        } else {
            usable = true;
            said = QString::fromStdString(s.text());
            if (s.zeroPhase) {
                said += tr(" (no delay)");
            } else {
                const core::dsp::ChannelFilter causal(s, rate);
                said += tr(", causal as live: it lags by %1 ms").arg(significantText(causal.delay_s() * 1e3, 3));
            }
        }
    }
    m_said->setText(said);
    m_add->setEnabled(usable);
}

}  // namespace tactiscope::ui
