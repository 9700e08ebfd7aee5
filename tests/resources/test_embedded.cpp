#include <QtTest>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "resources/embedded.h"

using namespace k528;
namespace fs = std::filesystem;

class TestEmbedded : public QObject {
    Q_OBJECT
private slots:
    // Every file of the embedded folders is in the binary, byte for byte.
    void matchesTheSourceTree() {
        const fs::path root = fs::path(K528_SOURCE_DIR) / "resources";
        std::size_t expected = 0;
        for (const char* dir : {"profiles", "machines", "samples", "link", "exercises"}) {
            if (!fs::exists(root / dir))
                continue;
            for (const auto& e : fs::recursive_directory_iterator(root / dir)) {
                if (!e.is_regular_file() || e.path().filename() == "README.md")
                    continue;
                ++expected;
                const std::string rel = fs::relative(e.path(), root).generic_string();
                const auto data = resources::find(rel);
                QVERIFY2(data.has_value(), rel.c_str());
                std::ifstream in(e.path(), std::ios::binary);
                std::stringstream ss;
                ss << in.rdbuf();
                QCOMPARE(std::string(*data), ss.str());
            }
        }
        QCOMPARE(resources::all().size(), expected);
    }
    void sortedForLookup() {
        const auto all = resources::all();
        for (std::size_t i = 1; i < all.size(); ++i)
            QVERIFY(all[i - 1].path < all[i].path);
        QVERIFY(!resources::find("no/such/file").has_value());
    }
};

QTEST_APPLESS_MAIN(TestEmbedded)
#include "test_embedded.moc"
