// SiteGridMap: grid size, cell colours, the legend and the moving selection.
#include "ui/SiteGridMap.h"

#include "ui/NumberText.h"
#include "ui/StiffnessScale.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace tactiscope::ui {
namespace {

constexpr int kValueRole = Qt::UserRole;

}  // namespace

QString siteName(int row, int column)
{
    return QStringLiteral("%1%2").arg(QChar(u'A' + row)).arg(column + 1);
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
    m_rows->setRange(1, 26);  // rows are letters
    m_columns->setRange(1, 40);
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
    const QLocale locale;
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
    if (!m_grid->currentIndex().isValid()) selectSite(0, 0);
}

QString SiteGridMap::currentSite() const
{
    if (!isActive() || !m_grid->currentIndex().isValid()) return {};
    return siteName(m_grid->currentRow(), m_grid->currentColumn());
}

void SiteGridMap::selectSite(int row, int column)
{
    m_grid->setCurrentCell(row, column);
}

void SiteGridMap::place(double stiffness_n_per_m, double standardError_n_per_m)
{
    const int row = m_grid->currentRow(), column = m_grid->currentColumn();
    if (row < 0 || column < 0) return;
    const QLocale locale;
    auto* cell = new QTableWidgetItem(fixedText(stiffness_n_per_m, 0));
    cell->setData(kValueRole, stiffness_n_per_m);
    cell->setTextAlignment(Qt::AlignCenter);
    const QColor colour = stiffnessColour(stiffness_n_per_m);
    cell->setBackground(colour);
    cell->setForeground(colour.lightnessF() > 0.55F ? Qt::black : Qt::white);
    cell->setToolTip(
        tr("%1: %2 ± %3 N/m")
            .arg(siteName(row, column), fixedText(stiffness_n_per_m, 1), fixedText(standardError_n_per_m, 1)));
    m_grid->setItem(row, column, cell);
    // Row by row, as one works across a phantom; wraps at the end.
    const int next = (row * m_grid->columnCount() + column + 1) % (m_grid->rowCount() * m_grid->columnCount());
    selectSite(next / m_grid->columnCount(), next % m_grid->columnCount());
}

std::optional<double> SiteGridMap::valueAt(int row, int column) const
{
    const QTableWidgetItem* cell = m_grid->item(row, column);
    if (!cell) return std::nullopt;
    return cell->data(kValueRole).toDouble();
}

}  // namespace tactiscope::ui
