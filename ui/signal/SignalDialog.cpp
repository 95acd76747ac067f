// SignalDialog: the filter rows, the math lines, applying them.
#include "ui/signal/SignalDialog.h"

#include "core/NumberRanges.h"
#include "core/dsp/ChannelFilter.h"
#include "ui/common/NumberText.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace tactiscope::ui {
namespace {

enum Column { kChannel, kNotch, kHighpass, kLowpass, kOrder, kAverage, kDelay, kColumns };

// A number typed in a cell: none when empty; `bad` when it is not one.
std::optional<double> cellNumber(const QTableWidget* table, int row, int column, bool& bad)
{
    const auto* edit = qobject_cast<const QLineEdit*>(table->cellWidget(row, column));
    const QString text = edit ? edit->text().trimmed() : QString();
    if (text.isEmpty()) return std::nullopt;
    bool ok = false;
    double value = QLocale().toDouble(text, &ok);
    if (!ok) value = text.toDouble(&ok);  // a dot typed in a comma locale
    if (!ok || !std::isfinite(value)) {
        bad = true;
        return std::nullopt;
    }
    return value;
}

QLineEdit* numberCell(QWidget* parent, const QString& placeholder, const std::optional<double>& value)
{
    auto* edit = new QLineEdit(parent);
    edit->setPlaceholderText(placeholder);
    if (value) edit->setText(QLocale().toString(*value, 'g', 6));
    edit->setFrame(false);
    return edit;
}

}  // namespace

SignalDialog::SignalDialog(Session session, QWidget* parent)
    : QDialog(parent),
      m_session(std::move(session)),
      m_filters(new QTableWidget(static_cast<int>(m_session.channels.size()), kColumns, this)),
      m_mains(new QComboBox(this)),
      m_mainsFound(new QLabel(this)),
      m_analyseFiltered(new QCheckBox(tr("The &mode analyses the filtered channels (detector, presses, force)"), this)),
      m_math(new QPlainTextEdit(this)),
      m_problem(new QLabel(this))
{
    setWindowTitle(tr("Filters and math channels"));
    setObjectName(QStringLiteral("signalDialog"));
    m_filters->setObjectName(QStringLiteral("signalFilters"));
    m_filters->setHorizontalHeaderLabels({tr("Channel"), tr("Mains notch"), tr("High-pass (Hz)"), tr("Low-pass (Hz)"),
                                          tr("Order"), tr("Moving average (ms)"), tr("Delay")});
    m_filters->verticalHeader()->hide();
    m_filters->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_filters->horizontalHeader()->setSectionResizeMode(kDelay, QHeaderView::Stretch);
    m_mains->setObjectName(QStringLiteral("signalMains"));
    m_mains->addItem(tr("50 Hz"), 50.0);
    m_mains->addItem(tr("60 Hz"), 60.0);
    // The site's mains frequency is the station's setting, kept between runs;
    // a notch already set says it too.
    m_mains->setCurrentIndex(QSettings().value(QStringLiteral("signal/mains_hz"), 50.0).toDouble() == 60.0 ? 1 : 0);
    for (const auto& filter : m_session.setup.filters)
        if (filter.settings.notch_hz) m_mains->setCurrentIndex(*filter.settings.notch_hz == 60.0 ? 1 : 0);

    for (std::size_t c = 0; c < m_session.channels.size(); ++c) {
        const int row = static_cast<int>(c);
        const std::string& name = m_session.channels[c].name;
        const auto* now = m_session.setup.filterOf(name);
        const core::dsp::FilterSettings settings = now ? *now : core::dsp::FilterSettings{};
        auto* channel = new QTableWidgetItem(QString::fromStdString(name));
        channel->setFlags(Qt::ItemIsEnabled);
        m_filters->setItem(row, kChannel, channel);
        auto* notch = new QCheckBox(tr("at the mains"), m_filters);
        notch->setChecked(settings.notch_hz.has_value());
        m_filters->setCellWidget(row, kNotch, notch);
        m_filters->setCellWidget(row, kHighpass, numberCell(m_filters, tr("none"), settings.highpass_hz));
        m_filters->setCellWidget(row, kLowpass, numberCell(m_filters, tr("none"), settings.lowpass_hz));
        auto* order = new QSpinBox(m_filters);
        order->setRange(static_cast<int>(core::kFilterOrderRange.least),
                        static_cast<int>(core::kFilterOrderRange.most));
        order->setValue(settings.order);
        order->setFrame(false);
        m_filters->setCellWidget(row, kOrder, order);
        const std::optional<double> average_ms =
            settings.movingAverage_s > 0.0 ? std::optional(settings.movingAverage_s * 1e3) : std::nullopt;
        m_filters->setCellWidget(row, kAverage, numberCell(m_filters, tr("none"), average_ms));
        auto* delay = new QTableWidgetItem;
        delay->setFlags(Qt::ItemIsEnabled);
        m_filters->setItem(row, kDelay, delay);
        connect(notch, &QCheckBox::toggled, this, &SignalDialog::refreshDelays);
        connect(order, &QSpinBox::valueChanged, this, &SignalDialog::refreshDelays);
        for (const int column : {kHighpass, kLowpass, kAverage})
            connect(qobject_cast<QLineEdit*>(m_filters->cellWidget(row, column)), &QLineEdit::textChanged, this,
                    &SignalDialog::refreshDelays);
    }
    connect(m_mains, &QComboBox::currentIndexChanged, this, &SignalDialog::refreshDelays);
    m_analyseFiltered->setObjectName(QStringLiteral("signalAnalyseFiltered"));
    m_analyseFiltered->setChecked(m_session.setup.analysisFiltered);
    m_math->setObjectName(QStringLiteral("signalMath"));
    QStringList lines;
    for (const auto& definition : m_session.setup.math) lines << QString::fromStdString(definition.text());
    m_math->setPlainText(lines.join(QLatin1Char('\n')));
    m_math->setPlaceholderText(tr("diff[µε]=a - b"));
    m_math->setMaximumHeight(m_math->fontMetrics().lineSpacing() * 5 + 12);
    m_mainsFound->setObjectName(QStringLiteral("signalMainsFound"));
    m_mainsFound->setWordWrap(true);
    m_problem->setObjectName(QStringLiteral("signalProblem"));
    m_problem->setStyleSheet(QStringLiteral("color: #b00020"));
    m_problem->setWordWrap(true);

    auto* filters = new QGroupBox(tr("Filters (live: causal; the stored samples stay as they came)"), this);
    auto* filtersLayout = new QGridLayout(filters);
    auto* mainsLabel = new QLabel(tr("Site &mains frequency"), filters);
    mainsLabel->setBuddy(m_mains);
    auto* find = new QPushButton(tr("&Find it in the signal"), filters);
    find->setObjectName(QStringLiteral("signalFindMains"));
    filtersLayout->addWidget(m_filters, 0, 0, 1, 4);
    filtersLayout->addWidget(mainsLabel, 1, 0);
    filtersLayout->addWidget(m_mains, 1, 1);
    filtersLayout->addWidget(find, 1, 2);
    filtersLayout->addWidget(m_mainsFound, 1, 3);
    filtersLayout->addWidget(m_analyseFiltered, 2, 0, 1, 4);
    filtersLayout->setColumnStretch(3, 1);
    auto* math = new QGroupBox(tr("Math channels"), this);
    auto* mathLayout = new QVBoxLayout(math);
    auto* mathHelp = new QLabel(tr("One per line, NAME[UNIT]=EXPR. A channel stands for its value in SI (a strain as "
                                   "a number, a force in N), filtered where it is filtered; the result is in UNIT. "
                                   "Units are checked. Limits and the trigger can watch a math channel by its name, "
                                   "and a filtered one as NAME.filtered."),
                                math);
    mathHelp->setWordWrap(true);
    mathLayout->addWidget(m_math);
    mathLayout->addWidget(mathHelp);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Apply | QDialogButtonBox::Close, this);
    buttons->button(QDialogButtonBox::Apply)->setObjectName(QStringLiteral("signalApply"));
    connect(buttons->button(QDialogButtonBox::Apply), &QPushButton::clicked, this, &SignalDialog::applyTyped);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::accept);
    connect(find, &QPushButton::clicked, this, &SignalDialog::findMains);
    // A refusal stays until what it was about is typed again.
    connect(m_math, &QPlainTextEdit::textChanged, m_problem, &QLabel::clear);

    auto* layout = new QVBoxLayout(this);
    if (m_session.devices.size() > 1) {
        auto* chooser = new QComboBox(this);
        chooser->setObjectName(QStringLiteral("signalDevice"));
        for (const std::string& device : m_session.devices) chooser->addItem(QString::fromStdString(device));
        chooser->setCurrentIndex(static_cast<int>(m_session.device));
        auto* row = new QHBoxLayout;
        auto* label = new QLabel(tr("&Device (each its own filters and math channels, recorded with its part):"), this);
        label->setBuddy(chooser);
        row->addWidget(label);
        row->addWidget(chooser, 1);
        layout->addLayout(row);
        // Queued: the dialog closes itself (and is deleted) on the switch.
        connect(chooser, &QComboBox::activated, this, [this](int index) {
            if (index != static_cast<int>(m_session.device))
                QMetaObject::invokeMethod(
                    this, [show = m_session.showDevice, index] { show(static_cast<std::size_t>(index)); },
                    Qt::QueuedConnection);
        });
    }
    layout->addWidget(filters, 1);
    layout->addWidget(math);
    layout->addWidget(m_problem);
    layout->addWidget(buttons);
    refreshDelays();
    resize(760, 520);
}

core::signal::SignalSetup SignalDialog::typed(QString& problem) const
{
    problem.clear();
    core::signal::SignalSetup setup;
    for (int row = 0; row < m_filters->rowCount(); ++row) {
        core::dsp::FilterSettings s;
        bool bad = false;
        if (qobject_cast<const QCheckBox*>(m_filters->cellWidget(row, kNotch))->isChecked())
            s.notch_hz = m_mains->currentData().toDouble();
        s.highpass_hz = cellNumber(m_filters, row, kHighpass, bad);
        s.lowpass_hz = cellNumber(m_filters, row, kLowpass, bad);
        s.order = qobject_cast<const QSpinBox*>(m_filters->cellWidget(row, kOrder))->value();
        s.movingAverage_s = cellNumber(m_filters, row, kAverage, bad).value_or(0.0) / 1e3;
        const QString channel = m_filters->item(row, kChannel)->text();
        if (bad && problem.isEmpty()) problem = tr("%1: a cut-off or an average is not a number.").arg(channel);
        if (!s.empty()) setup.filters.push_back({channel.toStdString(), s});
    }
    setup.analysisFiltered = m_analyseFiltered->isChecked() && !setup.filters.empty();
    for (const QString& line : m_math->toPlainText().split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        if (line.trimmed().isEmpty()) continue;
        try {
            setup.math.push_back(core::math::parseMathDefinition(line.trimmed().toStdString()));
        } catch (const core::math::MathError& e) {
            if (problem.isEmpty()) problem = QString::fromStdString(e.what());
        }
    }
    return setup;
}

// Each row's delay (the group delay where its signal lives), or why its
// filter cannot be at the device's rate.
void SignalDialog::refreshDelays()
{
    m_problem->clear();
    QString problem;
    const auto setup = typed(problem);
    for (int row = 0; row < m_filters->rowCount(); ++row) {
        QTableWidgetItem* delay = m_filters->item(row, kDelay);
        const auto* settings = setup.filterOf(m_filters->item(row, kChannel)->text().toStdString());
        if (!settings) {
            delay->setText(tr("none"));
            delay->setToolTip({});
            continue;
        }
        if (const auto refusal = core::dsp::filterRefusal(*settings, m_session.rate_hz)) {
            delay->setText(tr("cannot be"));
            delay->setToolTip(QString::fromStdString(*refusal));
            continue;
        }
        const core::dsp::ChannelFilter filter(*settings, m_session.rate_hz);
        delay->setText(tr("%1 ms").arg(significantText(filter.delay_s() * 1e3, 3)));
        delay->setToolTip(tr("The live filtered trace lags the channel by this much at %1 Hz.")
                              .arg(significantText(filter.delayFrequency_hz(), 3)));
    }
}

void SignalDialog::applyTyped()
{
    QString problem;
    const auto setup = typed(problem);
    if (problem.isEmpty()) {
        if (m_analyseFiltered->isChecked() && setup.filters.empty())
            problem = tr("The mode can analyse the filtered channels only when a channel is filtered.");
        else if (const auto refusal = m_session.apply(setup))
            problem = QString::fromStdString(*refusal);
    }
    m_problem->setText(problem);
    if (!problem.isEmpty()) return;
    m_session.setup = setup;
    const double mains_hz = m_mains->currentData().toDouble();
    QSettings().setValue(QStringLiteral("signal/mains_hz"), mains_hz);
    // Applied, but a notch at the other mains would leave the hum whole: say so.
    const bool notched =
        std::ranges::any_of(setup.filters, [](const auto& f) { return f.settings.notch_hz.has_value(); });
    if (!notched || !m_session.findMains) return;
    if (const auto found = m_session.findMains(); found && found->first != mains_hz)
        m_problem->setText(tr("Applied. But the signal's hum is at %1 Hz (%2), and the notch is at %3 Hz: it "
                              "leaves the hum as it is. Set the site's mains frequency to %1 Hz and apply again.")
                               .arg(found->first)
                               .arg(found->second)
                               .arg(mains_hz));
}

void SignalDialog::findMains()
{
    const auto found = m_session.findMains ? m_session.findMains() : std::nullopt;
    if (!found) {
        m_mainsFound->setText(tr("No mains hum stands out in the last seconds of the signal."));
        return;
    }
    m_mains->setCurrentIndex(found->first == 60.0 ? 1 : 0);
    m_mainsFound->setText(found->second);
}

}  // namespace tactiscope::ui
