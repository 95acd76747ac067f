// SiteGridMap: grid size, cell colours, the legend and the moving selection.
#include "ui/modes/palpation/SiteGridMap.h"

#include "ui/common/NumberText.h"
#include "ui/modes/palpation/StiffnessScale.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>
#include <utility>

namespace tactiscope::ui {
namespace {

constexpr int kValueRole = Qt::UserRole;

}  // namespace

QString siteName(int row, int column)
{
    return QString::fromStdString(core::compliance::SiteGrid::name({row, column}));
}

SiteGridMap::SiteGridMap(QWidget* parent)
    : QWidget(parent),
      m_active(new QCheckBox(tr("Grid map of sites"), this)),
      m_rows(new QSpinBox(this)),
      m_columns(new QSpinBox(this)),
      m_grid(new QTableWidget(this))
{
    m_active->setObjectName(QStringLiteral("gridMapBox"));
    m_grid->setObjectName(QStringLiteral("siteGrid"));
    m_rows->setRange(1, core::compliance::SiteGrid::kMaxRows);
    m_columns->setRange(1, core::compliance::SiteGrid::kMaxColumns);
    m_rows->setValue(3);
    m_columns->setValue(4);
    m_rows->setSuffix(tr(" rows"));
    m_columns->setSuffix(tr(" columns"));
    m_grid->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_grid->setSelectionMode(QAbstractItemView::SingleSelection);
    m_grid->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_grid->verticalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_grid->setToolTip(tr("Select the site you will press next"));

    // The legend: the colour map with its ends and middle in N/m.
    m_legend = new QWidget(this);
    auto* bar = new QLabel(m_legend);
    bar->setFixedHeight(12);
    bar->setStyleSheet(stiffnessGradientStyle());
    auto* ends = new QHBoxLayout;
    const double middle = std::sqrt(StiffnessScale::kLow_n_per_m * StiffnessScale::kHigh_n_per_m);
    ends->addWidget(new QLabel(fixedText(StiffnessScale::kLow_n_per_m, 0), m_legend));
    ends->addStretch(1);
    ends->addWidget(new QLabel(fixedText(middle, 0), m_legend));
    ends->addStretch(1);
    ends->addWidget(new QLabel(tr("%1 N/m").arg(fixedText(StiffnessScale::kHigh_n_per_m, 0)), m_legend));
    auto* legendLayout = new QVBoxLayout(m_legend);
    legendLayout->setContentsMargins(0, 0, 0, 0);
    legendLayout->setSpacing(2);
    legendLayout->addWidget(bar);
    legendLayout->addLayout(ends);

    auto* header = new QHBoxLayout;
    header->addWidget(m_active);
    header->addStretch(1);
    header->addWidget(m_rows);
    header->addWidget(m_columns);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(header);
    layout->addWidget(m_grid, 1);
    layout->addWidget(m_legend);

    connect(m_active, &QCheckBox::toggled, this, &SiteGridMap::setActive);
    connect(m_grid, &QTableWidget::currentCellChanged, this, [this](int row, int column) {
        if (!m_showing && row >= 0 && column >= 0) m_chosen = core::compliance::SiteCell{row, column};
    });
    connect(m_rows, &QSpinBox::valueChanged, this, &SiteGridMap::resizeGrid);
    connect(m_columns, &QSpinBox::valueChanged, this, &SiteGridMap::resizeGrid);
    resizeGrid();
    setActive(false);
}

bool SiteGridMap::isActive() const
{
    return m_active->isChecked();
}

void SiteGridMap::setActive(bool active)
{
    m_active->setChecked(active);
    for (QWidget* w :
         {static_cast<QWidget*>(m_rows), static_cast<QWidget*>(m_columns), static_cast<QWidget*>(m_grid), m_legend})
        w->setVisible(active);
}

void SiteGridMap::resizeGrid()
{
    // Readings already placed stay where they are; cells beyond the new size go.
    m_grid->setRowCount(m_rows->value());
    m_grid->setColumnCount(m_columns->value());
    QStringList rows, columns;
    for (int r = 0; r < m_rows->value(); ++r) rows << QString(QChar(u'A' + r));
    for (int c = 0; c < m_columns->value(); ++c) columns << QString::number(c + 1);
    m_grid->setVerticalHeaderLabels(rows);
    m_grid->setHorizontalHeaderLabels(columns);
    if (!m_grid->currentIndex().isValid()) showCurrent({0, 0});
}

std::optional<core::compliance::SiteGrid> SiteGridMap::grid() const
{
    if (!isActive()) return std::nullopt;
    return core::compliance::SiteGrid(m_rows->value(), m_columns->value());
}

QString SiteGridMap::currentSite() const
{
    if (!isActive() || !m_grid->currentIndex().isValid()) return {};
    return siteName(m_grid->currentRow(), m_grid->currentColumn());
}

void SiteGridMap::selectSite(int row, int column)
{
    m_grid->setCurrentCell(row, column);
    m_chosen = core::compliance::SiteCell{row, column};
}

void SiteGridMap::showCurrent(core::compliance::SiteCell cell)
{
    if (m_grid->currentRow() == cell.row && m_grid->currentColumn() == cell.column) return;
    m_showing = true;
    m_grid->setCurrentCell(cell.row, cell.column);
    m_showing = false;
}

void SiteGridMap::clearReadings()
{
    for (int row = 0; row < m_grid->rowCount(); ++row)
        for (int column = 0; column < m_grid->columnCount(); ++column) delete m_grid->takeItem(row, column);
}

void SiteGridMap::showReading(core::compliance::SiteCell cell, double stiffness_n_per_m, double standardError_n_per_m)
{
    if (cell.row >= m_grid->rowCount() || cell.column >= m_grid->columnCount()) return;
    auto* item = new QTableWidgetItem(fixedText(stiffness_n_per_m, 0));
    item->setData(kValueRole, stiffness_n_per_m);
    item->setTextAlignment(Qt::AlignCenter);
    const QColor colour = stiffnessColour(stiffness_n_per_m);
    item->setBackground(colour);
    item->setForeground(colour.lightnessF() > 0.55F ? Qt::black : Qt::white);
    item->setToolTip(tr("%1: %2 ± %3 N/m")
                         .arg(siteName(cell.row, cell.column), fixedText(stiffness_n_per_m, 1),
                              fixedText(standardError_n_per_m, 1)));
    m_grid->setItem(cell.row, cell.column, item);
}

std::optional<double> SiteGridMap::valueAt(int row, int column) const
{
    const QTableWidgetItem* cell = m_grid->item(row, column);
    if (!cell) return std::nullopt;
    return cell->data(kValueRole).toDouble();
}

}  // namespace tactiscope::ui
