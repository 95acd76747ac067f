// QuantityEdit: locale-aware parsing, the open range and the red mark.
#include "ui/common/QuantityEdit.h"

#include "ui/common/NumberText.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>

#include <cmath>

namespace tactiscope::ui {

QuantityEdit::QuantityEdit(const DisplayUnit& unit, double minimum_si, double maximum_si, QWidget* parent)
    : QWidget(parent),
      m_unit(unit),
      m_minimum(minimum_si),
      m_maximum(maximum_si),
      m_edit(new QLineEdit(this)),
      m_symbol(new QLabel(unit.symbol, this))
{
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_edit, 1);
    layout->addWidget(m_symbol);
    // Units line up in a column whatever their length ("m", "GPa").
    m_symbol->setMinimumWidth(m_symbol->fontMetrics().horizontalAdvance(QStringLiteral("GPa")) + 4);
    setFocusProxy(m_edit);
    connect(m_edit, &QLineEdit::textEdited, this, [this] {
        showValidity();
        emit edited();
    });
}

void QuantityEdit::setValue(double si)
{
    m_edit->setText(typedText(si * m_unit.scale));
    showValidity();
}

void QuantityEdit::clear()
{
    m_edit->clear();
    showValidity();
}

std::optional<double> QuantityEdit::value() const
{
    bool ok = false;
    const double shown = QLocale().toDouble(m_edit->text().trimmed(), &ok);
    if (!ok) return std::nullopt;
    const double si = shown / m_unit.scale;
    if (!std::isfinite(si) || !(si > m_minimum) || !(si < m_maximum)) return std::nullopt;
    return si;
}

QString QuantityEdit::problem() const
{
    if (value()) return {};
    return tr("must be a number above %1 and below %2 %3")
        .arg(typedText(m_minimum * m_unit.scale), typedText(m_maximum * m_unit.scale), m_unit.symbol)
        .trimmed();
}

void QuantityEdit::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::EnabledChange) showValidity();
}

// A disabled field is not in use, so it is never marked.
void QuantityEdit::showValidity()
{
    const bool valid = value().has_value() || !isEnabled();
    m_edit->setStyleSheet(valid ? QString() : QStringLiteral("QLineEdit { background: #fde0dc; }"));
    m_edit->setToolTip(valid ? QString() : problem());
}

}  // namespace tactiscope::ui
