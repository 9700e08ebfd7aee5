// The controller side of the link (shared/spec/link.md): what every holding
// register reads and writes on an engine::Positioner. The Modbus server (`k528
// serve`, Qt's QModbusRtuSerialServer) hands each request's registers here;
// the in-process transport of the tests does the same without a port.
//
// The F7 rule: a write of C- or R-parameters, and the commands that change
// memory (begin writing, delete, clear, stage a block), need the controller
// ready for the PC — УПРАВЛЕНИЕ ДАННЫМИ «РАБОТА С ПЭВМ» on the K923 (the
// owner says so with setPcReady; without it, the mode F7 with no program
// active) — else exception 06 (and status 16 for a command). The transfer
// state machine keeps one transfer at a time: a text (a program, the
// messages) or a block (C, R) staged through the same window. A written
// text is parsed and checked with the controller's own rules at commit and
// stored all or nothing; a staged block is checked at commit and goes in
// whole. Writes to the C and R registers themselves go in directly.
#pragma once

#include "link/register_map.h"

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace k528::engine {
class Positioner;
}

namespace k528::link {

// Modbus exception codes of the map.
enum class Exception : std::uint8_t {
    None = 0,
    IllegalFunction = 1, // 01
    IllegalAddress = 2,  // 02 an address outside the map (or a read-only register written)
    IllegalValue = 3,    // 03 a value outside its range; nothing of the request written
    NotReady = 6,        // 06 not in F7 «РАБОТА С ПЭВМ»
};

// Status register 7002.
enum class TransferStatus : std::uint16_t {
    Idle = 0,
    Ready = 1,
    Committed = 2,
    NotInF7 = 16,
    NoSuchProgram = 17,
    TextRefused = 18,
    CrcMismatch = 19,
    MemoryFull = 20,
};

enum class TransferCommand : std::uint16_t {
    ReadProgram = 1,
    WriteProgram = 2,
    ReadMessages = 3,
    WriteMessages = 4,
    Commit = 5,
    Abort = 6,
    DeleteProgram = 7,
    ClearC = 8,      // manual 2.6.8 «ОЧИСТКА С-ПАРАМ»
    ClearR = 9,      // «ОЧИСТКА Р-ПАРАМ»
    StageC = 10,     // begin writing the C block through the window, taken whole at commit
    StageR = 11,     // the same for the writable R-parameters
};
inline constexpr std::uint16_t kLastCommand = 11;

class ControllerImage {
public:
    explicit ControllerImage(engine::Positioner& controller, const RegisterMap& map = k528Map());

    // Who says the controller is ready for the PC (the K923's «РАБОТА С ПЭВМ»).
    void setPcReady(std::function<bool()> ready) { pcReady_ = std::move(ready); }
    bool pcReady() const;

    // FC 3: `count` registers from `first`. Exception 03 for a count outside
    // 1..125, 02 when any register is outside the map.
    Exception read(int first, int count, std::vector<std::uint16_t>& out);
    // FC 6 / 16: all or nothing. A write that covers the command register
    // sets the other registers first, then runs the command.
    Exception write(int first, std::span<const std::uint16_t> values);

    TransferStatus status() const { return status_; }
    const RegisterMap& map() const { return map_; }
    // Texts committed through the link (tests, the serve log).
    int commits() const { return commits_; }

private:
    std::uint16_t readOne(int reg) const;
    Exception writeC(int first, std::span<const std::uint16_t> values);
    Exception writeR(int first, std::span<const std::uint16_t> values);
    Exception writeTransfer(int first, std::span<const std::uint16_t> values);
    Exception command(std::uint16_t cmd);
    void commit();
    void commitBlock();
    void checkStillReady();
    bool writing() const;

    enum class Phase { Idle, ReadingProgram, ReadingMessages, WritingProgram, WritingMessages, StagingC, StagingR };

    engine::Positioner& ctl_;
    const RegisterMap& map_;
    std::function<bool()> pcReady_;
    Phase phase_ = Phase::Idle;
    TransferStatus status_ = TransferStatus::Idle;
    std::uint16_t programNumber_ = 0;
    std::uint16_t errorLine_ = 0;
    std::uint32_t length_ = 0, crc_ = 0, offset_ = 0;
    int transferProgram_ = 0; // the program of the transfer under way
    std::string text_;        // read: the controller's text; write: the bytes received
    int commits_ = 0;
};

} // namespace k528::link
