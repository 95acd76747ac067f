// ChannelRolesBox: a role list per channel, and the roles kept in QSettings.
#include "ui/device/ChannelRolesBox.h"

#include "core/modes/ModeDefinition.h"
#include "ui/common/VocabularyText.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QSettings>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace tactiscope::ui {
namespace {

QString roleName(core::ChannelRole role)
{
    switch (role) {
    case core::ChannelRole::CantileverA:
        return QObject::tr("cantilever A");
    case core::ChannelRole::CantileverB:
        return QObject::tr("cantilever B");
    case core::ChannelRole::StiffBeam:
        return QObject::tr("stiff beam");
    case core::ChannelRole::SoftBeam:
        return QObject::tr("soft beam");
    case core::ChannelRole::Displacement:
        return QObject::tr("displacement");
    case core::ChannelRole::Capacitance:
        return QObject::tr("capacitance");
    case core::ChannelRole::ReferenceForce:
        return QObject::tr("reference force");
    case core::ChannelRole::Position:
        return QObject::tr("stroke position");
    }
    return {};
}

// Each role a mode reads, then each it uses when a channel plays it, in the
// registry's order, titled with the mode's: "capacitance (capacitive)".
// A mode's roles are offered from its definition, none listed here.
std::vector<std::pair<core::ChannelRole, QString>> offeredRoles()
{
    std::vector<std::pair<core::ChannelRole, QString>> offered;
    const auto offer = [&offered](core::ChannelRole role, const QString& title) {
        if (std::ranges::none_of(offered, [role](const auto& o) { return o.first == role; }))
            offered.emplace_back(role, title);
    };
    for (const core::ModeDefinition& mode : core::modeDefinitions()) {
        const QString title = modeTitle(mode.mode).toLower();
        for (const core::ChannelRole role : mode.roles) offer(role, QObject::tr("%1 (%2)").arg(roleName(role), title));
        for (const core::ChannelRole role : mode.optionalRoles)
            offer(role, QObject::tr("%1 (%2, when present)").arg(roleName(role), title));
    }
    return offered;
}

QString roleTitle(core::ChannelRole role)
{
    for (const auto& [offered, title] : offeredRoles())
        if (offered == role) return title;
    return roleName(role);
}

// One settings key per device: its model and serial, so two boards of one
// model wired differently keep their own roles.
QString settingsKey(const devices::DeviceIdentity& device)
{
    const QString model = QString::fromStdString(device.model.empty() ? "unknown" : device.model);
    const QString serial = QString::fromStdString(device.serial.empty() ? "no-serial" : device.serial);
    return QStringLiteral("channelRoles/%1/%2").arg(model, serial).replace(QLatin1Char(' '), QLatin1Char('_'));
}

}  // namespace

ChannelRolesBox::ChannelRolesBox(QWidget* parent)
    : QFrame(parent),
      m_title(new QToolButton(this)),
      m_body(new QWidget(this)),
      m_rows(new QFormLayout)
{
    setObjectName(QStringLiteral("channelRolesBox"));
    m_title->setText(tr("Channel roles"));
    m_title->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_title->setAutoRaise(true);
    m_title->setCheckable(true);
    m_title->setToolTip(tr("What each channel is to a mode: a device that does not say records in general mode; "
                           "give its channels roles to run the panel scan, palpation or capacitive mode on it"));
    connect(m_title, &QToolButton::toggled, this, [this](bool open) {
        m_title->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
        m_body->setVisible(open);
    });
    auto* hint = new QLabel(tr("A device that says nothing records in general mode."), m_body);
    hint->setWordWrap(true);
    hint->setStyleSheet(QStringLiteral("color: palette(mid);"));
    m_rows->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_rows->setContentsMargins(0, 0, 0, 0);
    auto* body = new QVBoxLayout(m_body);
    body->setContentsMargins(6, 0, 0, 0);
    body->addLayout(m_rows);
    body->addWidget(hint);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(m_title);
    layout->addWidget(m_body);
    hide();
}

bool ChannelRolesBox::isOpen() const
{
    return m_title->isChecked();
}

void ChannelRolesBox::setChannels(const std::vector<core::ChannelDescriptor>& declared,
                                  const core::RoleAssignment& given, bool open)
{
    m_showing = true;
    while (m_rows->rowCount() > 0) m_rows->removeRow(0);
    m_choices.clear();
    for (const auto& channel : declared) {
        auto* choice = new QComboBox(this);
        const QString name = QString::fromStdString(channel.name);
        choice->setObjectName(name);
        // Without a role the modes take the channel by its kind.
        choice->addItem(channel.role
                            ? tr("device: %1").arg(roleTitle(*channel.role))
                            : tr("by kind (%1)").arg(QString::fromStdString(std::string(toString(channel.kind)))),
                        QString());
        for (const auto& [role, title] : offeredRoles())
            choice->addItem(title, QString::fromStdString(std::string(toString(role))));
        if (const auto found = given.find(channel.name); found != given.end())
            choice->setCurrentIndex(choice->findData(QString::fromStdString(std::string(toString(found->second)))));
        connect(choice, &QComboBox::currentIndexChanged, this, [this] {
            if (!m_showing) emit rolesChosen(roles());
        });
        // The unit the device gave, or none: a plain number.
        const QString unit =
            channel.unit.empty() ? QString() : QStringLiteral(" [%1]").arg(QString::fromStdString(channel.unit));
        m_rows->addRow((name + unit).toHtmlEscaped() + QLatin1Char(':'), choice);
        m_choices.push_back(choice);
    }
    setVisible(!declared.empty());
    m_title->setChecked(open);
    m_title->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
    m_body->setVisible(open);
    m_showing = false;
}

core::RoleAssignment ChannelRolesBox::roles() const
{
    core::RoleAssignment roles;
    for (const QComboBox* choice : m_choices)
        if (const auto role = core::channelRoleFromString(choice->currentData().toString().toStdString()))
            roles[choice->objectName().toStdString()] = *role;
    return roles;
}

void ChannelRolesBox::chooseRole(const QString& channel, std::optional<core::ChannelRole> role)
{
    for (QComboBox* choice : m_choices)
        if (choice->objectName() == channel)
            choice->setCurrentIndex(role ? choice->findData(QString::fromStdString(std::string(toString(*role)))) : 0);
}

void ChannelRolesBox::setLocked(bool locked)
{
    for (QComboBox* choice : m_choices) {
        choice->setEnabled(!locked);
        choice->setToolTip(locked ? tr("fixed while recording: a session keeps its channels' roles") : QString());
    }
}

core::RoleAssignment rememberedRoles(const devices::DeviceIdentity& device)
{
    const QString text = QSettings().value(settingsKey(device)).toString();
    try {
        return core::parseRoleAssignment(text.toStdString());
    } catch (const std::invalid_argument&) {
        return {};  // settings edited by hand: the device's own roles
    }
}

void rememberRoles(const devices::DeviceIdentity& device, const core::RoleAssignment& roles)
{
    QSettings settings;
    if (roles.empty())
        settings.remove(settingsKey(device));
    else
        settings.setValue(settingsKey(device), QString::fromStdString(core::roleAssignmentText(roles)));
}

}  // namespace tactiscope::ui
