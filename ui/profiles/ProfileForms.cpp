// ProfileForms: fields, their units and ranges, and the checks beyond one
// field (the stiff beam stiffer than the soft one, a sheet with a layer).
#include "ui/profiles/ProfileForms.h"
#include "ui/common/DisplayUnits.h"
#include "ui/common/NumberText.h"

#include "core/sensors/CapacitiveBeam.h"
#include "core/sensors/CompliancePair.h"
#include "ui/common/QuantityEdit.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>
#include <stdexcept>

namespace tactiscope::ui {
namespace {

using core::sensors::SensorProfile;

// Generous bounds: they catch a slip of units (a length in metres typed as
// millimetres), not unusual probes.
constexpr double kMaxLength_m = 10.0;
constexpr double kMaxModulus_pa = 1e13;
constexpr double kMaxCapacitance_f = 1e-3;

const DisplayUnit kMillimetre{1e3, QStringLiteral("mm"), {}};
const DisplayUnit kMicrometre{1e6, QStringLiteral("µm"), {}};
const DisplayUnit kGigapascal{1e-9, QStringLiteral("GPa"), {}};
const DisplayUnit kKilopascal{1e-3, QStringLiteral("kPa"), {}};
const DisplayUnit kPicofarad{1e12, QStringLiteral("pF"), {}};
const DisplayUnit kRatio{1.0, {}, {}};

// Three significant figures, without switching to exponents for the
// stiffnesses and sensitivities a probe has.
QString figures(double value)
{
    const int magnitude = value != 0.0 ? static_cast<int>(std::floor(std::log10(std::abs(value)))) : 0;
    return fixedText(value, std::clamp(2 - magnitude, 0, 6));
}

// Reads one field into `out`; false (with the problem said) when it has none.
bool take(const QuantityEdit* field, const QString& label, double& out, QString& problem)
{
    if (const auto value = field->value()) {
        out = *value;
        return true;
    }
    problem = QStringLiteral("%1: %2").arg(label, field->problem());
    return false;
}

}  // namespace

FormResult ProfileForm::result() const
{
    if (m_name->text().trimmed().isEmpty()) return {std::nullopt, tr("Name: give the probe a name")};
    FormResult result = fields();
    if (!result.profile) return result;
    // The core's reader is the final word: what it would refuse to load is
    // not offered for saving.
    try {
        const std::string name = m_name->text().trimmed().toStdString();
        result.profile = core::sensors::parseSensorProfile(core::sensors::toJson(*result.profile), name);
    } catch (const core::sensors::ProfileError& e) {
        return {std::nullopt, QString::fromStdString(e.what())};
    }
    return result;
}

QLineEdit* ProfileForm::createNameEdit()
{
    m_name = new QLineEdit(this);
    m_name->setObjectName(QStringLiteral("nameEdit"));
    m_name->setPlaceholderText(tr("How the probe is known in sessions and calibrations"));
    connect(m_name, &QLineEdit::textEdited, this, &ProfileForm::edited);
    return m_name;
}

QuantityEdit* ProfileForm::createField(const DisplayUnit& unit, double minimum_si, double maximum_si,
                                       const QString& objectName)
{
    auto* field = new QuantityEdit(unit, minimum_si, maximum_si, this);
    field->setObjectName(objectName);
    connect(field, &QuantityEdit::edited, this, &ProfileForm::edited);
    return field;
}

// ---- the compliance probe -------------------------------------------------

CompliancePairForm::CompliancePairForm(QWidget* parent)
    : ProfileForm(parent)
{
    auto* layout = new QVBoxLayout(this);
    auto* name = new QFormLayout;
    name->addRow(tr("Name:"), createNameEdit());
    layout->addLayout(name);
    auto* beams = new QHBoxLayout;
    beams->addWidget(createBeamBox(tr("Stiff beam (high)"), QStringLiteral("high"), m_high));
    beams->addWidget(createBeamBox(tr("Soft beam (low)"), QStringLiteral("low"), m_low));
    layout->addLayout(beams);
    auto* note = new QLabel(tr("Both beams are rectangular cantilevers loaded at the tip; "
                               "their ratio of stiffness sets the range of kₒ the probe resolves."),
                            this);
    note->setWordWrap(true);
    note->setEnabled(false);  // a hint, in the palette's quiet colour
    layout->addWidget(note);
    layout->addStretch(1);
}

QWidget* CompliancePairForm::createBeamBox(const QString& title, const QString& prefix, BeamFields& beam)
{
    auto* box = new QGroupBox(title, this);
    auto* form = new QFormLayout(box);
    beam.length = createField(kMillimetre, 0.0, kMaxLength_m, prefix + QStringLiteral("Length"));
    beam.width = createField(kMillimetre, 0.0, kMaxLength_m, prefix + QStringLiteral("Width"));
    beam.thickness = createField(kMillimetre, 0.0, kMaxLength_m, prefix + QStringLiteral("Thickness"));
    beam.modulus = createField(kGigapascal, 0.0, kMaxModulus_pa, prefix + QStringLiteral("Modulus"));
    form->addRow(tr("Length L:"), beam.length);
    form->addRow(tr("Width w:"), beam.width);
    form->addRow(tr("Thickness t:"), beam.thickness);
    form->addRow(tr("Young's modulus E:"), beam.modulus);
    return box;
}

void CompliancePairForm::setProfile(const SensorProfile& profile)
{
    const auto& pair = std::get<core::sensors::CompliancePairProfile>(profile);
    nameEdit()->setText(QString::fromStdString(pair.name));
    m_roles = pair.roles;
    for (const auto& [fields, geometry] : {std::pair{&m_high, &pair.high}, std::pair{&m_low, &pair.low}}) {
        fields->length->setValue(geometry->length_m);
        fields->width->setValue(geometry->width_m);
        fields->thickness->setValue(geometry->thickness_m);
        fields->modulus->setValue(geometry->youngsModulus_pa);
    }
}

FormResult CompliancePairForm::fields() const
{
    core::sensors::CompliancePairProfile pair;
    pair.name = nameEdit()->text().trimmed().toStdString();
    pair.roles = m_roles;
    QString problem;
    for (const auto& [fields, geometry, beam] :
         {std::tuple{&m_high, &pair.high, tr("Stiff beam")}, std::tuple{&m_low, &pair.low, tr("Soft beam")}}) {
        if (!take(fields->length, tr("%1, length").arg(beam), geometry->length_m, problem) ||
            !take(fields->width, tr("%1, width").arg(beam), geometry->width_m, problem) ||
            !take(fields->thickness, tr("%1, thickness").arg(beam), geometry->thickness_m, problem) ||
            !take(fields->modulus, tr("%1, Young's modulus").arg(beam), geometry->youngsModulus_pa, problem))
            return {std::nullopt, problem};
    }
    const double kHigh = core::sensors::CantileverBeam(pair.high).stiffness_n_per_m();
    const double kLow = core::sensors::CantileverBeam(pair.low).stiffness_n_per_m();
    if (!(kHigh > kLow))
        return {std::nullopt, tr("The stiff beam must be the stiffer one: k stiff = %1 N/m, k soft = %2 N/m")
                                  .arg(figures(kHigh), figures(kLow))};
    return {pair, {}};
}

// ---- the capacitive beam --------------------------------------------------

CapacitiveBeamForm::CapacitiveBeamForm(QWidget* parent)
    : ProfileForm(parent)
{
    auto* layout = new QVBoxLayout(this);
    auto* name = new QFormLayout;
    name->addRow(tr("Name:"), createNameEdit());
    layout->addLayout(name);

    auto* columns = new QHBoxLayout;
    auto* beamBox = new QGroupBox(tr("Uniform-strength beam"), this);
    auto* beam = new QFormLayout(beamBox);
    m_length = createField(kMillimetre, 0.0, kMaxLength_m, QStringLiteral("beamLength"));
    m_rootWidth = createField(kMillimetre, 0.0, kMaxLength_m, QStringLiteral("beamRootWidth"));
    m_thickness = createField(kMillimetre, 0.0, kMaxLength_m, QStringLiteral("beamThickness"));
    m_modulus = createField(kKilopascal, 0.0, kMaxModulus_pa, QStringLiteral("beamModulus"));
    m_sheetRatio = createField(kRatio, 0.0, 1.0, QStringLiteral("sheetRatio"));
    beam->addRow(tr("Length l:"), m_length);
    beam->addRow(tr("Root width b:"), m_rootWidth);
    beam->addRow(tr("Thickness:"), m_thickness);
    beam->addRow(tr("Young's modulus:"), m_modulus);
    beam->addRow(tr("Sheet length ratio α:"), m_sheetRatio);
    m_sheetRatio->setToolTip(tr("The part of the beam's length the sensing sheet covers, between 0 and 1"));
    columns->addWidget(beamBox);

    auto* capacitanceBox = new QGroupBox(tr("Capacitance"), this);
    auto* capacitance = new QFormLayout(capacitanceBox);
    m_c0 = createField(kPicofarad, 0.0, kMaxCapacitance_f, QStringLiteral("c0"));
    capacitance->addRow(tr("Undeformed C0:"), m_c0);
    m_doubleLayerOn = new QCheckBox(tr("Correct for the electrodes' double layers"), this);
    m_doubleLayerOn->setObjectName(QStringLiteral("doubleLayerOn"));
    m_doubleLayer = createField(kPicofarad, 0.0, kMaxCapacitance_f, QStringLiteral("doubleLayer"));
    capacitance->addRow(m_doubleLayerOn);
    capacitance->addRow(tr("C<sub>EDL</sub>:"), m_doubleLayer);
    connect(m_doubleLayerOn, &QCheckBox::toggled, m_doubleLayer, &QWidget::setEnabled);
    connect(m_doubleLayerOn, &QCheckBox::clicked, this, &ProfileForm::edited);
    columns->addWidget(capacitanceBox, 0, Qt::AlignTop);
    layout->addLayout(columns);

    auto* sheetBox = new QGroupBox(tr("Sensing sheet, from the beam surface outward"), this);
    auto* sheet = new QVBoxLayout(sheetBox);
    m_layerGrid = new QGridLayout;
    m_layerGrid->addWidget(new QLabel(tr("Layer"), this), 0, 0);
    m_layerGrid->addWidget(new QLabel(tr("Thickness"), this), 0, 1);
    m_layerGrid->addWidget(new QLabel(tr("Young's modulus"), this), 0, 2);
    m_layerGrid->setColumnStretch(0, 3);
    m_layerGrid->setColumnStretch(1, 1);
    m_layerGrid->setColumnStretch(2, 1);
    sheet->addLayout(m_layerGrid);
    auto* add = new QPushButton(tr("Add a layer"), this);
    add->setObjectName(QStringLiteral("addLayerButton"));
    connect(add, &QPushButton::clicked, this, [this] {
        addLayer({});
        emit edited();
    });
    sheet->addWidget(add, 0, Qt::AlignLeft);
    layout->addWidget(sheetBox);
    layout->addStretch(1);
}

void CapacitiveBeamForm::setProfile(const SensorProfile& profile)
{
    const auto& capacitive = std::get<core::sensors::CapacitiveBeamProfile>(profile);
    const auto& g = capacitive.geometry;
    nameEdit()->setText(QString::fromStdString(capacitive.name));
    m_roles = capacitive.roles;
    m_length->setValue(g.beam.length_m);
    m_rootWidth->setValue(g.beam.rootWidth_m);
    m_thickness->setValue(g.beam.thickness_m);
    m_modulus->setValue(g.beam.youngsModulus_pa);
    m_sheetRatio->setValue(g.beam.sheetLengthRatio);
    while (!m_layers.empty()) removeLayer(m_layers.size() - 1);
    for (const auto& layer : g.sheetLayers) addLayer(layer);
    m_c0->setValue(g.c0_f);
    m_doubleLayerOn->setChecked(g.doubleLayer_f.has_value());
    m_doubleLayer->setEnabled(g.doubleLayer_f.has_value());
    if (g.doubleLayer_f)
        m_doubleLayer->setValue(*g.doubleLayer_f);
    else
        m_doubleLayer->clear();
}

void CapacitiveBeamForm::addLayer(const core::sensors::SheetLayer& layer)
{
    LayerFields fields;
    const QString tag = QStringLiteral("layer%1").arg(m_layers.size());
    fields.name = new QLineEdit(QString::fromStdString(layer.name), this);
    fields.name->setObjectName(tag + QStringLiteral("Name"));
    fields.name->setPlaceholderText(tr("e.g. dielectric (Eco-flex 0050)"));
    connect(fields.name, &QLineEdit::textEdited, this, &ProfileForm::edited);
    fields.thickness = createField(kMicrometre, 0.0, kMaxLength_m, tag + QStringLiteral("Thickness"));
    fields.modulus = createField(kKilopascal, 0.0, kMaxModulus_pa, tag + QStringLiteral("Modulus"));
    if (layer.thickness_m > 0.0) fields.thickness->setValue(layer.thickness_m);
    if (layer.youngsModulus_pa > 0.0) fields.modulus->setValue(layer.youngsModulus_pa);
    auto* remove = new QToolButton(this);
    remove->setText(QStringLiteral("−"));
    remove->setToolTip(tr("Remove this layer"));
    remove->setObjectName(tag + QStringLiteral("Remove"));
    fields.remove = remove;
    connect(remove, &QToolButton::clicked, this, [this, remove] {
        for (std::size_t i = 0; i < m_layers.size(); ++i) {
            if (m_layers[i].remove == remove) {
                removeLayer(i);
                emit edited();
                return;
            }
        }
    });
    m_layers.push_back(fields);
    layOutLayers();
}

void CapacitiveBeamForm::removeLayer(std::size_t index)
{
    const LayerFields fields = m_layers[index];
    m_layers.erase(m_layers.begin() + static_cast<std::ptrdiff_t>(index));
    for (QWidget* widget : {static_cast<QWidget*>(fields.name), static_cast<QWidget*>(fields.thickness),
                            static_cast<QWidget*>(fields.modulus), fields.remove}) {
        m_layerGrid->removeWidget(widget);
        widget->deleteLater();
    }
    layOutLayers();
}

// Rows in order under the header; the last layer cannot go (a sheet has one).
void CapacitiveBeamForm::layOutLayers()
{
    for (std::size_t i = 0; i < m_layers.size(); ++i) {
        const int row = static_cast<int>(i) + 1;
        const LayerFields& fields = m_layers[i];
        m_layerGrid->addWidget(fields.name, row, 0);
        m_layerGrid->addWidget(fields.thickness, row, 1);
        m_layerGrid->addWidget(fields.modulus, row, 2);
        m_layerGrid->addWidget(fields.remove, row, 3);
        fields.remove->setEnabled(m_layers.size() > 1);
    }
}

FormResult CapacitiveBeamForm::fields() const
{
    core::sensors::CapacitiveBeamProfile capacitive;
    capacitive.name = nameEdit()->text().trimmed().toStdString();
    capacitive.roles = m_roles;
    auto& g = capacitive.geometry;
    QString problem;
    if (!take(m_length, tr("Beam length"), g.beam.length_m, problem) ||
        !take(m_rootWidth, tr("Beam root width"), g.beam.rootWidth_m, problem) ||
        !take(m_thickness, tr("Beam thickness"), g.beam.thickness_m, problem) ||
        !take(m_modulus, tr("Beam Young's modulus"), g.beam.youngsModulus_pa, problem) ||
        !take(m_sheetRatio, tr("Sheet length ratio"), g.beam.sheetLengthRatio, problem))
        return {std::nullopt, problem};
    for (std::size_t i = 0; i < m_layers.size(); ++i) {
        const LayerFields& fields = m_layers[i];
        core::sensors::SheetLayer layer;
        layer.name = fields.name->text().trimmed().toStdString();
        if (layer.name.empty()) return {std::nullopt, tr("Sheet layer %1: give it a name").arg(i + 1)};
        if (!take(fields.thickness, tr("Sheet layer %1, thickness").arg(i + 1), layer.thickness_m, problem) ||
            !take(fields.modulus, tr("Sheet layer %1, Young's modulus").arg(i + 1), layer.youngsModulus_pa, problem))
            return {std::nullopt, problem};
        g.sheetLayers.push_back(layer);
    }
    if (!take(m_c0, tr("C0"), g.c0_f, problem)) return {std::nullopt, problem};
    if (m_doubleLayerOn->isChecked()) {
        double doubleLayer_f = 0.0;
        if (!take(m_doubleLayer, tr("Double-layer capacitance"), doubleLayer_f, problem))
            return {std::nullopt, problem};
        g.doubleLayer_f = doubleLayer_f;
    }
    try {
        (void)core::sensors::CapacitiveBeam(g);
    } catch (const std::invalid_argument& e) {
        return {std::nullopt, QString::fromStdString(e.what())};
    }
    return {capacitive, {}};
}

// ---- summaries ------------------------------------------------------------

QString profileSummary(const SensorProfile& profile)
{
    if (const auto* pair = std::get_if<core::sensors::CompliancePairProfile>(&profile)) {
        const core::sensors::CompliancePair probe{core::sensors::CantileverBeam(pair->high),
                                                  core::sensors::CantileverBeam(pair->low)};
        return ProfileForm::tr("Beam stiffness: stiff %1 N/m, soft %2 N/m; Q = F stiff / F soft runs from 1 to %3.")
            .arg(figures(probe.kHigh_n_per_m()), figures(probe.kLow_n_per_m()), figures(probe.qMax()));
    }
    if (const auto* capacitive = std::get_if<core::sensors::CapacitiveBeamProfile>(&profile)) {
        const core::sensors::CapacitiveBeam beam(capacitive->geometry);
        // pF per mN and pF per mm: both F/N × 1e12 pF/F × 1e-3.
        return ProfileForm::tr("Beam stiffness kₛ = %1 N/m; sensitivity %2 pF/mN and %3 pF/mm of tip deflection.")
            .arg(figures(beam.stiffness_n_per_m()), figures(beam.capacitancePerNewton_f_per_n() * 1e9),
                 figures(beam.capacitancePerMetre_f_per_m() * 1e9));
    }
    const auto& cantilever = std::get<core::sensors::CantileverProfile>(profile);
    return ProfileForm::tr("Stiffness k = %1 N/m.")
        .arg(figures(core::sensors::CantileverBeam(cantilever.geometry).stiffness_n_per_m()));
}

}  // namespace tactiscope::ui
