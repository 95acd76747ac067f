// SessionBar: layout, the record button's two faces, elapsed time.
#include "ui/live/SessionBar.h"

#include "core/modes/ModeDefinition.h"
#include "devices/session/LiveSession.h"
#include "ui/common/VocabularyText.h"
#include "ui/live/LiveStation.h"

#include <QComboBox>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

#include <cmath>

namespace tactiscope::ui {
namespace {

QLabel* caption(const QString& text, QWidget* parent)
{
    auto* label = new QLabel(text, parent);
    label->setStyleSheet(QStringLiteral("color: palette(mid); font-weight: 600;"));
    return label;
}

}  // namespace

SessionBar::SessionBar(QWidget* parent)
    : QWidget(parent),
      m_mode(new QComboBox(this)),
      m_subject(new QLineEdit(this)),
      m_operator(new QLineEdit(this)),
      m_record(new QPushButton(this)),
      m_elapsed(new QLabel(this)),
      m_store(new QLabel(this))
{
    m_mode->setObjectName(QStringLiteral("modeBox"));
    m_subject->setObjectName(QStringLiteral("subjectEdit"));
    m_operator->setObjectName(QStringLiteral("operatorEdit"));
    m_record->setObjectName(QStringLiteral("recordButton"));
    m_elapsed->setObjectName(QStringLiteral("elapsedLabel"));
    m_store->setObjectName(QStringLiteral("storeLabel"));

    for (const auto& definition : core::modeDefinitions())
        m_mode->addItem(modeTitle(definition.mode), static_cast<int>(definition.mode));
    m_subject->setPlaceholderText(tr("panel or phantom id"));
    m_operator->setPlaceholderText(tr("your name"));
    m_subject->setMinimumWidth(160);
    m_operator->setMinimumWidth(120);

    // Big enough to hit with a gloved finger; the face says what a press does.
    QFont big = m_record->font();
    big.setPointSizeF(big.pointSizeF() * 1.3);
    big.setBold(true);
    m_record->setFont(big);
    m_record->setMinimumSize(150, 44);
    m_record->setToolTip(tr("Start or stop recording (Ctrl+R)"));
    QFont clock = m_elapsed->font();
    clock.setPointSizeF(clock.pointSizeF() * 1.6);
    clock.setStyleHint(QFont::Monospace);
    clock.setFamily(QStringLiteral("monospace"));
    m_elapsed->setFont(clock);
    m_elapsed->setMinimumWidth(m_elapsed->fontMetrics().horizontalAdvance(QStringLiteral("00:00:00")) + 8);
    m_store->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(10, 6, 10, 6);
    layout->setSpacing(8);
    layout->addWidget(caption(tr("Mode"), this));
    layout->addWidget(m_mode);
    layout->addSpacing(10);
    layout->addWidget(caption(tr("Subject"), this));
    layout->addWidget(m_subject, 2);
    layout->addSpacing(10);
    layout->addWidget(caption(tr("Operator"), this));
    layout->addWidget(m_operator, 1);
    layout->addSpacing(16);
    layout->addWidget(m_record);
    layout->addWidget(m_elapsed);
    layout->addWidget(m_store, 2);

    connect(m_record, &QPushButton::clicked, this, &SessionBar::recordClicked);
    connect(m_mode, &QComboBox::currentIndexChanged, this, &SessionBar::modeChanged);
    setRecording(false);
    setRecordEnabled(false);
    setElapsed(0.0);
}

void SessionBar::watch(const LiveStation& station)
{
    connect(&station, &LiveStation::connected, this, [this] { setRecordEnabled(true); });
    connect(&station, &LiveStation::disconnected, this, [this] { setRecordEnabled(false); });
    connect(&station, &LiveStation::recordingChanged, this, &SessionBar::setRecording);
    connect(&station, &LiveStation::armedChanged, this, &SessionBar::setArmed);
    connect(&station, &LiveStation::polled, this, [this, &station] {
        if (station.isRecording() && station.device()) setElapsed(station.device()->sessionTime_s());
    });
}

core::storage::SessionMetadata SessionBar::metadata() const
{
    core::storage::SessionMetadata m;
    m.mode = static_cast<core::Mode>(m_mode->currentData().toInt());
    m.subject = m_subject->text().trimmed().toStdString();
    m.operatorName = m_operator->text().trimmed().toStdString();
    return m;
}

void SessionBar::setMetadata(const core::storage::SessionMetadata& metadata)
{
    setMode(metadata.mode);
    m_subject->setText(QString::fromStdString(metadata.subject));
    m_operator->setText(QString::fromStdString(metadata.operatorName));
}

void SessionBar::setMode(core::Mode mode)
{
    m_mode->setCurrentIndex(m_mode->findData(static_cast<int>(mode)));
}

void SessionBar::setRecordEnabled(bool enabled)
{
    m_record->setEnabled(enabled || m_recording);
}

void SessionBar::setRecording(bool recording)
{
    m_recording = recording;
    applyState();
}

void SessionBar::setArmed(bool armed)
{
    m_armed = armed;
    applyState();
}

void SessionBar::applyState()
{
    m_record->setText(m_armed ? tr("■  Disarm") : m_recording ? tr("■  Stop") : tr("●  Record"));
    // Red while recording, so the state reads from across the room.
    m_record->setStyleSheet(m_recording ? QStringLiteral("QPushButton { background: #c62828; color: white; "
                                                         "border-radius: 6px; padding: 4px 14px; }")
                            : m_armed   ? QStringLiteral("QPushButton { background: #2f5d8a; color: white; "
                                                           "border-radius: 6px; padding: 4px 14px; }")
                                        : QString());
    m_elapsed->setStyleSheet(m_recording ? QStringLiteral("color: #c62828;") : QString());
    // Read-only rather than disabled, so the metadata stays legible.
    const bool hold = m_recording || m_armed;
    m_mode->setEnabled(!hold);
    m_subject->setReadOnly(hold);
    m_operator->setReadOnly(hold);
}

void SessionBar::setElapsed(double seconds)
{
    const auto whole = static_cast<long long>(std::floor(std::max(0.0, seconds)));
    m_elapsed->setText(QStringLiteral("%1:%2:%3")
                           .arg(whole / 3600, 2, 10, QLatin1Char('0'))
                           .arg(whole / 60 % 60, 2, 10, QLatin1Char('0'))
                           .arg(whole % 60, 2, 10, QLatin1Char('0')));
}

void SessionBar::setStorePath(const QString& path)
{
    m_store->setText(tr("→ %1").arg(QFileInfo(path).fileName()));
    m_store->setToolTip(tr("Sessions are written to %1").arg(path));
}

}  // namespace tactiscope::ui
