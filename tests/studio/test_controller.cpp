// The Controller dock against `k528 serve` on a socat pty pair (the RS485
// line): connect through the Modbus RTU plugin, the live monitor and the
// line's state, the workstation's views on the real controller (the seam of
// controller/controller.h), pull into a new database revision, push a file
// after its preview, cancel a push (nothing half-committed), disconnect.
#include "controller/controller_dock.h"
#include "controller/link_controller.h"
#include "controller/simulated_controller.h"
#include "k923/k923_widget.h"
#include "language.h"
#include "machine/status_views.h"
#include "main_window.h"
#include "monitor/program_monitor.h"
#include "profile/text_format.h"
#include "pty_line.h"
#include "rig/widgets.h"
#include "session/machine_source.h"
#include "test_util.h"

#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QProgressBar>
#include <QPushButton>
#include <QPlainTextEdit>
#include <QProcess>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QScrollArea>
#include <QtTest>
#include <memory>

using namespace k528;
using namespace k528::studio;
using testutil::finished;

class TestController : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    ptytest::PtyPair line_;
    ptytest::Serve serve_;

    static QString bigProgram(int number, int frames) {
        QString t = QStringLiteral("[program %1]\n%L%1 (long)\n").arg(number);
        for (int i = 1; i <= frames; ++i)
            t += QStringLiteral("N%1 G1 X%2 FX100\n").arg(i).arg(i % 50);
        return t + "[end program]\n";
    }

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("K528StudioTest");
        QSettings().clear();
        QVERIFY(setLanguage("en"));
        QVERIFY(dir_.isValid());
        qputenv("K528_DB", dir_.filePath("shop.db").toUtf8());
        qputenv("K528_PLUGIN_PATH", QFileInfo(QStringLiteral(K528_RTU_PLUGIN)).absolutePath().toUtf8());
        QVERIFY(line_.start(dir_.path(), "ctl"));
        // training-lathe in F7 «РАБОТА С ПЭВМ» (the keys of link.line).
        QVERIFY2(serve_.start(line_.a(), {"--profile", "training-lathe", "--keys", "F7 1 1 1 1 ENTER DOWN DOWN ENTER"}),
                 serve_.said().constData());
    }
    void cleanupTestCase() {
        serve_.stop();
        line_.stop();
    }

    // Controller > Connect asks for the line (no connection to the first port
    // the system lists); a failed connection says why, not «Connecting…».
    void connectAsksForTheLineAndSaysAFailure() {
        MainWindow w(loadMachine("training-lathe"));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* dock = w.findChild<ControllerDock*>("dock.controller");
        QVERIFY(dock);
        dock->hide();
        auto* connectAction = w.findChild<QAction*>("action.controller.connect");
        QVERIFY(connectAction && connectAction->isEnabled());
        connectAction->trigger();
        QVERIFY(dock->isVisible());
        QVERIFY(!dock->link()); // nothing opened
        QVERIFY(dock->lineLabel()->text().contains("port"));
        QTRY_COMPARE(QApplication::focusWidget(), static_cast<QWidget*>(dock->portBox()));
        dock->portBox()->setEditText(dir_.filePath("no-such-line"));
        QSignalSpy connected(dock, &ControllerDock::connectedChanged);
        dock->connectLine();
        QVERIFY(dock->lineLabel()->text().startsWith("Connecting"));
        QVERIFY(finished(connected, 10000));
        QVERIFY(!connected.first().first().toBool());
        QVERIFY2(dock->lineLabel()->text().startsWith("No connection on"), qPrintable(dock->lineLabel()->text()));
        QVERIFY(!dock->link());
    }

    // A failed connection says the port's or the socket's failure in the
    // window's language (from Qt's error code: «порт не найден», «соединение
    // отклонено», not Qt's English); each window is saved as a picture.
    void aConnectFailureInTheWindowsLanguage() {
        struct Case {
            const char* lang;
            const char* plugin;
            QString port;
            QString says;
        };
        const Case cases[] = {
            // A long port path (as /dev/serial/by-id/ names them) wraps in the dock, not cut at its edge.
            {"en", "modbus-rtu", dir_.filePath("serial/by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0"),
             QStringLiteral(": no such port")},
            {"ru", "modbus-rtu", dir_.filePath("serial/by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0"),
             QStringLiteral(": порт не найден")},
            {"en", "modbus-tcp", QStringLiteral("127.0.0.1:1"), QStringLiteral(": connection refused")},
            {"ru", "modbus-tcp", QStringLiteral("127.0.0.1:1"), QStringLiteral(": соединение отклонено")},
        };
        for (const Case& c : cases) {
            QVERIFY(setLanguage(c.lang));
            MainWindow w(loadMachine("training-lathe"));
            w.resize(1366, 768);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            auto* dock = w.findChild<ControllerDock*>("dock.controller");
            QVERIFY(dock);
            dock->show();
            dock->raise(); // its tab in front, for the picture
            auto* plugin = w.findChild<QComboBox*>("controller.plugin");
            QVERIFY(plugin);
            int index = -1;
            for (int i = 0; i < plugin->count(); ++i)
                if (plugin->itemText(i).contains(QLatin1String(c.plugin)))
                    index = i;
            if (index < 0)
                QSKIP(qPrintable(QStringLiteral("no %1 plugin here").arg(c.plugin)));
            plugin->setCurrentIndex(index);
            dock->portBox()->setEditText(c.port);
            QSignalSpy connected(dock, &ControllerDock::connectedChanged);
            dock->connectLine();
            QVERIFY(finished(connected, 10000));
            QVERIFY(!connected.first().first().toBool());
            const QString said = dock->lineLabel()->text();
            QVERIFY2(said.endsWith(c.says), qPrintable(said));
            QVERIFY2(!said.contains(QLatin1String("No such")) && !said.contains(QLatin1String("Connection refused")),
                     qPrintable(said));
            // The whole message is the tooltip; the label keeps within the dock's width.
            QVERIFY2(dock->lineLabel()->toolTip().contains(c.port), qPrintable(dock->lineLabel()->toolTip()));
            // The message in view, for the picture.
            for (QWidget* up = dock->lineLabel()->parentWidget(); up; up = up->parentWidget())
                if (auto* scroll = qobject_cast<QScrollArea*>(up)) {
                    scroll->ensureWidgetVisible(dock->lineLabel());
                    break;
                }
            QApplication::processEvents();
            const QLabel* label = dock->lineLabel();
            const QRect inDock(label->mapTo(dock, QPoint(0, 0)), label->size());
            QVERIFY2(inDock.left() >= 0 && inDock.right() < dock->width(), qPrintable(QStringLiteral("%1 wide in a dock of %2")
                                                                    .arg(inDock.right()).arg(dock->width())));
            QVERIFY2(label->minimumSizeHint().width() <= label->width(),
                     qPrintable(QStringLiteral("needs %1 of %2").arg(label->minimumSizeHint().width()).arg(label->width())));
            K528_VERIFY_SHOT(w.grab(),
                             QStringLiteral("connect_failure_%1_%2.png").arg(QLatin1String(c.plugin), QLatin1String(c.lang)));
        }
        QVERIFY(setLanguage("en"));
    }

    // The window closed while it shows the real controller and a pull runs
    // (a failed check leaves a test function the same way): the line is
    // closed before the views go, the transfer aborted, and the next window
    // opens the same line at once.
    void windowClosedWhileLinkedAndBusy() {
        for (int round = 0; round < 2; ++round) {
            auto w = std::make_unique<MainWindow>(loadMachine("training-lathe"));
            w->show();
            QVERIFY(QTest::qWaitForWindowExposed(w.get()));
            auto* dock = w->findChild<ControllerDock*>("dock.controller");
            dock->portBox()->setEditText(line_.b());
            QSignalSpy connected(dock, &ControllerDock::connectedChanged);
            dock->connectLine();
            QVERIFY(finished(connected, 10000));
            QVERIFY2(connected.first().first().toBool(), qPrintable(dock->lastMessage()));
            QVERIFY(w->viewedController() == dock->link());
            if (round == 0) {
                dock->pullIntoDatabase();
                QTRY_VERIFY_WITH_TIMEOUT(dock->progressBar()->isVisible() || dock->link()->busy(), 5000);
            }
            w.reset();
        }
    }

    void controllerDockOnTheLine() {
        MainWindow w(loadMachine("training-lathe"));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* dock = w.findChild<ControllerDock*>("dock.controller");
        QVERIFY(dock);
        QVERIFY(w.findChild<QMenu*>("menu.controller"));
        dock->show();
        dock->raise();
        QVERIFY(w.viewedController() == w.simulatedController());

        // Connect: the plugin was found, the port typed (a pty is not listed).
        QVERIFY2(dock->findChild<QComboBox*>("controller.plugin")->count() >= 1, qPrintable(dock->lineLabel()->text()));
        dock->portBox()->setEditText(line_.b());
        QSignalSpy connected(dock, &ControllerDock::connectedChanged);
        dock->connectLine();
        QVERIFY(finished(connected, 10000));
        QVERIFY2(connected.first().first().toBool(), qPrintable(dock->lastMessage()));
        QVERIFY(dock->link() && dock->link()->isOpen());
        QTRY_VERIFY_WITH_TIMEOUT(dock->monitorLabel()->text().contains("РАБОТА С ПЭВМ"), 5000);
        QVERIFY(dock->monitorLabel()->text().contains("F7"));
        QVERIFY(dock->monitorLabel()->text().contains("K12"));
        QTRY_VERIFY_WITH_TIMEOUT(dock->lineLabel()->text().contains(" answers"), 5000);
        QVERIFY(dock->lineLabel()->text().contains("round trip"));

        // The workstation's views show the real controller now.
        QVERIFY(w.viewedController() == dock->link());
        QCOMPARE(dock->link()->state().mode, 7);
        QTRY_VERIFY_WITH_TIMEOUT(w.axesView()->table()->item(0, 1)->text() != QString(), 3000);
        QCOMPARE(w.axesView()->table()->item(0, 6)->text(), QString()); // no DAC over the link
        // Keys: the map has them read-only; the window says so instead of sending.
        emit w.k923()->keyPressed(panel::KeyPress{panel::Key::F2, false});
        QVERIFY(w.statusBar()->currentMessage().contains("takes no keys"));

        // The dock says how busy the live monitor keeps the line (what share
        // it may take is a bench figure: bench/run link, not a wall-clock
        // sample here on a shared machine).
        QTRY_VERIFY_WITH_TIMEOUT(dock->link()->lineInfo().busyPercent > 0 &&
                                     dock->link()->lineInfo().wire.transactions > 5,
                                 10000);
        QTRY_VERIFY_WITH_TIMEOUT(dock->lineLabel()->text().contains("busy"), 5000);

        // Screenshot of the dock connected to `k528 serve`.
        dock->setFloating(true);
        dock->resize(460, 760);
        QApplication::processEvents();
        K528_VERIFY_SHOT(dock->grab(), QStringLiteral("controller_dock.png"));
        dock->setFloating(false);

        // Pull into a new database revision of the machine.
        QSignalSpy done(dock, &ControllerDock::transferFinished);
        dock->pullIntoDatabase();
        QVERIFY(finished(done, 30000));
        QVERIFY2(done.takeFirst().first().toBool(), qPrintable(dock->lastMessage()));
        const int rev = dock->lastRevision();
        QVERIFY2(rev > 0, qPrintable(dock->lastMessage()));
        // The Program tab lists the controller's programs.
        QVERIFY(w.programMonitor()->programChoice()->count() > 1);
        const profile::MachineProfile pulled = loadMachine("training-lathe").profile;
        QVERIFY(!pulled.programs.empty());

        // Push a file: program 42 new, R5 changed; the preview shows both.
        profile::MachineProfile file = pulled;
        file.r[5] = 4321;
        const QString fileText = QString::fromStdString(profile::writeMachineText(file));
        QString with42 = fileText;
        with42.insert(with42.indexOf("[program "), bigProgram(42, 12));
        const QString path = testutil::writeFile(dir_, "push.k528m", with42);
        QSignalSpy preview(dock, &ControllerDock::previewShown);
        dock->pushFile(path);
        QVERIFY(finished(preview, 30000));
        QVERIFY(dock->preview());
        const QString diff = dock->preview()->findChild<QPlainTextEdit*>("controller.pushPreview.diff")->toPlainText();
        QVERIFY2(diff.contains("L42") && diff.contains("4321"), qPrintable(diff));
        K528_VERIFY_SHOT(dock->preview()->grab(), QStringLiteral("controller_push_preview.png"));
        dock->preview()->accept();
        QVERIFY(finished(done, 60000));
        QVERIFY2(done.takeFirst().first().toBool(), qPrintable(dock->lastMessage()));
        QVERIFY2(dock->lastMessage().contains("L42"), qPrintable(dock->lastMessage()));

        // Cancel a long push: the long program is not committed half-way.
        QString big = fileText;
        big.insert(big.indexOf("[program "), bigProgram(60, 900));
        preview.clear();
        dock->pushFile(testutil::writeFile(dir_, "big.k528m", big));
        QVERIFY(finished(preview, 30000));
        QVERIFY(dock->preview());
        dock->preview()->accept();
        QTRY_VERIFY_WITH_TIMEOUT(dock->progressBar()->format().contains("program"), 20000);
        QVERIFY(dock->cancelButton()->isEnabled());
        dock->cancelTransfer();
        QVERIFY(finished(done, 30000));
        QVERIFY2(!done.takeFirst().first().toBool(), qPrintable(dock->lastMessage()));
        QVERIFY2(dock->lastMessage().contains("cancelled"), qPrintable(dock->lastMessage()));

        // What the controller holds now: L42 as sent, L60 absent (never half of it).
        dock->pullIntoDatabase();
        QVERIFY(finished(done, 30000));
        QVERIFY2(done.takeFirst().first().toBool(), qPrintable(dock->lastMessage()));
        QVERIFY(dock->lastRevision() > rev);
        const profile::MachineProfile now = loadMachine("training-lathe").profile;
        QVERIFY(now.programs.count(42));
        QVERIFY(!now.programs.count(60));
        QCOMPARE(now.r.at(5), std::int64_t{4321});

        // Disconnect: the views go back to the simulated controller.
        dock->disconnectLine();
        QVERIFY(!dock->link());
        QVERIFY(w.viewedController() == w.simulatedController());
    }
};

QTEST_MAIN(TestController)
#include "test_controller.moc"
