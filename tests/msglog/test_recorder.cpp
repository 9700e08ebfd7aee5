// The message recorder: what the positioner raises on the simulated machine
// appears in the message history with its number, text, program and line,
// its cause going and its acknowledgement (when and how) are recorded, the
// history survives closing and reopening the database, and a bad batch is
// refused whole.
#include "catalog/messages.h"
#include "profile/english.h"
#include "db/message_log.h"
#include "engine/run.h"
#include "machine/run.h"
#include "machine/simulation.h"
#include "msglog/recorder.h"
#include "profile/builtin.h"
#include "program/parser.h"

#include <QTemporaryDir>
#include <QtTest>
#include <filesystem>
#include <fstream>
#include <iterator>

using namespace k528;
using db::MessageEvent;
using db::MessageSource;

namespace QTest {
template <> inline char* toString(const std::string& s) {
    return qstrdup(s.c_str());
}
} // namespace QTest

namespace {

profile::MachineProfile lathe() {
    profile::MachineProfile p = profile::builtin("training-lathe");
    p.setC(8, 1); // АВТ.БЕЗ ПБТ
    p.setC(60, 1);
    return p;
}

db::OpenOptions options() {
    db::OpenOptions o;
    o.author = "tester";
    o.clock = [] { return std::int64_t{1715934600}; };
    return o;
}

std::filesystem::path dbFile(const QTemporaryDir& d) {
    return std::filesystem::path(d.path().toStdString()) / "k528.db";
}

// A machine with its recorder on every tick.
struct Rig {
    machine::Simulation sim{lathe()};
    msglog::Recorder rec{sim.controller()};
    Rig() {
        sim.addTickObserver([this] { rec.observe(); });
        sim.advance(10); // power on
    }
    engine::RunResult run(const char* text) {
        program::ParseOptions po;
        const auto parsed = program::parse(text, po);
        machine::SimulationRunMachine m(sim);
        engine::RunOptions o;
        o.home = false;
        o.maxSeconds = 20;
        return engine::runProgram(m, parsed.store, 1, o);
    }
    const MessageEvent* raised(MessageSource s, int number) const {
        for (const MessageEvent& e : rec.pending())
            if (e.kind == MessageEvent::Kind::Raised && e.message.source == s &&
                e.message.number == number)
                return &e;
        return nullptr;
    }
};

db::MessageFilter filter(std::string machine, std::string search = {}, bool unacked = false) {
    db::MessageFilter f;
    f.machine = std::move(machine);
    f.search = std::move(search);
    f.unacknowledgedOnly = unacked;
    return f;
}

const db::MessageRecord* find(const std::vector<db::MessageRecord>& rows, MessageSource s, int n) {
    for (const auto& r : rows)
        if (r.source == s && r.number == n)
            return &r;
    return nullptr;
}

} // namespace

class TestRecorder : public QObject {
    Q_OBJECT
private slots:
    // Message 45 «L отсутствует» of a call in L1's third line.
    void programErrorWithNumberTextProgramLine() {
        QTemporaryDir dir;
        Rig rig;
        const engine::RunResult r = rig.run("%L1\nN1 R1=1\nN2 L77\n");
        QCOMPARE(r.status, engine::RunStatus::Alarm);
        const MessageEvent* e = rig.raised(MessageSource::Positioner, 45);
        QVERIFY(e);
        QCOMPARE(e->message.program, 1);
        QCOMPARE(e->message.line, 3);
        QCOMPARE(e->message.text, std::string(catalog::positionerMessage(45).textRu));
        QCOMPARE(e->message.textEn, std::string(catalog::positionerMessage(45).textEn));
        QVERIFY(e->machineMs > 0 && e->machineMs <= rig.sim.timeMs());
        rig.rec.stampDayTime(1'800'000'000'000);
        {
            db::Database d = db::Database::open(dbFile(dir), options());
            db::MessageLog log(d);
            const auto run = log.beginRun("training-lathe", 1'800'000'000'000 - 5000);
            log.write(run, rig.rec.takeEvents());
            const auto rows = log.page(filter("training-lathe"), 0, 100);
            const db::MessageRecord* m = find(rows, MessageSource::Positioner, 45);
            QVERIFY(m);
            QCOMPARE(m->program, 1);
            QCOMPARE(m->line, 3);
            QCOMPARE(m->code(), std::string("45"));
            QCOMPARE(m->text, std::string(catalog::positionerMessage(45).textRu));
            QVERIFY(!m->acknowledged());
            QVERIFY(m->clearedMs.has_value()); // an event: over when it latched
            QVERIFY(m->dayMs <= 1'800'000'000'000 && m->dayMs > 1'800'000'000'000 - 30000);
            // ESC, as the K923 does (C123 = 1): acknowledged, how and when.
            const std::int64_t escAt = rig.sim.timeMs();
            rig.sim.controller().escape();
            rig.sim.advance(5);
            QVERIFY(!rig.sim.controller().alarmRegistry().latched(45));
            rig.rec.stampDayTime(1'800'000'000'100);
            log.write(run, rig.rec.takeEvents());
            const auto after = log.byIds(std::vector<std::int64_t>{m->id});
            QCOMPARE(after.size(), std::size_t(1));
            QVERIFY(after[0].acknowledged());
            QCOMPARE(after[0].ackHow, std::string("esc"));
            QVERIFY(*after[0].ackMs >= escAt && *after[0].ackMs <= escAt + 5);
            QVERIFY(log.count(filter("training-lathe", {}, true)) <
                    log.count(filter("training-lathe")));
        }
    }

    // A program's technological message: the machine file's with the English
    // the file gives; a program file's own text as written, in both, even
    // when it reads as the machine's message of that number.
    void programMessageInBothLanguages() {
        Rig rig;
        // The lathe's file: #1=ПОДВОД (APPROACH), #2=ТОРЦОВКА (FACING).
        QCOMPARE(rig.run("%L1\nN1 #2 G4 X0.1\nN2 #1 G4 X0.1\nN3 M30\n%MESSAGES\n#1=ПОДВОД\n").status,
                 engine::RunStatus::Completed);
        const MessageEvent* machines = rig.raised(MessageSource::Program, 2);
        QVERIFY(machines);
        QCOMPARE(machines->message.text, std::string("ТОРЦОВКА"));
        QCOMPARE(machines->message.textEn, std::string("FACING"));
        const MessageEvent* own = rig.raised(MessageSource::Program, 1);
        QVERIFY(own);
        QCOMPARE(own->message.text, std::string("ПОДВОД"));
        QCOMPARE(own->message.textEn, std::string("ПОДВОД"));
    }

    // The E-stop: 9 comes with its cause, the cause goes, ESC acknowledges;
    // the history is the same after closing and reopening the database.
    // A controller read over the link gives only what it shows: the
    // recorder turns its observations into the same events, with the PC's
    // time, the acknowledgement's way from Z1000.
    void observationsOfARealController() {
        const profile::MachineProfile p = lathe();
        msglog::Recorder rec(p, 0);
        msglog::Observation o;
        o.timeMs = 1000;
        rec.observe(o);
        QVERIFY(rec.pending().empty());
        engine::AlarmView a;
        a.number = 5;
        a.active = true;
        o.alarms = {a};
        o.plc.alarms = o.plc.alarmsPresent = 1u << 2; // A03
        o.program.state = engine::ProgramState::Running;
        o.program.program = 7;
        o.program.line = 3;
        o.program.messageNumber = 12;
        o.program.messageText = "ПРОВЕРКА";
        o.program.messageOrigin = engine::MessageOrigin::Program;
        o.timeMs = 1500;
        rec.observe(o);
        std::vector<MessageEvent> ev = rec.takeEvents();
        QCOMPARE(ev.size(), std::size_t{3});
        QCOMPARE(ev[0].message.source, MessageSource::Positioner);
        QCOMPARE(ev[0].message.number, 5);
        QCOMPARE(ev[0].message.program, 7);
        QCOMPARE(ev[0].message.line, 3);
        QVERIFY(!ev[0].message.text.empty());
        QCOMPARE(ev[0].machineMs, std::int64_t{1500});
        QCOMPARE(ev[1].message.source, MessageSource::PlcAlarm);
        QCOMPARE(ev[1].message.number, 3);
        // The machine file's text, and its English beside it for a reader of English.
        QCOMPARE(ev[1].message.text, p.plcAlarm.at(3));
        QCOMPARE(ev[1].message.textEn, p.simulation.getString(profile::englishKey("A03"), ""));
        QVERIFY(!ev[1].message.textEn.empty() && ev[1].message.textEn != ev[1].message.text);
        QCOMPARE(ev[2].message.source, MessageSource::Program);
        QCOMPARE(ev[2].message.text, std::string("ПРОВЕРКА"));
        QCOMPARE(ev[2].message.textEn, std::string("ПРОВЕРКА")); // a program's own message: as written
        // Gone with «Сброс» (Z1000.5): cleared and acknowledged by reset.
        o.alarms.clear();
        o.plc = {};
        o.z1000 = 1u << 5;
        o.timeMs = 2000;
        rec.observe(o);
        ev = rec.takeEvents();
        QCOMPARE(ev.size(), std::size_t{4});
        QCOMPARE(ev[0].kind, MessageEvent::Kind::Cleared);
        QCOMPARE(ev[1].kind, MessageEvent::Kind::Acknowledged);
        QCOMPARE(ev[1].how, std::string("reset"));
        QCOMPARE(ev[1].machineMs, std::int64_t{2000});
        rec.stampDayTime(1'700'000'000'000);
        QVERIFY(rec.pending().empty());
    }

    void survivesReopening() {
        QTemporaryDir dir;
        std::vector<db::MessageRecord> before;
        std::int64_t total = 0;
        {
            Rig rig;
            rig.sim.pressEmergencyStop();
            rig.sim.advance(50);
            const MessageEvent* e = rig.raised(MessageSource::Positioner, 9);
            QVERIFY(e);
            const std::int64_t raisedAt = e->machineMs;
            rig.sim.releaseEmergencyStop();
            rig.sim.advance(50);
            rig.rec.noteAcknowledgement("esc-dock");
            rig.sim.controller().escape();
            rig.rec.observe();
            rig.rec.stampDayTime(1'800'000'000'000);
            db::Database d = db::Database::open(dbFile(dir), options());
            db::MessageLog log(d);
            log.write(log.beginRun("training-lathe", 1'799'999'999'000), rig.rec.takeEvents());
            before = log.page({}, 0, 1000);
            total = log.count();
            const db::MessageRecord* m = find(before, MessageSource::Positioner, 9);
            QVERIFY(m);
            QCOMPARE(m->machineMs, raisedAt);
            QVERIFY(m->clearedMs && *m->clearedMs > raisedAt);
            QVERIFY(m->acknowledged());
            QCOMPARE(m->ackHow, std::string("esc-dock"));
        }
        QVERIFY(total > 0);
        db::Database d = db::Database::open(dbFile(dir), options());
        db::MessageLog log(d);
        QCOMPARE(log.count(), total);
        const auto after = log.page({}, 0, 1000);
        QCOMPARE(after.size(), before.size());
        for (std::size_t i = 0; i < after.size(); ++i) {
            QCOMPARE(after[i].id, before[i].id);
            QCOMPARE(after[i].text, before[i].text);
            QCOMPARE(after[i].machineMs, before[i].machineMs);
            QCOMPARE(after[i].ackHow, before[i].ackHow);
            QVERIFY(after[i].clearedMs == before[i].clearedMs);
        }
        // Search by text and by code; CSV of a row.
        QVERIFY(log.count(filter({}, "9")) >= 1);
        const std::string text9(catalog::positionerMessage(9).textRu);
        QVERIFY(log.count(filter({}, text9.substr(0, 6))) >= 1);
        QCOMPARE(log.count(filter({}, "no such text at all")), std::int64_t(0));
        const std::string row = db::MessageLog::csvRow(*find(after, MessageSource::Positioner, 9));
        QVERIFY(row.find(",positioner,9,") != std::string::npos);
        QVERIFY(row.find("esc-dock") != std::string::npos);
    }

    // Two identical runs record identical events (machine time, not a clock).
    void deterministic() {
        const auto events = [] {
            Rig rig;
            rig.run("%L1\nN1 R1=1\nN2 L77\n");
            rig.sim.pressEmergencyStop();
            rig.sim.advance(30);
            std::vector<std::string> out;
            for (const MessageEvent& e : rig.rec.pending())
                out.push_back(std::to_string(static_cast<int>(e.kind)) + " " +
                              std::to_string(e.seq) + " " + std::to_string(e.machineMs) + " " +
                              e.message.code() + " " + e.how);
            return out;
        };
        const auto a = events();
        QVERIFY(!a.empty());
        QVERIFY(a == events());
    }

    // Damage in the message log: the machines still open (the log is not
    // checked at every open), checkIntegrity() (`k528 db check`) finds it.
    void damagedLogIsFoundByTheCheck() {
        QTemporaryDir dir;
        const auto p = dbFile(dir);
        {
            db::Database d = db::Database::open(p, options());
            db::MessageLog log(d);
            const auto run = log.beginRun("training-lathe", 0);
            std::vector<MessageEvent> batch;
            for (int i = 1; i <= 3000; ++i) {
                MessageEvent e;
                e.seq = i;
                e.machineMs = i;
                e.message.source = MessageSource::PlcAlarm;
                e.message.number = 1 + i % 32;
                e.message.text = "Авария смазки, длинный текст сообщения номер " + std::to_string(i);
                batch.push_back(e);
            }
            log.write(run, batch);
        }
        std::string bytes;
        {
            std::ifstream in(p, std::ios::binary);
            bytes.assign(std::istreambuf_iterator<char>(in), {});
        }
        const std::size_t page = 4096;
        QVERIFY(bytes.size() > 40 * page);
        for (std::size_t i = 0; i < 600; ++i) // the middle of the last pages: the log's rows
            bytes[bytes.size() - 2 * page + 200 + i] = static_cast<char>(0x5A ^ i);
        {
            std::ofstream out(p, std::ios::binary | std::ios::trunc);
            out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        }
        db::Database d = db::Database::open(p, options());
        QVERIFY(d.loadMachine("training-lathe").name == "training-lathe");
        QVERIFY(!d.checkIntegrity().empty());
    }

    // A batch with an event of no raised message is refused whole.
    void badBatchWritesNothing() {
        QTemporaryDir dir;
        db::Database d = db::Database::open(dbFile(dir), options());
        db::MessageLog log(d);
        const auto run = log.beginRun("training-lathe", 0);
        std::vector<MessageEvent> batch(2);
        batch[0].seq = 1;
        batch[0].message.source = MessageSource::PlcAlarm;
        batch[0].message.number = 3;
        batch[0].message.text = "Нет смазки";
        batch[1].kind = MessageEvent::Kind::Acknowledged;
        batch[1].seq = 7;
        batch[1].how = "esc";
        try {
            log.write(run, batch);
            QFAIL("accepted");
        } catch (const db::Error& e) {
            QCOMPARE(e.kind(), db::ErrorKind::Invalid);
            QVERIFY2(std::string(e.what()).find("no such message") != std::string::npos, e.what());
            QVERIFY2(std::string(e.what()).find("none of the batch's 2 events was written") != std::string::npos,
                     e.what());
            // In Russian too (k528's --lang ru): the same ids.
            const std::string ru = e.text(db::Lang::Ru);
            QVERIFY2(ru == d.path().string() + ": событие сообщения 7 прогона " + std::to_string(run) +
                               ": такое сообщение не выдавалось; ни одно из 2 событий пакета не записано",
                     ru.c_str());
        }
        // A run that is not there: said of the database's file.
        try {
            log.write(run + 100, batch);
            QFAIL("accepted");
        } catch (const db::Error& e) {
            const std::string ru = e.text(db::Lang::Ru);
            QVERIFY2(ru == d.path().string() + ": нет прогона сообщений " + std::to_string(run + 100) +
                               "; ничего не записано",
                     ru.c_str());
            QVERIFY2(std::string(e.what()) == d.path().string() + ": no message run " + std::to_string(run + 100) +
                                                   "; nothing was written",
                     e.what());
        }
        QCOMPARE(log.count(), std::int64_t(0));
        batch.pop_back();
        log.write(run, batch);
        QCOMPARE(log.count(), std::int64_t(1));
        QCOMPARE(log.page({}, 0, 1).front().code(), std::string("A03"));
    }
};

QTEST_GUILESS_MAIN(TestRecorder)
#include "test_recorder.moc"
