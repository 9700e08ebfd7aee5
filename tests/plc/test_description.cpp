// Reading machine descriptions: every shipped one is valid; a bad one is
// refused with the file, the path in the document and what is wrong.
#include "machine/simulation.h"
#include "plc/description.h"
#include "plc/description_texts.h"
#include "plc/plc.h"
#include "profile/builtin.h"

#include <QtTest>

using namespace k528;

namespace {

// A small valid description; tests break one thing at a time.
std::string base(const std::string& extra = "") {
    return R"json({"format": 1, "name": "t",
 "modules": [{"place": 0}],
 "inputs": [{"name": "btn", "signal": "pendant.cycle_start", "module": 0}],
 "outputs": [{"name": "lamp", "signal": "lamp.cycle_start", "module": 0}],
 "flags": ["f"],
 "logic": [{"out": "lamp", "when": "btn"}])json" +
           extra + "}";
}

// The error of reading (and compiling) `text`: "" if it was accepted.
std::string errorOf(const std::string& text, std::string* path = nullptr) {
    try {
        const plc::MachineDescription d = plc::readDescription(text, "bad.json");
        plc::Plc p(d);
        machine::Simulation s(profile::builtin("training-lathe"), d);
        return "";
    } catch (const plc::DescriptionError& e) {
        if (path)
            *path = e.path();
        if (e.source() != "bad.json")
            return "wrong source " + e.source();
        return e.what();
    }
}

void expectError(const std::string& text, const std::string& wantPath,
                 const std::string& wantText) {
    std::string path;
    const std::string e = errorOf(text, &path);
    QVERIFY2(!e.empty(), ("accepted: " + text).c_str());
    QVERIFY2(path == wantPath, (e + "  [path " + path + ", want " + wantPath + "]").c_str());
    QVERIFY2(e.find(wantText) != std::string::npos, (e + "  [want: " + wantText + "]").c_str());
    QVERIFY2(e.rfind("bad.json", 0) == 0, e.c_str());
}

} // namespace

class TestDescription : public QObject {
    Q_OBJECT
private slots:
    void shippedDescriptionsAreValid() {
        const std::vector<std::string> names = plc::descriptionNames();
        QCOMPARE(names, (std::vector<std::string>{"generic", "grinder-205", "training-lathe"}));
        for (const std::string& n : names) {
            const plc::MachineDescription d = plc::loadDescription(n);
            QCOMPARE(d.name, n);
            QVERIFY(!d.title.empty());
            plc::Plc p(d);
            QVERIFY(p.inputCount() > 10);
        }
        QVERIFY(errorOf(base()).empty());
    }

    void unknownNameListsTheMachines() {
        try {
            plc::loadDescription("no-such");
            QFAIL("no exception");
        } catch (const plc::DescriptionError& e) {
            QVERIFY(std::string(e.what()).find("generic, grinder-205, training-lathe") !=
                    std::string::npos);
        }
        QVERIFY_THROWS_EXCEPTION(plc::DescriptionError, plc::loadDescription("/no/such/file.json"));
    }

    void jsonSyntax() {
        const std::string e = errorOf("{\"format\": 1,\n \"name\": \"t\",,}");
        QVERIFY2(e.find("line 2") != std::string::npos, e.c_str());
    }

    void structure() {
        expectError(R"json({"name": "t"})json", "format", "is missing");
        expectError(R"json({"format": 2, "name": "t"})json", "format", "format 1");
        expectError(R"json({"format": 1, "name": "t", "frobs": 1})json", "frobs", "unknown key");
        expectError(R"json({"format": 1, "name": "t", "inputs": {}})json", "inputs",
                    "expected an array");
        expectError(R"json({"format": 1, "name": "t", "inputs": [{"name": "a"}]})json",
                    "inputs[0].signal", "is missing");
        expectError(
            R"json({"format": 1, "name": "t", "inputs": [{"name": "a", "signal": "x", "contact": "maybe"}]})json",
            "inputs[0].contact", "normally closed");
        expectError(
            R"json({"format": 1, "name": "t", "inputs": [{"name": "a", "signal": "x", "debounce_ms": 500}]})json",
            "inputs[0].debounce_ms", "outside 0..100");
        expectError(
            R"json({"format": 1, "name": "t", "inputs": [{"name": "2a", "signal": "x"}]})json",
            "inputs[0].name", "not a valid name");
        expectError(
            R"json({"format": 1, "name": "t", "inputs": [{"name": "K3", "signal": "x"}]})json",
            "inputs[0].name", "reserved for the K923 keys");
        expectError(
            R"json({"format": 1, "name": "t", "inputs": [{"name": "link_ok", "signal": "x"}]})json",
            "inputs[0].name", "reserved");
        expectError(R"json({"format": 1, "name": "t", "modules": [{"place": 0}],
                        "inputs": [{"name": "a", "signal": "x", "module": 3}]})json",
                    "inputs[0].module", "no module at place 3");
        expectError(base(R"json(, "logic": [])json"), "logic", "appears twice");
        // A key twice anywhere, even where the reader would not look: the path of the second.
        expectError(
            R"json({"format": 1, "name": "t", "inputs": [{"name": "a", "signal": "x"}, {"name": "a", "name": "b"}]})json",
            "inputs[1].name", "appears twice");
        expectError(base(R"json(, "equipment": {"spindles": [], "_note": {"x": 1, "x": 2}})json"),
                    "equipment._note.x", "appears twice");
        // A whole number may be written 5.0, not 5.5.
        std::string whole = base();
        whole.replace(whole.find("\"format\": 1"), 11, "\"format\": 1.0");
        QVERIFY2(errorOf(whole).empty(), errorOf(whole).c_str());
        expectError(R"json({"format": 1.5, "name": "t"})json", "format",
                    "expected a whole number, found 1.5");
    }

    void names() {
        expectError(base(R"json(, "interlocks": [{"name": "btn", "when": "true"}])json"),
                    "interlocks[0]", "already used (inputs[0])");
        expectError(R"json({"format": 1, "name": "t", "flags": ["f", "f"]})json", "flags[1]",
                    "already used");
    }

    void conditions() {
        expectError(base(R"json(, "alarms": [{"k": 1, "when": "btn & nosuch"}])json"),
                    "alarms[0].when", "column 7: unknown signal 'nosuch'");
        expectError(base(R"json(, "alarms": [{"k": 1, "when": "btn &"}])json"), "alarms[0].when",
                    "ends too early");
        expectError(base(R"json(, "alarms": [{"k": 40, "when": "btn"}])json"), "alarms[0].k",
                    "outside 1..32");
        expectError(base(R"json(, "alarms": [{"k": 1, "when": "btn"}, {"k": 1, "when": "f"}])json"),
                    "alarms[1].k", "two conditions");
    }

    // What is wrong is an id and its arguments, said in Russian or English
    // from core's catalog (the command line's --lang), the same words as what().
    void languages() {
        try {
            plc::Plc p(plc::readDescription(base(R"json(, "alarms": [{"k": 1, "when": "btn & nosuch"}])json"),
                                            "bad.json"));
            QFAIL("accepted");
        } catch (const plc::DescriptionError& e) {
            QCOMPARE(e.problem().id, std::string("condition"));
            QCOMPARE(e.text(false), std::string(e.what()));
            QCOMPARE(e.text(false),
                     std::string("bad.json: alarms[0].when: column 7: unknown signal 'nosuch' in \"btn & nosuch\""));
            QCOMPARE(e.text(true),
                     std::string("bad.json: alarms[0].when: столбец 7: неизвестный сигнал «nosuch» в \"btn & nosuch\""));
        }
        try {
            plc::readDescription(R"json({"format": 1, "name": 5})json", "bad.json");
            QFAIL("accepted");
        } catch (const plc::DescriptionError& e) {
            QCOMPARE(e.message(), std::string("expected a string, found a number"));
            QCOMPARE(e.text(true), std::string("bad.json: name: ожидается строка, а здесь число"));
        }
        // Every text of the catalog has both languages, the Russian in Russian.
        for (const util::CatalogText& t : plc::descriptionTexts().texts()) {
            QVERIFY2(!t.en.empty() && !t.ru.empty(), t.id.data());
            QVERIFY2(plc::descriptionTexts().find(t.id) == &t, t.id.data()); // one entry per id
            if (!t.id.starts_with("type."))
                QVERIFY2(t.ru != t.en, t.id.data());
        }
    }

    void writers() {
        // An input cannot be written.
        expectError(base(R"json(, "keys": [{"key": 1, "set": "btn"}])json"), "keys[0].set",
                    "cannot be written");
        // One coil per signal.
        expectError(
            R"json({"format": 1, "name": "t", "outputs": [{"name": "o", "signal": "lamp.alarm"}],
                        "logic": [{"out": "o", "when": "true"}, {"out": "o", "when": "false"}]})json",
            "logic[1].out", "already has a coil");
        // A pulsed signal must not have a coil.
        expectError(R"json({"format": 1, "name": "t", "flags": ["f"],
                        "logic": [{"out": "f", "when": "true"}], "keys": [{"key": 2, "pulse": "f"}]})json",
                    "flags[0]", "pulsed by an action and also has a coil");
        // The positioner's state words are read only.
        expectError(base(R"json(, "keys": [{"key": 1, "set": "Z2000.1"}])json"), "keys[0].set",
                    "only Z1000..Z1013");
        expectError(base(R"json(, "keys": [{"key": 1, "pulse": "Z1000.11"}])json"), "keys[0].pulse",
                    "M acknowledged");
        // A slot and a coil on one bit.
        expectError(R"json({"format": 1, "name": "t", "flags": ["f"],
                        "logic": [{"out": "Z1000.4", "when": "f"}],
                        "positioner": {"stop": "f"}})json",
                    "positioner.stop", "already has a coil");
    }

    void positionerSection() {
        expectError(base(R"json(, "positioner": {"x": {"jog_plsu": "btn"}})json"),
                    "positioner.x.jog_plsu", "not a signal of the positioner interface");
        expectError(base(R"json(, "positioner": {"bits": {"Z1005.1": "btn"}})json"),
                    "positioner.bits.Z1005.1", "free words Z1011..Z1013");
        expectError(
            base(
                R"json(, "positioner": {"override": {"from_plc": "btn", "code": ["btn", "f"]}})json"),
            "positioner.override.code", "four code bits");
        expectError(base(R"json(, "positioner": {"mode": [{"code": 9, "when": "btn"}]})json"),
                    "positioner.mode[0].code", "outside 0..7");
    }

    void mFunctionsKeysInterlocks() {
        expectError(base(R"json(, "m_functions": [{"m": 3}, {"m": 3}])json"), "m_functions[1].m",
                    "described twice");
        expectError(base(R"json(, "m_functions": [{"m": 3, "timeout_ms": 100}])json"),
                    "m_functions[0]", "go together");
        expectError(base(R"json(, "m_functions": [{"m": 3, "done": "nosuch"}])json"),
                    "m_functions[0].done", "unknown signal 'nosuch'");
        expectError(base(R"json(, "unknown_m": {"acknowledge": true, "alarm": 3})json"),
                    "unknown_m", "either");
        expectError(base(R"json(, "keys": [{"key": 13, "set": "f"}])json"), "keys[0].key",
                    "outside 1..12");
        expectError(base(R"json(, "keys": [{"key": 2}])json"), "keys[0]", "needs an action");
        expectError(base(R"json(, "keys": [{"key": 2, "set": "f"}, {"key": 2, "reset": "f"}])json"),
                    "keys[1].key", "bound twice");
        expectError(
            base(R"json(, "interlocks": [{"name": "i", "when": "btn", "override_max": 15}])json"),
            "interlocks[0].override_max", "not an override step");
        expectError(
            R"json({"format": 1, "name": "t", "logic": [{"timer": "t", "when": "true"}]})json",
            "logic[0]", "exactly one of on_delay_ms");
    }

    // What an M does is said in the window's language: both texts read, a
    // missing or empty Russian refused (no silent English in a Russian
    // window), one plain string taken as written for both.
    void mFunctionTexts() {
        const plc::MachineDescription d = plc::readDescription(
            base(R"json(, "m_functions": [{"m": 8, "text": {"ru": "включение СОЖ", "en": "coolant on"}},
                                          {"m": 9, "text": "СОЖ выкл."}, {"m": 10}])json"),
            "t.json");
        QCOMPARE(d.mFunction(8)->textRu, std::string("включение СОЖ"));
        QCOMPARE(d.mFunction(8)->textEn, std::string("coolant on"));
        QCOMPARE(d.mFunction(9)->textRu, std::string("СОЖ выкл."));
        QCOMPARE(d.mFunction(9)->textEn, std::string("СОЖ выкл."));
        QVERIFY(d.mFunction(10)->textRu.empty() && d.mFunction(10)->textEn.empty());
        expectError(base(R"json(, "m_functions": [{"m": 8, "text": {"en": "coolant on"}}])json"),
                    "m_functions[0].text.ru", "is missing");
        expectError(base(R"json(, "m_functions": [{"m": 8, "text": {"ru": "", "en": "coolant on"}}])json"),
                    "m_functions[0].text.ru", "is empty");
        expectError(base(R"json(, "m_functions": [{"m": 8, "text": {"ru": "включение СОЖ"}}])json"),
                    "m_functions[0].text.en", "is missing");
        expectError(base(R"json(, "m_functions": [{"m": 8, "text": {"ru": "включение СОЖ", "de": "Kühlmittel"}}])json"),
                    "m_functions[0].text.de", "unknown key");
        expectError(base(R"json(, "m_functions": [{"m": 8, "text": 8}])json"), "m_functions[0].text",
                    "expected an object, found a number");
    }

    // The shipped machines say each of their M functions in both languages,
    // the Russian in Russian words (codes such as Z1007.0 or R224 aside).
    void shippedMFunctionsInBothLanguages() {
        const QRegularExpression latinWord(QStringLiteral("\\b[A-Za-z]{2,}\\b"));
        const QRegularExpression cyrillic(QStringLiteral("[\\x{0400}-\\x{04FF}]"));
        int described = 0;
        for (const std::string& n : plc::descriptionNames()) {
            for (const plc::MFunctionDef& f : plc::loadDescription(n).mFunctions) {
                const QString where = QString::fromStdString(n) + QStringLiteral(" M%1").arg(f.m);
                const QString ru = QString::fromStdString(f.textRu), en = QString::fromStdString(f.textEn);
                QVERIFY2(!ru.isEmpty() && !en.isEmpty(), qPrintable(where));
                QVERIFY2(ru != en, qPrintable(where + ": " + ru));
                QVERIFY2(ru.contains(cyrillic) && !ru.contains(latinWord), qPrintable(where + ": " + ru));
                QVERIFY2(en.contains(latinWord), qPrintable(where + ": " + en));
                ++described;
            }
        }
        QCOMPARE(described, 31); // the training lathe's 15 and the grinder's 16
    }

    // The wiring to the machine: signals the machine does not have, equipment.
    void wiring() {
        expectError(
            R"json({"format": 1, "name": "t", "inputs": [{"name": "a", "signal": "spindle.at_sped"}]})json",
            "inputs[0].signal", "is not a sensor of this machine");
        expectError(
            R"json({"format": 1, "name": "t", "outputs": [{"name": "a", "signal": "pendant.reset"}]})json",
            "outputs[0].signal", "is not an actuator");
        expectError(
            R"json({"format": 1, "name": "t", "outputs": [{"name": "a", "signal": "lamp.alarm"},
                        {"name": "b", "signal": "lamp.alarm"}]})json",
            "outputs[1].signal", "driven by another output");
        expectError(
            R"json({"format": 1, "name": "t", "equipment": {"spindles": [{"name": "main", "rpm": 100}]}})json",
            "equipment.spindles[0].name", "\"spindle\", \"wheel\" or \"work\"");
        expectError(
            R"json({"format": 1, "name": "t", "equipment": {"spindles": [{"name": "spindle"}]}})json",
            "equipment.spindles[0].rpm", "is missing");
        expectError(
            R"json({"format": 1, "name": "t", "equipment": {"turret": {"positions": 9}}})json",
            "equipment.turret.positions", "outside 2..7");
        expectError(R"json({"format": 1, "name": "t", "equipment": {"grinding": {}}})json",
                    "equipment.grinding.wheel", "is missing");
        expectError(
            R"json({"format": 1, "name": "t", "equipment": {"fast_inputs": {"x": {"erase1": "gauge.touch"}}}})json",
            "equipment.fast_inputs.x.erase1", "unknown machine signal 'gauge.touch'");
        expectError(
            R"json({"format": 1, "name": "t", "equipment": {"pendant": {"handwheel": {"x": 3}}}})json",
            "equipment.pendant.handwheel.x", "outside 1..2");
    }

    // A message without a text in the profile is a warning, not an error.
    void missingTextsAreWarnings() {
        const plc::MachineDescription d = plc::readDescription(
            base(
                R"json(, "alarms": [{"k": 31, "when": "btn"}], "work": [{"k": 30, "when": "f"}])json"),
            "w.json");
        profile::MachineProfile p = profile::builtin("training-lathe");
        p.plcAlarm.erase(31);
        p.plcWork.erase(30);
        machine::Simulation s(p, d);
        QCOMPARE(s.warnings().size(), std::size_t(2));
        QVERIFY(s.warnings()[0].find("A31") != std::string::npos);
        QVERIFY(s.warnings()[1].find("W30") != std::string::npos);
    }
};

QTEST_APPLESS_MAIN(TestDescription)
#include "test_description.moc"
