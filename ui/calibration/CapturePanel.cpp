// CapturePanel: entry, light, table and plot of a calibration's points.
#include "ui/calibration/CapturePanel.h"

#include "ui/calibration/CalibrationPlot.h"
#include "ui/calibration/StabilityIndicator.h"
#include "ui/calibration/WizardText.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace tactiscope::ui {

CapturePanel::CapturePanel(const StabilityWatch* watch, const DisplayUnit& signalUnit,
                           const std::vector<std::pair<QString, int>>& loadUnits, const QStringList& columns,
                           QWidget* parent)
    : QWidget(parent),
      m_entry(new QWidget(this)),
      m_value(new QDoubleSpinBox(this)),
      m_unit(new QComboBox(this)),
      m_capture(new QPushButton(tr("&Capture"), this)),
      m_status(wrappedLabel({}, this)),
      m_table(new QTableWidget(0, static_cast<int>(columns.size()), this)),
      m_retake(new QPushButton(tr("&Retake selected"), this)),
      m_remove(new QPushButton(tr("Re&move selected"), this)),
      m_buttonRow(new QHBoxLayout),
      m_plot(new CalibrationPlot(this)),
      m_fitSummary(wrappedLabel({}, this))
{
    m_value->setObjectName(QStringLiteral("loadValue"));
    m_value->setRange(0.0, 1e6);
    m_value->setDecimals(3);
    m_unit->setObjectName(QStringLiteral("loadUnit"));
    for (const auto& [name, id] : loadUnits) m_unit->addItem(name, id);
    m_capture->setObjectName(QStringLiteral("captureButton"));
    m_status->setObjectName(QStringLiteral("captureStatus"));
    m_table->setObjectName(QStringLiteral("pointsTable"));
    m_table->setHorizontalHeaderLabels(columns);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->setVisible(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_retake->setObjectName(QStringLiteral("retakeButton"));
    m_remove->setObjectName(QStringLiteral("removeButton"));
    m_fitSummary->setObjectName(QStringLiteral("fitSummary"));
    auto* indicator = new StabilityIndicator(watch, this);
    indicator->setUnit(signalUnit);

    auto* entry = new QHBoxLayout(m_entry);
    entry->setContentsMargins(0, 0, 0, 0);
    auto* loadLabel = new QLabel(tr("&Load"), this);
    loadLabel->setBuddy(m_value);
    entry->addWidget(loadLabel);
    entry->addWidget(m_value);
    entry->addWidget(m_unit);
    entry->addWidget(m_capture);
    entry->addStretch();
    m_buttonRow->addWidget(m_retake);
    m_buttonRow->addWidget(m_remove);
    m_buttonRow->addStretch();
    auto* left = new QVBoxLayout;
    left->addWidget(m_entry);
    left->addWidget(indicator);
    left->addWidget(m_status);
    left->addWidget(m_table, 1);
    left->addLayout(m_buttonRow);
    auto* right = new QVBoxLayout;
    right->addWidget(m_plot, 1);
    right->addWidget(m_fitSummary);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(left, 1);
    layout->addLayout(right, 1);

    connect(m_capture, &QPushButton::clicked, this, &CapturePanel::captureRequested);
    connect(m_retake, &QPushButton::clicked, this, [this] {
        if (selectedRow() >= 0) emit retakeRequested(selectedRow());
    });
    connect(m_remove, &QPushButton::clicked, this, [this] {
        if (selectedRow() >= 0) emit removeRequested(selectedRow());
    });
}

void CapturePanel::setLoadsByHand(bool byHand)
{
    m_entry->setVisible(byHand);
    m_retake->setVisible(byHand);
    m_remove->setVisible(byHand);
}

double CapturePanel::loadValue() const
{
    return m_value->value();
}

int CapturePanel::loadUnit() const
{
    return m_unit->currentData().toInt();
}

void CapturePanel::setLoad(double value, int unit)
{
    m_value->setValue(value);
    m_unit->setCurrentIndex(m_unit->findData(unit));
}

void CapturePanel::setWaiting(bool waiting)
{
    m_capture->setEnabled(!waiting);
    for (QPushButton* button : m_extraButtons) button->setEnabled(!waiting);
    m_retake->setEnabled(!waiting && m_table->rowCount() > 0);
    m_remove->setEnabled(!waiting && m_table->rowCount() > 0);
}

void CapturePanel::setStatus(const QString& text)
{
    m_status->setText(text);
}

void CapturePanel::setRows(const std::vector<QStringList>& rows, int leftColumns)
{
    m_table->setRowCount(static_cast<int>(rows.size()));
    for (std::size_t r = 0; r < rows.size(); ++r) {
        for (int c = 0; c < rows[r].size(); ++c) {
            auto* item = new QTableWidgetItem(rows[r][c]);
            if (c >= leftColumns) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(static_cast<int>(r), c, item);
        }
    }
    setWaiting(!m_capture->isEnabled());
}

int CapturePanel::selectedRow() const
{
    const int row = m_table->currentRow();
    return row >= 0 && row < m_table->rowCount() ? row : -1;
}

void CapturePanel::setFitSummary(const QString& text)
{
    m_fitSummary->setText(text);
}

void CapturePanel::addButton(QPushButton* button)
{
    button->setParent(this);
    m_extraButtons << button;
    m_buttonRow->addWidget(button);
}

void CapturePanel::focusEntry()
{
    m_value->setFocus();
    m_value->selectAll();
}

}  // namespace tactiscope::ui
