// SensorProfileDialog: the list, the form, and which actions each state allows.
#include "ui/profiles/SensorProfileDialog.h"

#include "ui/profiles/ActiveProfiles.h"
#include "ui/profiles/ProfileForms.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QStackedWidget>
#include <QStyle>
#include <QVBoxLayout>

#include <algorithm>

namespace tactiscope::ui {
namespace {

QString modeTitle(const QString& mode)
{
    return mode == QLatin1String("capacitive") ? SensorProfileDialog::tr("capacitive")
                                               : SensorProfileDialog::tr("palpation");
}

QString jsonFilter()
{
    return SensorProfileDialog::tr("Sensor profiles (*.json);;All files (*)");
}

bool samePath(const QString& a, const QString& b)
{
    return !a.isEmpty() && !b.isEmpty() && QFileInfo(a) == QFileInfo(b);
}

}  // namespace

SensorProfileDialog::SensorProfileDialog(const QString& libraryDirectory, QWidget* parent)
    : QDialog(parent),
      m_library(libraryDirectory),
      m_modeBox(new QComboBox(this)),
      m_activeLabel(new QLabel(this)),
      m_list(new QListWidget(this)),
      m_new(new QPushButton(tr("New"), this)),
      m_import(new QPushButton(tr("Import…"), this)),
      m_export(new QPushButton(tr("Export…"), this)),
      m_delete(new QPushButton(tr("Delete…"), this)),
      m_editorTitle(new QLabel(this)),
      m_forms(new QStackedWidget(this)),
      m_summary(new QLabel(this)),
      m_problem(new QLabel(this)),
      m_save(new QPushButton(tr("Save"), this)),
      m_revert(new QPushButton(tr("Revert"), this)),
      m_use(new QPushButton(this)),
      m_message(new QLabel(this))
{
    setWindowTitle(tr("Sensor profiles"));
    setObjectName(QStringLiteral("profileDialog"));
    m_modeBox->setObjectName(QStringLiteral("modeBox"));
    m_activeLabel->setObjectName(QStringLiteral("activeLabel"));
    m_list->setObjectName(QStringLiteral("profileList"));
    m_new->setObjectName(QStringLiteral("newButton"));
    m_import->setObjectName(QStringLiteral("importButton"));
    m_export->setObjectName(QStringLiteral("exportButton"));
    m_delete->setObjectName(QStringLiteral("deleteButton"));
    m_editorTitle->setObjectName(QStringLiteral("editorTitle"));
    m_summary->setObjectName(QStringLiteral("summaryLabel"));
    m_problem->setObjectName(QStringLiteral("problemLabel"));
    m_save->setObjectName(QStringLiteral("saveButton"));
    m_revert->setObjectName(QStringLiteral("revertButton"));
    m_use->setObjectName(QStringLiteral("useButton"));
    m_message->setObjectName(QStringLiteral("messageLabel"));

    m_modeBox->addItem(tr("Palpation: two-beam compliance probe"), QStringLiteral("palpation"));
    m_modeBox->addItem(tr("Capacitive: uniform-strength beam"), QStringLiteral("capacitive"));
    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Mode:"), this));
    top->addWidget(m_modeBox);
    top->addSpacing(16);
    top->addWidget(m_activeLabel, 1);

    m_new->setToolTip(tr("A new profile, starting from the selected one"));
    m_import->setToolTip(tr("Copy a profile file into your library"));
    m_export->setToolTip(tr("Write the profile shown to a JSON file"));
    auto* listButtons = new QGridLayout;
    listButtons->addWidget(m_new, 0, 0);
    listButtons->addWidget(m_delete, 0, 1);
    listButtons->addWidget(m_import, 1, 0);
    listButtons->addWidget(m_export, 1, 1);
    auto* left = new QVBoxLayout;
    left->addWidget(m_list, 1);
    left->addLayout(listButtons);
    // Probe names are long ("Perspex two-beam probe (seed 001: …)"): wrapped, not cut.
    m_list->setMinimumWidth(260);
    m_list->setWordWrap(true);
    m_list->setResizeMode(QListView::Adjust);
    m_list->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_list->setSpacing(2);
    m_list->setIconSize(QSize(16, 16));

    m_forms->addWidget(new CompliancePairForm(this));
    m_forms->addWidget(new CapacitiveBeamForm(this));
    auto* unreadable = new QLabel(tr("This file cannot be read as a sensor profile."), this);
    unreadable->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_forms->addWidget(unreadable);
    for (int i = 0; i < 2; ++i) {
        connect(static_cast<ProfileForm*>(m_forms->widget(i)), &ProfileForm::edited, this, [this] { setDirty(true); });
    }
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(m_forms);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    QFont title = m_editorTitle->font();
    title.setBold(true);
    m_editorTitle->setFont(title);
    m_editorTitle->setWordWrap(true);
    m_summary->setWordWrap(true);
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #c62828;"));
    m_message->setWordWrap(true);
    auto* editButtons = new QHBoxLayout;
    editButtons->addStretch(1);
    editButtons->addWidget(m_revert);
    editButtons->addWidget(m_save);
    auto* right = new QVBoxLayout;
    right->addWidget(m_editorTitle);
    right->addWidget(scroll, 1);
    right->addWidget(m_summary);
    right->addWidget(m_problem);
    right->addLayout(editButtons);

    auto* middle = new QHBoxLayout;
    middle->addLayout(left);
    middle->addSpacing(12);
    middle->addLayout(right, 1);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_use, QDialogButtonBox::ActionRole);
    auto* bottom = new QHBoxLayout;
    bottom->addWidget(m_message, 1);
    bottom->addWidget(buttons);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addLayout(middle, 1);
    layout->addLayout(bottom);
    resize(960, 600);

    connect(m_modeBox, &QComboBox::currentIndexChanged, this, [this] {
        reload();
        say({});
    });
    connect(m_list, &QListWidget::currentRowChanged, this, &SensorProfileDialog::showSelected);
    connect(m_new, &QPushButton::clicked, this, &SensorProfileDialog::newProfile);
    connect(m_save, &QPushButton::clicked, this, &SensorProfileDialog::save);
    connect(m_revert, &QPushButton::clicked, this, &SensorProfileDialog::revert);
    connect(m_use, &QPushButton::clicked, this, &SensorProfileDialog::useSelected);
    connect(m_delete, &QPushButton::clicked, this, &SensorProfileDialog::requestDelete);
    connect(buttons, &QDialogButtonBox::rejected, this, &SensorProfileDialog::reject);
    connect(m_import, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Import a sensor profile"), {}, jsonFilter());
        if (!path.isEmpty()) importProfile(path);
    });
    connect(m_export, &QPushButton::clicked, this, [this] {
        const auto profile = form()->result().profile;
        const QString name = profile ? QString::fromStdString(core::sensors::profileName(*profile)) : QString();
        const QString path = QFileDialog::getSaveFileName(this, tr("Export the sensor profile"),
                                                          name + QStringLiteral(".json"), jsonFilter());
        if (!path.isEmpty()) exportProfile(path);
    });
    reload();
}

void SensorProfileDialog::setMode(const QString& mode)
{
    const int index = m_modeBox->findData(mode);
    if (index >= 0) m_modeBox->setCurrentIndex(index);
}

QString SensorProfileDialog::mode() const
{
    return m_modeBox->currentData().toString();
}

void SensorProfileDialog::setLocked(bool locked, const QString& reason)
{
    m_locked = locked;
    m_lockReason = reason;
    updateState();
}

void SensorProfileDialog::reload(const QString& selectPath)
{
    // Read (and parsed) here once, not on every keystroke in updateState().
    m_activePath = activeProfile(mode()).path;
    const QString& active = m_activePath;
    m_entries = m_library.entries(mode(), active);
    const QSignalBlocker blocker(m_list);
    m_list->clear();
    int select = 0;
    for (std::size_t i = 0; i < m_entries.size(); ++i) {
        const ProfileEntry& entry = m_entries[i];
        QString text = entry.name;
        if (entry.builtIn) text += tr("  (built-in)");
        auto* item = new QListWidgetItem(text, m_list);
        item->setToolTip(entry.error.isEmpty() ? (entry.builtIn ? tr("Built into Tactiscope") : entry.path)
                                               : entry.error);
        if (!entry.error.isEmpty()) item->setIcon(style()->standardIcon(QStyle::SP_MessageBoxWarning));
        if (samePath(entry.path, active)) {
            QFont font = item->font();
            font.setBold(true);
            item->setFont(font);
            item->setText(tr("%1  ✓ in use").arg(text));
        }
        if (samePath(entry.path, selectPath.isEmpty() ? active : selectPath)) select = static_cast<int>(i);
    }
    m_list->setCurrentRow(select);
    showSelected();
}

void SensorProfileDialog::selectPath(const QString& path)
{
    if (m_dirty) return;  // the list is held until the changes are saved or reverted
    for (std::size_t i = 0; i < m_entries.size(); ++i)
        if (samePath(m_entries[i].path, path)) m_list->setCurrentRow(static_cast<int>(i));
}

QString SensorProfileDialog::selectedPath() const
{
    const ProfileEntry* entry = selectedEntry();
    return entry ? entry->path : QString();
}

const ProfileEntry* SensorProfileDialog::selectedEntry() const
{
    const int row = m_list->currentRow();
    return row >= 0 && row < static_cast<int>(m_entries.size()) ? &m_entries[static_cast<std::size_t>(row)] : nullptr;
}

ProfileForm* SensorProfileDialog::form() const
{
    return static_cast<ProfileForm*>(m_forms->widget(mode() == QLatin1String("capacitive") ? 1 : 0));
}

void SensorProfileDialog::showSelected()
{
    const ProfileEntry* entry = selectedEntry();
    m_editingPath = entry ? entry->path : QString();
    if (entry && entry->profile) {
        form()->setProfile(*entry->profile);
        m_forms->setCurrentWidget(form());
    } else {
        m_forms->setCurrentIndex(2);
    }
    setDirty(false);
}

void SensorProfileDialog::setDirty(bool dirty)
{
    m_dirty = dirty;
    updateState();
}

void SensorProfileDialog::updateState()
{
    const ProfileEntry* entry = selectedEntry();
    const QString& active = m_activePath;
    const bool onForm = m_forms->currentWidget() == form();
    const FormResult result = onForm ? form()->result() : FormResult{std::nullopt, entry ? entry->error : QString()};
    const bool valid = result.profile.has_value();
    const bool inLibrary = m_library.contains(m_editingPath);
    const bool editingActive = samePath(m_editingPath, active);
    const bool selectable = entry && entry->profile && !m_dirty;

    if (m_editingPath.isEmpty())
        m_editorTitle->setText(tr("New profile (not saved yet)"));
    else if (entry && entry->builtIn)
        m_editorTitle->setText(tr("The paper's probe, built in: read-only. Save keeps your changes as a new profile."));
    else
        m_editorTitle->setText(inLibrary ? tr("In your library: %1").arg(QFileInfo(m_editingPath).fileName())
                                         : tr("File: %1").arg(QDir::toNativeSeparators(m_editingPath)));
    m_editorTitle->setToolTip(QDir::toNativeSeparators(m_editingPath));
    m_summary->setText(valid ? profileSummary(*result.profile) : QString());
    m_problem->setText(result.problem);
    m_problem->setVisible(!result.problem.isEmpty());

    // Unsaved changes hold the list, so a click elsewhere cannot lose them.
    m_modeBox->setEnabled(!m_dirty);
    m_list->setEnabled(!m_dirty);
    m_new->setEnabled(selectable);
    m_import->setEnabled(!m_dirty);
    m_export->setEnabled(valid);
    m_delete->setEnabled(!m_dirty && inLibrary && !editingActive);
    m_delete->setToolTip(editingActive ? tr("The profile in use cannot be deleted: use another one first")
                                       : tr("Delete the profile file from your library"));
    m_save->setText(inLibrary ? tr("Save") : tr("Save as new"));
    m_save->setEnabled(m_dirty && valid && !(m_locked && editingActive));
    m_revert->setEnabled(m_dirty);
    m_use->setText(tr("Use for %1").arg(modeTitle(mode())));
    m_use->setEnabled(selectable && !m_locked && !editingActive);

    const auto activeEntry = std::find_if(m_entries.begin(), m_entries.end(),
                                          [&](const ProfileEntry& e) { return samePath(e.path, active); });
    const QString activeName = activeEntry != m_entries.end() ? activeEntry->name : QFileInfo(active).fileName();
    QString activeText = tr("In use for %1: <b>%2</b>").arg(modeTitle(mode()), activeName.toHtmlEscaped());
    if (m_locked) activeText += tr(" — %1").arg(m_lockReason.toHtmlEscaped());
    m_activeLabel->setText(activeText);
}

void SensorProfileDialog::say(const QString& message, bool problem)
{
    m_message->setText(message);
    m_message->setStyleSheet(problem ? QStringLiteral("color: #c62828;") : QString());
}

void SensorProfileDialog::newProfile()
{
    const ProfileEntry* entry = selectedEntry();
    if (!entry || !entry->profile || m_dirty) return;
    auto copy = *entry->profile;
    std::visit([](auto& profile) { profile.name += " (copy)"; }, copy);
    form()->setProfile(copy);
    m_editingPath.clear();
    setDirty(true);
    form()->nameEdit()->setFocus();
    form()->nameEdit()->selectAll();
    say(tr("Change the name and the values, then save."));
}

bool SensorProfileDialog::save()
{
    const FormResult result = form()->result();
    if (!m_dirty || !result.profile) return false;
    const bool wasActive = samePath(m_editingPath, m_activePath) && m_library.contains(m_editingPath);
    if (wasActive && m_locked) return false;
    QString path;
    try {
        path = m_library.save(*result.profile, m_editingPath);
    } catch (const core::sensors::ProfileError& e) {
        say(tr("Not saved: %1").arg(QString::fromStdString(e.what())), true);
        return false;
    }
    m_dirty = false;
    reload(path);
    say(tr("Saved to %1").arg(QDir::toNativeSeparators(path)));
    if (wasActive) emit activeProfileChanged(mode());
    return true;
}

void SensorProfileDialog::revert()
{
    showSelected();
    say({});
}

bool SensorProfileDialog::importProfile(const QString& path)
{
    if (m_dirty) return false;
    core::sensors::SensorProfile profile;
    try {
        profile = readProfile(path);
    } catch (const core::sensors::ProfileError& e) {
        say(tr("Not imported: %1").arg(QString::fromStdString(e.what())), true);
        return false;
    }
    const QStringList& modes = profileModes();
    const auto target =
        std::find_if(modes.begin(), modes.end(), [&](const QString& m) { return profileFitsMode(profile, m); });
    if (target == modes.end()) {
        say(tr("Not imported: %1 describes a single cantilever (a test specimen), not a probe for palpation or "
               "the capacitive beam.")
                .arg(QFileInfo(path).fileName()),
            true);
        return false;
    }
    QString saved;
    try {
        saved = m_library.save(profile);
    } catch (const core::sensors::ProfileError& e) {
        say(tr("Not imported: %1").arg(QString::fromStdString(e.what())), true);
        return false;
    }
    setMode(*target);
    reload(saved);
    say(tr("Imported into your library as %1").arg(QFileInfo(saved).fileName()));
    return true;
}

bool SensorProfileDialog::exportProfile(const QString& path)
{
    const FormResult result = form()->result();
    if (!result.profile) return false;
    try {
        writeProfile(*result.profile, path);
    } catch (const core::sensors::ProfileError& e) {
        say(tr("Not exported: %1").arg(QString::fromStdString(e.what())), true);
        return false;
    }
    say(tr("Exported to %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

void SensorProfileDialog::requestDelete()
{
    const ProfileEntry* entry = selectedEntry();
    if (!entry || !m_delete->isEnabled()) return;
    const QString path = entry->path;
    auto* box = new QMessageBox(QMessageBox::Question, tr("Delete profile"),
                                tr("Delete \"%1\" from your library?").arg(entry->name),
                                QMessageBox::Yes | QMessageBox::Cancel, this);
    box->setObjectName(QStringLiteral("deleteProfileBox"));
    box->setInformativeText(tr("The file %1 is removed. Sessions recorded with it keep their copy of the profile.")
                                .arg(QDir::toNativeSeparators(path)));
    box->setDefaultButton(QMessageBox::Cancel);
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(box, &QMessageBox::finished, this, [this, path](int answer) {
        if (answer != QMessageBox::Yes) return;
        try {
            m_library.remove(path);
        } catch (const core::sensors::ProfileError& e) {
            say(tr("Not deleted: %1").arg(QString::fromStdString(e.what())), true);
            return;
        }
        reload();
        say(tr("Deleted %1").arg(QFileInfo(path).fileName()));
    });
    box->open();
}

bool SensorProfileDialog::useSelected()
{
    if (!m_use->isEnabled()) return false;
    const ProfileEntry* entry = selectedEntry();
    const QString path = entry->path;
    const QString name = entry->name;
    setActiveProfilePath(mode(), path);
    reload(path);
    say(tr("%1 is now used for %2.").arg(name, modeTitle(mode())));
    emit activeProfileChanged(mode());
    return true;
}

void SensorProfileDialog::reject()
{
    if (m_dirty) {
        const auto answer =
            QMessageBox::question(this, tr("Unsaved changes"), tr("The profile has unsaved changes. Discard them?"),
                                  QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Discard) return;
        revert();
    }
    QDialog::reject();
}

}  // namespace tactiscope::ui
