#include "engine/m_handshake.h"

namespace k528::engine {

void MHandshake::begin(const int* codes, int count, std::int64_t nowMs) {
    count_ = count < 0 ? 0 : (count > 3 ? 3 : count);
    for (int i = 0; i < count_; ++i)
        codes_[static_cast<std::size_t>(i)] = codes[i];
    next_ = 0;
    t0_ = nowMs;
    codeWritten_ = false;
    phase_ = count_ > 0 ? Phase::Lead : Phase::Idle;
}

void MHandshake::startCode(InterfaceWords& w, std::int64_t nowMs) {
    w.setField(z::MCodeWord, z::MCodeFirst, z::MCodeWidth,
               static_cast<unsigned>(codes_[static_cast<std::size_t>(next_)]));
    w.setBit(z::MStrobe, false);
    t0_ = nowMs;
    codeWritten_ = true;
}

bool MHandshake::tick(InterfaceWords& w, std::int64_t nowMs) {
    switch (phase_) {
    case Phase::Idle:
        return true;
    case Phase::Lead:
        if (!codeWritten_)
            startCode(w, nowMs);
        if (nowMs - t0_ >= leadMs_ && !w.bit(z::MAcknowledge)) {
            w.setBit(z::MStrobe, true);
            phase_ = Phase::Strobe;
        }
        return false;
    case Phase::Strobe:
        if (w.bit(z::MAcknowledge)) {
            w.setBit(z::MStrobe, false);
            phase_ = Phase::Release;
        }
        return false;
    case Phase::Release:
        if (!w.bit(z::MAcknowledge)) {
            ++next_;
            if (next_ >= count_) {
                phase_ = Phase::Idle;
                return true;
            }
            phase_ = Phase::Lead;
            startCode(w, nowMs);
        }
        return false;
    }
    return true;
}

void MHandshake::cancel(InterfaceWords& w) {
    w.setBit(z::MStrobe, false);
    w.setField(z::MCodeWord, z::MCodeFirst, z::MCodeWidth, 0);
    phase_ = Phase::Idle;
    count_ = next_ = 0;
    codeWritten_ = false;
}

} // namespace k528::engine
