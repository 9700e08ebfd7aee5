// Handing M functions to the PLC (manual 2.7.1.1: «Их номера в начале
// отработки кадра передаются в ПЛК»; appendix И: Z2001.0-6 «Номер
// вспомогательной M-функции», Z2001.7 «Сигнал изменения M-функции»), with
// the strobe timing of GOST 26642 §6.4 and the acknowledgement the K528-05
// reads on the extension bit Z1000.11 (GOST «FIN»):
//
//   for each M of the frame, in the order written:
//     1. the code goes to Z2001.0-6;
//     2. ≥ T2 (m_code_lead_ms, 20 ms) later, and once Z1000.11 = 0, the strobe Z2001.7 = 1;
//     3. the PLC does the function and sets Z1000.11 = 1;
//     4. the strobe drops; the PLC drops Z1000.11 -> the next M.
//   The code stays on Z2001.0-6 until the next M or «Сброс».
// The PLC may hold a frame for as long as it wishes (no time-out).
#pragma once

#include "engine/interface_words.h"

#include <array>
#include <cstdint>

namespace k528::engine {

class MHandshake {
public:
    enum class Phase : std::uint8_t { Idle, Lead, Strobe, Release };

    void setLeadMs(std::int64_t ms) { leadMs_ = ms < 0 ? 0 : ms; }
    // Starts handing over `count` (0..3) codes.
    void begin(const int* codes, int count, std::int64_t nowMs);
    // Advances the protocol; true once every code is acknowledged.
    bool tick(InterfaceWords& w, std::int64_t nowMs);
    // Abandons the hand-over («Сброс»): strobe off, code 0.
    void cancel(InterfaceWords& w);

    bool busy() const { return phase_ != Phase::Idle; }
    Phase phase() const { return phase_; }
    int currentCode() const { return busy() ? codes_[static_cast<std::size_t>(next_)] : -1; }

private:
    void startCode(InterfaceWords& w, std::int64_t nowMs);

    std::array<int, 3> codes_{};
    int count_ = 0, next_ = 0;
    Phase phase_ = Phase::Idle;
    bool codeWritten_ = false;
    std::int64_t t0_ = 0, leadMs_ = 20;
};

} // namespace k528::engine
