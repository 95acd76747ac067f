// HelpWindows: a text browser on the guide, a table of the shortcuts.
#include "ui/common/HelpWindows.h"

#include <QAction>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileInfo>
#include <QFont>
#include <QHeaderView>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QTableWidget>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

namespace tactiscope::ui {
namespace {

QDialog* helpDialog(QWidget* parent, const QString& name, const QString& title)
{
    auto* dialog = new QDialog(parent);
    dialog->setObjectName(name);
    dialog->setWindowTitle(title);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    auto* layout = new QVBoxLayout(dialog);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
    layout->addWidget(buttons);
    return dialog;
}

// The menu's entries with shortcuts, "Session › Start / stop recording".
void collect(const QMenu& menu, const QString& path, QList<ShortcutRow>& rows)
{
    for (const QAction* action : menu.actions()) {
        const QString text = QString(action->text()).remove(QLatin1Char('&'));
        if (action->menu()) {
            collect(*action->menu(), path + QStringLiteral(" › ") + text, rows);
            continue;
        }
        if (!action->shortcuts().isEmpty())
            rows.append({path + QStringLiteral(" › ") + text, keysText(action->shortcuts())});
    }
}

}  // namespace

QString userGuidePath(const QString& executableDirectory)
{
    for (const QString& candidate :
         {QStringLiteral("../share/doc/tactiscope/user-guide.md"), QStringLiteral("doc/user-guide.md")}) {
        const QFileInfo file(QDir(executableDirectory).filePath(candidate));
        if (file.isReadable()) return file.canonicalFilePath();
    }
    return {};
}

void showUserGuide(QWidget* parent, const QString& executableDirectory)
{
    const QString path = userGuidePath(executableDirectory);
    if (path.isEmpty()) {
        auto* box = new QMessageBox(QMessageBox::Information, QObject::tr("User guide"),
                                    QObject::tr("The user guide is not installed beside this program. It is "
                                                "docs/user-guide.md in the source, and share/doc/tactiscope/ in a "
                                                "package."),
                                    QMessageBox::Close, parent);
        box->setObjectName(QStringLiteral("userGuideMissing"));
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
        return;
    }
    QDialog* dialog = helpDialog(parent, QStringLiteral("userGuide"), QObject::tr("Tactiscope user guide"));
    auto* browser = new QTextBrowser(dialog);
    browser->setObjectName(QStringLiteral("userGuideText"));
    browser->setOpenExternalLinks(true);
    browser->setSearchPaths({QFileInfo(path).absolutePath()});  // its screenshots/
    browser->setSource(QUrl::fromLocalFile(path), QTextDocument::MarkdownResource);
    qobject_cast<QVBoxLayout*>(dialog->layout())->insertWidget(0, browser, 1);
    dialog->resize(900, 700);
    dialog->show();
}

QString keysText(const QList<QKeySequence>& keys)
{
    QStringList texts;
    for (const QKeySequence& key : keys) texts << key.toString(QKeySequence::NativeText);
    return texts.join(QObject::tr(" or "));
}

QList<ShortcutRow> menuShortcuts(const QMenuBar& menus)
{
    QList<ShortcutRow> rows;
    for (const QAction* action : menus.actions())
        if (action->menu()) collect(*action->menu(), QString(action->text()).remove(QLatin1Char('&')), rows);
    return rows;
}

void showKeyboardShortcuts(const QList<ShortcutGroup>& groups, QWidget* parent)
{
    QDialog* dialog = helpDialog(parent, QStringLiteral("keyboardShortcuts"), QObject::tr("Keyboard shortcuts"));
    auto* table = new QTableWidget(0, 2, dialog);
    table->setObjectName(QStringLiteral("shortcutTable"));
    table->setHorizontalHeaderLabels({QObject::tr("Command"), QObject::tr("Keys")});
    table->verticalHeader()->hide();
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setWordWrap(false);
    for (const ShortcutGroup& group : groups) {
        // A heading row per window, across both columns.
        const int heading = table->rowCount();
        table->insertRow(heading);
        auto* title = new QTableWidgetItem(group.window);
        QFont bold = title->font();
        bold.setBold(true);
        title->setFont(bold);
        title->setData(Qt::UserRole, QStringLiteral("window"));
        table->setItem(heading, 0, title);
        table->setSpan(heading, 0, 1, 2);
        for (const ShortcutRow& row : group.rows) {
            const int r = table->rowCount();
            table->insertRow(r);
            table->setItem(r, 0, new QTableWidgetItem(QStringLiteral("    ") + row.command));
            table->setItem(r, 1, new QTableWidgetItem(row.keys));
        }
    }
    table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    table->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    qobject_cast<QVBoxLayout*>(dialog->layout())->insertWidget(0, table, 1);
    dialog->resize(600, 640);
    dialog->show();
}

}  // namespace tactiscope::ui
