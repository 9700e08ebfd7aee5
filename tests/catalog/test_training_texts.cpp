// The texts of a training grade in core's catalog: one entry per id, both
// languages, the same arguments in both.
#include "catalog/training_texts.h"
#include "util/utf8.h"

#include <QtTest>
#include <set>
#include <string>

using namespace k528;
using namespace k528::catalog;

namespace {

// The %1..%9 a template uses.
std::set<char> arguments(std::string_view t) {
    std::set<char> out;
    for (std::size_t i = 0; i + 1 < t.size(); ++i)
        if (t[i] == '%' && t[i + 1] >= '1' && t[i + 1] <= '9')
            out.insert(t[++i]);
    return out;
}

} // namespace

class TestTrainingTexts : public QObject {
    Q_OBJECT
private slots:
    void everyIdOnceInBothLanguages() {
        std::set<std::string_view> ids;
        QVERIFY(trainingTexts().texts().size() >= 50);
        for (const util::CatalogText& t : trainingTexts().texts()) {
            QVERIFY2(ids.insert(t.id).second, std::string(t.id).c_str());
            QVERIFY2(!t.ru.empty() && !t.en.empty(), std::string(t.id).c_str());
            QVERIFY(utf8::isValid(t.ru) && utf8::isValid(t.en));
            QVERIFY2(arguments(t.ru) == arguments(t.en), std::string(t.id).c_str());
            QCOMPARE(trainingTexts().find(t.id), &t);
        }
        QVERIFY(trainingTexts().find("no-such-text") == nullptr);
        // The collisions by the prove-out's rule ids (core/proveout/rules.h).
        for (const char* id : {"collision.rapid-into-material", "collision.tool-into-chuck.jaws",
                               "collision.feed-spindle-stopped", "collision.manual-into-material",
                               "collision.rapid-into-material.ring"})
            QVERIFY2(trainingTexts().find(id), id);
    }
};

QTEST_MAIN(TestTrainingTexts)
#include "test_training_texts.moc"
