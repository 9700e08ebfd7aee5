// SHA-256 against the test vectors of FIPS 180-2 (appendix B) and lengths
// around the padding boundary (reference values from Python's hashlib).
#include "db/sha256.h"

#include <QtTest>

using k528::db::Sha256;
using k528::db::sha256Hex;

class TestSha256 : public QObject {
    Q_OBJECT
private slots:
    void fipsVectors() {
        QCOMPARE(sha256Hex(""),
                 std::string("e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855"));
        QCOMPARE(sha256Hex("abc"),
                 std::string("ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"));
        QCOMPARE(sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
                 std::string("248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1"));
        QCOMPARE(sha256Hex(std::string(1000000, 'a')),
                 std::string("cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0"));
    }
    void paddingBoundaries_data() {
        QTest::addColumn<int>("length");
        QTest::addColumn<QString>("digest");
        QTest::newRow("55") << 55
                            << "9f4390f8d30c2dd92ec9f095b65e2b9ae9b0a925a5258e241c9f1e910f734318";
        QTest::newRow("56") << 56
                            << "b35439a4ac6f0948b6d6f9e3c6af0f5f590ce20f1bde7090ef7970686ec6738a";
        QTest::newRow("63") << 63
                            << "7d3e74a05d7db15bce4ad9ec0658ea98e3f06eeecf16b4c6fff2da457ddc2f34";
        QTest::newRow("64") << 64
                            << "ffe054fe7ae0cb6dc65c3af9b61d5209f439851db43d0ba5997337df154668eb";
        QTest::newRow("65") << 65
                            << "635361c48bb9eab14198e76ea8ab7f1a41685d6ad62aa9146d301d4f17eb0ae0";
    }
    void paddingBoundaries() {
        QFETCH(int, length);
        QFETCH(QString, digest);
        QCOMPARE(
            QString::fromStdString(sha256Hex(std::string(static_cast<std::size_t>(length), 'a'))),
            digest);
    }
    void utf8Text() {
        QCOMPARE(sha256Hex("Привет"),
                 std::string("dd679c0b9fd408a04148aa7d30c9df393f67b7227f65693fffe0ed6d0f0ade59"));
    }
    // Feeding the data in pieces of any size gives the same digest.
    void streaming() {
        std::string data;
        for (int i = 0; i < 1000; ++i)
            data += static_cast<char>(i * 7 + 3);
        const std::string whole = sha256Hex(data);
        for (std::size_t piece : {1u, 3u, 63u, 64u, 65u, 200u}) {
            Sha256 s;
            for (std::size_t pos = 0; pos < data.size(); pos += piece)
                s.update(std::string_view(data).substr(pos, piece));
            std::string hex;
            for (auto b : s.finish()) {
                static const char* const h = "0123456789abcdef";
                hex += h[b >> 4];
                hex += h[b & 15];
            }
            QCOMPARE(hex, whole);
        }
    }
    void oneBitChangesTheDigest() { QVERIFY(sha256Hex("N1 G1 X10\n") != sha256Hex("N1 G1 X11\n")); }
};

QTEST_APPLESS_MAIN(TestSha256)
#include "test_sha256.moc"
