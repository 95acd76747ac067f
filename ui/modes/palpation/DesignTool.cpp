// DesignTool: the inputs, four panels and one curve per length in each.
#include "ui/modes/palpation/DesignTool.h"

#include "core/sensors/CompliancePair.h"
#include "ui/common/NumberText.h"
#include "ui/common/QuantityEdit.h"
#include "ui/profiles/ActiveProfiles.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <array>

namespace tactiscope::ui {
namespace {

constexpr std::size_t kPoints = 200;
constexpr double kMaxStiffness_n_per_m = 1e6;
const std::array<QColor, 6> kLengthColours{QColor(31, 119, 180), QColor(255, 127, 14),  QColor(44, 160, 44),
                                           QColor(214, 39, 40),  QColor(148, 103, 189), QColor(140, 86, 75)};

struct Panel {
    DesignTool::Curve curve;
    const char* title;
    double (*value)(const core::sensors::DesignPoint&);
};

const std::array<Panel, 4> kPanels{{
    {DesignTool::Curve::ForceRatio, "Q = F stiff / F soft", [](const core::sensors::DesignPoint& p) { return p.q; }},
    {DesignTool::Curve::Sensitivity, "dQ/dkₒ (mm/N)",
     [](const core::sensors::DesignPoint& p) { return p.dqDk_m_per_n * 1e3; }},
    {DesignTool::Curve::StrainRatio, "Strain ratio ε soft / ε stiff",
     [](const core::sensors::DesignPoint& p) { return p.strainRatio; }},
    {DesignTool::Curve::DeflectionRatio, "Deflection ratio Δ soft / Δ stiff",
     [](const core::sensors::DesignPoint& p) { return p.deflectionRatio; }},
}};

}  // namespace

DesignTool::DesignTool(const QString& libraryDirectory, QWidget* parent)
    : QDialog(parent),
      m_probeBox(new QComboBox(this)),
      m_lengths(new QLineEdit(QStringLiteral("40, 50, 60"), this)),
      m_from(new QuantityEdit({1.0, QStringLiteral("N/m"), {}}, -1e-12, kMaxStiffness_n_per_m, this)),
      m_to(new QuantityEdit({1.0, QStringLiteral("N/m"), {}}, 0.0, kMaxStiffness_n_per_m, this)),
      m_problem(new QLabel(this)),
      m_plot(new QCustomPlot(this))
{
    setWindowTitle(tr("Compliance probe design (seed 001, Figs 5–7)"));
    setObjectName(QStringLiteral("designTool"));
    m_probeBox->setObjectName(QStringLiteral("probeBox"));
    m_lengths->setObjectName(QStringLiteral("lengthsEdit"));
    m_from->setObjectName(QStringLiteral("fromEdit"));
    m_to->setObjectName(QStringLiteral("toEdit"));
    m_problem->setObjectName(QStringLiteral("problemLabel"));
    m_problem->setStyleSheet(QStringLiteral("color: #c62828;"));
    m_lengths->setToolTip(tr("Both beams at each length, in mm, separated by commas"));

    const ProfileLibrary library(libraryDirectory);
    for (ProfileEntry& entry :
         library.entries(QStringLiteral("palpation"), activeProfile(QStringLiteral("palpation")).path)) {
        if (!entry.profile) continue;
        m_probeBox->addItem(entry.name);
        m_probes.push_back(std::move(entry));
    }
    m_from->setValue(0.0);
    m_to->setValue(1000.0);  // the paper's working range of soft tissue

    auto* inputs = new QFormLayout;
    inputs->addRow(tr("Probe:"), m_probeBox);
    auto* lengths = new QHBoxLayout;
    lengths->addWidget(m_lengths, 1);
    lengths->addWidget(new QLabel(tr("mm"), this));
    inputs->addRow(tr("Beam lengths:"), lengths);
    auto* range = new QHBoxLayout;
    range->addWidget(m_from);
    range->addWidget(new QLabel(tr("to"), this));
    range->addWidget(m_to);
    inputs->addRow(tr("Object stiffness kₒ:"), range);
    auto* note = new QLabel(tr("Each length is applied to both beams; widths, thicknesses and moduli are the "
                               "probe's. Higher Q and dQ/dkₒ read kₒ more finely; ratios near 1 keep the two "
                               "beams' signals and deflections alike (less crosstalk through the tissue)."),
                            this);
    note->setWordWrap(true);
    note->setEnabled(false);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(inputs);
    layout->addWidget(note);
    layout->addWidget(m_problem);
    layout->addWidget(m_plot, 1);
    resize(980, 720);

    m_plot->plotLayout()->clear();
    for (std::size_t i = 0; i < kPanels.size(); ++i) {
        auto* rect = new QCPAxisRect(m_plot);
        m_plot->plotLayout()->addElement(static_cast<int>(i / 2), static_cast<int>(i % 2), rect);
        rect->axis(QCPAxis::atBottom)->setLabel(tr("kₒ (N/m)"));
        rect->axis(QCPAxis::atLeft)->setLabel(tr(kPanels[i].title));
    }
    // The default legend went with the default axis rect: one of our own,
    // in the first panel, since the lengths are the same in all four.
    m_plot->setAutoAddPlottableToLegend(false);
    m_legend = new QCPLegend;
    m_plot->axisRect(0)->insetLayout()->addElement(m_legend, Qt::AlignBottom | Qt::AlignRight);
    m_legend->setLayer(QStringLiteral("legend"));
    connect(m_probeBox, &QComboBox::currentIndexChanged, this, &DesignTool::redraw);
    connect(m_lengths, &QLineEdit::textEdited, this, &DesignTool::redraw);
    connect(m_from, &QuantityEdit::edited, this, &DesignTool::redraw);
    connect(m_to, &QuantityEdit::edited, this, &DesignTool::redraw);
    redraw();
}

bool DesignTool::setLengths(const QString& lengths_mm)
{
    m_lengths->setText(lengths_mm);
    redraw();
    return m_problem->text().isEmpty();
}

std::vector<QPointF> DesignTool::curvePoints(Curve curve, std::size_t length) const
{
    std::vector<QPointF> points;
    const auto panel = static_cast<std::size_t>(curve);
    const int lengths = m_plot->graphCount() / static_cast<int>(kPanels.size());
    if (static_cast<int>(length) >= lengths) return points;
    const QCPGraph* graph = m_plot->graph(static_cast<int>(panel) * lengths + static_cast<int>(length));
    for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it)
        points.emplace_back(it->key, it->value);
    return points;
}

void DesignTool::redraw()
{
    m_plot->clearGraphs();
    m_problem->clear();
    const auto fail = [this](const QString& problem) {
        m_problem->setText(problem);
        m_plot->replot();
    };
    const int index = m_probeBox->currentIndex();
    if (index < 0) return fail(tr("No palpation profile to start from."));
    std::vector<double> lengths_m;
    for (const QString& part : m_lengths->text().split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        bool ok = false;
        const double mm = QLocale().toDouble(part.trimmed(), &ok);
        if (!ok || !(mm > 0.0) || mm > 10000.0)
            return fail(tr("Beam lengths: \"%1\" is not a length in mm").arg(part.trimmed()));
        lengths_m.push_back(mm * 1e-3);
    }
    if (lengths_m.empty()) return fail(tr("Beam lengths: give at least one, e.g. 40, 50, 60"));
    if (lengths_m.size() > kLengthColours.size())
        return fail(tr("Beam lengths: at most %1 at a time").arg(kLengthColours.size()));
    const auto from = m_from->value(), to = m_to->value();
    if (!from || !to || *from < 0.0 || !(*from < *to))
        return fail(tr("Object stiffness: give a range from 0 up, lowest first"));

    const auto& probe =
        std::get<core::sensors::CompliancePairProfile>(*m_probes[static_cast<std::size_t>(index)].profile);
    const core::sensors::CompliancePair pair{core::sensors::CantileverBeam(probe.high),
                                             core::sensors::CantileverBeam(probe.low)};
    for (std::size_t p = 0; p < kPanels.size(); ++p) {
        QCPAxisRect* rect = m_plot->axisRect(static_cast<int>(p));
        for (std::size_t l = 0; l < lengths_m.size(); ++l) {
            const auto curve = pair.withLength(lengths_m[l]).designCurve(*from, *to, kPoints);
            QCPGraph* graph = m_plot->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
            graph->setName(tr("L = %1 mm").arg(typedText(lengths_m[l] * 1e3)));
            graph->setPen(QPen(kLengthColours[l], 1.6));
            for (const auto& point : curve) graph->addData(point.objectStiffness_n_per_m, kPanels[p].value(point));
        }
        rect->axis(QCPAxis::atBottom)->setRange(*from, *to);
        rect->axis(QCPAxis::atLeft)->rescale();
        const QCPRange values = rect->axis(QCPAxis::atLeft)->range();
        rect->axis(QCPAxis::atLeft)->setRange(values.lower - 0.05 * values.size(), values.upper + 0.05 * values.size());
    }
    m_legend->clearItems();
    for (int g = 0; g < static_cast<int>(lengths_m.size()); ++g) m_plot->graph(g)->addToLegend(m_legend);
    m_plot->replot();
}

}  // namespace tactiscope::ui
