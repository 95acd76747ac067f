// ReviewActions: texts, shortcuts and tips of the review window's commands.
#include "ui/review/ReviewActions.h"

#include "ui/review/ReanalysisPanel.h"

#include <QAction>
#include <QKeySequence>

namespace tactiscope::ui {
namespace {

QAction* action(QObject* parent, const QString& text, const QString& name, const QList<QKeySequence>& keys = {},
                const QString& tip = {})
{
    auto* a = new QAction(text, parent);
    a->setObjectName(name);
    a->setShortcuts(keys);
    if (!tip.isEmpty()) a->setToolTip(tip);
    return a;
}

}  // namespace

ReviewActions::ReviewActions(QObject* parent)
    : QObject(parent),
      report(
          action(this, tr("Inspection &report (PDF)…"), QStringLiteral("reportAction"), {QKeySequence(tr("Ctrl+E"))})),
      print(action(this, tr("&Print the report…"), QStringLiteral("printAction"), {QKeySequence::Print})),
      plotImage(action(this, tr("The &plot as PNG or SVG…"), QStringLiteral("plotImageAction"))),
      csvWhole(action(this, tr("The whole session as &CSV…"), QStringLiteral("csvWholeAction"))),
      csvShown(action(this, tr("The range &shown as CSV…"), QStringLiteral("csvShownAction"))),
      close(action(this, tr("&Close"), QStringLiteral("closeAction"), {QKeySequence::Close})),
      wholeSession(action(this, tr("Whole session"), QStringLiteral("wholeSessionAction"), {QKeySequence(Qt::Key_Home)},
                          tr("Show the whole session (Home)"))),
      zoomIn(action(this, tr("Zoom in"), QStringLiteral("zoomInAction"),
                    {QKeySequence::ZoomIn, QKeySequence(Qt::Key_Plus)})),
      zoomOut(action(this, tr("Zoom out"), QStringLiteral("zoomOutAction"),
                     {QKeySequence::ZoomOut, QKeySequence(Qt::Key_Minus)})),
      play(action(this, tr("Play"), QStringLiteral("playAction"), {QKeySequence(Qt::Key_Space)},
                  tr("Replay from the left of the view (Space)"))),
      addNote(action(this, tr("Add note…"), QStringLiteral("addNoteAction"), {QKeySequence(tr("Ctrl+N"))},
                     tr("A note at the pinned cursor (click the plot to pin it), Ctrl+N"))),
      undoDelete(action(this, tr("Undo delete"), QStringLiteral("undoDeleteAction"), {QKeySequence::Undo},
                        tr("Bring back the last deleted note (Ctrl+Z)"))),
      verdict(action(this, tr("Verdict…"), QStringLiteral("verdictAction"), {},
                     tr("Keep or change the panel's verdict, with a note; the report shows who decided what"))),
      deleteNote(action(this, tr("Delete note"), QStringLiteral("deleteNoteAction"), {QKeySequence::Delete}))
{
    deleteNote->setShortcutContext(Qt::WidgetShortcut);
}

QList<QPair<QString, QAction*>> ReviewActions::withShortcuts() const
{
    const QString exportMenu = tr("Export");
    const QList<QPair<QString, QAction*>> placed{{exportMenu, report},    {exportMenu, print},
                                                 {exportMenu, plotImage}, {exportMenu, csvWhole},
                                                 {exportMenu, csvShown},  {exportMenu, close},
                                                 {{}, wholeSession},      {{}, zoomIn},
                                                 {{}, zoomOut},           {{}, play},
                                                 {{}, addNote},           {{}, undoDelete},
                                                 {{}, verdict},           {tr("List of events and notes"), deleteNote}};
    QList<QPair<QString, QAction*>> rows;
    for (const auto& [where, a] : placed) {
        if (!a || a->shortcuts().isEmpty()) continue;
        const QString text = QString(a->text()).remove(QLatin1Char('&'));
        rows.append({where.isEmpty() ? text : where + QStringLiteral(" › ") + text, a});
    }
    return rows;
}

QList<ShortcutRow> ReviewActions::helpRows()
{
    const ReviewActions actions(nullptr);
    QList<ShortcutRow> rows;
    for (const auto& [where, action] : actions.withShortcuts()) rows.append({where, keysText(action->shortcuts())});
    rows.append({tr("Re-analysis › Run"), keysText({ReanalysisPanel::runKeys()})});
    return rows;
}

}  // namespace tactiscope::ui
