// core/proveout: collisions and plausibility over the preview (docs/proveout.md).
// Each unsafe program is found with its frame; the same program made safe
// finds nothing.
#include "profile/builtin.h"
#include "program/parser.h"
#include "proveout/actual.h"
#include "proveout/material.h"
#include "proveout/proveout.h"
#include "rig/facing.h"
#include "stock/stock.h"

#include <QtTest>

#include <cmath>
#include <set>

using namespace k528;
using testrig::kBadFacing;
using testrig::kBar;
using testrig::kSafeFacing;

namespace {

proveout::Proof prove(const char* text, const char* machine = "training-lathe") {
    const program::ParseResult parsed = program::parse(text);
    if (parsed.hasErrors())
        qFatal("the program does not parse: %s", text);
    std::string error;
    const std::optional<stock::Blank> blank = stock::findUcg(text, &error);
    engine::PreviewOptions po;
    po.fromReferencePoint = true; // as `k528 run` starts: after homing
    return proveout::proveProgram(profile::builtin(machine), parsed.store,
                                  parsed.store.firstWritten(), po, blank);
}

std::string summary(const proveout::Result& r) {
    std::string s;
    for (const proveout::Finding& f : r.findings)
        s += std::string(proveout::ruleId(f.rule)) + " N" + std::to_string(f.n) + " line " +
             std::to_string(f.line) + ": " + f.message(false) + "\n";
    return s.empty() ? "nothing" : s;
}

#define EXPECT_NOTHING(proof)                                                                      \
    QVERIFY2((proof).result.findings.empty(), summary((proof).result).c_str())

const proveout::Finding* only(const proveout::Result& r, proveout::Rule rule) {
    const proveout::Finding* found = nullptr;
    for (const proveout::Finding& f : r.findings)
        if (f.rule == rule) {
            if (found)
                return nullptr;
            found = &f;
        }
    return found;
}

} // namespace

class TestProveoutRules : public QObject {
    Q_OBJECT
private slots:
    // The rules both callers use (the check before the run, the grade of an
    // attempt along its actual path): which rule a motion into the material
    // breaks, and the chuck's contact.
    void oneRuleSetForTheCheckAndTheGrade() {
        using proveout::Motion;
        using proveout::Rule;
        QCOMPARE(*proveout::materialRule(Motion::Rapid, true, false), Rule::RapidIntoMaterial);
        QCOMPARE(*proveout::materialRule(Motion::Rapid, false, true), Rule::RapidIntoMaterial);
        QCOMPARE(*proveout::materialRule(Motion::Manual, true, false), Rule::ManualIntoMaterial);
        QVERIFY(!proveout::materialRule(Motion::Feed, true, false)); // a cut
        QCOMPARE(*proveout::materialRule(Motion::Feed, false, false), Rule::FeedSpindleStopped);
        QCOMPARE(*proveout::materialRule(Motion::Feed, false, true), Rule::FeedWheelStopped);
        std::set<std::string_view> ids;
        for (const Rule r : proveout::allRules())
            QVERIFY(ids.insert(proveout::ruleId(r)).second);
        QVERIFY(ids.count("manual-into-material"));
        // A Ø40 part gripped by jaws 20 long, 15 high, their faces at Z-100.
        proveout::ChuckGeometry c;
        c.present = true;
        c.jawFaceZMm = -100;
        c.jawLengthMm = 20;
        c.jawHeightMm = 15;
        c.bodyDiameterMm = 160;
        c.bodyLengthMm = 80;
        const proveout::ChuckBoxes b = proveout::chuckBoxes(c, 40);
        QCOMPARE(b.jaws.z0, -120.0);
        QCOMPARE(b.jaws.r0, 20.0);
        QCOMPARE(b.jaws.r1, 35.0);
        const proveout::Box tool{0, 3, 0, 1000};
        // Along the part towards the jaws, above the part: into the jaws.
        QVERIFY(proveout::chuckContact(b, tool, {-50, 25}, {-110, 25}).part == proveout::ChuckContact::Jaws);
        // Stopping short of them: nothing.
        QVERIFY(proveout::chuckContact(b, tool, {-50, 25}, {-99, 25}).part == proveout::ChuckContact::None);
    }

    // Where a tool meets the material is decided once (rules.h firstMeeting
    // over material.h's columns): the check of a program and the grade of an
    // attempt along the path the machine took find the same rapid at the same
    // place when the machine took the programmed path.
    void oneContactForTheCheckAndTheGrade() {
        const std::string& bad = kBadFacing;
        const proveout::Proof p = prove(bad.c_str());
        const proveout::Finding* f = only(p.result, proveout::Rule::RapidIntoMaterial);
        QVERIFY2(f, summary(p.result).c_str());
        std::vector<toolpath::ActualSample> taken;
        for (const toolpath::Segment& s : p.path.segments) {
            const toolpath::PointMm* q = p.path.pointsOf(s);
            for (int k = 0; k < s.pointCount; ++k) {
                toolpath::ActualSample a;
                a.tMs = 10.0 * static_cast<double>(taken.size());
                a.x = q[k].x;
                a.z = q[k].z;
                a.program = s.program;
                a.line = s.line;
                a.n = s.n;
                a.kind = s.kind;
                taken.push_back(a);
            }
        }
        proveout::SpindleTimeline turning;
        turning.runningAtStart = true;
        const proveout::CutResult cut =
            proveout::cutAlong(*stock::findUcg(bad), 0, stock::Tool{}, proveout::ChuckGeometry{}, taken,
                               p.path.diameterX, turning);
        QCOMPARE(cut.collisions.size(), std::size_t(1));
        const proveout::Collision& c = cut.collisions.front();
        QCOMPARE(c.rule, proveout::Rule::RapidIntoMaterial);
        QCOMPARE(c.n, f->n);
        QCOMPARE(c.line, f->line);
        const double toD = p.path.diameterX ? 2.0 : 1.0;
        QVERIFY2(std::fabs(c.at.z - f->at.z) < 1e-3 && std::fabs(c.at.r * toD - f->at.x) < 1e-3,
                 qPrintable(QString("grade X%1 Z%2, check X%3 Z%4")
                                .arg(c.at.r * toD).arg(c.at.z).arg(f->at.x).arg(f->at.z)));

        // How far a body went into the material: a plunge's depth (along the
        // motion), a pass's depth of cut (across it) — not the tool's width.
        const stock::Blank bar = *stock::findUcg(kBar);
        const proveout::Box tool{0, 3, 0, 1000};
        proveout::LatheMaterial m(bar);
        proveout::Sweep plunge(tool, {-10, 25}, {-10, 18});
        const proveout::LatheMaterial::Cut down = m.cut(plunge, 0, -7);
        QVERIFY2(std::fabs(down.penetrationMm() - 2) < 0.011, qPrintable(QString::number(down.penetrationMm())));
        QVERIFY2(std::fabs(down.depthMm - 3) < 0.011, qPrintable(QString::number(down.depthMm)));
        proveout::Sweep pass(tool, {-30, 19}, {-60, 19});
        const proveout::LatheMaterial::Cut along = m.cut(pass, -30, 0);
        QVERIFY2(std::fabs(along.penetrationMm() - 1) < 0.011, qPrintable(QString::number(along.penetrationMm())));
    }

    // The handbook's third error (rig/facing.h) and its cure.
    void facingReturnRapidCutsTheBlank() {
        const std::string& bad = kBadFacing;
        const proveout::Proof p = prove(bad.c_str());
        QVERIFY(p.result.material);
        const proveout::Finding* f = only(p.result, proveout::Rule::RapidIntoMaterial);
        QVERIFY2(f, summary(p.result).c_str());
        QCOMPARE(f->n, 4);
        QCOMPARE(f->line, 6);
        QVERIFY(f->isError());
        QCOMPARE(f->text, std::string_view("rapid-into-material"));
        // The place: on the move from X-1 Z-1 towards the corner, inside the bar.
        QVERIFY2(f->at.z < -1 && f->at.z > -20 && std::fabs(f->at.x) < 40,
                 f->message(false).c_str());
        QCOMPARE(p.result.findings.size(), std::size_t(1));

        const proveout::Proof ok = prove(kSafeFacing.c_str());
        EXPECT_NOTHING(ok);
        QVERIFY(ok.result.removedMm2 > 19.5 && ok.result.removedMm2 < 20.5); // 1 mm × Ø40/2
    }

    // The positioner's dogleg: Z arrives first, the corner lies in the bar,
    // both ends and the straight line between them are outside it.
    void doglegCornerInsideTheMaterial() {
        const std::string bad = std::string(kBar) + "%L1\n"
                                                   "N1 G90 G0 M3 X10 Z20\n"
                                                   "N2 X50 Z-2\n"
                                                   "N3 M30\n";
        const proveout::Proof p = prove(bad.c_str());
        const proveout::Finding* f = only(p.result, proveout::Rule::RapidIntoMaterial);
        QVERIFY2(f, summary(p.result).c_str());
        QCOMPARE(f->n, 2);
        QCOMPARE(f->text, std::string_view("rapid-into-material.dogleg"));
        QCOMPARE(f->args.at(2), std::string("Z"));
        // The segment has its corner at Z-2, X below the bar's Ø40.
        const toolpath::Segment& s = p.path.segments.at(f->segment);
        QCOMPARE(int(s.pointCount), 3);
        QVERIFY(p.path.pointsOf(s)[1].x < 40 && p.path.pointsOf(s)[1].z == -2);

        const std::string safe = std::string(kBar) + "%L1\n"
                                                    "N1 G90 G0 M3 X10 Z20\n"
                                                    "N2 X50\n"
                                                    "N3 Z-2\n"
                                                    "N4 M30\n";
        EXPECT_NOTHING(prove(safe.c_str()));
    }

    // Turning close to the chuck: the tool's tip stays clear of the jaws, the
    // turret (35 mm to the left of the tip, 30 mm above it) does not.
    void turretIntoTheJaws() {
        const char* blank = "; UCG,2,Z-130Z0,X40X0,S0S0,0,-5\n";
        const std::string bad = std::string(blank) + "%L1\n"
                                                    "N1 G90 G0 M3 X42 Z2\n"
                                                    "N2 X39\n"
                                                    "N3 G1 Z-110 FZ200\n"
                                                    "N4 G0 X42\n"
                                                    "N5 Z2\n"
                                                    "N6 M30\n";
        const proveout::Proof p = prove(bad.c_str());
        QVERIFY(p.result.chuck);
        const proveout::Finding* f = only(p.result, proveout::Rule::TurretIntoChuck);
        QVERIFY2(f, summary(p.result).c_str());
        QCOMPARE(f->n, 3);
        QCOMPARE(f->text, std::string_view("turret-into-chuck.jaws"));
        // It starts where the turret's left side (Z - 35) reaches the jaws' face (-120).
        QVERIFY2(std::fabs(f->at.z - -85) < 0.01, f->message(false).c_str());
        QCOMPARE(only(p.result, proveout::Rule::ToolIntoChuck), nullptr);
        QCOMPARE(p.result.findings.size(), std::size_t(1));

        const std::string safe = std::string(blank) + "%L1\n"
                                                     "N1 G90 G0 M3 X42 Z2\n"
                                                     "N2 X39\n"
                                                     "N3 G1 Z-80 FZ200\n"
                                                     "N4 G0 X42\n"
                                                     "N5 Z2\n"
                                                     "N6 M30\n";
        EXPECT_NOTHING(prove(safe.c_str()));
    }

    // The drill (station 4) sticks out 40 mm further than the reference
    // tool: with its offsets applied, a hole 145 mm deep reaches the chuck's body.
    void drillIntoTheChucksBody() {
        const char* blank = "; UCG,2,Z-130Z0,X40X0,S0S0,0,-5\n";
        const auto program = [&](const char* depth) {
            return std::string(blank) + "%L1\n"
                                        "N1 G90 G0 M64\n"
                                        "N2 R226=R106\n"
                                        "N3 R227=R107\n"
                                        "N4 M3 X0 Z5\n"
                                        "N5 G1 Z" +
                   depth + " FZ50\n"
                           "N6 G0 Z5\n"
                           "N7 M5 M30\n";
        };
        const proveout::Proof p = prove(program("-145").c_str());
        const proveout::Finding* f = only(p.result, proveout::Rule::ToolIntoChuck);
        QVERIFY2(f, summary(p.result).c_str());
        QCOMPARE(f->n, 5);
        QCOMPARE(f->text, std::string_view("tool-into-chuck.body"));
        QCOMPARE(f->args.at(2), std::string("4"));
        EXPECT_NOTHING(prove(program("-60").c_str()));
    }

    // The tool change applies the offsets the way the machine does: the
    // program copies the tool's offset R-parameters into R226/R227. A
    // program that forgets has the drill 30 mm off the centre and 40 mm
    // nearer the chuck than it thinks: its approach runs into the bar.
    void toolOffsetsNotAppliedAreFound() {
        const std::string bad = std::string(kBar) + "%L1\n"
                                                   "N1 G90 G0 M64\n"
                                                   "N2 M3 X0 Z5\n"
                                                   "N3 G1 Z-30 FZ50\n"
                                                   "N4 G0 Z5\n"
                                                   "N5 M5 M30\n";
        const proveout::Proof p = prove(bad.c_str());
        QVERIFY2(!p.result.findings.empty(), "the drill's offsets were not applied");
        QCOMPARE(p.result.findings.front().n, 2);
        QCOMPARE(p.result.findings.front().rule, proveout::Rule::RapidIntoMaterial);
        std::string applied = bad;
        applied.replace(applied.find("N2 "), 0, "N11 R226=R106\nN12 R227=R107\n");
        EXPECT_NOTHING(prove(applied.c_str()));
    }

    void feedWithTheSpindleStopped() {
        const auto program = [](const char* m) {
            return std::string(kBar) + "%L1\n"
                                       "N1 G90 G0 " +
                   m +
                   " X38 Z2\n"
                   "N2 G1 Z-20 FZ100\n"
                   "N3 G0 X44\n"
                   "N4 Z2\n"
                   "N5 M30\n";
        };
        const proveout::Proof p = prove(program("M5").c_str());
        const proveout::Finding* f = only(p.result, proveout::Rule::FeedSpindleStopped);
        QVERIFY2(f, summary(p.result).c_str());
        QCOMPARE(f->n, 2);
        QVERIFY(std::fabs(f->at.z - 0) < 0.05); // where the tool meets the bar's face
        EXPECT_NOTHING(prove(program("M3").c_str()));
        // M4 turns it too; M5 after M3 stops it again.
        EXPECT_NOTHING(prove(program("M4").c_str()));
    }

    // Tool 1 takes 4 mm: Ø40 to Ø30 in one pass is 5 mm.
    void cutDeeperThanTheToolTakes() {
        const std::string bad = std::string(kBar) + "%L1\n"
                                                   "N1 G90 G0 M3 X30 Z2\n"
                                                   "N2 G1 Z-20 FZ100\n"
                                                   "N3 G0 X44\n"
                                                   "N4 Z2\n"
                                                   "N5 M30\n";
        const proveout::Proof p = prove(bad.c_str());
        const proveout::Finding* f = only(p.result, proveout::Rule::CutTooDeep);
        QVERIFY2(f, summary(p.result).c_str());
        QVERIFY(!f->isError());
        QCOMPARE(f->args.at(0), std::string("5"));
        QCOMPARE(f->args.at(1), std::string("1"));
        QCOMPARE(f->args.at(2), std::string("4"));
        const std::string safe = std::string(kBar) + "%L1\n"
                                                    "N1 G90 G0 M3 X32 Z2\n"
                                                    "N2 G1 Z-20 FZ100\n"
                                                    "N3 G0 X44\n"
                                                    "N4 Z2\n"
                                                    "N5 X30\n"
                                                    "N6 G1 Z-20\n"
                                                    "N7 G0 X44\n"
                                                    "N8 Z2\n"
                                                    "N9 M30\n";
        EXPECT_NOTHING(prove(safe.c_str()));
    }

    // A frame in a loop is one finding with its count.
    void aLoopIsOneFindingCounted() {
        const std::string bad = std::string(kBar) + "%L1\n"
                                                   "N1 G90 G0 X44 Z2\n"
                                                   "N2 R1=3\n"
                                                   "N3 G1 X38 FX100\n"
                                                   "N4 G0 X44\n"
                                                   "N5 R1=R1-1\n"
                                                   "N6 IF R1>0 GOTO 3\n"
                                                   "N7 M30\n";
        // X38 at Z2 is in front of the face: nothing. At Z-1 it cuts, spindle stopped.
        EXPECT_NOTHING(prove(bad.c_str()));
        std::string cutting = bad;
        cutting.replace(cutting.find("Z2"), 2, "Z-1");
        const proveout::Proof p = prove(cutting.c_str());
        QCOMPARE(p.result.findings.size(), std::size_t(1));
        QCOMPARE(p.result.findings[0].rule, proveout::Rule::FeedSpindleStopped);
        QCOMPARE(p.result.findings[0].occurrences, 1); // the 2nd and 3rd pass cut air
    }

    // The grinder: the wheel fed into the ring while it stands, and a rapid
    // into the ring; the shipped cycle is clean.
    void grinderWheel() {
        const char* cycle = "%L5\n"
                            "N1 G90 G54 G55\n"
                            "N2 G0 %1 M13 M8 Z=R193\n"
                            "N3 M20 X24.4\n"
                            "N4 G281 Z-8 FZ2000\n"
                            "N5 G1 G136 X24.9 FX3\n"
                            "N6 %2 X25.2 FX1.2\n"
                            "N7 G0 X24.6\n"
                            "N8 G280\n"
                            "N9 M21 X20\n"
                            "N10 M5 M9 Z=R221\n"
                            "N11 M30\n";
        const auto make = [&](const char* m, const char* g) {
            return QString::fromUtf8(cycle).arg(QString::fromUtf8(m), QString::fromUtf8(g)).toStdString();
        };
        EXPECT_NOTHING(prove(make("M3", "G137").c_str(), "grinder-205"));
        // Both feeds grind with the wheel standing: the first where it touches the bore.
        const proveout::Proof stopped = prove(make("M9", "G137").c_str(), "grinder-205");
        QCOMPARE(stopped.result.findings.size(), std::size_t(2));
        const proveout::Finding* f = &stopped.result.findings[0];
        QCOMPARE(f->rule, proveout::Rule::FeedWheelStopped);
        QCOMPARE(f->n, 5);
        QCOMPARE(f->args.at(0), std::string("24.7"));
        QCOMPARE(stopped.result.findings[1].n, 6);
        const proveout::Proof rapid = prove(make("M3", "G0").c_str(), "grinder-205");
        const proveout::Finding* r = only(rapid.result, proveout::Rule::RapidIntoMaterial);
        QVERIFY2(r, summary(rapid.result).c_str());
        QCOMPARE(r->n, 6);
        QCOMPARE(r->text, std::string_view("rapid-into-material.ring"));
    }

    // The columns take away what Boost.Geometry's exact removal (core/stock)
    // takes, within the columns' width.
    void materialAgreesWithTheStock() {
        const std::string text = std::string("; UCG,2,Z-60Z0,X40X0,S0S0,0,-5\n") +
                                 "%L1\n"
                                 "N1 G90 G0 M3 X44 Z2\n"
                                 "N2 Z-0.5\n"
                                 "N3 G1 X-1 FX150\n"
                                 "N4 G0 Z2\n"
                                 "N5 X36\n"
                                 "N6 G1 Z-30 FZ200\n"
                                 "N7 X40 Z-40 FX80 FZ200\n"
                                 "N8 G0 X44\n"
                                 "N9 Z2\n"
                                 "N10 M30\n";
        const proveout::Proof p = prove(text.c_str());
        EXPECT_NOTHING(p);
        const program::ParseResult parsed = program::parse(text);
        const stock::Blank blank = *stock::findUcg(text);
        stock::Stock exact(blank);
        exact.cutPath(p.path, stock::Tool{});
        const double blankArea = 60.0 * 20.0;
        QVERIFY2(std::fabs((blankArea - exact.areaMm2()) - p.result.removedMm2) < 0.2,
                 qPrintable(QString("exact %1, columns %2")
                                .arg(blankArea - exact.areaMm2())
                                .arg(p.result.removedMm2)));
    }

    // Every shipped sample (with its blank) and machine program, on its
    // machine, started as `k528 run` starts it (after homing), finds nothing.
    void shippedProgramsAreClean() {
        for (const auto& [file, machine] :
             {std::pair{"lathe-shaft.k528", "training-lathe"},
              std::pair{"lathe-grooves.k528", "training-lathe"},
              std::pair{"grinder-bore-205.k528", "grinder-205"}}) {
            QFile f(QStringLiteral(K528_SOURCE_DIR "/resources/samples/") + file);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const std::string text = f.readAll().toStdString();
            const program::ParseResult parsed = program::parse(text);
            QVERIFY(!parsed.hasErrors());
            const std::optional<stock::Blank> blank = stock::findUcg(text);
            QVERIFY2(blank || std::string(machine) == "grinder-205", file);
            engine::PreviewOptions po;
            po.fromReferencePoint = true;
            const proveout::Proof p = proveout::proveProgram(
                profile::builtin(machine), parsed.store, parsed.store.firstWritten(), po, blank);
            QVERIFY2(p.result.findings.empty(), (std::string(file) + ": " + summary(p.result)).c_str());
            QVERIFY(p.result.material);
            if (blank)
                QVERIFY2(p.result.removedMm2 > 10, file); // it cuts the bar
        }
        for (const char* machine : {"training-lathe", "grinder-205"}) {
            const profile::MachineProfile m = profile::builtin(machine);
            for (const auto& [n, text] : m.programs) {
                const program::ParseResult parsed = program::parse(text);
                engine::PreviewOptions po;
                po.fromReferencePoint = true;
                const proveout::Proof p = proveout::proveProgram(m, parsed.store, n, po, std::nullopt);
                QVERIFY2(p.result.findings.empty(),
                         (std::string(machine) + " L" + std::to_string(n) + ": " +
                          summary(p.result))
                             .c_str());
            }
        }
    }
};

QTEST_APPLESS_MAIN(TestProveoutRules)
#include "test_rules.moc"
