// util::sameBytes: equal blocks are equal, and a difference in any byte of
// any block size the tick uses (or near them) is found.
#include "util/same_bytes.h"

#include <QtTest>

#include <array>
#include <cstring>

using k528::util::sameBytes;

namespace {

template <std::size_t N> bool everyByteCounts() {
    std::array<unsigned char, N + 2> a{}, b{};
    for (std::size_t i = 0; i < a.size(); ++i)
        a[i] = b[i] = static_cast<unsigned char>(i * 37 + 11);
    if (!sameBytes<N>(a.data() + 1, b.data() + 1)) // unaligned on purpose
        return false;
    for (std::size_t i = 0; i < N; ++i) {
        for (unsigned char bit = 1; bit != 0; bit = static_cast<unsigned char>(bit << 1)) {
            b[i + 1] = static_cast<unsigned char>(b[i + 1] ^ bit);
            const bool same = sameBytes<N>(a.data() + 1, b.data() + 1);
            b[i + 1] = static_cast<unsigned char>(b[i + 1] ^ bit);
            if (same)
                return false;
        }
    }
    // Bytes outside the block do not count.
    b[0] ^= 0xFF;
    b[N + 1] ^= 0xFF;
    return sameBytes<N>(a.data() + 1, b.data() + 1);
}

} // namespace

class TestSameBytes : public QObject {
    Q_OBJECT
private slots:
    void everySize() {
        QVERIFY(everyByteCounts<1>());
        QVERIFY(everyByteCounts<7>());
        QVERIFY(everyByteCounts<8>());
        QVERIFY(everyByteCounts<9>());
        QVERIFY(everyByteCounts<15>());
        QVERIFY(everyByteCounts<16>());
        QVERIFY(everyByteCounts<17>());
        QVERIFY(everyByteCounts<18>());
        QVERIFY(everyByteCounts<32>());
        QVERIFY(everyByteCounts<60>());
        QVERIFY(everyByteCounts<64>());
    }
};

QTEST_APPLESS_MAIN(TestSameBytes)
#include "test_same_bytes.moc"
