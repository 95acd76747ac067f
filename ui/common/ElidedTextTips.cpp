// ElidedTextTips: tooltips with the whole text of cut cells and combo boxes.
#include "ui/common/ElidedTextTips.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QComboBox>
#include <QHelpEvent>
#include <QStyle>
#include <QStyleOptionComboBox>
#include <QToolTip>

namespace tactiscope::ui {
namespace {

// The margin Qt's item delegates and combo boxes draw text within.
int textMargin(const QWidget& widget)
{
    return 2 * (widget.style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, &widget) + 1);
}

// A view's cell under the pointer whose text is wider than the cell.
bool showCellText(QAbstractItemView& view, const QHelpEvent& help)
{
    const QModelIndex index = view.indexAt(help.pos());
    if (!index.isValid() || index.data(Qt::ToolTipRole).isValid()) return false;
    const QString text = index.data(Qt::DisplayRole).toString();
    if (text.isEmpty()) return false;
    QFont font = view.font();
    if (const QVariant f = index.data(Qt::FontRole); f.canConvert<QFont>()) font = f.value<QFont>();
    const QRect cell = view.visualRect(index);
    // The decoration (an icon) and the tree's indentation take room before the text.
    const int decoration = index.data(Qt::DecorationRole).isValid() ? view.iconSize().width() + 4 : 0;
    if (QFontMetrics(font).horizontalAdvance(text) + decoration + textMargin(view) <= cell.width()) return false;
    QToolTip::showText(help.globalPos(), text, view.viewport(), cell);
    return true;
}

bool showComboText(QComboBox& combo, const QHelpEvent& help)
{
    if (!combo.toolTip().isEmpty() || combo.currentText().isEmpty()) return false;
    QStyleOptionComboBox option;
    option.initFrom(&combo);
    option.editable = combo.isEditable();
    const QRect field =
        combo.style()->subControlRect(QStyle::CC_ComboBox, &option, QStyle::SC_ComboBoxEditField, &combo);
    if (combo.fontMetrics().horizontalAdvance(combo.currentText()) + textMargin(combo) <= field.width()) return false;
    QToolTip::showText(help.globalPos(), combo.currentText(), &combo);
    return true;
}

}  // namespace

void ElidedTextTips::install()
{
    auto* app = QCoreApplication::instance();
    if (!app || app->findChild<ElidedTextTips*>(QString(), Qt::FindDirectChildrenOnly)) return;
    app->installEventFilter(new ElidedTextTips(app));
}

bool ElidedTextTips::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() != QEvent::ToolTip || !watched->isWidgetType()) return false;
    const auto& help = static_cast<const QHelpEvent&>(*event);
    auto* widget = static_cast<QWidget*>(watched);
    if (auto* view = qobject_cast<QAbstractItemView*>(widget->parentWidget()); view && view->viewport() == widget)
        return showCellText(*view, help);
    if (auto* combo = qobject_cast<QComboBox*>(widget)) return showComboText(*combo, help);
    return false;
}

}  // namespace tactiscope::ui
