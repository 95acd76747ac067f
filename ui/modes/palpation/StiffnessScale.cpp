// StiffnessScale: log axis, tissue marks with spread labels, reading arrow.
#include "ui/modes/palpation/StiffnessScale.h"

#include "ui/common/NumberText.h"

#include <QFile>
#include <QHelpEvent>
#include <QLocale>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>

#include <algorithm>
#include <array>
#include <cmath>

namespace tactiscope::ui {
namespace {

constexpr int kMargin = 12;
// Left to right: tick labels, the colour bar, the reading's arrow, the
// tissues' marks, their names.
constexpr int kAxisX = 70;
constexpr int kMarkX = kAxisX + 26;
constexpr int kLabelX = kMarkX + 22;
constexpr int kMarkLabelWidth = 60;  // a site's name, at the right edge

// Viridis at five stops: even in lightness, readable by the colour-blind.
constexpr std::array<QRgb, 5> kStops{0x440154, 0x3b528b, 0x21918c, 0x5ec962, 0xfde725};

double logPosition(double stiffness_n_per_m)
{
    const double clamped = std::clamp(stiffness_n_per_m, StiffnessScale::kLow_n_per_m, StiffnessScale::kHigh_n_per_m);
    return std::log(clamped / StiffnessScale::kLow_n_per_m) /
           std::log(StiffnessScale::kHigh_n_per_m / StiffnessScale::kLow_n_per_m);
}

}  // namespace

std::vector<core::compliance::ReferenceTissue> builtInTissues()
{
    QFile file(QStringLiteral(":/tactiscope/reference-tissues.json"));
    if (!file.open(QIODevice::ReadOnly)) return {};
    return core::compliance::parseReferenceTissues(file.readAll().toStdString(), "reference-tissues.json");
}

QColor stiffnessColour(double stiffness_n_per_m)
{
    const double x = logPosition(stiffness_n_per_m) * static_cast<double>(kStops.size() - 1);
    const auto i = std::min<std::size_t>(static_cast<std::size_t>(x), kStops.size() - 2);
    const double f = x - static_cast<double>(i);
    const QColor a(kStops[i]), b(kStops[i + 1]);
    const auto mix = [f](float from, float to) {
        return static_cast<float>(static_cast<double>(from) + f * static_cast<double>(to - from));
    };
    return QColor::fromRgbF(mix(a.redF(), b.redF()), mix(a.greenF(), b.greenF()), mix(a.blueF(), b.blueF()));
}

QString stiffnessGradientStyle()
{
    QString stops;
    for (std::size_t i = 0; i < kStops.size(); ++i)
        stops += QStringLiteral(", stop:%1 %2")
                     .arg(static_cast<double>(i) / static_cast<double>(kStops.size() - 1))
                     .arg(QColor(kStops[i]).name());
    return QStringLiteral("background: qlineargradient(x1:0, y1:0, x2:1, y2:0%1);").arg(stops);
}

StiffnessScale::StiffnessScale(QWidget* parent)
    : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void StiffnessScale::setTissues(std::vector<core::compliance::ReferenceTissue> tissues)
{
    m_tissues = std::move(tissues);
    update();
}

void StiffnessScale::setReading(std::optional<double> stiffness_n_per_m)
{
    m_reading = stiffness_n_per_m;
    update();
}

void StiffnessScale::setMarks(std::vector<Mark> marks)
{
    m_marks = std::move(marks);
    update();
}

QSize StiffnessScale::minimumSizeHint() const
{
    // Every tissue's name on a line of its own, with the margins: shorter,
    // and the stack of names ran off the top ("Muscle" cut).
    const int lines = std::max<int>(8, static_cast<int>(m_tissues.size()) + 1);
    return {260, lines * fontMetrics().height() + 2 * kMargin};
}

bool StiffnessScale::event(QEvent* event)
{
    if (event->type() == QEvent::ToolTip) {
        const auto* help = static_cast<QHelpEvent*>(event);
        const auto tip = std::ranges::find_if(m_tips, [&](const Tip& t) { return t.area.contains(help->pos()); });
        if (tip != m_tips.end())
            QToolTip::showText(help->globalPos(), tip->text, this, tip->area.toAlignedRect());
        else
            QToolTip::hideText();
        return true;
    }
    return QWidget::event(event);
}

double StiffnessScale::yOf(double stiffness_n_per_m) const
{
    // Stiff at the top, soft at the bottom.
    return height() - kMargin - logPosition(stiffness_n_per_m) * (height() - 2 * kMargin);
}

void StiffnessScale::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QFontMetrics metrics = fontMetrics();
    const QColor text = palette().color(QPalette::WindowText);
    const QColor mid = palette().color(QPalette::Mid);

    // The axis as a colour bar, so the grid map's colours read off it.
    const QRectF bar(kAxisX - 4, yOf(kHigh_n_per_m), 8, yOf(kLow_n_per_m) - yOf(kHigh_n_per_m));
    QLinearGradient gradient(bar.bottomLeft(), bar.topLeft());
    for (int i = 0; i <= 10; ++i) {
        const double k = kLow_n_per_m * std::pow(kHigh_n_per_m / kLow_n_per_m, i / 10.0);
        gradient.setColorAt(i / 10.0, stiffnessColour(k));
    }
    p.fillRect(bar, gradient);
    p.setPen(text);
    const QLocale locale;
    for (const double tick : {20.0, 50.0, 100.0, 200.0, 500.0, 1000.0}) {
        const double y = yOf(tick);
        p.drawLine(QPointF(kAxisX - 8, y), QPointF(kAxisX - 4, y));
        const QString label = fixedText(tick, 0);
        p.drawText(QPointF(kAxisX - 12 - metrics.horizontalAdvance(label), y + metrics.ascent() / 2.0), label);
    }
    p.save();
    p.translate(metrics.height() / 2.0 + 2, height() / 2.0);
    p.rotate(-90);
    const QString title = tr("N/m");
    p.drawText(QPointF(-metrics.horizontalAdvance(title) / 2.0, metrics.ascent() / 2.0), title);
    p.restore();

    // Tissue names right of the axis, spread so none overlaps the next.
    std::vector<const core::compliance::ReferenceTissue*> tissues;
    for (const auto& t : m_tissues) tissues.push_back(&t);
    std::ranges::sort(tissues, [](const auto* a, const auto* b) { return a->min_n_per_m > b->min_n_per_m; });
    const double line = metrics.height();
    std::vector<double> labelY;
    for (const auto* t : tissues) {
        const double y = yOf(std::sqrt(t->min_n_per_m * t->max_n_per_m));
        labelY.push_back(labelY.empty() ? std::max(y, line / 2) : std::max(y, labelY.back() + line));
    }
    // Pushed off the bottom: shift the stack back up.
    const double overflow = labelY.empty() ? 0.0 : labelY.back() - (height() - line / 2);
    for (std::size_t i = labelY.size(); overflow > 0 && i-- > 0;)
        labelY[i] = std::min(labelY[i], height() - line / 2 - static_cast<double>(labelY.size() - 1 - i) * line);
    const int labelX = kLabelX;
    m_tips.clear();
    for (std::size_t i = 0; i < tissues.size(); ++i) {
        const auto* t = tissues[i];
        const double top = yOf(t->max_n_per_m), bottom = yOf(t->min_n_per_m);
        p.setPen(QPen(text, 2));
        p.drawLine(QPointF(kMarkX, top), QPointF(kMarkX, bottom));  // a range, or a dot's worth
        p.drawLine(QPointF(kMarkX - 3, (top + bottom) / 2), QPointF(kMarkX + 3, (top + bottom) / 2));
        p.setPen(QPen(mid, 1));
        p.drawLine(QPointF(kMarkX + 3, (top + bottom) / 2), QPointF(labelX - 3, labelY[i]));
        p.setPen(text);
        const int room = width() - labelX - 4 - (m_marks.empty() ? 0 : kMarkLabelWidth + 4);
        // Short of room, the source in brackets goes first ("Muscle", not
        // "Muscle (needle-insertion simul…"), then the end of the name.
        QString name = QString::fromStdString(t->name);
        if (metrics.horizontalAdvance(name) > room && name.contains(QStringLiteral(" (")))
            name = name.left(name.indexOf(QStringLiteral(" (")));
        name = metrics.elidedText(name, Qt::ElideRight, room);
        p.drawText(QPointF(labelX, labelY[i] + metrics.ascent() / 2.0 - 1), name);
        // The whole name, its range and its source where the pointer rests on it.
        const QString range = t->min_n_per_m == t->max_n_per_m
                                  ? fixedText(t->min_n_per_m, 0)
                                  : fixedText(t->min_n_per_m, 0) + QStringLiteral("–") + fixedText(t->max_n_per_m, 0);
        m_tips.push_back(
            {QRectF(labelX, labelY[i] - line / 2, room, line),
             tr("%1: %2 N/m").arg(QString::fromStdString(t->name), range) +
                 (t->source.empty() ? QString() : QStringLiteral("\n") + QString::fromStdString(t->source))});
    }

    // The reading: a red arrow at the bar, its line reaching the tissues' marks.
    const auto drawArrow = [&](double stiffness_n_per_m) {
        const double y = yOf(stiffness_n_per_m);
        QPainterPath arrow;
        arrow.moveTo(kAxisX + 5, y);
        arrow.lineTo(kAxisX + 19, y - 7);
        arrow.lineTo(kAxisX + 19, y + 7);
        arrow.closeSubpath();
        p.fillPath(arrow, QColor(0xc62828));
        p.setPen(QPen(QColor(0xc62828), 2));
        p.drawLine(QPointF(kAxisX - 4, y), QPointF(kMarkX + 6, y));
        return y;
    };
    if (m_reading) drawArrow(*m_reading);
    // Sites' means: each arrow with its site's name in red at the far right,
    // clear of the tissues' names.
    double lastLabelY = -line;
    std::vector<const Mark*> marks;
    for (const auto& mark : m_marks) marks.push_back(&mark);
    std::ranges::sort(marks, [](const Mark* a, const Mark* b) { return a->stiffness_n_per_m > b->stiffness_n_per_m; });
    for (const Mark* mark : marks) {
        const double y = drawArrow(mark->stiffness_n_per_m);
        const double markY = std::max(y, lastLabelY + line);
        lastLabelY = markY;
        const QString label = metrics.elidedText(mark->label, Qt::ElideRight, kMarkLabelWidth);
        p.drawText(QPointF(width() - 4 - metrics.horizontalAdvance(label), markY + metrics.ascent() / 2.0 - 1), label);
    }
}

}  // namespace tactiscope::ui
