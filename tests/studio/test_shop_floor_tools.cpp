// The setter's tools beside the program: the cutting-data calculator (beside
// the C-constant one), the trial part's correction of a tool's offset kept
// as the machine's preset (the R-parameter dock), and teach-in in the editor
// (the viewed controller's position as a frame or into a preset R-parameter).
#include "constants/constants_dock.h"
#include "rig/widgets.h"
#include "constants/cutting_dialog.h"
#include "constants/machine_store.h"
#include "controller/simulated_controller.h"
#include "editor/editor_tab.h"
#include "editor/teach_in.h"
#include "editor/program_editor.h"
#include "editing/teach.h"
#include "program/diagnostic.h"
#include "units/units.h"
#include "profile/builtin.h"
#include "rparams/rparams_dock.h"
#include "rparams/trial_dialog.h"
#include "session/simulation_session.h"
#include "language.h"
#include "rig/studio_rig.h"

#include <QDir>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QSettings>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

using namespace k528;
using namespace k528::studio;
using testrig::latheNamed;
using testrig::SimulatedSeam;

class TestShopFloorTools : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        qputenv("K528_DB", dir_.filePath("k528.db").toUtf8());
        QCoreApplication::setOrganizationName("K528StudioTestShopFloorTools");
        QSettings().clear();
    }

    void cuttingData() {
        const profile::MachineProfile grinder = profile::builtin("grinder-205");
        CuttingDataDialog d(grinder, nullptr);
        d.cuttingSpeed()->setValue(120);
        d.diameter()->setValue(40);
        QVERIFY2(d.spindleResult()->text().contains("955"), qPrintable(d.spindleResult()->text()));
        d.feedPerRev()->setValue(0.2);
        QVERIFY2(d.feedResult()->text().contains("191"), qPrintable(d.feedResult()->text()));
        // R207 of the grinder's presets: Ø18.5 at 30000 rev/min = 29.06 m/s.
        QCOMPARE(d.r207()->value(), 18500.0);
        d.wheelRpm()->setValue(30000);
        QVERIFY2(d.wheelResult()->text().contains("29") && d.wheelResult()->text().contains("18"),
                 qPrintable(d.wheelResult()->text()));
        d.r207()->setValue(0);
        QVERIFY(d.wheelResult()->text().startsWith(QStringLiteral("—")));
    }

    void cuttingDataBesideTheCalculator() {
        SimulatedSeam sim(latheNamed("lathe-cutting"));
        ConstantsPane pane(sim.seam, sim.session.simulation().profile());
        auto* b = pane.findChild<QToolButton*>("constants.cuttingData");
        QVERIFY(b);
        b->click();
        auto* d = pane.findChild<CuttingDataDialog*>("constants.cuttingDialog");
        QVERIFY(d);
        QVERIFY(d->isVisible());
        d->close();
    }

    // Ø40.06 turned with tool 2 for Ø40.00: R102 1200 -> 1140, kept as the
    // machine's next revision with the measurement as its note, and set in
    // the controller.
    void trialPartKeepsTheOffset() {
        SimulatedSeam sim(latheNamed("lathe-trial"));
        RParamsPane pane(sim.seam, sim.session.simulation().profile());
        TrialPartDialog* d = pane.trialPartDialog();
        // Opened: both sizes 0, nothing computed from them, nothing to keep.
        QCOMPARE(d->findChild<QDoubleSpinBox*>("trial.measured")->value(), 0.0);
        QCOMPARE(d->findChild<QDoubleSpinBox*>("trial.drawing")->value(), 0.0);
        QVERIFY(!d->correction());
        QVERIFY(!d->keepButton()->isEnabled());
        QVERIFY2(d->result()->text().startsWith("Enter the size"), qPrintable(d->result()->text()));
        // As opened, in each language (to be looked at).
        const QString shots = QStringLiteral(K528_BINARY_DIR "/screenshots");
        QDir().mkpath(shots);
        for (const QString lang : {"en", "ru"}) {
            QVERIFY(setLanguage(lang));
            TrialPartDialog* fresh = pane.trialPartDialog();
            fresh->show();
            QTest::qWait(50);
            K528_VERIFY_SHOT(fresh->grab(), "trial-dialog-" + lang + ".png");
            if (lang == "ru")
                QVERIFY2(fresh->result()->text().startsWith(QStringLiteral("Введите")), qPrintable(fresh->result()->text()));
            fresh->close();
        }
        QVERIFY(setLanguage("en"));
        d->setInputs(2, true, 40.06, 40.00);
        QVERIFY(d->correction());
        QCOMPARE(d->correction()->rNumber, 102);
        QCOMPARE(d->correction()->newValue, std::int64_t(1140));
        QVERIFY2(d->result()->text().contains("1140"), qPrintable(d->result()->text()));
        QVERIFY(d->keepButton()->isEnabled());
        d->keepButton()->click();
        QCOMPARE(MachineStore(sim.session.simulation().profile()).current().r.at(102), std::int64_t(1140));
        QCOMPARE(sim.session.controller().r(102), 1140);
        QVERIFY2(pane.statusText().contains("trial part: T2 X measured 40.060 for 40.000"), qPrintable(pane.statusText()));
        // Z of the same tool: R103.
        TrialPartDialog* z = pane.trialPartDialog();
        z->setInputs(2, false, -49.95, -50.00);
        QCOMPARE(z->correction()->rNumber, 103);
        QCOMPARE(z->correction()->newValue, std::int64_t(-3550));
        // No error, no change: nothing to keep.
        z->setInputs(2, false, -50, -50);
        QVERIFY(!z->keepButton()->isEnabled());
        QVERIFY2(z->result()->text().contains("(offset 0.000 mm)"), qPrintable(z->result()->text())); // not «-0.000»
        z->close();
    }

    void teachIn() {
        SimulatedSeam sim(latheNamed("lathe-teach"));
        EditorTab tab(&sim.seam);
        tab.newFile();
        ProgramEditor* ed = tab.currentEditor();
        ed->setText("%L1\nN5 G90 G0 X100 Z50\nN10 M30\n");
        ed->setCursorPosition(1, 0);
        sim.session.advance(50);
        const auto& axes = sim.seam.current().state().axes;
        const double x = units::discToMm(axes[0].currentDisc, axes[0].scale);
        QString taught;
        QVERIFY(tab.teachIn()->teachPosition(&taught));
        QVERIFY2(taught.startsWith("N6 X"), qPrintable(taught));
        QVERIFY(taught.contains(QString::fromStdString(editing::teachFrame(0, x, std::nullopt)).mid(1)));
        QCOMPARE(ed->text(2).trimmed(), taught);
        ed->validateNow();
        QVERIFY(!program::hasErrors(ed->diagnostics()));
        // Into R220 (MX: the machine coordinate of X): a new frame, then the
        // same line again when the cursor is on it.
        QVERIFY(tab.teachIn()->teachIntoR(220, &taught));
        QCOMPARE(taught, QStringLiteral("N7 R220=%1").arg(axes[0].machineDisc));
        const int lines = ed->lines();
        QVERIFY(tab.teachIn()->teachIntoR(220, &taught));
        QCOMPARE(ed->lines(), lines); // replaced, not added
        QCOMPARE(taught, QStringLiteral("N7 R220=%1").arg(axes[0].machineDisc));
        auto* menu = tab.findChild<QMenu*>("menu.editor.teachR");
        QVERIFY(menu);
        QVERIFY(menu->actions().size() >= 8);
    }
};

QTEST_MAIN(TestShopFloorTools)
#include "test_shop_floor_tools.moc"
