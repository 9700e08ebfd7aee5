// The register map of the controller link (shared/spec/link.md) as data:
// resources/link/k528-05.json, embedded. Holding register n is word Zn of
// the controller; the file names the blocks, where every machine constant
// sits (table Е.1, «Адрес в БП»), the R-parameters, the live state and the
// transfer registers. A controller whose firmware differs is a new file.
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace k528::link {

// A map file that cannot be used: what() is "<source>: <path>: <message>".
class MapError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

enum class BlockKind { Interface, C, R, Live, Transfer };
enum class Access {
    Read,    // read only
    WritePc, // read; write only while the controller is ready for the PC (F7 «РАБОТА С ПЭВМ»)
    Write,   // read and write (the transfer registers; commands check F7 themselves)
};

struct Block {
    int first = 0, last = 0; // inclusive register numbers
    BlockKind kind = BlockKind::Interface;
    Access access = Access::Read;
    int count() const { return last - first + 1; }
    bool holds(int reg) const { return reg >= first && reg <= last; }
};

enum class CForm { Bit, Word, LowByte, HighByte, TwoWords };

// Where machine constant `number` sits: Z<word>.<bit>, a word, a byte of a
// word, or two words (low word at the lower address).
struct CPlacement {
    int number = 0;
    CForm form = CForm::Word;
    int word = 0;
    int bit = 0;
};

struct LiveLayout {
    int mode = 0, flags = 0, program = 0, frame = 0, overridePct = 0;
    int xCurrent = 0, zCurrent = 0, xMachine = 0, zMachine = 0, xError = 0, zError = 0;
    int alarms = 0, alarmWords = 0, message = 0, programs = 0, programWords = 0;
};

struct TransferLayout {
    int command = 0, program = 0, status = 0, errorLine = 0, length = 0, crc = 0, offset = 0,
        window = 0, windowBytes = 0;
    std::int64_t capacityBytes = 0; // the longest text the controller takes (else status 20)
    int windowRegisters() const { return windowBytes / 2; }
};

struct RegisterMap {
    std::string name, title;
    int baud = 115200;
    char parity = 'N'; // 'N', 'E', 'O'
    int stopBits = 1;
    int address = 1;
    int maxRead = 125, maxWrite = 123;
    std::vector<Block> blocks;
    std::vector<CPlacement> c; // in number order; reserved parameters without an address absent
    // R0..R<rWritableLast> are written in F7, but those of rReadOnly (the
    // positioner's own: R158, R222, R223); the rest is read only.
    int rFirst = 0, rCount = 0, rWritableLast = 0;
    std::vector<int> rReadOnly;
    LiveLayout live;
    TransferLayout transfer;

    // The block holding `reg`, or nullptr (exception 02).
    const Block* blockOf(int reg) const;
    const Block& block(BlockKind k) const; // the first block of that kind
    int rRegister(int number) const { return rFirst + 2 * number; }
    bool rWritable(int number) const;
    // The writable R-parameters as runs of consecutive numbers (first, last).
    std::vector<std::pair<int, int>> rWritableRuns() const;
    // "R0..R157, R159..R221, R224..R231"
    std::string rWritableText() const;
};

// A block staged and committed whole (transfer commands 10 and 11): the
// registers a client sends — the whole C block, the registers of the
// writable R-parameters — in address order, taken from the whole block's
// registers (C: 117 values from its first register; R: 2 per R-parameter
// from R0). They go through the transfer window as bytes, each register
// high byte first (registerBytes); length and CRC-32 of those bytes are
// given before the block is begun, as for a text.
std::vector<std::uint16_t> stagedRegisters(const RegisterMap& map, BlockKind kind,
                                           std::span<const std::uint16_t> wholeBlock);
std::size_t stagedCount(const RegisterMap& map, BlockKind kind);
std::string registerBytes(std::span<const std::uint16_t> regs);
std::uint32_t registersCrc(std::span<const std::uint16_t> regs);

// Reads a map file; throws MapError naming `source` and the key at fault.
RegisterMap readMap(std::string_view json, std::string_view source);

// The K528-05 map (resources/link/k528-05.json), read once.
const RegisterMap& k528Map();

// The C block's registers from the constants (index = number, 153 values),
// and back. Words of a parameter whose range is signed are two's complement.
std::vector<std::uint16_t> packC(const RegisterMap& map, std::span<const std::int64_t> c);
std::vector<std::int64_t> unpackC(const RegisterMap& map, std::span<const std::uint16_t> regs);

// 32-bit values in two registers, low word first.
inline std::uint16_t lowWord(std::int64_t v) { return static_cast<std::uint16_t>(static_cast<std::uint32_t>(v) & 0xFFFFu); }
inline std::uint16_t highWord(std::int64_t v) { return static_cast<std::uint16_t>(static_cast<std::uint32_t>(v) >> 16); }
inline std::int32_t joinSigned(std::uint16_t lo, std::uint16_t hi) {
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(lo) | (static_cast<std::uint32_t>(hi) << 16));
}

// CRC-32 (IEEE 802.3, as zlib's crc32) of a text.
std::uint32_t crc32(std::string_view bytes);

// Text <-> registers: two bytes a register, the first in the high half.
std::vector<std::uint16_t> textRegisters(std::string_view bytes);
void appendRegisterText(std::string& out, std::span<const std::uint16_t> regs, std::size_t bytes);

} // namespace k528::link
