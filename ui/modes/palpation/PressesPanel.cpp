// PressesPanel: two lists, the grid map's table and the scale.
#include "ui/modes/palpation/PressesPanel.h"

#include "core/report/PressTable.h"
#include "ui/modes/palpation/PalpationFigures.h"
#include "ui/modes/palpation/PalpationReanalysisBox.h"
#include "ui/modes/palpation/StiffnessScale.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QTabWidget>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace tactiscope::ui {
namespace {

enum Role { StartRole = Qt::UserRole, EndRole };

QTreeWidget* list(const QStringList& headers, const QString& name, QWidget* parent)
{
    auto* tree = new QTreeWidget(parent);
    tree->setObjectName(name);
    tree->setHeaderLabels(headers);
    tree->setRootIsDecorated(false);
    tree->setAlternatingRowColors(true);
    tree->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    return tree;
}

}  // namespace

PressesPanel::PressesPanel(const ReviewAccountContext& context, QWidget* parent)
    : ReviewAccount(tr("Presses"), parent),
      m_presses(list({tr("Time (s)"), tr("Source"), tr("Site"), tr("kₒ ± u (N/m)"), tr("Depth (mm)")},
                     QStringLiteral("pressList"), this)),
      m_reanalysis(new PalpationReanalysisBox(context.store, context.session, this)),
      m_sites(list({tr("Site"), tr("n"), tr("Mean (N/m)"), tr("SD (N/m)"), tr("Range (N/m)")},
                   QStringLiteral("siteList"), this)),
      m_grid(new QLabel(this)),
      m_scale(new StiffnessScale(this))
{
    setObjectName(QStringLiteral("pressesPanel"));
    m_grid->setObjectName(QStringLiteral("siteGrid"));
    m_grid->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_scale->setTissues(builtInTissues());
    m_scale->setObjectName(QStringLiteral("tissueScale"));

    auto* sites = new QWidget(this);
    auto* sitesLayout = new QVBoxLayout(sites);
    sitesLayout->setContentsMargins(0, 0, 0, 0);
    sitesLayout->addWidget(m_sites, 1);
    sitesLayout->addWidget(m_grid);
    auto* tabs = new QTabWidget(this);
    tabs->addTab(m_presses, tr("Each press"));
    tabs->addTab(sites, tr("By site"));
    tabs->addTab(m_reanalysis, tr("Read again"));
    // What was read again shows beside the recorded presses.
    connect(m_reanalysis, &PalpationReanalysisBox::analysed, tabs, [tabs, this] { tabs->setCurrentWidget(m_presses); });
    connect(m_reanalysis, &PalpationReanalysisBox::analysed, this, &ReviewAccount::recordsChanged);
    connect(m_reanalysis, &PalpationReanalysisBox::saved, this, &ReviewAccount::recordsChanged);
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(tabs, 3);
    layout->addWidget(m_scale, 2);

    connect(m_presses, &QTreeWidget::itemClicked, this, [this](QTreeWidgetItem* item) {
        emit spanChosen(item->data(0, StartRole).toDouble(), item->data(0, EndRole).toDouble());
    });
}

std::optional<ReviewAccount::Unsaved> PressesPanel::unsaved() const
{
    const auto* result = m_reanalysis->unsaved();
    if (!result) return std::nullopt;
    return Unsaved{{}, result->readings};
}

void PressesPanel::showReadings(const std::vector<core::storage::SessionReading>& recordedReadings,
                                const std::vector<Readings>& others)
{
    const auto recorded = core::report::pressRows(recordedReadings);
    std::vector<std::pair<QString, std::vector<core::report::PressRow>>> read;
    for (const auto& source : others) read.emplace_back(source.source, core::report::pressRows(source.readings));
    m_presses->clear();
    m_sites->clear();
    // Every source's presses in time order, so a re-read press sits by its recorded one.
    std::vector<std::pair<const core::report::PressRow*, QString>> rows;
    for (const auto& p : recorded) rows.emplace_back(&p, tr("recorded"));
    for (const auto& [source, presses] : read)
        for (const auto& p : presses) rows.emplace_back(&p, source);
    std::ranges::stable_sort(rows, {}, [](const auto& row) { return row.first->start_s; });
    for (const auto& [press, source] : rows) {
        QStringList cells = pressCells(*press);
        cells.insert(1, source);
        auto* item = new QTreeWidgetItem(m_presses, cells);
        item->setData(0, StartRole, press->start_s);
        item->setData(0, EndRole, press->end_s);
        for (const int column : {0, 3, 4}) item->setTextAlignment(column, Qt::AlignRight | Qt::AlignVCenter);
    }
    const auto sites = core::report::siteSummaries(recorded);
    for (const auto& cells : siteRows(sites)) {
        auto* item = new QTreeWidgetItem(m_sites, cells);
        for (const int column : {1, 2, 3, 4}) item->setTextAlignment(column, Qt::AlignRight | Qt::AlignVCenter);
    }
    const QString grid = siteGridHtml(sites);
    m_grid->setText(grid);
    m_grid->setVisible(!grid.isEmpty());
    markSites(*m_scale, core::report::scaleMarks(recorded, tr("all").toStdString()));
    setTitle(tr("Presses (%1 recorded)").arg(recorded.size()));
}

}  // namespace tactiscope::ui
