// ShuntCheckDialog: the form, the run on a timer, the result kept.
#include "ui/calibration/ShuntCheckDialog.h"

#include "core/NumberRanges.h"
#include "core/storage/SessionStore.h"
#include "ui/common/NumberText.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace tactiscope::ui {
namespace {

// A box held to the range the CLI holds the same number to (core/NumberRanges.h).
QDoubleSpinBox* numberBox(double value, const core::NumberRange& range, int decimals, const QString& suffix,
                          QWidget* parent)
{
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(range.least, range.most);
    box->setDecimals(decimals);
    box->setValue(value);
    box->setSuffix(suffix);
    return box;
}

QString microstrain(double strain)
{
    return QObject::tr("%1 µε").arg(fixedText(strain * 1e6, 1));
}

}  // namespace

ShuntCheckDialog::ShuntCheckDialog(Context context, QWidget* parent)
    : QDialog(parent),
      m_context(std::move(context)),
      m_channel(new QComboBox(this)),
      m_bridge(new QComboBox(this)),
      m_gauge(numberBox(350.0, core::kGaugeOhmsRange, 1, QStringLiteral(" Ω"), this)),
      m_shunt(numberBox(100e3, core::kShuntOhmsRange, 0, QStringLiteral(" Ω"), this)),
      m_factor(numberBox(2.0, core::kGaugeFactorRange, 3, QString(), this)),
      m_tolerance(numberBox(1.0, core::kShuntToleranceRange, 2, QStringLiteral(" %"), this)),
      m_expected(new QLabel(this)),
      m_progress(new QProgressBar(this)),
      m_result(new QLabel(this)),
      m_runButton(new QPushButton(tr("Run"), this))
{
    setWindowTitle(tr("Shunt check"));
    setObjectName(QStringLiteral("shuntCheckDialog"));
    m_channel->setObjectName(QStringLiteral("shuntChannel"));
    m_bridge->setObjectName(QStringLiteral("shuntBridge"));
    m_factor->setObjectName(QStringLiteral("shuntGaugeFactor"));
    m_tolerance->setObjectName(QStringLiteral("shuntTolerance"));
    m_result->setObjectName(QStringLiteral("shuntResult"));
    m_runButton->setObjectName(QStringLiteral("shuntRun"));
    if (auto* live = m_context.session())
        for (std::size_t c = 0; c < live->channels().size(); ++c)
            if (live->channels()[c].kind == core::ChannelKind::Strain) {
                m_channels.push_back(c);
                m_channel->addItem(QString::fromStdString(live->channels()[c].name));
            }
    m_bridge->addItems({tr("Quarter bridge"), tr("Half bridge (bending)"), tr("Full bridge (bending)")});
    auto* form = new QFormLayout;
    form->addRow(tr("Strain channel"), m_channel);
    form->addRow(tr("Bridge"), m_bridge);
    form->addRow(tr("Gauge resistance R_g"), m_gauge);
    form->addRow(tr("Shunt resistance R_s"), m_shunt);
    form->addRow(tr("Gauge factor (data sheet)"), m_factor);
    form->addRow(tr("Passes within"), m_tolerance);
    form->addRow(tr("Expected step"), m_expected);
    auto* how = new QLabel(tr("Hold the probe still and unloaded. The channel is averaged for a second, the probe "
                              "switches its shunt across the first gauge, and after it settles the channel is "
                              "averaged again; then the shunt goes off."),
                           this);
    how->setWordWrap(true);
    m_result->setWordWrap(true);
    m_result->setTextFormat(Qt::RichText);
    m_progress->setRange(0, 100);
    m_progress->setValue(0);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_runButton, QDialogButtonBox::ActionRole);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(how);
    layout->addWidget(m_progress);
    layout->addWidget(m_result);
    layout->addWidget(buttons);

    const auto showExpected = [this] {
        try {
            m_expected->setText(microstrain(
                core::straingauge::shuntStrain(static_cast<core::straingauge::BridgeType>(m_bridge->currentIndex()),
                                               m_gauge->value(), m_shunt->value(), m_factor->value())));
        } catch (const std::invalid_argument& e) {
            m_expected->setText(QString::fromStdString(e.what()));
        }
    };
    connect(m_bridge, &QComboBox::currentIndexChanged, this, showExpected);
    for (QDoubleSpinBox* box : {m_gauge, m_shunt, m_factor})
        connect(box, &QDoubleSpinBox::valueChanged, this, showExpected);
    showExpected();
    connect(m_runButton, &QPushButton::clicked, this, &ShuntCheckDialog::run);
    connect(&m_timer, &QTimer::timeout, this, &ShuntCheckDialog::advance);
    m_timer.setInterval(50);
    if (m_channels.empty()) {
        m_runButton->setEnabled(false);
        m_result->setText(tr("This device has no strain channel: there is no bridge to check."));
    }
    setMinimumWidth(460);
}

ShuntCheckDialog::~ShuntCheckDialog() = default;  // a run still going switches its shunt off

void ShuntCheckDialog::run()
{
    auto* live = m_context.session();
    if (!live || m_channels.empty() || m_run) return;
    m_settings = {};
    m_settings.channel = m_channels.at(static_cast<std::size_t>(m_channel->currentIndex()));
    m_settings.bridge = static_cast<core::straingauge::BridgeType>(m_bridge->currentIndex());
    m_settings.gauge_ohm = m_gauge->value();
    m_settings.shunt_ohm = m_shunt->value();
    m_settings.gaugeFactor = m_factor->value();
    m_settings.tolerance = m_tolerance->value() / 100.0;
    try {
        m_run = std::make_unique<devices::session::ShuntCheckRun>(*live, m_settings);
    } catch (const std::invalid_argument& e) {
        m_result->setText(QString::fromStdString(e.what()));
        return;
    }
    m_runButton->setEnabled(false);
    m_result->setText(tr("Checking…"));
    m_timer.start();
}

void ShuntCheckDialog::advance()
{
    if (!m_context.session()) {  // the device went: the run goes with it
        m_timer.stop();
        m_run.reset();
        m_runButton->setEnabled(false);
        m_result->setText(tr("The device was disconnected: the check did not finish."));
        return;
    }
    if (!m_run->advance()) {
        m_progress->setValue(static_cast<int>(m_run->progress() * 100.0));
        return;
    }
    finished();
}

void ShuntCheckDialog::finished()
{
    m_timer.stop();
    m_progress->setValue(100);
    const auto& result = *m_run->result();
    auto* live = m_context.session();
    const std::string channel = live->channels()[m_settings.channel].name;
    if (!result.refusal.empty()) {
        m_result->setText(tr("<b>Not checked.</b> %1").arg(QString::fromStdString(result.refusal).toHtmlEscaped()));
    } else {
        const auto& check = result.check;
        const QString deviation = QStringLiteral("%1%2 %").arg(check.deviation > 0 ? QStringLiteral("+") : QString(),
                                                               fixedText(check.deviation * 100.0, 2));
        m_result->setText(tr("<span style='font-size:16pt; color:%1'><b>%2</b></span><br>expected %3, measured %4 µε: "
                             "deviation %5 (passes within %6 %)")
                              .arg(check.passed ? QStringLiteral("#2e7d32") : QStringLiteral("#c62828"),
                                   check.passed ? tr("PASS") : tr("FAIL"), microstrain(check.expected),
                                   valueWithErrorText(check.measured * 1e6, result.measured.uncertainty * 1e6),
                                   deviation, fixedText(m_settings.tolerance * 100.0, 2)));
        // Kept with the sensor's calibrations, and in the session being recorded.
        const auto record =
            m_run->record(live->source().identity().serial + " " + channel, m_context.operatorName.toStdString());
        try {
            core::storage::SessionStore(m_context.storePath.toStdString()).addCalibration(record);
        } catch (const core::storage::StorageError& e) {
            m_result->setText(m_result->text() +
                              tr("<br>Not kept in the history: %1").arg(QString::fromStdString(e.what())));
        }
        if (live->isRecording())
            live->addMarker(live->sessionTime_s(), "shunt check " + channel + ": " + (check.passed ? "PASS" : "FAIL") +
                                                       ", deviation " + deviation.toStdString() + " of the expected " +
                                                       microstrain(check.expected).toStdString());
    }
    m_run.reset();
    m_runButton->setEnabled(true);
}

QString ShuntCheckDialog::resultText() const
{
    return m_result->text();
}

}  // namespace tactiscope::ui
