// core/link without a port: the register map against table Е.1, the
// controller image (exceptions 02/03/06, the F7 rule, the transfer state
// machine, all-or-nothing commits) and the client procedures (identify,
// pull, push with read-back) over the in-process transport, also through a
// transport that loses and damages exchanges.
#include "catalog/cparams.h"
#include "engine/positioner.h"
#include "engine/ideal_machine.h"
#include "link/client.h"
#include "link/image.h"
#include "link/monitor.h"
#include "profile/builtin.h"
#include "program/formatter.h"
#include "program/parser.h"
#include "resources/embedded.h"
#include "transfer/transfer.h"

#include <QtTest>
#include <algorithm>
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
    std::unique_ptr<engine::Positioner> ctl;
    std::unique_ptr<engine::IdealMachine> m;
    std::unique_ptr<ControllerImage> image;
    explicit Bench(std::string_view name = "training-lathe") {
        prof = profile::builtin(name);
        ctl = std::make_unique<engine::Positioner>(prof);
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
        // R0..R231 are the PC's but R158, R222, R223 (the positioner's own); R232.. read only.
        QVERIFY(im.write(5300, one) == Exception::None); // R150
        QCOMPARE(b.ctl->r(150), 7);
        const std::uint16_t r221[] = {9, 0};
        QVERIFY(im.write(5442, r221) == Exception::None);
        QCOMPARE(b.ctl->r(221), 9);
        QVERIFY(im.write(5316, one) == Exception::IllegalAddress); // R158
        QVERIFY(im.write(5444, one) == Exception::IllegalAddress); // R222
        QVERIFY(im.write(5446, one) == Exception::IllegalAddress); // R223
        QVERIFY(im.write(5464, one) == Exception::IllegalAddress); // R232
        const std::uint16_t across[] = {1, 0, 2, 0, 3, 0}; // R157..R159: R158 inside, nothing written
        QVERIFY(im.write(5314, across) == Exception::IllegalAddress);
        QCOMPARE(b.ctl->r(157), 0);
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
        const std::uint16_t bad[] = {12};
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
        QVERIFY(e.text(false).find("РАБОТА С ПЭВМ") != std::string::npos);
        QCOMPARE(b.ctl->c()[26], b.prof.c[26]);
        b.f7();
        e = push(lb, file, rep);
        QVERIFY2(!e, e.text(false).c_str());
        QVERIFY(rep.constants && rep.rParameters);
        QCOMPARE(rep.programs.size(), file.programs.size());
        for (int n = 1; n <= 152; ++n)
            QCOMPARE(b.ctl->c()[static_cast<std::size_t>(n)], a.ctl->c()[static_cast<std::size_t>(n)]);
        for (const auto& [n, text] : pulled.programs)
            QCOMPARE(b.programText(n), text);
        QCOMPARE(b.image->commits(), 2 + static_cast<int>(file.programs.size()) + (file.messages.empty() ? 0 : 1)); // C, R, texts
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
        QVERIFY2(e.text(false).find("C17") != std::string::npos, e.text(false).c_str());
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
        QVERIFY2(e.text(false).find("line 3") != std::string::npos, e.text(false).c_str());
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
                QVERIFY2(!b.ctl->programs().contains(n) || b.programText(n) == text, e.text(false).c_str());
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
    void stagedBlocksGoInWhole() {
        Bench b;
        b.f7();
        ControllerImage& im = *b.image;
        const RegisterMap& map = k528Map();
        std::vector<std::uint16_t> whole(600, 0);
        auto setR = [&](int n, std::int32_t v) {
            whole[2 * static_cast<std::size_t>(n)] = lowWord(v);
            whole[2 * static_cast<std::size_t>(n) + 1] = highWord(v);
        };
        setR(5, 55);
        setR(200, 2000);
        setR(231, -3);
        const std::vector<std::uint16_t> sent = stagedRegisters(map, BlockKind::R, whole);
        QCOMPARE(sent.size(), std::size_t{2 * (232 - 3)});
        QCOMPARE(sent.size(), stagedCount(map, BlockKind::R));
        const std::string bytes = registerBytes(sent);
        auto begin = [&](std::uint16_t cmd, const std::string& data, std::uint32_t crc) {
            const auto len = static_cast<std::uint32_t>(data.size());
            const std::uint16_t h[] = {lowWord(len), highWord(len), lowWord(crc), highWord(crc)};
            QVERIFY(im.write(7004, h) == Exception::None);
            const std::uint16_t c[] = {cmd};
            QVERIFY(im.write(7000, c) == Exception::None);
        };
        auto windows = [&](const std::string& data, std::size_t upTo) {
            const std::vector<std::uint16_t> regs = textRegisters(data);
            for (std::uint32_t off = 0; off < std::min(upTo, data.size()); off += 240) {
                std::vector<std::uint16_t> f = {lowWord(off), highWord(off)};
                const std::size_t n = std::min<std::size_t>(120, regs.size() - off / 2);
                f.insert(f.end(), regs.begin() + off / 2, regs.begin() + off / 2 + n);
                QVERIFY(im.write(7008, f) == Exception::None);
            }
        };
        auto status = [&] {
            std::vector<std::uint16_t> out;
            im.read(7002, 2, out);
            return out[0];
        };
        const std::uint16_t commit[] = {5}, abort[] = {6};
        // Held apart until the commit; an abort leaves everything as it was.
        begin(11, bytes, crc32(bytes));
        QCOMPARE(status(), std::uint16_t{1});
        windows(bytes, bytes.size());
        QCOMPARE(b.ctl->r(5), 0);
        QVERIFY(im.write(7000, abort) == Exception::None);
        QCOMPARE(b.ctl->r(5), 0);
        // A block cut short, or not the CRC given: 19, nothing stored.
        begin(11, bytes, crc32(bytes));
        windows(bytes, 480);
        QVERIFY(im.write(7000, commit) == Exception::None);
        QCOMPARE(status(), std::uint16_t{19});
        QCOMPARE(b.ctl->r(5), 0);
        begin(11, bytes, crc32(bytes) ^ 1u);
        windows(bytes, bytes.size());
        QVERIFY(im.write(7000, commit) == Exception::None);
        QCOMPARE(status(), std::uint16_t{19});
        QCOMPARE(b.ctl->r(200), 0);
        // Of another length than the map's writable R: 19.
        const std::string shorter = bytes.substr(0, bytes.size() - 4);
        begin(11, shorter, crc32(shorter));
        windows(shorter, shorter.size());
        QVERIFY(im.write(7000, commit) == Exception::None);
        QCOMPARE(status(), std::uint16_t{19});
        // Leaving F7 drops the block (16).
        begin(11, bytes, crc32(bytes));
        windows(bytes, bytes.size());
        QVERIFY(b.ctl->selectMode(engine::Mode::Manual).ok());
        QCOMPARE(status(), std::uint16_t{16});
        QVERIFY(im.write(7000, commit) == Exception::NotReady);
        QCOMPARE(b.ctl->r(5), 0);
        b.f7();
        // A block begun and left: a direct write of a register still goes in at once.
        begin(11, bytes, crc32(bytes));
        const std::uint16_t r9[] = {99, 0};
        QVERIFY(im.write(5018, r9) == Exception::None);
        QCOMPARE(b.ctl->r(9), 99);
        // Whole: every writable R at once, the positioner's own untouched.
        const std::int32_t nesting = b.ctl->r(158);
        begin(11, bytes, crc32(bytes));
        windows(bytes, bytes.size());
        QVERIFY(im.write(7000, commit) == Exception::None);
        QCOMPARE(status(), std::uint16_t{2});
        QCOMPARE(b.ctl->r(5), 55);
        QCOMPARE(b.ctl->r(9), 0);
        QCOMPARE(b.ctl->r(200), 2000);
        QCOMPARE(b.ctl->r(231), -3);
        QCOMPARE(b.ctl->r(158), nesting);
        // The C block the same way; a value outside table Е.1 refuses it whole
        // (18, 7003 = the constant's number).
        std::vector<std::uint16_t> c = packC(map, b.ctl->c());
        c[10] = static_cast<std::uint16_t>(c[10] + 1); // C26
        std::vector<std::uint16_t> wrong = c;
        wrong[1] = 9; // C17 N ДОС: 1..4
        const std::string bad = registerBytes(wrong);
        begin(10, bad, crc32(bad));
        windows(bad, bad.size());
        QVERIFY(im.write(7000, commit) == Exception::None);
        std::vector<std::uint16_t> st;
        im.read(7002, 2, st);
        QCOMPARE(st[0], std::uint16_t{18});
        QCOMPARE(st[1], std::uint16_t{17});
        QCOMPARE(b.ctl->c()[26], b.prof.c[26]);
        const std::string good = registerBytes(c);
        begin(10, good, crc32(good));
        windows(good, good.size());
        QVERIFY(im.write(7000, commit) == Exception::None);
        QCOMPARE(status(), std::uint16_t{2});
        QCOMPARE(b.ctl->c()[26], b.prof.c[26] + 1);
    }

    void pushCarriesEveryWritableR() {
        Bench b;
        b.f7();
        ImageTransport t(*b.image);
        Link link(t);
        profile::MachineProfile file = b.prof;
        for (int n = 0; n <= 231; ++n)
            file.r[n] = 1000 + n;
        file.r[240] = 7; // read only: not sent
        const std::int32_t nesting = b.ctl->r(158), before222 = b.ctl->r(222);
        PushReport rep;
        const LinkError e = push(link, file, rep);
        QVERIFY2(!e, e.text(false).c_str());
        for (int n = 0; n <= 231; ++n) {
            if (n == 158 || n == 222 || n == 223)
                continue;
            QCOMPARE(b.ctl->r(n), 1000 + n);
        }
        QCOMPARE(b.ctl->r(158), nesting);
        QCOMPARE(b.ctl->r(222), before222);
        QCOMPARE(rep.parts[1].name, std::string("R-parameters (R0..R157, R159..R221, R224..R231)"));
        QVERIFY(render(rep.summary(), false).rfind("new: C-parameters, R-parameters", 0) == 0);
        // And the pull gives them back as the file's presets.
        PullResult pulled;
        QVERIFY(!pull(link, pulled));
        const profile::MachineProfile back = pulledProfile(pulled, "m", "t");
        QCOMPARE(back.r.at(231), std::int64_t{1231});
        QVERIFY(!back.r.count(158) && !back.r.count(240));
    }

    void clearOnlyOnTheScreenOfThePc() {
        Bench b;
        ImageTransport t(*b.image);
        Link link(t);
        LinkError e = clearArea(link, BlockKind::C);
        QCOMPARE(e.kind, LinkError::Kind::NotReady);
        QVERIFY2(e.text(false).find("not in F7 «РАБОТА С ПЭВМ» (mode F") != std::string::npos, e.text(false).c_str());
        // The same id in Russian: wholly Russian, the action named.
        QVERIFY2(e.text(true).rfind("контроллер не в F7 «РАБОТА С ПЭВМ» (сейчас режим F", 0) == 0, e.text(true).c_str());
        QVERIFY2(e.text(true).find("повторите очистку C; ничего не отправлено") != std::string::npos, e.text(true).c_str());
        QCOMPARE(e.said.id, std::string("link.not-ready-mode"));
        QCOMPARE(b.ctl->c()[26], b.prof.c[26]);
        // In F7 but the K923 not on «РАБОТА С ПЭВМ»: refused, naming that screen.
        b.f7();
        bool onScreen = false;
        b.image->setPcReady([&] { return onScreen; });
        e = clearArea(link, BlockKind::R);
        QCOMPARE(e.kind, LinkError::Kind::NotReady);
        QVERIFY2(e.text(false).find("in F7 УПРАВЛЕНИЕ ДАННЫМИ but not on «РАБОТА С ПЭВМ»") != std::string::npos,
                 e.text(false).c_str());
        // The command itself outside the screen: exception 06 and status 16.
        const std::uint16_t clearC[] = {8};
        QVERIFY(b.image->write(7000, clearC) == Exception::NotReady);
        QCOMPARE(b.image->status(), TransferStatus::NotInF7);
        onScreen = true;
        QVERIFY(b.ctl->setR(7, 77).ok());
        e = clearArea(link, BlockKind::R);
        QVERIFY2(!e, e.text(false).c_str());
        QCOMPARE(b.ctl->r(7), 0);
        e = clearArea(link, BlockKind::C);
        QVERIFY2(!e, e.text(false).c_str());
        for (int n = 1; n <= 152; ++n)
            QCOMPARE(b.ctl->c()[static_cast<std::size_t>(n)], std::int64_t{0});
    }

    // One value written as the studio's docks write it: F7 only, a bit
    // merged into its word, two words, refused values and R's the PC may
    // not write; each read back.
    void oneValueWrittenDirectly() {
        Bench b;
        ImageTransport t(*b.image);
        Link link(t);
        const RegisterMap& map = link.map();
        const auto bit = std::find_if(map.c.begin(), map.c.end(), [](const CPlacement& p) { return p.form == CForm::Bit; });
        const auto two = std::find_if(map.c.begin(), map.c.end(), [](const CPlacement& p) { return p.form == CForm::TwoWords; });
        QVERIFY(bit != map.c.end() && two != map.c.end());
        LinkError e = setConstant(link, bit->number, 1 - b.ctl->c()[static_cast<std::size_t>(bit->number)]);
        QCOMPARE(e.kind, LinkError::Kind::NotReady);
        e = setRParameter(link, 5, 12);
        QCOMPARE(e.kind, LinkError::Kind::NotReady);
        QVERIFY2(e.text(false).find("not in F7") != std::string::npos, e.text(false).c_str());
        b.f7();
        const std::vector<std::int64_t> before(b.ctl->c().begin(), b.ctl->c().end());
        const std::int64_t flipped = 1 - before[static_cast<std::size_t>(bit->number)];
        e = setConstant(link, bit->number, flipped);
        QVERIFY2(!e, e.text(false).c_str());
        for (int n = 1; n <= 152; ++n) // only that one changed, its word's neighbours as they were
            QCOMPARE(b.ctl->c()[static_cast<std::size_t>(n)], n == bit->number ? flipped : before[static_cast<std::size_t>(n)]);
        const catalog::CParamDef& d = catalog::cParam(two->number);
        const std::int64_t v = std::min<std::int64_t>(d.max, 70000);
        e = setConstant(link, two->number, v);
        QVERIFY2(!e, e.text(false).c_str());
        QCOMPARE(b.ctl->c()[static_cast<std::size_t>(two->number)], v);
        e = setConstant(link, two->number, d.max + 1);
        QCOMPARE(e.kind, LinkError::Kind::Exception);
        QCOMPARE(e.code, 3);
        QCOMPARE(b.ctl->c()[static_cast<std::size_t>(two->number)], v);
        e = setRParameter(link, 231, -123456);
        QVERIFY2(!e, e.text(false).c_str());
        QCOMPARE(b.ctl->r(231), -123456);
        for (int n : {158, 222, 232, 299}) {
            e = setRParameter(link, n, 1);
            QCOMPARE(e.kind, LinkError::Kind::Input);
            QVERIFY2(e.text(false).find("read only") != std::string::npos, e.text(false).c_str());
        }
        QCOMPARE(setRParameter(link, 7, std::int64_t{1} << 40).kind, LinkError::Kind::Input);
    }

    void aBrokenPushSaysWhatIsNew() {
        // The line breaks after every number of exchanges a push takes: C, R
        // and each program are afterwards wholly old or wholly new, and the
        // report says which (in doubt only between a commit and its answer).
        const Bench probe;
        profile::MachineProfile file = probe.prof;
        file.c[26] += 1;
        for (int n = 0; n <= 231; ++n)
            file.r[n] = 500 + n;
        const int p = probe.ctl->programs().numbers().front();
        std::string text = header(p) + " (new)\n";
        for (int i = 1; i <= 150; ++i)
            text += frameLine(i);
        file.programs = {{p, text}, {60, header(60) + "\n" + frameLine(1)}};
        file.messages.clear();
        int inDoubt = 0, stopped = 0;
        for (int budget = 1; budget < 200; ++budget) {
            Bench b;
            b.f7();
            const std::string oldProgram = b.programText(p);
            ImageTransport inner(*b.image);
            BreakingTransport broken(inner, budget);
            Link link(broken);
            PushReport rep;
            const LinkError e = push(link, file, rep);
            const bool cNew = b.ctl->c()[26] == file.c[26];
            QVERIFY(cNew || b.ctl->c()[26] == probe.prof.c[26]);
            int rNew = 0;
            for (int n = 0; n <= 231; ++n)
                if (k528Map().rWritable(n) && b.ctl->r(n) == 500 + n)
                    ++rNew;
            QVERIFY2(rNew == 0 || rNew == 229, std::to_string(rNew).c_str()); // never a part of the block
            const bool pNew = b.programText(p) != oldProgram;
            const bool p60 = b.ctl->programs().contains(60);
            const bool now[] = {cNew, rNew == 229, pNew, p60};
            QCOMPARE(rep.parts.size(), std::size_t{4}); // C, R, program 60, program p (no messages)
            for (std::size_t i = 0; i < rep.parts.size(); ++i) {
                const bool isNew = now[i < 2 ? i : (rep.parts[i].name == "program 60" ? 3 : 2)];
                switch (rep.parts[i].state) {
                case PushReport::State::New:
                    QVERIFY2(isNew, (rep.parts[i].name + " said new: " + render(rep.summary(), false)).c_str());
                    break;
                case PushReport::State::AsItWas:
                    QVERIFY2(!isNew, (rep.parts[i].name + " said as it was: " + render(rep.summary(), false)).c_str());
                    break;
                case PushReport::State::InDoubt:
                    ++inDoubt;
                    break;
                }
            }
            if (!e)
                break;
            ++stopped;
            QCOMPARE(e.kind, LinkError::Kind::NoAnswer);
        }
        QVERIFY(stopped > 20);
        QVERIFY(inDoubt > 0);
    }

    void aProgramFileIsCheckedAgainstTheController() {
        Bench b;
        b.f7();
        ImageTransport t(*b.image);
        Link link(t);
        // L50 calls L51 (both in the file) and the controller's own program.
        const int own = b.ctl->programs().numbers().front();
        const std::string text = "%L50 (caller)\nN1 G1 X10 FX100\nN2 L51\nN3 L" + std::to_string(own) +
                                 "\n%L51\nN1 G1 X5 FX100\nN2 M17\n%MESSAGES\n#1=ПРОВЕРКА\n";
        PushPlan plan;
        LinkError e = planProgramFile(link, text, "p.k528", plan);
        QVERIFY2(!e, e.text(false).c_str());
        QVERIFY(!plan.hasC && !plan.hasR && plan.hasMessages);
        PushReport rep;
        e = push(link, plan, rep);
        QVERIFY2(!e, e.text(false).c_str());
        QCOMPARE(rep.parts[1].name, std::string("program 51")); // the called one first
        QVERIFY(b.ctl->programs().contains(50) && b.ctl->programs().contains(51));
        QCOMPARE(*b.ctl->programs().messages.text(1), std::string("ПРОВЕРКА"));
        // A call to a program neither the file nor the controller has: refused before anything is sent.
        const int commits = b.image->commits();
        e = planProgramFile(link, "%L52\nN1 L77\n", "bad.k528", plan);
        QCOMPARE(e.kind, LinkError::Kind::Input);
        QVERIFY2(e.text(false).find("bad.k528:2:") != std::string::npos && e.text(false).find("nothing was sent") != std::string::npos,
                 e.text(false).c_str());
        QCOMPARE(b.image->commits(), commits);
        e = planProgramFile(link, "N1 G1 X1\n", "none.k528", plan);
        QCOMPARE(e.kind, LinkError::Kind::Input);
    }
    // A stored machine the controller would refuse: the machine first, then
    // the link's words, in either language (transfer::PlanError).
    void aMachineThePlanRefusesIsNamed() {
        profile::MachineProfile p = profile::builtin("grinder-205");
        p.r[5] = std::int64_t(1) << 40; // outside the controller's 32 bits
        PushPlan plan;
        const LinkError e = planMachineFile(k528Map(), p, plan);
        QCOMPARE(e.kind, LinkError::Kind::Input);
        const transfer::PlanError refused("grinder-205", e);
        QCOMPARE(refused.text(true), "станок grinder-205: " + e.text(true));
        QCOMPARE(refused.text(false), "machine grinder-205: " + e.text(false));
        QCOMPARE(std::string(refused.what()), refused.text(false));
    }
    void monitorReadsEveryViewsDataAndSaysWhatChanged() {
        Bench b;
        ImageTransport t(*b.image);
        Link link(t);
        Monitor m;
        Monitor::Changes ch;
        // The first 2.5 s: the live state, both halves of the words, C, all of R.
        for (int i = 0; i < 25; ++i)
            QVERIFY(!m.tick(link, ch));
        QVERIFY(m.haveLive() && m.haveWords());
        QVERIFY(m.rRevision() > 0);
        QVERIFY(m.cRevision() > 0);
        QCOMPARE(m.c()[26], b.prof.c[26]);
        QCOMPARE(m.words().word(1906), b.ctl->words().word(1906));
        // Nothing moves: no revision changes, no change reported.
        const std::uint64_t r0 = m.rRevision(), c0 = m.cRevision();
        for (int i = 0; i < 120; ++i) {
            QVERIFY(!m.tick(link, ch));
            QVERIFY(!ch.r && !ch.c);
        }
        QCOMPARE(m.rRevision(), r0);
        QCOMPARE(m.cRevision(), c0);
        // An R set on the panel shows within a round of the R block (2.5 s).
        QVERIFY(b.ctl->setR(120, 4321).ok());
        bool seen = false;
        for (int i = 0; i < 26 && !seen; ++i) {
            QVERIFY(!m.tick(link, ch));
            seen = m.r()[120] == 4321;
            QVERIFY(!seen || ch.r);
        }
        QVERIFY(seen);
        QVERIFY(m.rRevision() > r0);
        // After a push or a clear: all of the memory again at once.
        b.f7();
        QVERIFY(b.ctl->clearCParameters().ok());
        m.memoryChanged();
        seen = false;
        for (int i = 0; i < 6 && !seen; ++i) {
            QVERIFY(!m.tick(link, ch));
            seen = ch.c;
        }
        QVERIFY(seen);
        QCOMPARE(m.c()[26], std::int64_t{0});
        QCOMPARE(m.live().mode, 7);
    }
};

QTEST_APPLESS_MAIN(TestLink)
#include "test_link.moc"
