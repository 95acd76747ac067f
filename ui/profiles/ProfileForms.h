// The editable forms of the two probes a mode runs on: the palpation
// mode's pair of cantilevers and the capacitive mode's uniform-strength beam
// with its sensing sheet. Each field is a QuantityEdit in the unit people
// measure it in (mm, µm, GPa, kPa, pF); the form hands out the profile in SI
// or the first problem, named by its field, and what the probe's numbers
// come to (the beams' stiffness, the sensitivities) so a typo shows at once.
#pragma once

#include "core/sensors/SensorProfile.h"
#include "ui/common/DisplayUnits.h"

#include <QString>
#include <QWidget>

#include <optional>
#include <vector>

class QGridLayout;
class QLineEdit;
class QCheckBox;

namespace tactiscope::ui {

class QuantityEdit;

// What the fields describe: a profile, or why not.
struct FormResult {
    std::optional<core::sensors::SensorProfile> profile;
    QString problem;
};

class ProfileForm : public QWidget {
    Q_OBJECT

public:
    using QWidget::QWidget;

    // Fills the fields; the profile must be of the form's kind.
    virtual void setProfile(const core::sensors::SensorProfile& profile) = 0;
    FormResult result() const;
    QLineEdit* nameEdit() const { return m_name; }

signals:
    void edited();  // any field, by the user

protected:
    // The kind-specific profile from the fields, or the first field's problem.
    virtual FormResult fields() const = 0;
    QLineEdit* createNameEdit();
    QuantityEdit* createField(const DisplayUnit& unit, double minimum_si, double maximum_si, const QString& objectName);

    // The channel roles the profile gave, kept as read: the form edits the
    // probe's mechanics, the device panel its wiring.
    core::RoleAssignment m_roles;

private:
    QLineEdit* m_name = nullptr;
};

// The compliance probe (seed 001): the stiff (high) and the soft (low) beam.
class CompliancePairForm : public ProfileForm {
    Q_OBJECT

public:
    explicit CompliancePairForm(QWidget* parent = nullptr);
    void setProfile(const core::sensors::SensorProfile& profile) override;

protected:
    FormResult fields() const override;

private:
    struct BeamFields {
        QuantityEdit* length = nullptr;
        QuantityEdit* width = nullptr;
        QuantityEdit* thickness = nullptr;
        QuantityEdit* modulus = nullptr;
    };
    QWidget* createBeamBox(const QString& title, const QString& prefix, BeamFields& beam);

    BeamFields m_high, m_low;
};

// The capacitive beam (seed 002): the triangular beam, the sheet's layers
// (from the beam surface outward, any number) and the capacitances.
class CapacitiveBeamForm : public ProfileForm {
    Q_OBJECT

public:
    explicit CapacitiveBeamForm(QWidget* parent = nullptr);
    void setProfile(const core::sensors::SensorProfile& profile) override;
    int layerCount() const { return static_cast<int>(m_layers.size()); }

protected:
    FormResult fields() const override;

private:
    struct LayerFields {
        QLineEdit* name = nullptr;
        QuantityEdit* thickness = nullptr;
        QuantityEdit* modulus = nullptr;
        QWidget* remove = nullptr;
    };
    void addLayer(const core::sensors::SheetLayer& layer);
    void removeLayer(std::size_t index);
    void layOutLayers();

    QuantityEdit* m_length = nullptr;
    QuantityEdit* m_rootWidth = nullptr;
    QuantityEdit* m_thickness = nullptr;
    QuantityEdit* m_modulus = nullptr;
    QuantityEdit* m_sheetRatio = nullptr;
    QGridLayout* m_layerGrid = nullptr;
    std::vector<LayerFields> m_layers;
    QuantityEdit* m_c0 = nullptr;
    QCheckBox* m_doubleLayerOn = nullptr;
    QuantityEdit* m_doubleLayer = nullptr;
};

// What a valid profile's numbers come to, in one or two lines.
QString profileSummary(const core::sensors::SensorProfile& profile);

}  // namespace tactiscope::ui
