#include "link/image.h"

#include "engine/positioner.h"
#include "engine/program_check.h"
#include "profile/validate.h"
#include "program/formatter.h"
#include "program/parser.h"

#include <algorithm>
#include <cmath>

namespace k528::link {

namespace {

std::int64_t errorDisplayDisc(const engine::AxisView& v) {
    // ERR is in internal units, ½ discrete of motion; a display discrete is
    // one discrete of motion, two on a diameter axis.
    return std::llround(v.errorInternal / 2.0 * (v.scale.diameter ? 2.0 : 1.0));
}

std::uint16_t word32(std::int64_t v, bool high) {
    return high ? highWord(v) : lowWord(v);
}

} // namespace

ControllerImage::ControllerImage(engine::Positioner& controller, const RegisterMap& map)
    : ctl_(controller), map_(map) {}

bool ControllerImage::pcReady() const {
    if (pcReady_)
        return pcReady_();
    return ctl_.poweredOn() && ctl_.mode() == engine::Mode::DataControl &&
           !engine::programActive(ctl_.state());
}

bool ControllerImage::writing() const {
    return phase_ == Phase::WritingProgram || phase_ == Phase::WritingMessages || phase_ == Phase::StagingC ||
           phase_ == Phase::StagingR;
}

void ControllerImage::checkStillReady() {
    // Leaving F7 drops a text being written or a staged block: nothing of it is stored.
    if (writing() && !pcReady()) {
        phase_ = Phase::Idle;
        text_.clear();
        status_ = TransferStatus::NotInF7;
    }
}

Exception ControllerImage::read(int first, int count, std::vector<std::uint16_t>& out) {
    out.clear();
    if (count < 1 || count > map_.maxRead)
        return Exception::IllegalValue;
    for (int reg = first; reg < first + count; ++reg)
        if (!map_.blockOf(reg))
            return Exception::IllegalAddress;
    checkStillReady();
    const Block& cb = map_.block(BlockKind::C);
    std::vector<std::uint16_t> cRegs;
    if (first <= cb.last && first + count - 1 >= cb.first)
        cRegs = packC(map_, ctl_.c());
    out.reserve(static_cast<std::size_t>(count));
    for (int reg = first; reg < first + count; ++reg)
        out.push_back(cb.holds(reg) ? cRegs[static_cast<std::size_t>(reg - cb.first)] : readOne(reg));
    return Exception::None;
}

std::uint16_t ControllerImage::readOne(int reg) const {
    const Block* b = map_.blockOf(reg);
    switch (b->kind) {
    case BlockKind::Interface:
        return ctl_.words().word(reg);
    case BlockKind::C:
        return 0; // read() packs the whole block
    case BlockKind::R: {
        const int i = (reg - map_.rFirst) / 2;
        return word32(ctl_.r(i), (reg - map_.rFirst) % 2 == 1);
    }
    case BlockKind::Live: {
        const LiveLayout& L = map_.live;
        const engine::ProgramView pv = ctl_.programView();
        auto axis32 = [&](int base, engine::AxisId a, int which) -> std::optional<std::uint16_t> {
            if (reg != base && reg != base + 1)
                return std::nullopt;
            const engine::AxisView v = ctl_.axisView(a);
            const std::int64_t val = which == 0 ? v.currentDisc : which == 1 ? v.machineDisc : errorDisplayDisc(v);
            return word32(val, reg == base + 1);
        };
        if (reg == L.mode)
            return ctl_.poweredOn() ? static_cast<std::uint16_t>(engine::modeKey(ctl_.mode())) : 0;
        if (reg == L.flags) {
            std::uint16_t f = 0;
            if (pcReady())
                f |= 1u << 0;
            if (engine::executing(ctl_.state()))
                f |= 1u << 1;
            if (!ctl_.alarms().empty())
                f |= 1u << 2;
            if (ctl_.axisView(engine::AxisId::X).referenced)
                f |= 1u << 3;
            if (ctl_.axisView(engine::AxisId::Z).referenced)
                f |= 1u << 4;
            return f;
        }
        if (reg == L.program)
            return static_cast<std::uint16_t>(pv.program);
        if (reg == L.frame)
            return static_cast<std::uint16_t>(pv.frameNumber);
        if (reg == L.overridePct)
            return static_cast<std::uint16_t>(pv.overridePercent);
        for (auto [base, axis, which] : {std::tuple{L.xCurrent, engine::AxisId::X, 0},
                                         std::tuple{L.zCurrent, engine::AxisId::Z, 0},
                                         std::tuple{L.xMachine, engine::AxisId::X, 1},
                                         std::tuple{L.zMachine, engine::AxisId::Z, 1},
                                         std::tuple{L.xError, engine::AxisId::X, 2},
                                         std::tuple{L.zError, engine::AxisId::Z, 2}})
            if (const auto w = axis32(base, axis, which))
                return *w;
        if (reg >= L.alarms && reg < L.alarms + L.alarmWords) {
            std::uint16_t w = 0;
            for (const engine::AlarmView& a : ctl_.alarms())
                if (a.number >= 1 && (a.number - 1) / 16 == reg - L.alarms)
                    w |= static_cast<std::uint16_t>(1u << ((a.number - 1) % 16));
            return w;
        }
        if (reg == L.message)
            return static_cast<std::uint16_t>(pv.messageNumber);
        if (reg >= L.programs && reg < L.programs + L.programWords) {
            std::uint16_t w = 0;
            for (const program::Program& p : ctl_.programs().programs())
                if (p.number >= 1 && (p.number - 1) / 16 == reg - L.programs)
                    w |= static_cast<std::uint16_t>(1u << ((p.number - 1) % 16));
            return w;
        }
        return 0;
    }
    case BlockKind::Transfer: {
        const TransferLayout& T = map_.transfer;
        if (reg == T.command)
            return 0;
        if (reg == T.program)
            return programNumber_;
        if (reg == T.status)
            return static_cast<std::uint16_t>(status_);
        if (reg == T.errorLine)
            return errorLine_;
        if (reg == T.length || reg == T.length + 1)
            return word32(length_, reg == T.length + 1);
        if (reg == T.crc || reg == T.crc + 1)
            return word32(crc_, reg == T.crc + 1);
        if (reg == T.offset || reg == T.offset + 1)
            return word32(offset_, reg == T.offset + 1);
        if (reg >= T.window && reg < T.window + T.windowRegisters()) {
            if (phase_ != Phase::ReadingProgram && phase_ != Phase::ReadingMessages)
                return 0;
            const std::size_t at = offset_ + static_cast<std::size_t>(reg - T.window) * 2;
            const auto byte = [&](std::size_t i) -> unsigned {
                return i < text_.size() ? static_cast<unsigned char>(text_[i]) : 0u;
            };
            return static_cast<std::uint16_t>((byte(at) << 8) | byte(at + 1));
        }
        return 0;
    }
    }
    return 0;
}

Exception ControllerImage::write(int first, std::span<const std::uint16_t> values) {
    const int count = static_cast<int>(values.size());
    if (count < 1 || count > map_.maxWrite)
        return Exception::IllegalValue;
    const Block* b = map_.blockOf(first);
    for (int reg = first; reg < first + count; ++reg)
        if (map_.blockOf(reg) != b || !b || b->access == Access::Read)
            return Exception::IllegalAddress;
    checkStillReady();
    switch (b->kind) {
    case BlockKind::C:
        return writeC(first, values);
    case BlockKind::R:
        return writeR(first, values);
    case BlockKind::Transfer:
        return writeTransfer(first, values);
    default:
        return Exception::IllegalAddress;
    }
}

Exception ControllerImage::writeC(int first, std::span<const std::uint16_t> values) {
    if (!pcReady())
        return Exception::NotReady;
    const Block& cb = map_.block(BlockKind::C);
    std::vector<std::uint16_t> regs = packC(map_, ctl_.c());
    std::copy(values.begin(), values.end(), regs.begin() + (first - cb.first));
    const std::vector<std::int64_t> c = unpackC(map_, regs);
    // A bit or byte the map does not place must stay 0: repacking gives the
    // registers back exactly, or something was written where nothing lives.
    if (packC(map_, c) != regs)
        return Exception::IllegalValue;
    for (int n = 1; n < static_cast<int>(c.size()); ++n)
        if (!profile::checkCValue(n, c[static_cast<std::size_t>(n)]).empty())
            return Exception::IllegalValue;
    return ctl_.loadCParameters(c).ok() ? Exception::None : Exception::IllegalValue;
}

Exception ControllerImage::writeR(int first, std::span<const std::uint16_t> values) {
    if (!pcReady())
        return Exception::NotReady;
    const int last = first + static_cast<int>(values.size()) - 1;
    const int firstR = (first - map_.rFirst) / 2, lastR = (last - map_.rFirst) / 2;
    // Every R the request touches must be one the PC may write (R0..R231
    // but the positioner's own R158, R222, R223).
    for (int i = firstR; i <= lastR; ++i)
        if (!map_.rWritable(i))
            return Exception::IllegalAddress;
    std::vector<std::int32_t> v;
    for (int i = firstR; i <= lastR; ++i) {
        const int lo = map_.rRegister(i), hi = lo + 1;
        auto reg = [&](int r, std::uint16_t current) {
            return r >= first && r <= last ? values[static_cast<std::size_t>(r - first)] : current;
        };
        const std::int32_t cur = ctl_.r(i);
        v.push_back(joinSigned(reg(lo, lowWord(cur)), reg(hi, highWord(cur))));
    }
    if (engine::executing(ctl_.state()))
        return Exception::NotReady;
    for (int i = firstR; i <= lastR; ++i)
        if (!ctl_.setR(i, v[static_cast<std::size_t>(i - firstR)]).ok())
            return Exception::IllegalValue; // not reached: checked above
    return Exception::None;
}

Exception ControllerImage::writeTransfer(int first, std::span<const std::uint16_t> values) {
    const TransferLayout& T = map_.transfer;
    const int last = first + static_cast<int>(values.size()) - 1;
    auto has = [&](int reg) { return reg >= first && reg <= last; };
    auto val = [&](int reg) { return values[static_cast<std::size_t>(reg - first)]; };
    if (has(T.status) || has(T.errorLine))
        return Exception::IllegalAddress;
    // Check everything before anything changes.
    if (has(T.program) && (val(T.program) < 1 || val(T.program) > 99))
        return Exception::IllegalValue;
    const bool writesWindow = last >= T.window;
    if (writesWindow) {
        if (!pcReady())
            return Exception::NotReady;
        if (!writing())
            return Exception::IllegalValue;
    }
    auto pair32 = [&](int reg, std::uint32_t current) {
        const std::uint16_t lo = has(reg) ? val(reg) : lowWord(current);
        const std::uint16_t hi = has(reg + 1) ? val(reg + 1) : highWord(current);
        return static_cast<std::uint32_t>(lo) | (static_cast<std::uint32_t>(hi) << 16);
    };
    const std::uint32_t length = pair32(T.length, length_);
    const std::uint32_t crc = pair32(T.crc, crc_);
    const std::uint32_t offset = pair32(T.offset, offset_);
    if ((has(T.offset) || has(T.offset + 1)) && offset > std::max<std::uint32_t>(length, 0) &&
        (phase_ == Phase::WritingProgram || phase_ == Phase::WritingMessages ||
         phase_ == Phase::ReadingProgram || phase_ == Phase::ReadingMessages))
        return Exception::IllegalValue;
    if (writesWindow) {
        const std::size_t firstByte = offset + static_cast<std::size_t>(std::max(first, T.window) - T.window) * 2;
        if (firstByte > text_.size())
            return Exception::IllegalValue;
    }
    if (has(T.command)) {
        const std::uint16_t cmd = val(T.command);
        if (cmd < 1 || cmd > kLastCommand)
            return Exception::IllegalValue;
        const bool needsPc = cmd == 2 || cmd == 4 || cmd == 5 || cmd >= 7;
        if (needsPc && !pcReady()) {
            status_ = TransferStatus::NotInF7; // for a client that reads the status
            return Exception::NotReady;
        }
        if (cmd == 5 && !writing())
            return Exception::IllegalValue;
    }
    // Apply: registers first, the command last.
    if (has(T.program))
        programNumber_ = val(T.program);
    if (has(T.length) || has(T.length + 1))
        length_ = length;
    if (has(T.crc) || has(T.crc + 1))
        crc_ = crc;
    if (has(T.offset) || has(T.offset + 1))
        offset_ = offset;
    if (writesWindow) {
        const int from = std::max(first, T.window);
        const int to = std::min(last, T.window + T.windowRegisters() - 1);
        for (int reg = from; reg <= to; ++reg) {
            const std::size_t at = offset_ + static_cast<std::size_t>(reg - T.window) * 2;
            const std::uint16_t w = val(reg);
            if (at < text_.size())
                text_[at] = static_cast<char>(w >> 8);
            if (at + 1 < text_.size())
                text_[at + 1] = static_cast<char>(w & 0xFF);
        }
    }
    if (has(T.command))
        return command(val(T.command));
    return Exception::None;
}

Exception ControllerImage::command(std::uint16_t cmd) {
    errorLine_ = 0;
    switch (static_cast<TransferCommand>(cmd)) {
    case TransferCommand::ReadProgram: {
        const program::Program* p = ctl_.programs().find(programNumber_);
        phase_ = Phase::Idle;
        text_.clear();
        if (!p) {
            status_ = TransferStatus::NoSuchProgram;
            return Exception::None;
        }
        program::ProgramStore one;
        one.insert(*p);
        text_ = program::format(one);
        phase_ = Phase::ReadingProgram;
        transferProgram_ = programNumber_;
        break;
    }
    case TransferCommand::ReadMessages: {
        program::ProgramStore one;
        one.messages = ctl_.programs().messages;
        one.messages.present = true;
        text_ = program::format(one);
        phase_ = Phase::ReadingMessages;
        break;
    }
    case TransferCommand::WriteProgram:
    case TransferCommand::WriteMessages:
    case TransferCommand::StageC:
    case TransferCommand::StageR:
        // A text, or a block's registers, come through the window: held
        // apart from what the controller keeps, nothing of them counts
        // before the commit.
        text_.clear();
        phase_ = Phase::Idle;
        if (length_ > map_.transfer.capacityBytes) {
            status_ = TransferStatus::MemoryFull;
            return Exception::None;
        }
        text_.assign(length_, '\0');
        phase_ = cmd == 2    ? Phase::WritingProgram
                 : cmd == 4  ? Phase::WritingMessages
                 : cmd == 10 ? Phase::StagingC
                             : Phase::StagingR;
        transferProgram_ = programNumber_;
        status_ = TransferStatus::Ready;
        return Exception::None;
    case TransferCommand::Commit:
        commit();
        return Exception::None;
    case TransferCommand::Abort:
        phase_ = Phase::Idle;
        text_.clear();
        status_ = TransferStatus::Idle;
        return Exception::None;
    case TransferCommand::DeleteProgram: {
        phase_ = Phase::Idle;
        text_.clear();
        program::ProgramStore* store = ctl_.editablePrograms();
        if (!store) {
            status_ = TransferStatus::NotInF7;
            return Exception::None;
        }
        if (!store->remove(programNumber_)) {
            status_ = TransferStatus::NoSuchProgram;
            return Exception::None;
        }
        ctl_.programsEdited();
        ++commits_;
        status_ = TransferStatus::Committed;
        return Exception::None;
    }
    case TransferCommand::ClearC:
    case TransferCommand::ClearR: {
        phase_ = Phase::Idle;
        text_.clear();
        const engine::OpResult r =
            cmd == 8 ? ctl_.clearCParameters() : ctl_.clearRParameters();
        if (!r.ok()) {
            status_ = TransferStatus::NotInF7;
            return Exception::None;
        }
        ++commits_;
        status_ = TransferStatus::Committed;
        return Exception::None;
    }
    }
    length_ = static_cast<std::uint32_t>(text_.size());
    crc_ = crc32(text_);
    offset_ = 0;
    status_ = TransferStatus::Ready;
    return Exception::None;
}

void ControllerImage::commitBlock() {
    const BlockKind kind = phase_ == Phase::StagingC ? BlockKind::C : BlockKind::R;
    const std::string bytes = std::move(text_);
    phase_ = Phase::Idle;
    text_.clear();
    // What a client sends of the block (stagedRegisters): C all 117
    // registers, R those of the writable R-parameters; two bytes each.
    const std::size_t expected = stagedCount(map_, kind);
    if (bytes.size() != length_ || crc32(bytes) != crc_ || bytes.size() != 2 * expected) {
        status_ = TransferStatus::CrcMismatch;
        return;
    }
    std::vector<std::uint16_t> regs(expected);
    for (std::size_t i = 0; i < expected; ++i)
        regs[i] = static_cast<std::uint16_t>((static_cast<unsigned char>(bytes[2 * i]) << 8) |
                                             static_cast<unsigned char>(bytes[2 * i + 1]));
    if (kind == BlockKind::C) {
        const std::vector<std::int64_t> c = unpackC(map_, regs);
        // Every value against table Е.1; a bit or byte where no constant lives
        // stays 0. 7003 = the number of the first constant at fault.
        if (packC(map_, c) != regs) {
            status_ = TransferStatus::TextRefused;
            errorLine_ = 0;
            return;
        }
        for (int n = 1; n < static_cast<int>(c.size()); ++n)
            if (!profile::checkCValue(n, c[static_cast<std::size_t>(n)]).empty()) {
                status_ = TransferStatus::TextRefused;
                errorLine_ = static_cast<std::uint16_t>(n);
                return;
            }
        if (!ctl_.loadCParameters(c).ok()) { // values checked: only leaving F7 refuses
            status_ = TransferStatus::NotInF7;
            return;
        }
    } else {
        if (engine::executing(ctl_.state())) {
            status_ = TransferStatus::NotInF7;
            return;
        }
        std::size_t at = 0;
        for (const auto& [a, b] : map_.rWritableRuns())
            for (int i = a; i <= b; ++i, at += 2) {
                const std::int32_t v = joinSigned(regs[at], regs[at + 1]);
                if (v != ctl_.r(i))
                    (void)ctl_.setR(i, v); // a writable number, a 32-bit value, no program executing: accepted
            }
    }
    ++commits_;
    status_ = TransferStatus::Committed;
}

void ControllerImage::commit() {
    if (phase_ == Phase::StagingC || phase_ == Phase::StagingR) {
        commitBlock();
        return;
    }
    const bool messages = phase_ == Phase::WritingMessages;
    const std::string text = std::move(text_);
    const int number = transferProgram_;
    phase_ = Phase::Idle;
    text_.clear();
    if (text.size() != length_ || crc32(text) != crc_) {
        status_ = TransferStatus::CrcMismatch;
        return;
    }
    auto refuse = [&](int line) {
        status_ = TransferStatus::TextRefused;
        errorLine_ = static_cast<std::uint16_t>(std::clamp(line, 1, 65535));
    };
    program::ParseOptions po;
    po.programNumber = messages ? 1 : number;
    const engine::FileCheck check = engine::checkFileForMachine(text, po, ctl_.profile(), ctl_.programs());
    for (const program::Diagnostic& d : check.diagnostics)
        if (d.isError()) {
            refuse(d.line);
            return;
        }
    const program::ProgramStore& got = check.parsed.store;
    if (messages) {
        if (!got.empty() || !got.messages.present) {
            refuse(got.empty() ? 1 : got.programs()[0].headerLine);
            return;
        }
    } else {
        if (got.size() != 1 || got.programs()[0].number != number || got.messages.present ||
            got.programs()[0].headerLine == 0) {
            refuse(got.size() >= 1 ? std::max(1, got.programs()[got.size() > 1 ? 1 : 0].headerLine) : 1);
            return;
        }
    }
    program::ProgramStore* store = ctl_.editablePrograms();
    if (!store) {
        status_ = TransferStatus::NotInF7;
        return;
    }
    if (messages)
        store->messages = got.messages;
    else
        store->insert(got.programs()[0]);
    ctl_.programsEdited();
    ++commits_;
    status_ = TransferStatus::Committed;
}

} // namespace k528::link
