// core/link without a port: the register map against table Е.1, the
// controller image (exceptions 02/03/06, the F7 rule, the transfer state
// machine, all-or-nothing commits) and the client procedures (identify,
// pull, push with read-back) over the in-process transport, also through a
// transport that loses and damages exchanges.
#include "catalog/cparams.h"
#include "engine/controller.h"
#include "engine/ideal_machine.h"
#include "link/client.h"
#include "link/image.h"
#include "profile/builtin.h"
#include "program/formatter.h"
#include "program/parser.h"
#include "resources/embedded.h"

#include <QtTest>
#include <memory>
#include <random>

using namespace k528;
using namespace k528::link;

namespace {

std::string header(int n) {
    std::string s = "%L";
    s += std::to_string(n);
    return s;
}

std::string frameLine(int i) {
    std::string s = "N";
    s += std::to_string(i);
    s += " G1 X";
    s += std::to_string(i);
    s += " FX100\n";
    return s;
}

struct Bench {
    profile::MachineProfile prof;
    std::unique_ptr<engine::Controller> ctl;
    std::unique_ptr<engine::IdealMachine> m;
    std::unique_ptr<ControllerImage> image;
    explicit Bench(std::string_view name = "training-lathe") {
        prof = profile::builtin(name);
        ctl = std::make_unique<engine::Controller>(prof);
        m = std::make_unique<engine::IdealMachine>(*ctl);
        ctl->powerOn();
        m->advance(10);
        image = std::make_unique<ControllerImage>(*ctl);
    }
    void f7() { QVERIFY(ctl->selectMode(engine::Mode::DataControl).ok()); }
    std::string programText(int n) const {
        program::ProgramStore one;
        one.insert(*ctl->programs().find(n));
        return program::format(one);
    }
};

// Loses a share of the exchanges (before or after the controller saw them)
// and flips a bit in some window writes that the line's CRC let through.
class FaultyTransport : public RegisterTransport {
public:
    FaultyTransport(RegisterTransport& inner, unsigned seed, double lose, double damage)
        : inner_(inner), rng_(seed), lose_(lose), damage_(damage) {}
    Reply read(int first, int count, std::vector<std::uint16_t>& out) override {
        if (chance(lose_ / 2))
            return Reply::lost("request lost");
        Reply r = inner_.read(first, count, out);
        if (chance(lose_ / 2))
            return Reply::lost("reply lost");
        if (r.ok() && chance(damage_ / 4) && !out.empty())
            out.pop_back(); // a short reply: the Link must see it
        return r;
    }
    Reply write(int first, std::span<const std::uint16_t> values) override {
        if (chance(lose_ / 2))
            return Reply::lost("request lost");
        std::vector<std::uint16_t> v(values.begin(), values.end());
        if (first == k528Map().transfer.offset && v.size() > 2 && chance(damage_)) {
            v[2 + rng_() % (v.size() - 2)] ^= 0x0100;
            ++damaged;
        }
        Reply r = inner_.write(first, v);
        if (chance(lose_ / 2))
            return Reply::lost("reply lost");
        return r;
    }
    Reply writeRead(int wf, std::span<const std::uint16_t> values, int rf, int rc,
                    std::vector<std::uint16_t>& out) override {
        if (chance(lose_ / 2))
            return Reply::lost("request lost");
        Reply r = inner_.writeRead(wf, values, rf, rc, out);
        if (chance(lose_ / 2))
            return Reply::lost("reply lost");
        return r;
    }
    Reply echo(std::uint16_t v) override { return inner_.echo(v); }
    int damaged = 0;

private:
    bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
    RegisterTransport& inner_;
    std::mt19937 rng_;
    double lose_, damage_;
};

// A transport whose line breaks after `budget` exchanges.
class BreakingTransport : public RegisterTransport {
public:
    BreakingTransport(RegisterTransport& inner, int budget) : inner_(inner), budget_(budget) {}
    Reply read(int f, int c, std::vector<std::uint16_t>& o) override { return alive() ? inner_.read(f, c, o) : Reply::lost(); }
    Reply write(int f, std::span<const std::uint16_t> v) override { return alive() ? inner_.write(f, v) : Reply::lost(); }
    Reply writeRead(int wf, std::span<const std::uint16_t> v, int rf, int rc, std::vector<std::uint16_t>& o) override {
        return alive() ? inner_.writeRead(wf, v, rf, rc, o) : Reply::lost();
    }
    Reply echo(std::uint16_t v) override { return alive() ? inner_.echo(v) : Reply::lost(); }

private:
    bool alive() { return budget_-- > 0; }
    RegisterTransport& inner_;
    int budget_;
};

} // namespace

class TestLink : public QObject {
    Q_OBJECT
private slots:
    void mapMatchesTableE1() {
        const RegisterMap& m = k528Map();
        QCOMPARE(m.name, std::string("k528-05"));
        QCOMPARE(m.baud, 115200);
        QCOMPARE(m.address, 1);
        QCOMPARE(m.block(BlockKind::C).first, 4100);
        QCOMPARE(m.block(BlockKind::C).last, 4216);
        int placed = 0;
        for (const catalog::CParamDef& d : catalog::cParams()) {
            const CPlacement* p = nullptr;
            for (const CPlacement& c : m.c)
                if (c.number == d.number)
                    p = &c;
            if (d.address.form == catalog::AddressForm::None) {
                QVERIFY2(!p, d.key().c_str());
                continue;
            }
            QVERIFY2(p, d.key().c_str());
            ++placed;
            QCOMPARE(p->word, d.address.word);
            switch (d.address.form) {
            case catalog::AddressForm::Bit:
                QVERIFY(p->form == CForm::Bit);
                QCOMPARE(p->bit, d.address.bit);
                break;
            case catalog::AddressForm::Word:
                QVERIFY(p->form == CForm::Word);
                break;
            case catalog::AddressForm::LowByte:
                QVERIFY(p->form == CForm::LowByte);
                break;
            case catalog::AddressForm::HighByte:
                QVERIFY(p->form == CForm::HighByte);
                break;
            case catalog::AddressForm::TwoWords:
                QVERIFY(p->form == CForm::TwoWords);
                break;
            case catalog::AddressForm::None:
                break;
            }
        }
        QCOMPARE(placed, static_cast<int>(m.c.size()));
    }

    void badMapsAreRefused() {
        const std::string good(*resources::find("link/k528-05.json"));
        QVERIFY_THROWS_EXCEPTION(MapError, readMap("{", "x"));
        std::string twice = good;
        twice.replace(twice.find("{\"c\":2,"), 7, "{\"c\":1,");
        try {
            readMap(twice, "twice.json");
            QFAIL("a constant placed twice was accepted");
        } catch (const MapError& e) {
            QVERIFY2(std::string(e.what()).find("C1 is placed twice") != std::string::npos, e.what());
        }
        std::string outside = good;
        outside.replace(outside.find("\"word\":4101"), 11, "\"word\":4301");
        QVERIFY_THROWS_EXCEPTION(MapError, readMap(outside, "outside.json"));
    }

    void packsAsTheTablePrintsIt() {
        const profile::MachineProfile p = profile::builtin("grinder-205");
        const RegisterMap& m = k528Map();
        const std::vector<std::uint16_t> regs = packC(m, p.c);
        QCOMPARE(static_cast<int>(regs.size()), 117);
        // C40 F ОБЫЧНАЯ at Z4124 (low), Z4125 (high); C1..C14 bits of Z4100.
        QCOMPARE(regs[24], lowWord(p.c[40]));
        QCOMPARE(regs[25], highWord(p.c[40]));
        for (int n = 1; n <= 14; ++n)
            QCOMPARE((regs[0] >> (n - 1)) & 1, static_cast<int>(p.c[static_cast<std::size_t>(n)] & 1));
        // C107 low byte, C108 high byte of Z4202.
        QCOMPARE(regs[102], static_cast<std::uint16_t>(p.c[107] | (p.c[108] << 8)));
        const std::vector<std::int64_t> back = unpackC(m, regs);
        for (int n = 1; n <= 152; ++n)
            QCOMPARE(back[static_cast<std::size_t>(n)], p.c[static_cast<std::size_t>(n)]);
        // A negative word (C34 КОМП.ДРЕЙФА) is two's complement.
        profile::CValues c = p.c;
        c[34] = -5;
        QCOMPARE(packC(m, c)[18], static_cast<std::uint16_t>(0xFFFB));
        QCOMPARE(unpackC(m, packC(m, c))[34], std::int64_t{-5});
    }

    void crcIsZlibs() {
        QCOMPARE(crc32("123456789"), 0xCBF43926u);
        QCOMPARE(crc32(""), 0u);
        std::string t;
        appendRegisterText(t, textRegisters("abc"), 3);
        QCOMPARE(t, std::string("abc"));
        QCOMPARE(textRegisters("ab")[0], static_cast<std::uint16_t>(('a' << 8) | 'b'));
    }

    void imageExceptions() {
        Bench b;
        ControllerImage& im = *b.image;
        std::vector<std::uint16_t> out;
        QVERIFY(im.read(3000, 1, out) == Exception::IllegalAddress);
        QVERIFY(im.read(4210, 10, out) == Exception::IllegalAddress); // runs past 4216
        QVERIFY(im.read(5000, 126, out) == Exception::IllegalValue);
        QVERIFY(im.read(5000, 125, out) == Exception::None);
        QCOMPARE(static_cast<int>(out.size()), 125);
        const std::uint16_t one[] = {7};
        QVERIFY(im.write(6000, one) == Exception::IllegalAddress); // live state is read only
        QVERIFY(im.write(2000, one) == Exception::IllegalAddress);
        // Not in F7: 06, nothing written.
        QVERIFY(im.write(5000, one) == Exception::NotReady);
        QCOMPARE(b.ctl->r(0), 0);
        const std::uint16_t begin[] = {2, 5};
        QVERIFY(im.write(7000, begin) == Exception::NotReady);
        b.f7();
        QVERIFY(im.write(5000, one) == Exception::None);
        QCOMPARE(b.ctl->r(0), 7);
        const std::uint16_t neg[] = {0xFFFF, 0xFFFF};
        QVERIFY(im.write(5002, neg) == Exception::None);
        QCOMPARE(b.ctl->r(1), -1);
        QVERIFY(im.write(5300, one) == Exception::IllegalAddress); // R150 is not the PC's
        // A constant out of range: 03 and nothing of the request written.
        QVERIFY(im.read(4100, 117, out) == Exception::None);
        const std::vector<std::uint16_t> before = out;
        std::vector<std::uint16_t> w(out.begin() + 1, out.begin() + 3); // C17, C18 (N ДОС, N ЦАП: 1..4)
        w[0] = 2;
        w[1] = 9;
        QVERIFY(im.write(4101, w) == Exception::IllegalValue);
        QVERIFY(im.read(4100, 117, out) == Exception::None);
        QVERIFY(out == before);
        // A reserved bit (C15) set: 03.
        std::uint16_t bits[] = {static_cast<std::uint16_t>(out[0] | 0x4000)};
        QVERIFY(im.write(4100, bits) == Exception::IllegalValue);
        // A good one changes the controller.
        const std::uint16_t ks[] = {static_cast<std::uint16_t>(b.ctl->c()[26] + 1)};
        QVERIFY(im.write(4110, ks) == Exception::None);
        QCOMPARE(b.ctl->c()[26], b.prof.c[26] + 1);
        // Command values and commit without a text: 03.
        const std::uint16_t bad[] = {9};
        QVERIFY(im.write(7000, bad) == Exception::IllegalValue);
        const std::uint16_t commit[] = {5};
        QVERIFY(im.write(7000, commit) == Exception::IllegalValue);
        const std::uint16_t status[] = {1};
        QVERIFY(im.write(7002, status) == Exception::IllegalAddress);
    }

    void liveState() {
        Bench b;
        ImageTransport t(*b.image);
        Link link(t);
        LiveState s;
        QVERIFY(!identify(link, s));
        QCOMPARE(s.mode, engine::modeKey(b.ctl->mode()));
        QVERIFY(!s.pcReady);
        std::vector<int> expected = b.ctl->programs().numbers();
        QVERIFY(!expected.empty());
        QCOMPARE(s.programs, expected);
        QCOMPARE(s.xCurrent, static_cast<std::int32_t>(b.ctl->axisView(engine::AxisId::X).currentDisc));
        QCOMPARE(s.overridePercent, b.ctl->programView().overridePercent);
        b.f7();
        QVERIFY(!readLive(link, s));
        QCOMPARE(s.mode, 7);
        QVERIFY(s.pcReady);
    }

    void pullThenPushIntoAnother() {
        Bench a("grinder-205");
        ImageTransport ta(*a.image);
        Link la(ta);
        PullResult pulled;
        QVERIFY(!pull(la, pulled));
        QCOMPARE(pulled.programs.size(), a.ctl->programs().size());
        for (const auto& [n, text] : pulled.programs)
            QCOMPARE(text, a.programText(n));
        for (int n = 1; n <= 152; ++n)
            QCOMPARE(pulled.c[static_cast<std::size_t>(n)], a.ctl->c()[static_cast<std::size_t>(n)]);
        const profile::MachineProfile file = pulledProfile(pulled, "pulled", "from a");

        Bench b("training-lathe");
        ImageTransport tb(*b.image);
        Link lb(tb);
        PushReport rep;
        LinkError e = push(lb, file, rep);
        QCOMPARE(e.kind, LinkError::Kind::NotReady); // F2: nothing sent
        QVERIFY(e.message.find("РАБОТА С ПЭВМ") != std::string::npos);
        QCOMPARE(b.ctl->c()[26], b.prof.c[26]);
        b.f7();
        e = push(lb, file, rep);
        QVERIFY2(!e, e.message.c_str());
        QVERIFY(rep.constants && rep.rParameters);
        QCOMPARE(rep.programs.size(), file.programs.size());
        for (int n = 1; n <= 152; ++n)
            QCOMPARE(b.ctl->c()[static_cast<std::size_t>(n)], a.ctl->c()[static_cast<std::size_t>(n)]);
        for (const auto& [n, text] : pulled.programs)
            QCOMPARE(b.programText(n), text);
        QCOMPARE(b.image->commits(), static_cast<int>(file.programs.size()) + (file.messages.empty() ? 0 : 1));
    }

    void badConstantIsNotSent() {
        Bench b;
        b.f7();
        ImageTransport t(*b.image);
        Link link(t);
        profile::MachineProfile file = b.prof;
        file.c[17] = 9; // N ДОС: 1..4
        PushReport rep;
        const LinkError e = push(link, file, rep);
        QCOMPARE(e.kind, LinkError::Kind::Input);
        QVERIFY2(e.message.find("C17") != std::string::npos, e.message.c_str());
        QCOMPARE(t.transactions(), std::int64_t{0});
    }

    void refusedTextKeepsTheProgram() {
        Bench b;
        b.f7();
        ImageTransport t(*b.image);
        Link link(t);
        const int n = b.ctl->programs().numbers().front();
        const std::string before = b.programText(n);
        // GOTO to a frame that does not exist: the controller's own check refuses it.
        const std::string bad = header(n) + "\nN1 G1 X1 FX100\nN2 GOTO 77\n";
        const LinkError e = writeText(link, false, n, bad);
        QCOMPARE(e.kind, LinkError::Kind::Refused);
        QCOMPARE(e.code, 18);
        QVERIFY2(e.message.find("line 3") != std::string::npos, e.message.c_str());
        QCOMPARE(b.programText(n), before);
        // A text for another number than the command's: refused too.
        const LinkError e2 = writeText(link, false, n, "%L98\nN1 G1 X1 FX100\n");
        QCOMPARE(e2.code, 18);
        QVERIFY(!b.ctl->programs().contains(98));
        // Leaving F7 in the middle drops the text.
        const std::string good = "%L97\nN1 G1 X1 FX100\n";
        const std::uint32_t len = static_cast<std::uint32_t>(good.size()), crc = crc32(good);
        const std::uint16_t head[] = {lowWord(len), highWord(len), lowWord(crc), highWord(crc)};
        QVERIFY(b.image->write(7004, head) == Exception::None);
        const std::uint16_t begin[] = {2, 97};
        QVERIFY(b.image->write(7000, begin) == Exception::None);
        QVERIFY(b.ctl->selectMode(engine::Mode::Manual).ok());
        std::vector<std::uint16_t> out;
        QVERIFY(b.image->read(7002, 1, out) == Exception::None);
        QCOMPARE(out[0], static_cast<std::uint16_t>(TransferStatus::NotInF7));
        QVERIFY(!b.ctl->programs().contains(97));
    }

    void damagedTransfersNeverCommit() {
        // Many transfers through a line that loses exchanges and damages
        // windows: each either commits the exact text or leaves the old one.
        int committed = 0, damagedSeen = 0;
        for (unsigned seed = 1; seed <= 12; ++seed) {
            Bench b;
            b.f7();
            ImageTransport inner(*b.image);
            FaultyTransport faulty(inner, seed, 0.15, 0.3);
            Link link(faulty, k528Map(), 6);
            const int n = 40 + static_cast<int>(seed);
            std::string text = header(n) + " (faults)\n";
            for (int i = 1; i <= 60; ++i)
                text += frameLine(i);
            const LinkError e = writeText(link, false, n, text);
            damagedSeen += faulty.damaged;
            if (!e) {
                ++committed;
                QCOMPARE(b.programText(n), text);
            } else {
                QVERIFY2(!b.ctl->programs().contains(n) || b.programText(n) == text, e.message.c_str());
            }
            QVERIFY(link.stats().noAnswer > 0 || link.stats().badReplies > 0);
        }
        QVERIFY(damagedSeen > 0);
        QVERIFY(committed > 0);
    }

    void brokenLineLeavesTheOldProgram() {
        Bench b;
        b.f7();
        const int n = b.ctl->programs().numbers().front();
        const std::string before = b.programText(n);
        std::string text = header(n) + "\n";
        for (int i = 1; i <= 200; ++i)
            text += frameLine(i);
        for (int budget = 1; budget < 20; ++budget) {
            ImageTransport inner(*b.image);
            BreakingTransport broken(inner, budget);
            Link link(broken);
            const LinkError e = writeText(link, false, n, text);
            QCOMPARE(e.kind, LinkError::Kind::NoAnswer);
            // Broken before the commit: the old program; after it (the read-back
            // lost): the whole new one. Never anything between.
            const std::string now = b.programText(n);
            QVERIFY(now == before || now == text);
            if (budget < 10)
                QCOMPARE(now, before);
        }
        // And the command can be run again.
        ImageTransport t(*b.image);
        Link link(t);
        QVERIFY(!writeText(link, false, n, text));
        QCOMPARE(b.programText(n), text);
    }
};

QTEST_APPLESS_MAIN(TestLink)
#include "test_link.moc"
