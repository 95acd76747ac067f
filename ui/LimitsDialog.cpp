// LimitsDialog: the table of limits watched, the editor, applying them.
#include "ui/LimitsDialog.h"

#include "ui/DisplayUnits.h"
#include "ui/NumberText.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QHBoxLayout>
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

QString levelText(const std::optional<double>& si, const DisplayUnit& unit)
{
    return si ? watchedText(*si, unit) : QStringLiteral("—");
}

}  // namespace

LimitsDialog::LimitsDialog(Session session, QWidget* parent)
    : QDialog(parent),
      m_session(std::move(session)),
      m_table(new QTableWidget(0, 5, this)),
      m_quantity(new QComboBox(this)),
      m_side(new QComboBox(this)),
      m_warning(new QLineEdit(this)),
      m_critical(new QLineEdit(this)),
      m_unit(new QLabel(this)),
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
    m_side->addItems({tr("above"), tr("below")});
    m_quantity->setObjectName(QStringLiteral("limitQuantity"));
    m_side->setObjectName(QStringLiteral("limitSide"));
    m_warning->setObjectName(QStringLiteral("limitWarning"));
    m_critical->setObjectName(QStringLiteral("limitCritical"));
    m_warning->setPlaceholderText(tr("warning"));
    m_critical->setPlaceholderText(tr("critical"));
    m_problem->setObjectName(QStringLiteral("limitProblem"));
    m_problem->setStyleSheet(QStringLiteral("color: #b00020"));
    m_problem->setWordWrap(true);
    m_remove->setObjectName(QStringLiteral("removeLimit"));
    auto* set = new QPushButton(tr("Set"), this);
    set->setObjectName(QStringLiteral("setLimit"));

    auto* editor = new QHBoxLayout;
    editor->addWidget(m_quantity, 2);
    editor->addWidget(m_side);
    editor->addWidget(m_warning, 1);
    editor->addWidget(m_critical, 1);
    editor->addWidget(m_unit);
    editor->addWidget(set);
    auto* explain = new QLabel(tr("A limit set here replaces the probe's own on the same quantity and side. An alarm "
                                  "is raised once its value has been past the level for the hold time and clears "
                                  "2 % of the level back, so noise at a level does not chatter."),
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
        m_unit->setText(
            watchedUnit(m_session.watchable, m_quantity->currentText().toStdString(), m_session.mode).symbol);
    };
    connect(m_quantity, &QComboBox::currentIndexChanged, this, unitChanged);
    connect(set, &QPushButton::clicked, this, &LimitsDialog::setLimit);
    connect(m_remove, &QPushButton::clicked, this, &LimitsDialog::removeLimit);
    connect(m_table, &QTableWidget::itemSelectionChanged, this, [this] {
        const int row = m_table->currentRow();
        m_remove->setEnabled(row >= 0 && m_table->item(row, 0)->data(Qt::UserRole).toBool());
    });
    unitChanged();
    refreshTable();
    resize(760, 420);
}

std::optional<double> LimitsDialog::level(const QLineEdit* edit) const
{
    bool ok = false;
    const double shown = QLocale().toDouble(edit->text().trimmed(), &ok);
    if (!ok || !std::isfinite(shown) || m_quantity->currentIndex() < 0) return std::nullopt;
    return shown / watchedUnit(m_session.watchable, m_quantity->currentText().toStdString(), m_session.mode).scale;
}

void LimitsDialog::refreshTable()
{
    const auto limits = m_session.limits();
    m_table->setRowCount(static_cast<int>(limits.size()));
    for (int row = 0; row < static_cast<int>(limits.size()); ++row) {
        const auto& entry = limits[static_cast<std::size_t>(row)];
        const auto& limit = entry.limit;
        const DisplayUnit unit = watchedUnit(m_session.watchable, limit.quantity, m_session.mode);
        const bool given = std::ranges::any_of(m_session.given, [&limit](const auto& g) {
            return g.quantity == limit.quantity && g.above == limit.above;
        });
        const QStringList cells{QString::fromStdString(limit.quantity), limit.above ? tr("above") : tr("below"),
                                levelText(limit.warning, unit), levelText(limit.critical, unit),
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
    limit.above = m_side->currentIndex() == 0;
    if (!m_warning->text().trimmed().isEmpty()) limit.warning = level(m_warning);
    if (!m_critical->text().trimmed().isEmpty()) limit.critical = level(m_critical);
    if ((!m_warning->text().trimmed().isEmpty() && !limit.warning) ||
        (!m_critical->text().trimmed().isEmpty() && !limit.critical))
        return m_problem->setText(tr("Type each level as a number, in %1.").arg(m_unit->text()));
    // The rules the command line's --limit is read by.
    const auto checked = core::trigger::parseLimit(limit.text());
    if (!checked.limit) return m_problem->setText(QString::fromStdString(checked.error));
    auto given = m_session.given;
    std::erase_if(given, [&limit](const auto& g) { return g.quantity == limit.quantity && g.above == limit.above; });
    given.push_back(limit);
    if (const auto refusal = m_session.apply(given)) return m_problem->setText(QString::fromStdString(*refusal));
    m_session.given = std::move(given);
    m_problem->clear();
    m_warning->clear();
    m_critical->clear();
    refreshTable();
}

void LimitsDialog::removeLimit()
{
    const int row = m_table->currentRow();
    if (row < 0) return;
    const auto limit = m_session.limits().at(static_cast<std::size_t>(row)).limit;
    auto given = m_session.given;
    std::erase_if(given, [&limit](const auto& g) { return g.quantity == limit.quantity && g.above == limit.above; });
    if (const auto refusal = m_session.apply(given)) return m_problem->setText(QString::fromStdString(*refusal));
    m_session.given = std::move(given);
    refreshTable();
}

}  // namespace tactiscope::ui
