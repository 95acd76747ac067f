// The device panel's channel roles: one row per channel of the connected
// device, its name and kind and what it is to a mode (cantilever A, the
// stiff beam, the capacitance …). A choice goes to the live session at once
// (MainWindow::setRoles), and is remembered per device model and serial
// number, so a maker's board that prints unlabelled columns is set up once.
// The rows fold away behind their title for a probe that says what its
// channels are, and open for one that records in the general mode.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/modes/ChannelRoles.h"
#include "devices/BlockSource.h"

#include <QFrame>

#include <vector>

class QComboBox;
class QFormLayout;
class QLabel;
class QToolButton;

namespace tactiscope::ui {

class ChannelRolesBox : public QFrame {
    Q_OBJECT

public:
    explicit ChannelRolesBox(QWidget* parent = nullptr);

    // The device's channels as it declared them and the roles given to
    // them, the rows open or folded; no channels: nothing connected, the
    // box hides.
    void setChannels(const std::vector<core::ChannelDescriptor>& declared, const core::RoleAssignment& given,
                     bool open = true);
    bool isOpen() const;
    // The roles chosen (only channels given one here).
    core::RoleAssignment roles() const;
    // As the user's choice in the channel's list: none keeps the device's own.
    void chooseRole(const QString& channel, std::optional<core::ChannelRole> role);
    // A recording keeps its channels' roles.
    void setLocked(bool locked);

signals:
    void rolesChosen(const core::RoleAssignment& roles);

private:
    QToolButton* m_title = nullptr;
    QWidget* m_body = nullptr;
    QFormLayout* m_rows = nullptr;
    std::vector<QComboBox*> m_choices;  // one per channel, its name as object name
    bool m_showing = false;
};

// The roles remembered for a device (by model and serial), and remembering them.
core::RoleAssignment rememberedRoles(const devices::DeviceIdentity& device);
void rememberRoles(const devices::DeviceIdentity& device, const core::RoleAssignment& roles);

}  // namespace tactiscope::ui
