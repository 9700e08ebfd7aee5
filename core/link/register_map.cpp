#include "link/register_map.h"

#include "catalog/cparams.h"
#include "resources/embedded.h"
#include "util/json.h"

#include <algorithm>
#include <array>
#include <limits>

namespace k528::link {

namespace {

struct Reader {
    std::string source;
    [[noreturn]] void fail(const std::string& path, const std::string& msg) const {
        throw MapError(source + ": " + path + ": " + msg);
    }
    const Json& need(const Json& obj, std::string_view key, const std::string& path) const {
        const auto it = obj.find(key); // end() when obj is not an object
        if (it == obj.end())
            fail(path, "missing key '" + std::string(key) + "'");
        return *it;
    }
    int integer(const Json& obj, std::string_view key, const std::string& path, int lo,
                int hi) const {
        const Json& v = need(obj, key, path);
        // (nlohmann reads a non-negative integer as uint64; one above INT64_MAX is out of range)
        const bool whole =
            v.is_number_integer() &&
            !(v.is_number_unsigned() &&
              v.get<std::uint64_t>() >
                  static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()));
        const std::int64_t n = whole ? v.get<std::int64_t>() : 0;
        if (!whole || n < lo || n > hi)
            fail(path + "." + std::string(key), "an integer " + std::to_string(lo) + ".." + std::to_string(hi) + " expected");
        return static_cast<int>(n);
    }
    std::string text(const Json& obj, std::string_view key, const std::string& path) const {
        const Json& v = need(obj, key, path);
        if (!v.is_string())
            fail(path + "." + std::string(key), "a string expected");
        return v.get<std::string>();
    }
};

constexpr int kReg = 65535;

} // namespace

const Block* RegisterMap::blockOf(int reg) const {
    for (const Block& b : blocks)
        if (b.holds(reg))
            return &b;
    return nullptr;
}

bool RegisterMap::rWritable(int number) const {
    return number >= 0 && number <= rWritableLast &&
           std::find(rReadOnly.begin(), rReadOnly.end(), number) == rReadOnly.end();
}

std::vector<std::pair<int, int>> RegisterMap::rWritableRuns() const {
    std::vector<std::pair<int, int>> runs;
    for (int n = 0; n <= rWritableLast; ++n) {
        if (!rWritable(n))
            continue;
        if (!runs.empty() && runs.back().second == n - 1)
            runs.back().second = n;
        else
            runs.emplace_back(n, n);
    }
    return runs;
}

std::string RegisterMap::rWritableText() const {
    std::string t;
    for (const auto& [a, b] : rWritableRuns()) {
        if (!t.empty())
            t.append(", ");
        t.append("R").append(std::to_string(a));
        if (b != a)
            t.append("..R").append(std::to_string(b));
    }
    return t;
}

std::vector<std::uint16_t> stagedRegisters(const RegisterMap& map, BlockKind kind,
                                           std::span<const std::uint16_t> whole) {
    if (kind == BlockKind::C)
        return {whole.begin(), whole.end()};
    std::vector<std::uint16_t> out;
    for (int n = 0; n < map.rCount && 2 * static_cast<std::size_t>(n) + 1 < whole.size(); ++n)
        if (map.rWritable(n)) {
            out.push_back(whole[2 * static_cast<std::size_t>(n)]);
            out.push_back(whole[2 * static_cast<std::size_t>(n) + 1]);
        }
    return out;
}

std::size_t stagedCount(const RegisterMap& map, BlockKind kind) {
    if (kind == BlockKind::C)
        return static_cast<std::size_t>(map.block(BlockKind::C).count());
    std::size_t n = 0;
    for (const auto& [a, b] : map.rWritableRuns())
        n += 2 * static_cast<std::size_t>(b - a + 1);
    return n;
}

std::string registerBytes(std::span<const std::uint16_t> regs) {
    std::string bytes;
    bytes.reserve(regs.size() * 2);
    for (std::uint16_t r : regs) {
        bytes.push_back(static_cast<char>(r >> 8));
        bytes.push_back(static_cast<char>(r & 0xFF));
    }
    return bytes;
}

std::uint32_t registersCrc(std::span<const std::uint16_t> regs) { return crc32(registerBytes(regs)); }

const Block& RegisterMap::block(BlockKind k) const {
    for (const Block& b : blocks)
        if (b.kind == k)
            return b;
    throw MapError("map " + name + " has no such block");
}

RegisterMap readMap(std::string_view text, std::string_view source) {
    Reader rd{std::string(source)};
    Json doc;
    try {
        doc = json::parse(text);
    } catch (const json::ParseError& e) {
        rd.fail("line " + std::to_string(e.line), e.what());
    }
    if (!doc.is_object())
        rd.fail("", "an object expected");
    RegisterMap m;
    if (rd.integer(doc, "format", "", 1, 1) != 1)
        rd.fail("format", "format 1 expected");
    m.name = rd.text(doc, "name", "");
    m.title = rd.text(doc, "title", "");
    const Json& line = rd.need(doc, "line", "");
    m.baud = rd.integer(line, "baud", "line", 1200, 4000000);
    const std::string parity = rd.text(line, "parity", "line");
    if (parity == "none")
        m.parity = 'N';
    else if (parity == "even")
        m.parity = 'E';
    else if (parity == "odd")
        m.parity = 'O';
    else
        rd.fail("line.parity", "none, even or odd expected");
    m.stopBits = rd.integer(line, "stop_bits", "line", 1, 2);
    m.address = rd.integer(line, "address", "line", 1, 247);
    const Json& lim = rd.need(doc, "limits", "");
    m.maxRead = rd.integer(lim, "read", "limits", 1, 125);
    m.maxWrite = rd.integer(lim, "write", "limits", 1, 123);

    const Json& blocks = rd.need(doc, "blocks", "");
    if (!blocks.is_array())
        rd.fail("blocks", "an array expected");
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const std::string p = "blocks[" + std::to_string(i) + "]";
        const Json& b = blocks[i];
        Block blk;
        blk.first = rd.integer(b, "first", p, 0, kReg);
        blk.last = rd.integer(b, "last", p, blk.first, kReg);
        const std::string what = rd.text(b, "what", p);
        if (what == "interface")
            blk.kind = BlockKind::Interface;
        else if (what == "c")
            blk.kind = BlockKind::C;
        else if (what == "r")
            blk.kind = BlockKind::R;
        else if (what == "live")
            blk.kind = BlockKind::Live;
        else if (what == "transfer")
            blk.kind = BlockKind::Transfer;
        else
            rd.fail(p + ".what", "interface, c, r, live or transfer expected");
        const std::string access = rd.text(b, "access", p);
        if (access == "read")
            blk.access = Access::Read;
        else if (access == "write_pc")
            blk.access = Access::WritePc;
        else if (access == "write")
            blk.access = Access::Write;
        else
            rd.fail(p + ".access", "read, write_pc or write expected");
        for (const Block& o : m.blocks)
            if (blk.first <= o.last && o.first <= blk.last)
                rd.fail(p, "overlaps another block");
        m.blocks.push_back(blk);
    }
    for (BlockKind k : {BlockKind::C, BlockKind::R, BlockKind::Live, BlockKind::Transfer}) {
        bool found = false;
        for (const Block& b : m.blocks)
            found = found || b.kind == k;
        if (!found)
            rd.fail("blocks", "the c, r, live and transfer blocks are all needed");
    }

    const Json& r = rd.need(doc, "r", "");
    m.rFirst = rd.integer(r, "first", "r", 0, kReg);
    m.rCount = rd.integer(r, "count", "r", 1, 300);
    rd.integer(r, "registers_each", "r", 2, 2);
    m.rWritableLast = rd.integer(r, "writable_last", "r", -1, m.rCount - 1);
    if (r.contains("read_only")) {
        const Json& ro = r["read_only"];
        if (!ro.is_array())
            rd.fail("r.read_only", "an array of R numbers expected");
        for (std::size_t i = 0; i < ro.size(); ++i) {
            if (!ro[i].is_number_integer() || ro[i].get<std::int64_t>() < 0 ||
                ro[i].get<std::int64_t>() > m.rWritableLast)
                rd.fail("r.read_only[" + std::to_string(i) + "]", "an R number 0.." + std::to_string(m.rWritableLast) + " expected");
            m.rReadOnly.push_back(ro[i].get<int>());
        }
    }
    const Block& rb = m.block(BlockKind::R);
    if (rb.first != m.rFirst || rb.count() != 2 * m.rCount)
        rd.fail("r", "does not match the r block");

    const Json& lv = rd.need(doc, "live", "");
    const Block& lb = m.block(BlockKind::Live);
    auto liveReg = [&](std::string_view key, int words) {
        const int v = rd.integer(lv, key, "live", lb.first, lb.last);
        if (v + words - 1 > lb.last)
            rd.fail("live." + std::string(key), "outside the live block");
        return v;
    };
    m.live.mode = liveReg("mode", 1);
    m.live.flags = liveReg("flags", 1);
    m.live.program = liveReg("program", 1);
    m.live.frame = liveReg("frame", 1);
    m.live.overridePct = liveReg("override", 1);
    m.live.xCurrent = liveReg("x_current", 2);
    m.live.zCurrent = liveReg("z_current", 2);
    m.live.xMachine = liveReg("x_machine", 2);
    m.live.zMachine = liveReg("z_machine", 2);
    m.live.xError = liveReg("x_error", 2);
    m.live.zError = liveReg("z_error", 2);
    m.live.alarmWords = rd.integer(lv, "alarm_words", "live", 4, 4);
    m.live.alarms = liveReg("alarms", m.live.alarmWords);
    m.live.message = liveReg("message", 1);
    m.live.programWords = rd.integer(lv, "program_words", "live", 7, 7);
    m.live.programs = liveReg("programs", m.live.programWords);

    const Json& tr = rd.need(doc, "transfer", "");
    const Block& tb = m.block(BlockKind::Transfer);
    auto trReg = [&](std::string_view key) { return rd.integer(tr, key, "transfer", tb.first, tb.last); };
    m.transfer.command = trReg("command");
    m.transfer.program = trReg("program");
    m.transfer.status = trReg("status");
    m.transfer.errorLine = trReg("error_line");
    m.transfer.length = trReg("length");
    m.transfer.crc = trReg("crc");
    m.transfer.offset = trReg("offset");
    m.transfer.window = trReg("window");
    m.transfer.windowBytes = rd.integer(tr, "window_bytes", "transfer", 2, 246);
    if (m.transfer.windowBytes % 2 != 0 || m.transfer.window + m.transfer.windowRegisters() - 1 > tb.last)
        rd.fail("transfer.window_bytes", "an even count whose registers fit the transfer block");
    m.transfer.capacityBytes = rd.integer(tr, "capacity_bytes", "transfer", 1, 1 << 30);

    const Json& cs = rd.need(doc, "c", "");
    if (!cs.is_array())
        rd.fail("c", "an array expected");
    const Block& cb = m.block(BlockKind::C);
    std::array<bool, catalog::kCParamCount + 1> seen{};
    for (std::size_t i = 0; i < cs.size(); ++i) {
        const std::string p = "c[" + std::to_string(i) + "]";
        const Json& e = cs[i];
        CPlacement pl;
        pl.number = rd.integer(e, "c", p, 1, catalog::kCParamCount);
        if (seen[static_cast<std::size_t>(pl.number)])
            rd.fail(p, "C" + std::to_string(pl.number) + " is placed twice");
        seen[static_cast<std::size_t>(pl.number)] = true;
        pl.word = rd.integer(e, "word", p, cb.first, cb.last);
        if (e.contains("bit")) {
            pl.form = CForm::Bit;
            pl.bit = rd.integer(e, "bit", p, 0, 15);
        } else if (e.contains("byte")) {
            const std::string b = rd.text(e, "byte", p);
            if (b != "low" && b != "high")
                rd.fail(p + ".byte", "low or high expected");
            pl.form = b == "low" ? CForm::LowByte : CForm::HighByte;
        } else if (e.contains("words")) {
            rd.integer(e, "words", p, 2, 2);
            pl.form = CForm::TwoWords;
            if (pl.word + 1 > cb.last)
                rd.fail(p, "the second word is outside the c block");
        } else {
            pl.form = CForm::Word;
        }
        m.c.push_back(pl);
    }
    return m;
}

const RegisterMap& k528Map() {
    static const RegisterMap map = [] {
        const auto data = resources::find("link/k528-05.json");
        if (!data)
            throw MapError("link/k528-05.json is not embedded");
        return readMap(*data, "link/k528-05.json");
    }();
    return map;
}

std::vector<std::uint16_t> packC(const RegisterMap& map, std::span<const std::int64_t> c) {
    const Block& cb = map.block(BlockKind::C);
    std::vector<std::uint16_t> regs(static_cast<std::size_t>(cb.count()), 0);
    for (const CPlacement& p : map.c) {
        if (static_cast<std::size_t>(p.number) >= c.size())
            continue;
        const std::int64_t v = c[static_cast<std::size_t>(p.number)];
        std::uint16_t& w = regs[static_cast<std::size_t>(p.word - cb.first)];
        switch (p.form) {
        case CForm::Bit:
            if (v & 1)
                w = static_cast<std::uint16_t>(w | (1u << p.bit));
            break;
        case CForm::Word:
            w = static_cast<std::uint16_t>(v & 0xFFFF);
            break;
        case CForm::LowByte:
            w = static_cast<std::uint16_t>((w & 0xFF00u) | (v & 0xFF));
            break;
        case CForm::HighByte:
            w = static_cast<std::uint16_t>((w & 0x00FFu) | ((v & 0xFF) << 8));
            break;
        case CForm::TwoWords:
            w = lowWord(v);
            regs[static_cast<std::size_t>(p.word + 1 - cb.first)] = highWord(v);
            break;
        }
    }
    return regs;
}

std::vector<std::int64_t> unpackC(const RegisterMap& map, std::span<const std::uint16_t> regs) {
    const Block& cb = map.block(BlockKind::C);
    std::vector<std::int64_t> c(catalog::kCParamCount + 1, 0);
    auto at = [&](int word) -> std::uint16_t {
        const auto i = static_cast<std::size_t>(word - cb.first);
        return i < regs.size() ? regs[i] : 0;
    };
    for (const CPlacement& p : map.c) {
        const catalog::CParamDef& d = catalog::cParam(p.number);
        const std::uint16_t w = at(p.word);
        std::int64_t v = 0;
        switch (p.form) {
        case CForm::Bit:
            v = (w >> p.bit) & 1;
            break;
        case CForm::Word:
            v = d.min < 0 ? static_cast<std::int16_t>(w) : w;
            break;
        case CForm::LowByte:
            v = w & 0xFF;
            break;
        case CForm::HighByte:
            v = w >> 8;
            break;
        case CForm::TwoWords:
            v = joinSigned(w, at(p.word + 1));
            break;
        }
        c[static_cast<std::size_t>(p.number)] = v;
    }
    return c;
}

std::uint32_t crc32(std::string_view bytes) {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t i = 0; i < 256; ++i) {
            std::uint32_t c = i;
            for (int k = 0; k < 8; ++k)
                c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            t[i] = c;
        }
        return t;
    }();
    std::uint32_t crc = 0xFFFFFFFFu;
    for (unsigned char b : bytes)
        crc = table[(crc ^ b) & 0xFF] ^ (crc >> 8);
    return crc ^ 0xFFFFFFFFu;
}

std::vector<std::uint16_t> textRegisters(std::string_view bytes) {
    std::vector<std::uint16_t> regs((bytes.size() + 1) / 2, 0);
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const auto b = static_cast<unsigned char>(bytes[i]);
        regs[i / 2] = static_cast<std::uint16_t>(regs[i / 2] | (i % 2 == 0 ? b << 8 : b));
    }
    return regs;
}

void appendRegisterText(std::string& out, std::span<const std::uint16_t> regs, std::size_t bytes) {
    for (std::size_t i = 0; i < bytes && i / 2 < regs.size(); ++i) {
        const std::uint16_t r = regs[i / 2];
        out.push_back(static_cast<char>(i % 2 == 0 ? r >> 8 : r & 0xFF));
    }
}

} // namespace k528::link
