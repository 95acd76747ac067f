// TriggerDialog: the form, its units, and the condition it makes.
#include "ui/live/TriggerDialog.h"

#include "core/NumberRanges.h"
#include "ui/common/DisplayUnits.h"
#include "ui/common/NumberText.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace tactiscope::ui {
namespace {

using core::trigger::TriggerKind;

struct KindChoice {
    TriggerKind kind;
    const char* text;
};
constexpr KindChoice kKinds[] = {
    {TriggerKind::Above, QT_TRANSLATE_NOOP("TriggerDialog", "is above")},
    {TriggerKind::Below, QT_TRANSLATE_NOOP("TriggerDialog", "is below")},
    {TriggerKind::Rising, QT_TRANSLATE_NOOP("TriggerDialog", "rises through")},
    {TriggerKind::Falling, QT_TRANSLATE_NOOP("TriggerDialog", "falls through")},
    {TriggerKind::Inside, QT_TRANSLATE_NOOP("TriggerDialog", "is inside")},
    {TriggerKind::Outside, QT_TRANSLATE_NOOP("TriggerDialog", "is outside")},
};

bool isWindowKind(TriggerKind kind)
{
    return kind == TriggerKind::Inside || kind == TriggerKind::Outside;
}

// Seconds held to the range the CLI holds them to (core/NumberRanges.h):
// the pre-trigger buffer's 60 s bound its memory in the GUI too.
QDoubleSpinBox* seconds(double value, const core::NumberRange& range, QWidget* parent)
{
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(range.least, range.most);
    box->setDecimals(2);
    box->setSingleStep(0.1);
    box->setSuffix(QStringLiteral(" s"));
    box->setValue(value);
    return box;
}

}  // namespace

QString conditionText(const core::trigger::TriggerCondition& condition,
                      const std::vector<core::ChannelDescriptor>& watchable, core::Mode mode)
{
    const DisplayUnit unit = watchedUnit(watchable, condition.quantity, mode);
    const auto shown = [&unit](double si) { return watchedText(si, unit); };
    const QString name = QString::fromStdString(condition.quantity);
    switch (condition.kind) {
    case TriggerKind::Above:
        return QStringLiteral("%1 > %2").arg(name, shown(condition.level));
    case TriggerKind::Below:
        return QStringLiteral("%1 < %2").arg(name, shown(condition.level));
    case TriggerKind::Rising:
        return TriggerDialog::tr("%1 rises through %2").arg(name, shown(condition.level));
    case TriggerKind::Falling:
        return TriggerDialog::tr("%1 falls through %2").arg(name, shown(condition.level));
    case TriggerKind::Inside:
        return TriggerDialog::tr("%1 inside %2 … %3").arg(name, shown(condition.level), shown(condition.high));
    case TriggerKind::Outside:
        return TriggerDialog::tr("%1 outside %2 … %3").arg(name, shown(condition.level), shown(condition.high));
    }
    return name;
}

TriggerDialog::TriggerDialog(std::vector<core::ChannelDescriptor> watchable, core::Mode mode, QWidget* parent)
    : QDialog(parent),
      m_watchable(std::move(watchable)),
      m_mode(mode),
      m_quantity(new QComboBox(this)),
      m_kind(new QComboBox(this)),
      m_level(new QLineEdit(this)),
      m_and(new QLabel(tr("and"), this)),
      m_high(new QLineEdit(this)),
      m_unit(new QLabel(this)),
      m_highUnit(new QLabel(this)),
      m_pre(seconds(0.5, core::kPreTriggerRange, this)),
      m_post(seconds(1.0, core::kPostTriggerRange, this)),
      m_holdOff(seconds(0.0, core::kHoldOffRange, this)),
      m_sessions(new QSpinBox(this)),
      m_rearm(new QCheckBox(tr("Re-arm after each session until disarmed"), this)),
      m_command(new QLabel(this)),
      m_problem(new QLabel(this)),
      m_arm(nullptr)
{
    setWindowTitle(tr("Trigger"));
    setObjectName(QStringLiteral("triggerDialog"));
    for (const auto& q : m_watchable) {
        const DisplayUnit unit = laneUnit(q, m_mode);
        m_quantity->addItem(unit.symbol.isEmpty() ? QString::fromStdString(q.name)
                                                  : tr("%1 (%2)").arg(QString::fromStdString(q.name), unit.symbol));
    }
    for (const auto& choice : kKinds) m_kind->addItem(tr(choice.text));
    m_quantity->setObjectName(QStringLiteral("triggerQuantity"));
    m_kind->setObjectName(QStringLiteral("triggerKind"));
    m_level->setObjectName(QStringLiteral("triggerLevel"));
    m_high->setObjectName(QStringLiteral("triggerHigh"));
    m_pre->setObjectName(QStringLiteral("triggerPre"));
    m_post->setObjectName(QStringLiteral("triggerPost"));
    m_holdOff->setObjectName(QStringLiteral("triggerHoldOff"));
    m_sessions->setObjectName(QStringLiteral("triggerSessions"));
    m_rearm->setObjectName(QStringLiteral("triggerRearm"));
    m_sessions->setRange(1, 9999);
    m_sessions->setValue(1);
    m_sessions->setSuffix(tr(" sessions, then stop"));

    auto* condition = new QHBoxLayout;
    condition->addWidget(m_quantity, 2);
    condition->addWidget(m_kind, 1);
    condition->addWidget(m_level, 1);
    condition->addWidget(m_unit);
    condition->addWidget(m_and);
    condition->addWidget(m_high, 1);
    condition->addWidget(m_highUnit);

    auto* form = new QFormLayout;
    form->addRow(tr("Start a session when"), condition);
    form->addRow(tr("Keep before the trigger"), m_pre);
    form->addRow(tr("Keep after it clears"), m_post);
    form->addRow(tr("Then wait before re-arming"), m_holdOff);
    form->addRow(tr("Record"), m_sessions);
    form->addRow(QString(), m_rearm);

    m_command->setObjectName(QStringLiteral("triggerCommand"));
    m_command->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_command->setWordWrap(true);
    m_problem->setObjectName(QStringLiteral("triggerProblem"));
    m_problem->setStyleSheet(QStringLiteral("color: #b00020"));
    m_problem->setWordWrap(true);
    auto* note = new QLabel(tr("Each session takes the subject in the session bar, numbered on (door-17, door-18, …), "
                               "and a trigger event at its instant. An edge keeps its time after from the edge."),
                            this);
    note->setWordWrap(true);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_arm = buttons->addButton(tr("Arm"), QDialogButtonBox::AcceptRole);
    m_arm->setObjectName(QStringLiteral("armButton"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    // The rows stay under the pointer as the texts below them come and go:
    // those have room kept for them, and spare height goes to the stretch.
    const int line = fontMetrics().lineSpacing();
    m_command->setMinimumHeight(3 * line);
    m_problem->setMinimumHeight(2 * line);
    m_command->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_problem->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(note);
    layout->addWidget(m_command);
    layout->addWidget(m_problem);
    layout->addStretch(1);
    layout->addWidget(buttons);

    connect(m_quantity, &QComboBox::currentIndexChanged, this, &TriggerDialog::quantityChanged);
    connect(m_kind, &QComboBox::currentIndexChanged, this, &TriggerDialog::refresh);
    for (QLineEdit* edit : {m_level, m_high}) connect(edit, &QLineEdit::textEdited, this, &TriggerDialog::refresh);
    for (QDoubleSpinBox* box : {m_pre, m_post, m_holdOff})
        connect(box, &QDoubleSpinBox::valueChanged, this, &TriggerDialog::refresh);
    connect(m_sessions, &QSpinBox::valueChanged, this, &TriggerDialog::refresh);
    connect(m_rearm, &QCheckBox::toggled, this, [this](bool rearm) {
        m_sessions->setEnabled(!rearm);
        refresh();
    });
    setMinimumWidth(620);
    quantityChanged();
}

const core::ChannelDescriptor& TriggerDialog::watched() const
{
    return m_watchable.at(static_cast<std::size_t>(std::max(0, m_quantity->currentIndex())));
}

DisplayUnit TriggerDialog::watchedUnitNow() const
{
    return laneUnit(watched(), m_mode);
}

void TriggerDialog::quantityChanged()
{
    if (m_watchable.empty()) return;
    const QString symbol = watchedUnitNow().symbol;
    m_unit->setText(symbol);
    m_highUnit->setText(symbol);
    refresh();
}

// A level typed in the quantity's display unit, in SI.
std::optional<double> TriggerDialog::level(const QLineEdit* edit) const
{
    bool ok = false;
    const double shown = QLocale().toDouble(edit->text().trimmed(), &ok);
    if (!ok || !std::isfinite(shown)) return std::nullopt;
    return shown / watchedUnitNow().scale;
}

void TriggerDialog::setSettings(const core::trigger::TriggerSettings& settings)
{
    for (std::size_t i = 0; i < m_watchable.size(); ++i)
        if (m_watchable[i].name == settings.condition.quantity) m_quantity->setCurrentIndex(static_cast<int>(i));
    for (int i = 0; i < static_cast<int>(std::size(kKinds)); ++i)
        if (kKinds[i].kind == settings.condition.kind) m_kind->setCurrentIndex(i);
    const double scale = watchedUnitNow().scale;
    m_level->setText(typedText(settings.condition.level * scale));
    if (isWindowKind(settings.condition.kind)) m_high->setText(typedText(settings.condition.high * scale));
    m_pre->setValue(settings.pre_s);
    m_post->setValue(settings.post_s);
    m_holdOff->setValue(settings.holdOff_s);
    m_rearm->setChecked(!settings.sessions);
    if (settings.sessions) m_sessions->setValue(static_cast<int>(*settings.sessions));
    refresh();
}

std::optional<core::trigger::TriggerSettings> TriggerDialog::settings() const
{
    if (m_watchable.empty()) return std::nullopt;
    const TriggerKind kind = kKinds[std::max(0, m_kind->currentIndex())].kind;
    const auto low = level(m_level);
    const auto high = isWindowKind(kind) ? level(m_high) : low;
    if (!low || !high || (isWindowKind(kind) && *high < *low)) return std::nullopt;
    core::trigger::TriggerSettings s;
    s.condition.quantity = watched().name;
    s.condition.kind = kind;
    s.condition.level = *low;
    s.condition.high = isWindowKind(kind) ? *high : 0.0;
    s.pre_s = m_pre->value();
    s.post_s = m_post->value();
    s.holdOff_s = m_holdOff->value();
    if (!m_rearm->isChecked()) s.sessions = static_cast<unsigned>(m_sessions->value());
    return s;
}

QString TriggerDialog::problem() const
{
    if (m_watchable.empty()) return tr("Connect a device: there is nothing to watch.");
    const TriggerKind kind = kKinds[std::max(0, m_kind->currentIndex())].kind;
    if (!level(m_level)) return tr("Type the level as a number, in %1.").arg(m_unit->text());
    if (isWindowKind(kind)) {
        if (!level(m_high)) return tr("Type the window's upper end as a number.");
        if (*level(m_high) < *level(m_level)) return tr("The window's upper end must not be below its lower end.");
    }
    return {};
}

void TriggerDialog::refresh()
{
    const bool window = isWindowKind(kKinds[std::max(0, m_kind->currentIndex())].kind);
    m_and->setVisible(window);
    m_high->setVisible(window);
    m_highUnit->setVisible(window);
    const auto s = settings();
    m_problem->setText(problem());
    m_arm->setEnabled(s.has_value());
    m_command->setText(
        s ? tr("The same from the command line: <code>record --trigger \"%1\" --pre %2 --post %3 --hold-off %4 "
               "%5</code>")
                .arg(QString::fromStdString(s->condition.text()).toHtmlEscaped(), typedText(s->pre_s),
                     typedText(s->post_s), typedText(s->holdOff_s),
                     s->sessions ? QStringLiteral("--sessions %1").arg(*s->sessions) : QStringLiteral("--rearm"))
          : QString());
}

}  // namespace tactiscope::ui
