// Session ▸ Central store…: where this station sends its sessions (a libpq
// connection string, never with a password), as which station, and how the
// sending goes: how many sessions wait, the last outcome, the last error
// and when it tries again. Non-modal; it follows the controller live.
#pragma once

#include <QDialog>

class QLabel;
class QLineEdit;
class QPushButton;

namespace tactiscope::ui {

class CentralSyncController;

class CentralStoreDialog : public QDialog {
    Q_OBJECT

public:
    CentralStoreDialog(CentralSyncController* controller, QWidget* parent = nullptr);

signals:
    // Browse the sessions of the central store at `conninfo`.
    void browseRequested(const QString& conninfo);

private:
    void checkAddress();
    void save();
    void showState();

    CentralSyncController* m_controller;
    QLineEdit* m_server;
    QLineEdit* m_station;
    QLabel* m_addressProblem;
    QLabel* m_waiting;
    QLabel* m_last;
    QLabel* m_error;
    QPushButton* m_send;
    QPushButton* m_browse;
};

}  // namespace tactiscope::ui
