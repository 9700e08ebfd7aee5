// core's Modbus without a port: the PDUs and CRC-16 against the standard's
// examples, the server's answers, and the RTU client over an in-memory bus
// whose bytes are damaged on purpose — a flipped bit is a CRC error, a lost
// byte a frame cut short, silence a timeout, a late answer is dropped; each
// is counted per station and logged with its CRC; exceptions are counted
// by code; a bus scan finds the station that is there and who it is.
#include "engine/positioner.h"
#include "engine/ideal_machine.h"
#include "link/client.h"
#include "link/image.h"
#include "link/modbus.h"
#include "profile/builtin.h"

#include <QtTest>
#include <functional>
#include <memory>

using namespace k528;
using namespace k528::link;

namespace {

// Stations on one in-memory RS485 bus: each request frame reaches every
// station; the one addressed answers (FC 3/6/16/23 through its register
// handler, FC 8 echo and counters, FC 17). `damage` may change the answer's
// bytes on the way back (or drop it).
class MemoryBus final : public BytePort {
public:
    struct Station {
        int address = 0;
        RegisterHandler* handler = nullptr;
        std::string identity;
        std::uint16_t messages = 0, crcErrors = 0, exceptions = 0;
    };
    std::vector<Station> stations;
    std::function<void(Bytes&)> damage;          // on each answer
    int requests = 0;
    // Bytes that come while the line is idle (a late answer).
    void arrive(const Bytes& b) { rx_.insert(rx_.end(), b.begin(), b.end()); }

    bool write(std::span<const std::uint8_t> frame, std::string&) override {
        ++requests;
        for (Station& s : stations) {
            if (!modbus::rtuCrcOk(frame)) {
                ++s.crcErrors;
                continue;
            }
            ++s.messages;
            if (frame[0] != s.address)
                continue;
            const Bytes pdu(frame.begin() + 1, frame.end() - 2);
            Bytes answer = serve(s, pdu);
            if (answer[0] & 0x80)
                ++s.exceptions;
            Bytes out = modbus::rtuFrame(s.address, answer);
            if (damage)
                damage(out);
            rx_.insert(rx_.end(), out.begin(), out.end());
        }
        return true;
    }
    bool read(Bytes& into, int, std::string&) override {
        into.insert(into.end(), rx_.begin(), rx_.end());
        rx_.clear();
        return true;
    }
    bool isOpen() const override { return true; }
    bool reopen(std::string&) override { return true; }

private:
    Bytes serve(Station& s, const Bytes& pdu) {
        if (pdu[0] == modbus::Diagnostics) {
            const int sub = (pdu[1] << 8) | pdu[2];
            Bytes out = pdu;
            const auto put = [&](std::uint16_t v) {
                out[3] = static_cast<std::uint8_t>(v >> 8);
                out[4] = static_cast<std::uint8_t>(v & 0xFF);
            };
            if (sub == modbus::BusMessages)
                put(s.messages);
            else if (sub == modbus::BusCommunicationErrors)
                put(s.crcErrors);
            else if (sub == modbus::BusExceptions)
                put(s.exceptions);
            else if (sub != 0)
                put(0);
            return out;
        }
        if (pdu[0] == modbus::ReportServerId) {
            Bytes out{modbus::ReportServerId, static_cast<std::uint8_t>(2 + s.identity.size()), 0x28, 0xFF};
            out.insert(out.end(), s.identity.begin(), s.identity.end());
            return out;
        }
        return modbus::serveRegisters(pdu, *s.handler);
    }
    Bytes rx_;
};

struct Controller {
    profile::MachineProfile prof = profile::builtin("training-lathe");
    std::unique_ptr<engine::Positioner> ctl;
    std::unique_ptr<engine::IdealMachine> m;
    std::unique_ptr<ControllerImage> image;
    std::unique_ptr<ImageHandler> handler;
    Controller() {
        ctl = std::make_unique<engine::Positioner>(prof);
        m = std::make_unique<engine::IdealMachine>(*ctl);
        ctl->powerOn();
        m->advance(10);
        image = std::make_unique<ControllerImage>(*ctl);
        handler = std::make_unique<ImageHandler>(*image);
    }
};

RtuSettings fast(int station = 1) {
    RtuSettings s;
    s.station = station;
    s.timeoutMs = 10;
    return s;
}

} // namespace

class TestLinkModbus : public QObject {
    Q_OBJECT
private slots:
    void crcAndPdusAsTheStandardPrintsThem() {
        // Modbus over serial line, 6.2.2: 01 03 00 00 00 0A -> CRC C5 CD (low byte first on the line).
        const Bytes f = modbus::rtuFrame(1, modbus::readRequest(0, 10));
        QCOMPARE(f, (Bytes{0x01, 0x03, 0x00, 0x00, 0x00, 0x0A, 0xC5, 0xCD}));
        QVERIFY(modbus::rtuCrcOk(f));
        Bytes bad = f;
        bad[3] ^= 0x10;
        QVERIFY(!modbus::rtuCrcOk(bad));
        const std::uint16_t two[] = {0x000A, 0x0102};
        QCOMPARE(modbus::writeRequest(1, two), (Bytes{0x10, 0x00, 0x01, 0x00, 0x02, 0x04, 0x00, 0x0A, 0x01, 0x02}));
        const std::uint16_t one[] = {3};
        QCOMPARE(modbus::writeRequest(1, one), (Bytes{0x06, 0x00, 0x01, 0x00, 0x03}));
        QCOMPARE(modbus::responseLength(Bytes{0x03, 0x14}), 22);
        QCOMPARE(modbus::responseLength(Bytes{0x83}), 2);
        QCOMPARE(modbus::responseLength(Bytes{0x03}), -1);
        QCOMPARE(modbus::responseLength(Bytes{0x2B}), 0);
        QCOMPARE(modbus::requestLength(modbus::writeRequest(1, two)), 10);
        // A reply of the wrong count is a bad reply, an exception is an exception.
        std::vector<std::uint16_t> out;
        const Bytes req = modbus::readRequest(0, 2);
        QCOMPARE(modbus::decodeRegisters(req, Bytes{0x03, 0x02, 0, 1}, out).kind, Reply::Kind::BadReply);
        const Reply ex = modbus::decodeRegisters(req, Bytes{0x83, 0x02}, out);
        QCOMPARE(ex.kind, Reply::Kind::Exception);
        QCOMPARE(ex.exception, 2);
        QVERIFY(modbus::decodeRegisters(req, Bytes{0x03, 0x04, 0, 1, 0, 2}, out).ok());
        QCOMPARE(out, (std::vector<std::uint16_t>{1, 2}));
    }

    void serverAnswersTheMap() {
        Controller c;
        std::vector<std::uint16_t> out;
        Bytes a = modbus::serveRegisters(modbus::readRequest(6000, 1), *c.handler);
        QCOMPARE(a[0], std::uint8_t{3});
        QCOMPARE(a[1], std::uint8_t{2});
        a = modbus::serveRegisters(modbus::readRequest(3000, 1), *c.handler);
        QCOMPARE(a, (Bytes{0x83, 0x02}));
        const std::uint16_t v[] = {5};
        a = modbus::serveRegisters(modbus::writeRequest(5000, v), *c.handler); // not in F7
        QCOMPARE(a, (Bytes{0x86, 0x06}));
        a = modbus::serveRegisters(Bytes{0x2B, 0x0E, 0x01, 0x00}, *c.handler); // FC 43: not ours
        QCOMPARE(a, (Bytes{0xAB, 0x01}));
        a = modbus::serveRegisters(Bytes{0x10, 0x13, 0x88, 0x00, 0x02, 0x03, 0, 0, 0}, *c.handler); // count mismatch
        QCOMPARE(a, (Bytes{0x90, 0x03}));
    }

    void rtuClientCountsWhatTheLineDoes() {
        Controller c;
        MemoryBus bus;
        bus.stations.push_back({1, c.handler.get(), "K528-05 test", 0, 0, 0});
        RtuMaster master(bus, fast());
        Link link(master);
        LiveState s;
        QVERIFY(!identify(link, s));
        QCOMPARE(link.stats().exchanges, std::int64_t{2});
        QVERIFY(link.stats().roundTrip.count() == 2);

        // A flipped bit in the first answer: a CRC error, logged, then the retry.
        int n = 0;
        bus.damage = [&](Bytes& b) {
            if (n++ == 0)
                b[4] ^= 0x01;
        };
        QVERIFY(!readLive(link, s));
        QCOMPARE(link.stats().crcErrors, std::int64_t{1});
        QCOMPARE(link.stats().retries, std::int64_t{1});
        bool sawBad = false;
        for (const Frame& f : master.frameLog().frames())
            sawBad = sawBad || (!f.sent && f.check == Frame::Check::Bad);
        QVERIFY(sawBad);
        QVERIFY(formatFrameLog(master.frameLog()).find("CRC BAD") != std::string::npos);

        // A byte lost: the answer stops short, also a damaged frame.
        n = 0;
        bus.damage = [&](Bytes& b) {
            if (n++ == 0)
                b.pop_back();
        };
        QVERIFY(!readLive(link, s));
        QCOMPARE(link.stats().crcErrors, std::int64_t{2});
        QVERIFY(formatFrameLog(master.frameLog()).find("SHORT") != std::string::npos);

        // Silence: timeouts, and after the attempts the line "does not answer".
        bus.damage = [](Bytes& b) { b.clear(); };
        const LinkError e = readLive(link, s);
        QCOMPARE(e.kind, LinkError::Kind::NoAnswer);
        QCOMPARE(link.stats().noAnswer, std::int64_t{4});
        // Said in either language from the same id: the transport's "timeout" too.
        QCOMPARE(e.text(false), std::string("reading registers 6000..6031: the controller does not answer (4 attempts, last: timeout)"));
        QCOMPARE(e.text(true), std::string("чтение регистров 6000..6031: контроллер не отвечает (попыток: 4, последняя: время ожидания истекло)"));
        QVERIFY(formatFrameLog(master.frameLog()).find("no answer within 10 ms") != std::string::npos);

        // A late answer meets the next request: dropped as unexpected, the real one read.
        bus.damage = {};
        bus.arrive(modbus::rtuFrame(1, Bytes{0x03, 0x02, 0x12, 0x34}));
        std::vector<std::uint16_t> regs;
        QVERIFY(!link.read(6000, 1, regs));
        QCOMPARE(regs[0], static_cast<std::uint16_t>(engine::modeKey(c.ctl->mode())));
        QVERIFY(formatFrameLog(master.frameLog()).find("unexpected between exchanges") != std::string::npos);
        // A late answer's tail in front of the answer, in the same read: dropped, the answer found, no retry.
        n = 0;
        bus.damage = [&](Bytes& b) {
            if (n++ == 0)
                b.insert(b.begin(), {0x34, 0x01, 0x03, 0x02, 0x12});
        };
        const std::int64_t retriesBefore = link.stats().retries;
        QVERIFY(!link.read(6000, 1, regs));
        QCOMPARE(regs[0], static_cast<std::uint16_t>(engine::modeKey(c.ctl->mode())));
        QCOMPARE(link.stats().retries, retriesBefore);
        QVERIFY(formatFrameLog(master.frameLog()).find("before the answer") != std::string::npos);
        bus.damage = {};

        // Exceptions by code.
        const std::uint16_t v[] = {1};
        QCOMPARE(link.write(5000, v).code, 6);
        QCOMPARE(link.read(3000, 1, regs).code, 2);
        QCOMPARE(link.read(3000, 1, regs).code, 2);
        QCOMPARE(link.stats().exceptionsByCode.at(6), std::int64_t{1});
        QCOMPARE(link.stats().exceptionsByCode.at(2), std::int64_t{2});
        QCOMPARE(link.stations().at(1).exceptions, std::int64_t{3});
        const std::string d = describe(link.stats());
        QVERIFY2(d.find("02×2") != std::string::npos && d.find("06×1") != std::string::npos, d.c_str());

        // The station's own counters (FC 8): it saw every request.
        BusCounters bc;
        QVERIFY(!readBusCounters(link, bc));
        QVERIFY(bc.values[0] > 0);
        QCOMPARE(bc.values[2], static_cast<std::uint16_t>(3)); // exceptions answered
        // The wire: every byte both ways counted.
        QVERIFY(master.wire().bytes > 0 && master.wire().frames >= 2 * master.wire().transactions - 10);
    }

    void roundTripQuantiles() {
        RoundTrips r;
        for (int i = 1; i <= 100; ++i)
            r.add(i);
        QCOMPARE(r.median(), 50.0);
        QCOMPARE(r.p95(), 95.0);
        QCOMPARE(r.last(), 100.0);
        for (int i = 0; i < 5000; ++i) // only the newest are kept
            r.add(1000);
        QCOMPARE(r.median(), 1000.0);
    }

    void scanFindsTheStationAndWhoItIs() {
        Controller c;
        MemoryBus bus;
        bus.stations.push_back({7, c.handler.get(), "K528-05 simulated by k528 serve: training-lathe", 0, 0, 0});
        RtuMaster master(bus, fast());
        Link link(master, k528Map(), 1);
        std::vector<StationInfo> found;
        for (int a = 1; a <= 247; ++a) {
            const StationInfo s = probeStation(link, a);
            if (s.answers)
                found.push_back(s);
        }
        QCOMPARE(found.size(), std::size_t{1});
        QCOMPARE(found[0].address, 7);
        QVERIFY(found[0].id);
        QCOMPARE(found[0].id->data, std::string("K528-05 simulated by k528 serve: training-lathe"));
        QVERIFY(found[0].live);
        QCOMPARE(found[0].live->mode, engine::modeKey(c.ctl->mode()));
        const std::string text = describe(found[0]);
        QVERIFY2(text.find("address 7: echo ok") != std::string::npos, text.c_str());
        // One attempt per address: 246 silent stations cost 246 timeouts, no retries.
        QCOMPARE(link.stats().noAnswer, std::int64_t{246});
        QCOMPARE(link.stats().retries, std::int64_t{0});
        QCOMPARE(link.stations().size(), std::size_t{247});
        // A station whose answers come back damaged is told apart from silence.
        bus.damage = [](Bytes& b) { b[2] ^= 0x40; };
        const StationInfo g = probeStation(link, 7);
        QVERIFY(!g.answers);
        QVERIFY(g.garbled);
    }
};

QTEST_APPLESS_MAIN(TestLinkModbus)
#include "test_link_modbus.moc"
