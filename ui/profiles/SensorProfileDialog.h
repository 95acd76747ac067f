// The sensor-profile dialog: for each mode that runs on a probe model
// (palpation, capacitive), the profiles to choose from — the paper's probe
// built in, the user's library, the active file — with the selected one in
// a form of validated fields with units. Create (from the selected profile),
// edit and save, import a JSON file into the library, export one, delete
// one, and make one the mode's active profile.
//
// Built-in profiles are read-only: saving one keeps the changes as a new
// library profile. While a form has unsaved changes the list is held, so
// nothing is lost by a stray click; Save or Revert release it. While a
// recording runs (setLocked) the active profile stays as it is: a session
// keeps one sensor from start to end.
#pragma once

#include "ui/profiles/ProfileLibrary.h"

#include <QDialog>
#include <QString>

#include <vector>

class QComboBox;
class QLabel;
class QListWidget;
class QPushButton;
class QStackedWidget;

namespace tactiscope::ui {

class ProfileForm;

class SensorProfileDialog : public QDialog {
    Q_OBJECT

public:
    explicit SensorProfileDialog(const QString& libraryDirectory, QWidget* parent = nullptr);

    void setMode(const QString& mode);  // "palpation" or "capacitive"
    QString mode() const;
    // No change of the active profile while locked; `reason` says why.
    void setLocked(bool locked, const QString& reason = {});
    bool hasUnsavedChanges() const { return m_dirty; }

    // What the buttons do, without the file dialogs.
    void selectPath(const QString& path);
    QString selectedPath() const;
    void newProfile();  // a copy of the selected one, not saved yet
    bool save();
    void revert();
    bool importProfile(const QString& path);
    bool exportProfile(const QString& path);
    void requestDelete();  // asks first (deleteProfileBox)
    bool useSelected();

signals:
    // The mode's active profile changed: another one was chosen, or its
    // file was saved with new values.
    void activeProfileChanged(const QString& mode);

protected:
    void reject() override;

private:
    void reload(const QString& selectPath = {});
    void showSelected();
    void setDirty(bool dirty);
    void updateState();
    void say(const QString& message, bool problem = false);
    ProfileForm* form() const;
    const ProfileEntry* selectedEntry() const;

    ProfileLibrary m_library;
    std::vector<ProfileEntry> m_entries;  // as listed
    QString m_activePath;                 // the mode's profile in use, as of the last reload()
    QString m_editingPath;                // empty for a new profile
    bool m_dirty = false;
    bool m_locked = false;
    QString m_lockReason;

    QComboBox* m_modeBox;
    QLabel* m_activeLabel;
    QListWidget* m_list;
    QPushButton* m_new;
    QPushButton* m_import;
    QPushButton* m_export;
    QPushButton* m_delete;
    QLabel* m_editorTitle;
    QStackedWidget* m_forms;
    QLabel* m_summary;
    QLabel* m_problem;
    QPushButton* m_save;
    QPushButton* m_revert;
    QPushButton* m_use;
    QLabel* m_message;
};

}  // namespace tactiscope::ui
