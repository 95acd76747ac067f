// The sensor-profile dialog on a real library folder: the list per mode,
// fields in display units, validation naming the field, save (a built-in
// one as a copy), import, export, delete with a question, and choosing the
// active profile — refused while locked by a recording; in the main window,
// the chosen probe reads the live presses and goes into the session.
#include "ui/profiles/SensorProfileDialog.h"

#include "core/sensors/BuiltInProfiles.h"
#include "core/storage/SessionStore.h"
#include "devices/simulator/PalpationScenario.h"
#include "support/MainWindowHelpers.h"
#include "support/Screenshot.h"
#include "support/TextFiles.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/common/QuantityEdit.h"
#include "ui/live/LiveStation.h"
#include "ui/modes/palpation/PalpationView.h"
#include "ui/profiles/ActiveProfiles.h"
#include "ui/profiles/ProfileForms.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::testing::child;
using tactiscope::testing::writeText;

namespace {

const QString kThickerPair =
    QStringLiteral(R"({"kind": "compliance_pair", "name": "Thick probe", )"
                   R"("high": {"length_m": 0.04, "width_m": 0.01, "thickness_m": 0.004, "youngs_modulus_pa": 3e9}, )"
                   R"("low": {"length_m": 0.04, "width_m": 0.01, "thickness_m": 0.0015, "youngs_modulus_pa": 3e9}})");
const QString kCapacitive = QStringLiteral(
    R"({"kind": "capacitive_beam", "name": "Short beam", )"
    R"("beam": {"length_m": 0.01, "root_width_m": 0.005, "thickness_m": 0.002, "youngs_modulus_pa": 83000, )"
    R"("sheet_length_ratio": 0.5}, )"
    R"("sheet_layers": [{"name": "dielectric", "thickness_m": 0.00002, "youngs_modulus_pa": 83000}], "c0_pf": 40})");

// A dialog on an empty library folder, with the modes' choices reset and put
// back afterwards, so tests neither see nor leave a user's settings.
class SensorProfileDialogTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_TRUE(m_library.isValid());
        for (const QString& mode : ui::profileModes()) QSettings().remove(QStringLiteral("profiles/") + mode);
    }
    void TearDown() override
    {
        for (const QString& mode : ui::profileModes()) QSettings().remove(QStringLiteral("profiles/") + mode);
    }

    QString libraryFile(const QString& name, const QString& text) const
    {
        const QString path = m_library.filePath(name);
        writeText(path, text);
        return path;
    }
    QString fieldText(const ui::SensorProfileDialog& dialog, const char* name) const
    {
        return child<ui::QuantityEdit>(dialog, name)->lineEdit()->text();
    }
    void type(ui::SensorProfileDialog& dialog, const char* field, const QString& text) const
    {
        QLineEdit* edit = child<ui::QuantityEdit>(dialog, field)->lineEdit();
        edit->selectAll();
        QTest::keyClicks(edit, text);
    }
    QStringList listed(const ui::SensorProfileDialog& dialog) const
    {
        QStringList texts;
        const auto* list = child<QListWidget>(dialog, "profileList");
        for (int i = 0; i < list->count(); ++i) texts << list->item(i)->text();
        return texts;
    }
    // The name field of the form on show (each form has one).
    static QLineEdit* nameEdit(const ui::SensorProfileDialog& dialog)
    {
        for (QLineEdit* edit : dialog.findChildren<QLineEdit*>(QStringLiteral("nameEdit")))
            if (edit->isVisibleTo(&dialog)) return edit;
        ADD_FAILURE() << "no name field on show";
        return nullptr;
    }
    static QString text(const ui::SensorProfileDialog& dialog, const char* label)
    {
        return child<QLabel>(dialog, label)->text();
    }
    static bool enabled(const ui::SensorProfileDialog& dialog, const char* button)
    {
        return child<QPushButton>(dialog, button)->isEnabled();
    }

    QTemporaryDir m_library;
};

}  // namespace

TEST_F(SensorProfileDialogTest, ListsTheBuiltInProbeThenTheLibraryOfTheModeAndMarksUnreadableFiles)
{
    libraryFile(QStringLiteral("thick.json"), kThickerPair);
    libraryFile(QStringLiteral("short.json"), kCapacitive);
    libraryFile(QStringLiteral("broken.json"), QStringLiteral(R"({"kind": "compliance_pair", "name": "x"})"));
    ui::SensorProfileDialog dialog(m_library.path());
    dialog.setMode(QStringLiteral("palpation"));
    const QStringList palpation = listed(dialog);
    ASSERT_EQ(palpation.size(), 3);
    EXPECT_TRUE(palpation[0].startsWith(QStringLiteral("Perspex two-beam probe")));
    EXPECT_TRUE(palpation[0].contains(QStringLiteral("(built-in)")));
    EXPECT_TRUE(palpation[0].contains(QStringLiteral("in use")));
    EXPECT_EQ(palpation[1], QStringLiteral("broken.json"));
    EXPECT_EQ(palpation[2], QStringLiteral("Thick probe"));
    // The broken file says what is wrong with it, by key.
    dialog.selectPath(m_library.filePath(QStringLiteral("broken.json")));
    EXPECT_TRUE(text(dialog, "problemLabel").contains(QStringLiteral("high: missing")));
    EXPECT_FALSE(enabled(dialog, "useButton"));
    EXPECT_TRUE(enabled(dialog, "deleteButton"));

    dialog.setMode(QStringLiteral("capacitive"));
    const QStringList capacitive = listed(dialog);
    ASSERT_EQ(capacitive.size(), 3);
    EXPECT_TRUE(capacitive[0].startsWith(QStringLiteral("Uniform-strength beam No. 1")));
    EXPECT_EQ(capacitive[2], QStringLiteral("Short beam"));

    dialog.setMode(QStringLiteral("palpation"));
    dialog.selectPath(m_library.filePath(QStringLiteral("thick.json")));
    dialog.show();
    tactiscope::testing::saveScreenshot(dialog, QStringLiteral("profile-dialog"));
}

TEST_F(SensorProfileDialogTest, AFileWithANumberBeyondADoubleIsListedWithItsProblem)
{
    // Before, opening the dialog with this file in the library aborted the
    // program, every time (issue 19).
    QString overflow = kThickerPair;
    overflow.replace(QStringLiteral("\"length_m\": 0.04"), QStringLiteral("\"length_m\": 1e400"));
    libraryFile(QStringLiteral("overflow.json"), overflow);
    ui::SensorProfileDialog dialog(m_library.path());
    dialog.setMode(QStringLiteral("palpation"));
    EXPECT_TRUE(listed(dialog).contains(QStringLiteral("overflow.json")));
    dialog.selectPath(m_library.filePath(QStringLiteral("overflow.json")));
    EXPECT_TRUE(text(dialog, "problemLabel").contains(QStringLiteral("number overflow parsing '1e400'")))
        << text(dialog, "problemLabel").toStdString();
    EXPECT_FALSE(enabled(dialog, "useButton"));
}

TEST_F(SensorProfileDialogTest, ShowsTheFieldsInTheUnitsTheyAreMeasuredInWithWhatTheyComeTo)
{
    ui::SensorProfileDialog dialog(m_library.path());
    dialog.setMode(QStringLiteral("palpation"));
    // The paper's probe: 50 × 10 mm Perspex (3 GPa) beams, 3 and 1 mm thick.
    EXPECT_EQ(fieldText(dialog, "highLength"), QStringLiteral("50"));
    EXPECT_EQ(fieldText(dialog, "highThickness"), QStringLiteral("3"));
    EXPECT_EQ(fieldText(dialog, "lowThickness"), QStringLiteral("1"));
    EXPECT_EQ(fieldText(dialog, "lowModulus"), QStringLiteral("3"));
    // By hand: k = E·w·t³/(4·L³) = 3e9 · 0.01 · 27e-9 / (4 · 1.25e-4) = 1620 N/m
    // and 60 N/m for the 1 mm beam; Q tops out at 1620/60 = 27.
    const QLocale locale;
    const QString summary = text(dialog, "summaryLabel");
    EXPECT_TRUE(summary.contains(QStringLiteral("stiff %1 N/m").arg(locale.toString(1620.0, 'f', 0))))
        << summary.toStdString();
    EXPECT_TRUE(summary.contains(QStringLiteral("soft %1 N/m").arg(locale.toString(60.0, 'f', 1))))
        << summary.toStdString();
    EXPECT_TRUE(summary.contains(QStringLiteral("from 1 to %1").arg(locale.toString(27.0, 'f', 1))))
        << summary.toStdString();

    dialog.setMode(QStringLiteral("capacitive"));
    // Seed 002's beam No. 1: hydrogel electrodes of 462 µm and 1.8 kPa
    // around 15 µm of Eco-flex (83 kPa); C0 = 51.44 pF.
    EXPECT_EQ(fieldText(dialog, "beamLength"), QStringLiteral("15"));
    EXPECT_EQ(fieldText(dialog, "beamModulus"), QStringLiteral("83"));
    EXPECT_EQ(fieldText(dialog, "sheetRatio"), locale.toString(0.6));
    EXPECT_EQ(fieldText(dialog, "layer0Thickness"), QStringLiteral("462"));
    EXPECT_EQ(fieldText(dialog, "layer0Modulus"), locale.toString(1.8));
    EXPECT_EQ(fieldText(dialog, "layer1Thickness"), QStringLiteral("15"));
    EXPECT_EQ(fieldText(dialog, "c0"), locale.toString(51.44));
    EXPECT_TRUE(text(dialog, "summaryLabel").contains(QStringLiteral("pF/mN")));
}

TEST_F(SensorProfileDialogTest, AnEditIsCheckedFieldByFieldAndAgainstThePhysicsBeforeItCanBeSaved)
{
    ui::SensorProfileDialog dialog(m_library.path());
    dialog.setMode(QStringLiteral("palpation"));
    type(dialog, "highThickness", QStringLiteral("-1"));
    EXPECT_TRUE(dialog.hasUnsavedChanges());
    EXPECT_TRUE(text(dialog, "problemLabel").startsWith(QStringLiteral("Stiff beam, thickness: must be a number")));
    EXPECT_FALSE(enabled(dialog, "saveButton"));
    // A thinner stiff beam than the soft one: each field fine, the pair not.
    type(dialog, "highThickness", QStringLiteral("0.5"));
    EXPECT_TRUE(text(dialog, "problemLabel").contains(QStringLiteral("must be the stiffer one")));
    EXPECT_FALSE(enabled(dialog, "saveButton"));
    type(dialog, "highThickness", QStringLiteral("4"));
    EXPECT_TRUE(text(dialog, "problemLabel").isEmpty());
    EXPECT_TRUE(enabled(dialog, "saveButton"));
    // Unsaved changes hold the list and the mode; Revert lets go.
    EXPECT_FALSE(child<QListWidget>(dialog, "profileList")->isEnabled());
    EXPECT_FALSE(child<QComboBox>(dialog, "modeBox")->isEnabled());
    EXPECT_FALSE(enabled(dialog, "useButton"));
    child<QPushButton>(dialog, "revertButton")->click();  // a hidden dialog: a synthetic mouse may miss
    EXPECT_EQ(fieldText(dialog, "highThickness"), QStringLiteral("3"));
    EXPECT_FALSE(dialog.hasUnsavedChanges());
    EXPECT_TRUE(child<QListWidget>(dialog, "profileList")->isEnabled());
}

TEST_F(SensorProfileDialogTest, SavingTheBuiltInProbeKeepsTheChangesAsANewLibraryProfile)
{
    ui::SensorProfileDialog dialog(m_library.path());
    dialog.setMode(QStringLiteral("palpation"));
    EXPECT_EQ(child<QPushButton>(dialog, "saveButton")->text(), QStringLiteral("Save as new"));
    QLineEdit* name = nameEdit(dialog);
    name->selectAll();
    QTest::keyClicks(name, QStringLiteral("Bench probe B"));
    type(dialog, "lowThickness", QStringLiteral("1.5"));
    ASSERT_TRUE(dialog.save());

    const QString saved = m_library.filePath(QStringLiteral("bench-probe-b.json"));
    EXPECT_EQ(dialog.selectedPath(), saved);
    EXPECT_EQ(child<QPushButton>(dialog, "saveButton")->text(), QStringLiteral("Save"));
    const auto profile = core::sensors::loadSensorProfile(saved.toStdString());
    const auto& pair = std::get<core::sensors::CompliancePairProfile>(profile);
    EXPECT_EQ(pair.name, "Bench probe B");
    EXPECT_DOUBLE_EQ(pair.low.thickness_m, 0.0015);
    EXPECT_DOUBLE_EQ(pair.high.thickness_m, 0.003);
    EXPECT_DOUBLE_EQ(pair.high.youngsModulus_pa, 3e9);
    // The built-in one is untouched and still listed first.
    EXPECT_TRUE(listed(dialog)[0].startsWith(QStringLiteral("Perspex two-beam probe")));

    // Saving again writes over the same file, not a second one.
    type(dialog, "lowWidth", QStringLiteral("12"));
    ASSERT_TRUE(dialog.save());
    EXPECT_EQ(QDir(m_library.path()).entryList({QStringLiteral("*.json")}).size(), 1);
    EXPECT_DOUBLE_EQ(
        std::get<core::sensors::CompliancePairProfile>(core::sensors::loadSensorProfile(saved.toStdString()))
            .low.width_m,
        0.012);
}

TEST_F(SensorProfileDialogTest, NewStartsFromTheSelectedProfileAndTheSheetTakesLayers)
{
    ui::SensorProfileDialog dialog(m_library.path());
    dialog.setMode(QStringLiteral("capacitive"));
    QTest::mouseClick(child<QPushButton>(dialog, "newButton"), Qt::LeftButton);
    EXPECT_TRUE(dialog.hasUnsavedChanges());
    EXPECT_EQ(text(dialog, "editorTitle"), QStringLiteral("New profile (not saved yet)"));
    EXPECT_TRUE(nameEdit(dialog)->text().endsWith(QStringLiteral("(copy)")));
    // A fourth layer must be named and sized before the profile is whole.
    QTest::mouseClick(child<QPushButton>(dialog, "addLayerButton"), Qt::LeftButton);
    EXPECT_EQ(text(dialog, "problemLabel"), QStringLiteral("Sheet layer 4: give it a name"));
    QTest::keyClicks(child<QLineEdit>(dialog, "layer3Name"), QStringLiteral("encapsulation"));
    EXPECT_TRUE(text(dialog, "problemLabel").startsWith(QStringLiteral("Sheet layer 4, thickness")));
    type(dialog, "layer3Thickness", QStringLiteral("50"));
    type(dialog, "layer3Modulus", QStringLiteral("83"));
    EXPECT_TRUE(text(dialog, "problemLabel").isEmpty());
    ASSERT_TRUE(dialog.save());
    const auto profile = core::sensors::loadSensorProfile(dialog.selectedPath().toStdString());
    const auto& layers = std::get<core::sensors::CapacitiveBeamProfile>(profile).geometry.sheetLayers;
    ASSERT_EQ(layers.size(), 4u);
    EXPECT_EQ(layers[3].name, "encapsulation");
    EXPECT_DOUBLE_EQ(layers[3].thickness_m, 50e-6);
    EXPECT_DOUBLE_EQ(layers[3].youngsModulus_pa, 83e3);
}

TEST_F(SensorProfileDialogTest, ImportCopiesAGoodFileIntoTheLibraryUnderItsModeAndRefusesOthers)
{
    QTemporaryDir elsewhere;
    const QString capacitive = elsewhere.filePath(QStringLiteral("from-a-colleague.json"));
    writeText(capacitive, kCapacitive);
    const QString bad = elsewhere.filePath(QStringLiteral("bad.json"));
    writeText(bad, QString(kThickerPair).replace(QStringLiteral("0.004"), QStringLiteral("-0.004")));
    const QString specimen = elsewhere.filePath(QStringLiteral("specimen.json"));
    writeText(specimen, QStringLiteral(R"({"kind": "cantilever", "name": "S", "length_m": 0.1, "width_m": 0.01, )"
                                       R"("thickness_m": 0.002, "youngs_modulus_pa": 3e9})"));
    ui::SensorProfileDialog dialog(m_library.path());
    dialog.setMode(QStringLiteral("palpation"));

    EXPECT_FALSE(dialog.importProfile(bad));
    EXPECT_TRUE(text(dialog, "messageLabel").contains(QStringLiteral("high.thickness_m: must be a positive number")));
    EXPECT_FALSE(dialog.importProfile(specimen));
    EXPECT_TRUE(text(dialog, "messageLabel").contains(QStringLiteral("single cantilever")));
    EXPECT_TRUE(QDir(m_library.path()).isEmpty());

    ASSERT_TRUE(dialog.importProfile(capacitive));
    EXPECT_EQ(dialog.mode(), QStringLiteral("capacitive"));
    EXPECT_EQ(dialog.selectedPath(), m_library.filePath(QStringLiteral("short-beam.json")));
    EXPECT_EQ(fieldText(dialog, "c0"), QStringLiteral("40"));
}

TEST_F(SensorProfileDialogTest, ExportWritesTheProfileShownAsTheCoreReadsIt)
{
    QTemporaryDir elsewhere;
    const QString path = elsewhere.filePath(QStringLiteral("probe.json"));
    ui::SensorProfileDialog dialog(m_library.path());
    dialog.setMode(QStringLiteral("palpation"));
    ASSERT_TRUE(dialog.exportProfile(path));
    const auto exported = core::sensors::loadSensorProfile(path.toStdString());
    const auto builtIn = ui::readProfile(ui::builtInProfilePath(QStringLiteral("palpation")));
    EXPECT_EQ(core::sensors::toJson(exported), core::sensors::toJson(builtIn));
}

TEST_F(SensorProfileDialogTest, UseMakesTheSelectedProfileActiveUnlessARecordingHoldsIt)
{
    const QString thick = libraryFile(QStringLiteral("thick.json"), kThickerPair);
    ui::SensorProfileDialog dialog(m_library.path());
    QSignalSpy changed(&dialog, &ui::SensorProfileDialog::activeProfileChanged);
    dialog.setMode(QStringLiteral("palpation"));
    dialog.selectPath(thick);
    dialog.setLocked(true, QStringLiteral("fixed while recording"));
    EXPECT_FALSE(enabled(dialog, "useButton"));
    EXPECT_FALSE(dialog.useSelected());
    EXPECT_TRUE(text(dialog, "activeLabel").contains(QStringLiteral("fixed while recording")));
    EXPECT_EQ(changed.count(), 0);

    dialog.setLocked(false);
    ASSERT_TRUE(dialog.useSelected());
    ASSERT_EQ(changed.count(), 1);
    EXPECT_EQ(changed.at(0).at(0).toString(), QStringLiteral("palpation"));
    EXPECT_EQ(ui::activeProfile(QStringLiteral("palpation")).path, thick);
    EXPECT_TRUE(text(dialog, "activeLabel").contains(QStringLiteral("Thick probe")));
    EXPECT_TRUE(listed(dialog)[1].contains(QStringLiteral("in use")));
    // The profile in use is not deleted from under the mode.
    EXPECT_FALSE(enabled(dialog, "deleteButton"));
    // Saving it with new values changes the mode's probe too.
    type(dialog, "lowThickness", QStringLiteral("1.6"));
    ASSERT_TRUE(dialog.save());
    EXPECT_EQ(changed.count(), 2);
}

TEST_F(SensorProfileDialogTest, DeleteAsksFirstAndRemovesOnlyOnYes)
{
    const QString thick = libraryFile(QStringLiteral("thick.json"), kThickerPair);
    ui::SensorProfileDialog dialog(m_library.path());
    dialog.setMode(QStringLiteral("palpation"));
    dialog.selectPath(thick);
    const auto answer = [&](QMessageBox::StandardButton button) {
        dialog.requestDelete();
        auto* box = child<QMessageBox>(dialog, "deleteProfileBox");
        ASSERT_NE(box, nullptr);
        QTest::mouseClick(box->button(button), Qt::LeftButton);
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
    };
    answer(QMessageBox::Cancel);
    EXPECT_TRUE(QFileInfo::exists(thick));
    answer(QMessageBox::Yes);
    EXPECT_FALSE(QFileInfo::exists(thick));
    EXPECT_EQ(listed(dialog).size(), 1);
    EXPECT_FALSE(enabled(dialog, "deleteButton"));  // the built-in one
}

// Both beams' modulus doubled: the same strains mean twice the forces, so
// k_H and k_L double, Q does not change, and k_o = k_H·k_L·(1 − Q)/(Q·k_L −
// k_H) doubles — the simulator's 117 N/m specimen reads 234 N/m.
TEST_F(SensorProfileDialogTest, AProbeChosenWhileStreamingReadsTheNextPressesAndGoesIntoTheRecording)
{
    QDir(ui::ProfileLibrary::defaultDirectory()).removeRecursively();
    const QString stiffer = m_library.filePath(QStringLiteral("stiffer.json"));
    writeText(stiffer, QStringLiteral(R"({"kind": "compliance_pair", "name": "Perspex at 6 GPa", )"
                                      R"("high": {"length_m": 0.05, "width_m": 0.01, "thickness_m": 0.003, )"
                                      R"("youngs_modulus_pa": 6e9}, )"
                                      R"("low": {"length_m": 0.05, "width_m": 0.01, "thickness_m": 0.001, )"
                                      R"("youngs_modulus_pa": 6e9}})"));
    const QString store = m_library.filePath(QStringLiteral("s.tactiscope"));
    ui::MainWindow window;
    window.setStorePath(store);
    window.resize(1400, 900);
    window.setMode(tactiscope::core::Mode::Palpation);
    window.station().connectSource(tactiscope::testing::liveSimulator("palpation"));
    window.show();
    ui::SensorProfileDialog* dialog = window.showProfiles();
    EXPECT_EQ(dialog->mode(), QStringLiteral("palpation"));
    ASSERT_TRUE(dialog->importProfile(stiffer));
    ASSERT_TRUE(dialog->useSelected());
    auto* probe = child<QLabel>(*window.findChild<ui::PalpationView*>(), "probeLabel");
    EXPECT_TRUE(probe->text().contains(QStringLiteral("Perspex at 6 GPa")));

    ASSERT_TRUE(window.startRecording());
    // A session keeps its sensor: the dialog will not change it now.
    dialog->selectPath(ui::builtInProfilePath(QStringLiteral("palpation")));
    EXPECT_FALSE(enabled(*dialog, "useButton"));
    auto* table = child<QTableWidget>(*window.findChild<ui::PalpationView*>(), "pressTable");
    ASSERT_TRUE(tactiscope::testing::waitFor([&] { return table->rowCount() >= 2; }, 12000));
    window.stopRecording();
    EXPECT_TRUE(enabled(*dialog, "useButton"));

    const double truth = 2.0 * devices::simulator::PalpationParameters{}.objectStiffness_n_per_m;
    for (int row = 0; row < table->rowCount(); ++row)
        EXPECT_NEAR(QLocale().toDouble(table->item(row, 1)->text()), truth, 0.05 * truth) << row;
    core::storage::SessionStore sessions(store.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto recorded =
        core::sensors::parseSensorProfile(sessions.sessions().front().metadata.profileJson, "session");
    EXPECT_EQ(std::get<core::sensors::CompliancePairProfile>(recorded).high.youngsModulus_pa, 6e9);
    QDir(ui::ProfileLibrary::defaultDirectory()).removeRecursively();
}

// The forms edit a probe's mechanics; the channel roles its file gave pass
// through an edit unchanged (they are the device panel's to change).
TEST_F(SensorProfileDialogTest, AnEditKeepsTheChannelRolesTheProfileGave)
{
    auto pair = std::get<core::sensors::CompliancePairProfile>(*core::sensors::builtInProfile(core::Mode::Palpation));
    pair.roles = core::parseRoleAssignment("ch1=stiff-beam,ch2=soft-beam,ch3=displacement");
    ui::CompliancePairForm pairForm;
    pairForm.setProfile(pair);
    pairForm.nameEdit()->setText(QStringLiteral("renamed"));
    const auto edited = pairForm.result();
    ASSERT_TRUE(edited.profile) << edited.problem.toStdString();
    EXPECT_EQ(core::sensors::profileRoles(*edited.profile), pair.roles);

    auto beam = std::get<core::sensors::CapacitiveBeamProfile>(*core::sensors::builtInProfile(core::Mode::Capacitive));
    beam.roles = core::parseRoleAssignment("C=capacitance");
    ui::CapacitiveBeamForm beamForm;
    beamForm.setProfile(beam);
    const auto kept = beamForm.result();
    ASSERT_TRUE(kept.profile) << kept.problem.toStdString();
    EXPECT_EQ(core::sensors::profileRoles(*kept.profile), beam.roles);
}
