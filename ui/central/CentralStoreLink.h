// The main window's side of the central store: the push controller, a
// status-bar field saying how the sending goes ("Central store: 3 waiting",
// "… cannot send" with the reason as its tooltip; a click opens the
// dialog), and the dialog itself, one at a time.
#pragma once

#include <QObject>
#include <QPointer>

class QLabel;
class QStatusBar;
class QWidget;

namespace tactiscope::ui {

class CentralStoreDialog;
class CentralSyncController;

class CentralStoreLink : public QObject {
    Q_OBJECT

public:
    CentralStoreLink(QStatusBar* bar, QWidget* window);

    void setStorePath(const QString& path) const;
    void sessionRecorded() const;
    void syncNow() const;  // e.g. an operator's verdict was just stored
    CentralStoreDialog* showDialog();
    CentralSyncController* controller() const { return m_controller; }

signals:
    void browseRequested(const QString& conninfo);

private:
    void showState();

    QWidget* m_window;
    CentralSyncController* m_controller;
    QLabel* m_field;
    QPointer<CentralStoreDialog> m_dialog;
};

}  // namespace tactiscope::ui
