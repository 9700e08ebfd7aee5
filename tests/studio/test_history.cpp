// The message history dock (app/studio/history): a raised alarm appears with
// its number and text, «Acknowledge (ESC)» acknowledges it as the K923's ESC
// does and the row says when and how, search and source filter, CSV export on
// its worker thread, the history survives closing and reopening the
// database, the main window has the dock; a screenshot of the dock.
#include "catalog/messages.h"
#include "rig/widgets.h"
#include "history/history_dock.h"
#include "history/history_model.h"
#include "history/history_service.h"
#include "main_window.h"
#include "profile/builtin.h"
#include "controller/simulated_controller.h"
#include "session/simulation_session.h"

#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QtTest>

using namespace k528;
using namespace k528::studio;

namespace {

profile::MachineProfile lathe() {
    profile::MachineProfile p = profile::builtin("training-lathe");
    p.setC(8, 1);
    p.setC(60, 1);
    return p;
}

int rowOf(const HistoryModel& m, db::MessageSource s, int number) {
    for (int i = 0; i < m.rowCount(); ++i)
        if (m.record(i).source == s && m.record(i).number == number)
            return i;
    return -1;
}

} // namespace

class TestHistory : public QObject {
    Q_OBJECT
private slots:
    void raiseAcknowledgeExportReopen() {
        QTemporaryDir dir;
        const QString dbPath = dir.filePath("k528.db");
        std::int64_t total = 0;
        {
            SimulationSession session(lathe());
            SimulatedController seamSim(session);
            HistoryService service(&seamSim, dbPath);
            QVERIFY2(service.isOpen(), qPrintable(service.error()));
            HistoryView view(service);
            view.resize(1200, 360);
            view.show();
            session.simulation().pressEmergencyStop();
            session.advance(50);
            service.flush();
            HistoryModel& m = *view.model();
            const int r9 = rowOf(m, db::MessageSource::Positioner, 9);
            QVERIFY(r9 >= 0);
            QCOMPARE(m.data(m.index(r9, HistoryModel::Code)).toString(), QString("9"));
            QVERIFY(!m.record(r9).acknowledged());
            QCOMPARE(m.record(r9).text, std::string(catalog::positionerMessage(9).textRu));
            QCOMPARE(m.data(m.index(r9, HistoryModel::Acknowledged)).toString(),
                     HistoryModel::tr("not yet"));
            // The cause goes; the dock's ESC acknowledges it.
            session.simulation().releaseEmergencyStop();
            session.advance(100);
            service.flush();
            QVERIFY(session.controller().alarmRegistry().latched(9));
            QTest::mouseClick(view.acknowledgeButton(), Qt::LeftButton);
            QVERIFY(!session.controller().alarmRegistry().latched(9));
            const int a9 = rowOf(m, db::MessageSource::Positioner, 9);
            QVERIFY(m.record(a9).acknowledged());
            QCOMPARE(m.record(a9).ackHow, std::string("esc-dock"));
            QVERIFY(m.record(a9).clearedMs.has_value());
            QVERIFY(m.data(m.index(a9, HistoryModel::Acknowledged))
                        .toString()
                        .contains(HistoryModel::howText("esc-dock")));
            // Search: by number, by text; nothing for a text no message has.
            view.searchBox()->setText("9");
            view.applyFilter();
            QVERIFY(rowOf(m, db::MessageSource::Positioner, 9) >= 0);
            view.searchBox()->setText("no such message text");
            view.applyFilter();
            QCOMPARE(m.rowCount(), 0);
            view.searchBox()->clear();
            view.applyFilter();
            total = m.total();
            QVERIFY(total >= 1);
            QCOMPARE(m.rowCount(), static_cast<int>(total));
            // CSV export on its thread.
            QSignalSpy done(&view, &HistoryView::exported);
            const QString csv = dir.filePath("messages.csv");
            QVERIFY(view.exportCsv(csv, true));
            QVERIFY(done.wait(10000));
            QCOMPARE(done.front().at(2).toString(), QString());
            QCOMPARE(done.front().at(1).toLongLong(), total);
            QFile f(csv);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const QList<QByteArray> lines = f.readAll().split('\n');
            QCOMPARE(lines.front().trimmed(), QByteArray::fromStdString(db::MessageLog::csvHeader()));
            QCOMPARE(lines.size() - 2, static_cast<int>(total)); // header, rows, final empty
            QVERIFY(f.readAll().isEmpty());
            // The screenshot of the dock.
            view.searchBox()->setText("");
            QTest::qWait(50);
            K528_VERIFY_SHOT(view.grab(), QStringLiteral("history-dock.png"));
        }
        // Closed and reopened: the same rows, the acknowledgement kept.
        SimulationSession session(lathe());
        SimulatedController seamSim(session);
        HistoryService service(&seamSim, dbPath);
        HistoryView view(service);
        HistoryModel& m = *view.model();
        QVERIFY(m.total() >= total);
        bool found = false;
        for (int i = 0; i < m.rowCount(); ++i)
            if (m.record(i).source == db::MessageSource::Positioner && m.record(i).number == 9 &&
                m.record(i).ackHow == "esc-dock")
                found = true;
        QVERIFY(found);
    }

    // A database that cannot be used: said in the dock, the machine runs on.
    void unusableDatabaseIsSaid() {
        QTemporaryDir dir;
        const QString bad = dir.filePath("not-a-db.db");
        QFile f(bad);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QByteArray(4096, 'x'));
        f.close();
        const QByteArray before = [&] { QFile g(bad); g.open(QIODevice::ReadOnly); return g.readAll(); }();
        SimulationSession session(lathe());
        SimulatedController seamSim(session);
        HistoryService service(&seamSim, bad);
        QVERIFY(!service.isOpen());
        QVERIFY(!service.error().isEmpty());
        HistoryView view(service);
        session.simulation().pressEmergencyStop();
        session.advance(50);
        service.flush();
        QCOMPARE(view.model()->rowCount(), 0);
        QVERIFY(view.findChild<QLabel*>("history.status")->text().contains(service.error()));
        QFile g(bad);
        QVERIFY(g.open(QIODevice::ReadOnly));
        QVERIFY(g.readAll() == before); // never changed
    }

    void mainWindowHasTheDock() {
        MainWindow w;
        auto* dock = w.findChild<QDockWidget*>("dock.history");
        QVERIFY(dock);
        QVERIFY(dock->findChild<HistoryView*>());
    }
};

QTEST_MAIN(TestHistory)
#include "test_history.moc"
