// The sample programs shipped in resources/samples/ (embedded in the
// binaries and shown to users) are correct, clean and canonical.
#include <QtTest>

#include "program/diagnostic_texts.h"
#include "program/formatter.h"
#include "program/validator.h"
#include "resources/embedded.h"

using namespace k528;
using namespace k528::program;

class TestSamples : public QObject {
    Q_OBJECT
private slots:
    void samplesAreCleanAndCanonical() {
        int programs = 0;
        int files = 0;
        for (const auto& r : resources::under("samples/")) {
            if (r.path.size() < 5 || r.path.substr(r.path.size() - 5) != ".k528")
                continue;
            ++files;
            const std::string name(r.path);
            const CheckResult c = check(r.data);
            for (const auto& d : c.diagnostics)
                qWarning("%s:%d:%d: %s", name.c_str(), d.line, d.column, k528::program::diagnosticText(d, false).c_str());
            QVERIFY2(c.diagnostics.empty(), name.c_str());
            QVERIFY2(!c.store.empty(), name.c_str());
            QCOMPARE(format(c.store), std::string(r.data));
            programs += static_cast<int>(c.store.size());
            // Every sample explains itself in both languages.
            QVERIFY2(std::string(r.data).find("; RU:") != std::string::npos, name.c_str());
            QVERIFY2(std::string(r.data).find("; EN:") != std::string::npos, name.c_str());
        }
        QVERIFY(files >= 3);
        QVERIFY(programs >= 6);
    }
};

QTEST_APPLESS_MAIN(TestSamples)
#include "test_samples.moc"
