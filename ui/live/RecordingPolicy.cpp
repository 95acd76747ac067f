// RecordingPolicy: the site's file first, then the user's setting.
#include "ui/live/RecordingPolicy.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QLabel>
#include <QSettings>
#include <QVBoxLayout>

namespace tactiscope::ui {
namespace {

const QString kRequireKey = QStringLiteral("recording/requireSubjectAndOperator");

}  // namespace

RecordingPolicy recordingPolicy()
{
    const QSettings site(QSettings::SystemScope, QCoreApplication::organizationName(),
                         QCoreApplication::applicationName());
    if (site.value(kRequireKey, false).toBool()) return {true, true};
    return {QSettings().value(kRequireKey, false).toBool(), false};
}

void setRequireSubjectAndOperator(bool required)
{
    QSettings().setValue(kRequireKey, required);
}

QString recordingRefusal(const RecordingPolicy& policy, const QString& subject, const QString& operatorName)
{
    if (!policy.requireSubjectAndOperator) return {};
    QStringList missing;
    if (subject.trimmed().isEmpty()) missing << QObject::tr("the subject (panel or phantom id)");
    if (operatorName.trimmed().isEmpty()) missing << QObject::tr("the operator's name");
    if (missing.isEmpty()) return {};
    return QObject::tr("This station records only with a subject and an operator: type %1 in the session bar.")
        .arg(missing.join(QObject::tr(" and ")));
}

void showSettingsDialog(QWidget* parent)
{
    auto* dialog = new QDialog(parent);
    dialog->setObjectName(QStringLiteral("settingsDialog"));
    dialog->setWindowTitle(QObject::tr("Settings"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    auto* layout = new QVBoxLayout(dialog);
    const RecordingPolicy policy = recordingPolicy();
    auto* require = new QCheckBox(QObject::tr("Require a subject and an operator before recording"), dialog);
    require->setObjectName(QStringLiteral("requireSubjectAndOperator"));
    require->setChecked(policy.requireSubjectAndOperator);
    require->setEnabled(!policy.setBySite);
    layout->addWidget(require);
    if (policy.setBySite) {
        auto* site =
            new QLabel(QObject::tr("Required by this site's settings; only its administrator can change it."), dialog);
        site->setWordWrap(true);
        layout->addWidget(site);
    }
    QObject::connect(require, &QCheckBox::toggled, dialog, [](bool on) { setRequireSubjectAndOperator(on); });
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
    layout->addWidget(buttons);
    dialog->show();
}

}  // namespace tactiscope::ui
