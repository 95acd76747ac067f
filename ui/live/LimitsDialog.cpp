// LimitsDialog: the table of limits watched, the editor, applying them.
#include "ui/live/LimitsDialog.h"

#include "ui/common/DisplayUnits.h"
#include "ui/common/NumberText.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace tactiscope::ui {
namespace {

using core::trigger::LimitSide;

QString levelText(const std::optional<core::trigger::LimitLevel>& si, LimitSide side, const DisplayUnit& unit)
{
    if (!si) return QStringLiteral("—");
    if (!core::trigger::isWindow(side)) return watchedText(si->low, unit);
    // One unit for both ends: "−900 … 900 count".
    const QString low = typedText(si->low * unit.scale);
    return LimitsDialog::tr("%1 … %2").arg(low, watchedText(si->high, unit));
}

// The side in the limit's own words ("above", "outside"), as the command line writes it.
QString sideText(LimitSide side)
{
    return QString::fromLatin1(core::trigger::toString(side));
}

constexpr LimitSide kSides[] = {LimitSide::Above, LimitSide::Below, LimitSide::Outside, LimitSide::Inside};

}  // namespace

LimitsDialog::LimitsDialog(Session session, QWidget* parent)
    : QDialog(parent),
      m_session(std::move(session)),
      m_table(new QTableWidget(0, 5, this)),
      m_quantity(new QComboBox(this)),
      m_side(new QComboBox(this)),
      m_warning(new QLineEdit(this)),
      m_warningHigh(new QLineEdit(this)),
      m_critical(new QLineEdit(this)),
      m_criticalHigh(new QLineEdit(this)),
      m_hold(new QLineEdit(this)),
      m_warningUnit(new QLabel(this)),
      m_criticalUnit(new QLabel(this)),
      m_problem(new QLabel(this)),
      m_remove(new QPushButton(tr("Remove the one set here"), this))
{
    setWindowTitle(tr("Limit alarms"));
    setObjectName(QStringLiteral("limitsDialog"));
    m_table->setObjectName(QStringLiteral("limitsTable"));
    m_table->setHorizontalHeaderLabels({tr("Quantity"), tr("Alarm when"), tr("Warning"), tr("Critical"), tr("From")});
    // The numbers as wide as they are; where a limit comes from takes the rest, wrapped.
    for (int column = 0; column < 4; ++column)
        m_table->horizontalHeader()->setSectionResizeMode(column, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(4, QHeaderView::Stretch);
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setWordWrap(true);
    for (const auto& q : m_session.watchable) m_quantity->addItem(QString::fromStdString(q.name));
    for (const LimitSide side : kSides)
        m_side->addItem(core::trigger::isWindow(side) ? tr("%1 a window").arg(sideText(side)) : sideText(side),
                        static_cast<int>(side));
    m_quantity->setObjectName(QStringLiteral("limitQuantity"));
    m_side->setObjectName(QStringLiteral("limitSide"));
    m_warning->setObjectName(QStringLiteral("limitWarning"));
    m_warningHigh->setObjectName(QStringLiteral("limitWarningHigh"));
    m_critical->setObjectName(QStringLiteral("limitCritical"));
    m_criticalHigh->setObjectName(QStringLiteral("limitCriticalHigh"));
    m_hold->setObjectName(QStringLiteral("limitHold"));
    m_hold->setPlaceholderText(QStringLiteral("0"));
    m_problem->setObjectName(QStringLiteral("limitProblem"));
    m_problem->setStyleSheet(QStringLiteral("color: #b00020"));
    m_problem->setWordWrap(true);
    m_remove->setObjectName(QStringLiteral("removeLimit"));
    auto* set = new QPushButton(tr("Set"), this);
    set->setObjectName(QStringLiteral("setLimit"));

    // A form: the quantity, the side and hold time, then each level (or
    // each window's two ends, aligned) on its own row.
    auto* editor = new QGridLayout;
    const auto label = [this](const QString& text, QWidget* buddy) {
        auto* l = new QLabel(text, this);
        l->setBuddy(buddy);
        return l;
    };
    auto* warningTo = new QLabel(tr("to"), this);
    auto* criticalTo = new QLabel(tr("to"), this);
    editor->addWidget(label(tr("&Quantity"), m_quantity), 0, 0);
    editor->addWidget(m_quantity, 0, 1, 1, 3);
    editor->addWidget(label(tr("&Alarm when"), m_side), 1, 0);
    editor->addWidget(m_side, 1, 1);
    editor->addWidget(label(tr("&Hold"), m_hold), 1, 2, Qt::AlignRight);
    editor->addWidget(m_hold, 1, 3);
    editor->addWidget(new QLabel(tr("s"), this), 1, 4);
    editor->addWidget(label(tr("&Warning"), m_warning), 2, 0);
    editor->addWidget(m_warning, 2, 1);
    editor->addWidget(warningTo, 2, 2, Qt::AlignRight);
    editor->addWidget(m_warningHigh, 2, 3);
    editor->addWidget(m_warningUnit, 2, 4);
    editor->addWidget(label(tr("&Critical"), m_critical), 3, 0);
    editor->addWidget(m_critical, 3, 1);
    editor->addWidget(criticalTo, 3, 2, Qt::AlignRight);
    editor->addWidget(m_criticalHigh, 3, 3);
    editor->addWidget(m_criticalUnit, 3, 4);
    editor->addWidget(set, 3, 6);
    editor->setColumnStretch(1, 1);
    editor->setColumnStretch(3, 1);
    editor->setColumnStretch(5, 1);
    m_windowOnly = {warningTo, m_warningHigh, criticalTo, m_criticalHigh};
    auto* explain = new QLabel(tr("A limit set here replaces the probe's own on the same quantity and side (outside a "
                                  "window is both above and below). An alarm is raised once its value has been past "
                                  "the level for the hold time and clears 2 % of the level back, so noise at a level "
                                  "does not chatter. Either level may be left empty."),
                               this);
    explain->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::accept);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_remove, 0, Qt::AlignLeft);
    layout->addLayout(editor);
    layout->addWidget(explain);
    layout->addWidget(m_problem);
    layout->addWidget(buttons);

    const auto unitChanged = [this] {
        if (m_quantity->currentIndex() < 0) return;
        const QString symbol =
            watchedUnit(m_session.watchable, m_quantity->currentText().toStdString(), m_session.mode).symbol;
        m_warningUnit->setText(symbol);
        m_criticalUnit->setText(symbol);
    };
    connect(m_quantity, &QComboBox::currentIndexChanged, this, unitChanged);
    connect(m_side, &QComboBox::currentIndexChanged, this, &LimitsDialog::sideChanged);
    connect(set, &QPushButton::clicked, this, &LimitsDialog::setLimit);
    connect(m_remove, &QPushButton::clicked, this, &LimitsDialog::removeLimit);
    connect(m_table, &QTableWidget::itemSelectionChanged, this, [this] {
        const int row = m_table->currentRow();
        m_remove->setEnabled(row >= 0 && m_table->item(row, 0)->data(Qt::UserRole).toBool());
    });
    unitChanged();
    sideChanged();
    refreshTable();
    resize(780, 460);
}

void LimitsDialog::sideChanged()
{
    const bool window = core::trigger::isWindow(static_cast<LimitSide>(m_side->currentData().toInt()));
    for (QWidget* w : m_windowOnly) w->setVisible(window);
    m_warning->setPlaceholderText(window ? tr("from") : QString());
    m_critical->setPlaceholderText(window ? tr("from") : QString());
}

double LimitsDialog::toSi(const QLineEdit* edit, bool& ok) const
{
    const double shown = QLocale().toDouble(edit->text().trimmed(), &ok);
    ok = ok && std::isfinite(shown) && m_quantity->currentIndex() >= 0;
    return shown / watchedUnit(m_session.watchable, m_quantity->currentText().toStdString(), m_session.mode).scale;
}

LimitsDialog::Typed LimitsDialog::typed(const QLineEdit* low, const QLineEdit* high) const
{
    const bool window = core::trigger::isWindow(static_cast<LimitSide>(m_side->currentData().toInt()));
    const bool lowEmpty = low->text().trimmed().isEmpty();
    const bool highEmpty = !window || high->text().trimmed().isEmpty();
    if (lowEmpty && highEmpty) return {};
    bool lowOk = false, highOk = !window;
    const double lowSi = toSi(low, lowOk);
    const double highSi = window ? toSi(high, highOk) : lowSi;
    if (!lowOk || !highOk) return {std::nullopt, true};
    return {core::trigger::LimitLevel(lowSi, highSi), false};
}

void LimitsDialog::refreshTable()
{
    const auto limits = m_session.limits();
    m_table->setRowCount(static_cast<int>(limits.size()));
    for (int row = 0; row < static_cast<int>(limits.size()); ++row) {
        const auto& entry = limits[static_cast<std::size_t>(row)];
        const auto& limit = entry.limit;
        const DisplayUnit unit = watchedUnit(m_session.watchable, limit.quantity, m_session.mode);
        const bool given =
            std::ranges::any_of(m_session.given, [&limit](const auto& g) { return g.text() == limit.text(); });
        const QStringList cells{QString::fromStdString(limit.quantity), sideText(limit.side),
                                levelText(limit.warning, limit.side, unit), levelText(limit.critical, limit.side, unit),
                                given ? tr("set here") : QString::fromStdString(entry.basis)};
        for (int column = 0; column < cells.size(); ++column) {
            auto* item = new QTableWidgetItem(cells[column]);
            item->setData(Qt::UserRole, given);
            m_table->setItem(row, column, item);
        }
    }
    m_table->resizeRowsToContents();
    m_remove->setEnabled(false);
}

void LimitsDialog::setLimit()
{
    core::trigger::LimitSpec limit;
    limit.quantity = m_quantity->currentText().toStdString();
    limit.side = static_cast<LimitSide>(m_side->currentData().toInt());
    const Typed warning = typed(m_warning, m_warningHigh);
    const Typed critical = typed(m_critical, m_criticalHigh);
    if (warning.bad || critical.bad)
        return m_problem->setText(
            core::trigger::isWindow(limit.side)
                ? tr("Type both ends of each window as numbers, in %1.").arg(m_warningUnit->text())
                : tr("Type each level as a number, in %1.").arg(m_warningUnit->text()));
    limit.warning = warning.level;
    limit.critical = critical.level;
    if (!m_hold->text().trimmed().isEmpty()) {
        bool ok = false;
        limit.hold_s = QLocale().toDouble(m_hold->text().trimmed(), &ok);
        if (!ok || !std::isfinite(limit.hold_s) || limit.hold_s < 0.0)
            return m_problem->setText(tr("Type the hold time in seconds, 0 or more."));
    }
    // The rules the command line's --limit is read by.
    const auto checked = core::trigger::parseLimit(limit.text());
    if (!checked.limit) return m_problem->setText(QString::fromStdString(checked.error));
    auto given = m_session.given;
    std::erase_if(given, [&limit](const auto& g) { return limit.replaces(g); });
    given.push_back(limit);
    if (const auto refusal = m_session.apply(given)) return m_problem->setText(QString::fromStdString(*refusal));
    m_session.given = std::move(given);
    m_problem->clear();
    for (QLineEdit* edit : {m_warning, m_warningHigh, m_critical, m_criticalHigh, m_hold}) edit->clear();
    refreshTable();
}

void LimitsDialog::removeLimit()
{
    const int row = m_table->currentRow();
    if (row < 0) return;
    const auto limit = m_session.limits().at(static_cast<std::size_t>(row)).limit;
    auto given = m_session.given;
    std::erase_if(given, [&limit](const auto& g) { return g.text() == limit.text(); });
    if (const auto refusal = m_session.apply(given)) return m_problem->setText(QString::fromStdString(*refusal));
    m_session.given = std::move(given);
    refreshTable();
}

}  // namespace tactiscope::ui
