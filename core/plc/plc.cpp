#include "plc/plc.h"

#include "plc/description_texts.h"

#include <algorithm>
#include <bit>
#include <climits>
#include <cstring>

namespace k528::plc {

namespace {

using profile::problem;

constexpr std::int64_t kNever = INT64_MAX;

std::string zName(int word, int bit) {
    return "Z" + std::to_string(word) + "." + std::to_string(bit);
}

std::uint16_t keyMaskBits() {
    std::uint16_t m = 0;
    for (int k = 1; k <= 12; ++k)
        m = static_cast<std::uint16_t>(m | (1u << engine::z::keyBit(k)));
    return m;
}

} // namespace

// `id` about signal `name`, with where signal `s` is declared (its path, or
// «built in») as the last argument.
profile::Problem Plc::declaredAt(std::string id, const std::string& name, std::uint32_t s) const {
    if (declaredAt_[s].empty())
        return withText(std::move(id), {name}, "plc.built-in");
    return problem(std::move(id), {name, declaredAt_[s]});
}

std::uint32_t Plc::addSignal(const std::string& name, Kind kind, const std::string& path) {
    if (const auto it = index_.find(name); it != index_.end())
        throw DescriptionError(d_.source, path, declaredAt("plc.name-used", name, it->second));
    const auto s = static_cast<std::uint32_t>(names_.size());
    names_.push_back(name);
    kinds_.push_back(kind);
    declaredAt_.push_back(path); // "" built in
    index_.emplace(name, s);
    return s;
}

std::optional<std::uint32_t> Plc::resolve(std::string_view name) const {
    if (const auto it = index_.find(name); it != index_.end())
        return it->second;
    if (const auto z = parseZ(name); z && zSlot(z->word) >= 0)
        return zSignal(z->word, z->bit);
    return std::nullopt;
}

Expr Plc::compile(const std::string& text, const std::string& path) const {
    ExprError err;
    auto e = compileExpr(
        text, [this](std::string_view n) { return resolve(n); }, err);
    if (!e) {
        profile::Problem p = problem("condition", {std::to_string(err.column), text});
        p.within.push_back(problem(err.id, err.args));
        throw DescriptionError(d_.source, path, std::move(p));
    }
    return std::move(*e);
}

// A signal the logic may write: an output, a flag, or a Z bit of the words
// the PLC writes to the positioner (Z1000..Z1013, not the M acknowledgement,
// not the mode or override code when those sections exist).
std::uint32_t Plc::writable(const std::string& name, const std::string& path, bool asDriver) {
    const auto s = resolve(name);
    if (!s)
        throw DescriptionError(d_.source, path, problem("plc.unknown-signal", {name}));
    const Kind k = *s < kinds_.size() ? kinds_[*s] : Kind::ZIn;
    if (*s >= zBase_) {
        const auto z = parseZ(name);
        const int word = z ? z->word : 0, bit = z ? z->bit : 0;
        if (word < 1000 || word > 1013)
            throw DescriptionError(d_.source, path, problem("plc.not-logic", {name}));
        if (word == 1000 && bit == 11)
            throw DescriptionError(d_.source, path, problem("plc.z1000-11"));
        if (word == 1000 && bit >= 8 && bit <= 10 && !d_.modeRules.empty())
            throw DescriptionError(d_.source, path, problem("plc.mode-code", {name}));
        if (word == 1001 && bit >= 11 && d_.override_.present)
            throw DescriptionError(d_.source, path, problem("plc.override-code", {name}));
    } else if (k != Kind::Output && k != Kind::Flag) {
        throw DescriptionError(d_.source, path, declaredAt("plc.not-writable", name, *s));
    }
    if (asDriver) {
        if (driven_[*s])
            throw DescriptionError(d_.source, path, problem("plc.coil-twice", {name}));
        driven_[*s] = 1;
    }
    return *s;
}

Plc::CompiledActions Plc::compileActions(const Actions& a, const std::string& path) {
    CompiledActions c;
    for (const std::string& n : a.set)
        c.set.push_back(writable(n, path + ".set", false));
    for (const std::string& n : a.reset)
        c.reset.push_back(writable(n, path + ".reset", false));
    for (const std::string& n : a.toggle)
        c.toggle.push_back(writable(n, path + ".toggle", false));
    for (const std::string& n : a.pulse) {
        const std::uint32_t s = writable(n, path + ".pulse", false);
        pulseTarget_[s] = 1;
        c.pulse.push_back(s);
    }
    return c;
}

Plc::Plc(const MachineDescription& description) : d_(description) {
    static_assert(zSlot(1000) == 0 && zSlot(1013) == 13 && zSlot(1300) == 14 && zSlot(1307) == 21 &&
                  zSlot(1900) == 22 && zSlot(1907) == 29 && zSlot(2000) == 30 &&
                  zSlot(2008) == kZWords - 1 && zSlot(1014) < 0 && zSlot(2009) < 0);
    // --- the signal space -------------------------------------------------
    for (const InputDef& in : d_.inputs)
        inputSig_.push_back(addSignal(in.name, Kind::Input, in.path));
    for (const OutputDef& out : d_.outputs)
        outputSig_.push_back(addSignal(out.name, Kind::Output, out.path));
    for (const FlagDef& f : d_.flags)
        addSignal(f.name, Kind::Flag, f.path);
    for (const RungDef& r : d_.logic)
        if (r.kind == RungKind::OnDelay || r.kind == RungKind::OffDelay ||
            r.kind == RungKind::Pulse)
            addSignal(r.target, Kind::Timer, r.path);
    for (const InterlockDef& il : d_.interlocks)
        addSignal(il.name, Kind::Interlock, il.path);
    firstScanSig_ = addSignal("first_scan", Kind::Builtin, "");
    linkOkSig_ = addSignal("link_ok", Kind::Builtin, "");
    mBusySig_ = addSignal("m_busy", Kind::Builtin, "");
    ackSig_ = addSignal("acknowledged", Kind::Builtin, "");
    alarmSig_ = addSignal("alarm_active", Kind::Builtin, "");
    for (int k = 1; k <= 12; ++k)
        keySig_[k] = addSignal("K" + std::to_string(k), Kind::Builtin, "");
    zBase_ = static_cast<std::uint32_t>(names_.size());
    const std::size_t n = names_.size() + static_cast<std::size_t>(kZWords) * 16;
    sig_.assign(n, 0);
    prev_.assign(n, 0);
    latch_.assign(n, 0);
    driven_.assign(n, 0);
    pulseTarget_.assign(n, 0);
    for (std::uint32_t s = 0; s < zBase_; ++s)
        if (kinds_[s] == Kind::Timer || kinds_[s] == Kind::Interlock || kinds_[s] == Kind::Input ||
            kinds_[s] == Kind::Builtin)
            driven_[s] = 1; // not writable anyway

    // --- compile --------------------------------------------------------------
    for (const RungDef& r : d_.logic) {
        Rung c{r.kind, 0, compile(r.when, r.path + ".when"), r.ms};
        switch (r.kind) {
        case RungKind::Coil:
            c.target = writable(r.target, r.path + ".out", true);
            break;
        case RungKind::Set:
        case RungKind::Reset:
            c.target =
                writable(r.target, r.path + (r.kind == RungKind::Set ? ".set" : ".reset"), false);
            break;
        default:
            c.target = *resolve(r.target);
            break;
        }
        rungs_.push_back(std::move(c));
    }
    for (const SlotDef& s : d_.slotDefs) {
        const std::uint32_t sigIdx = zSignal(s.word, s.bit);
        if (driven_[sigIdx])
            throw DescriptionError(d_.source, s.path, problem("plc.slot-coil", {zName(s.word, s.bit)}));
        driven_[sigIdx] = 1;
        slots_.push_back({sigIdx, compile(s.when, s.path)});
    }
    for (const ModeRule& m : d_.modeRules)
        modeRules_.push_back({m.code, compile(m.when, m.path + ".when")});
    if (d_.override_.present) {
        overrideFromPlc_ = compile(d_.override_.fromPlc, d_.override_.path + ".from_plc");
        for (std::size_t i = 0; i < 4; ++i) {
            const auto s = resolve(d_.override_.code[i]);
            if (!s)
                throw DescriptionError(d_.source, d_.override_.path + ".code",
                                       problem("plc.unknown-signal", {d_.override_.code[i]}));
            overrideBits_[i] = *s;
        }
    }
    for (const MFunctionDef& f : d_.mFunctions) {
        MFunction mf{&f, compileActions(f.actions, f.path), std::nullopt};
        if (!f.done.empty())
            mf.done = compile(f.done, f.path + ".done");
        mfuncs_.emplace(f.m, std::move(mf));
    }
    for (const InterlockDef& il : d_.interlocks) {
        Interlock c{&il, compile(il.when, il.path + ".when"), *resolve(il.name), {}};
        for (const std::string& o : il.off)
            c.off.push_back(writable(o, il.path + ".off", false));
        interlocks_.push_back(std::move(c));
    }
    interlockLatched_.assign(interlocks_.size(), 0);
    for (const KeyDef& k : d_.keys) {
        Key c{&k, std::nullopt, compileActions(k.actions, k.path)};
        if (!k.when.empty())
            c.when = compile(k.when, k.path + ".when");
        keys_.push_back(std::move(c));
    }
    for (const LedDef& l : d_.leds) {
        Led c{l.key, std::nullopt, std::nullopt};
        if (!l.green.empty())
            c.green = compile(l.green, l.path + ".green");
        if (!l.red.empty())
            c.red = compile(l.red, l.path + ".red");
        leds_.push_back(std::move(c));
    }
    for (const MessageDef& m : d_.alarms)
        alarms_.push_back({m.k, compile(m.when, m.path + ".when")});
    for (const MessageDef& m : d_.work)
        work_.push_back({m.k, compile(m.when, m.path + ".when")});
    // A pulse target with a coil would lose its pulse; slots OR it in.
    for (std::uint32_t s = 0; s < zBase_; ++s)
        if (pulseTarget_[s] && driven_[s] && kinds_[s] != Kind::Timer)
            throw DescriptionError(d_.source, declaredAt_[s], problem("plc.pulse-coil", {names_[s]}));

    terminal_.assign(d_.inputs.size(), 0);
    candidate_.assign(d_.inputs.size(), 0);
    candidateSince_.assign(d_.inputs.size(), 0);
    outputs_.assign(d_.outputs.size(), 0);
    sig_[firstScanSig_] = 1;
    sig_[linkOkSig_] = 1;
}

std::optional<int> Plc::inputIndex(std::string_view name) const {
    for (std::size_t i = 0; i < d_.inputs.size(); ++i)
        if (d_.inputs[i].name == name)
            return static_cast<int>(i);
    return std::nullopt;
}

std::optional<int> Plc::outputIndex(std::string_view name) const {
    for (std::size_t i = 0; i < d_.outputs.size(); ++i)
        if (d_.outputs[i].name == name)
            return static_cast<int>(i);
    return std::nullopt;
}

std::optional<bool> Plc::signal(std::string_view name) const {
    const auto s = resolve(name);
    if (!s)
        return std::nullopt;
    return sig_[*s] != 0;
}

std::vector<std::string> Plc::activeInterlocks() const {
    std::vector<std::string> out;
    for (const Interlock& il : interlocks_)
        if (sig_[il.signal])
            out.push_back(il.def->name);
    return out;
}

void Plc::setModuleFailed(int place, bool failed) {
    const auto bit = static_cast<std::uint16_t>(1u << place);
    const auto before = failedModules_;
    failedModules_ =
        static_cast<std::uint16_t>(failed ? (failedModules_ | bit) : (failedModules_ & ~bit));
    if (before != failedModules_) {
        dirty_ = true;
        for (std::size_t i = 0; i < outputs_.size(); ++i)
            if (moduleFailed(d_.outputs[i].module))
                outputs_[i] = 0;
    }
}

void Plc::setLinkOk(bool ok) {
    if (ok == linkOk_)
        return;
    linkOk_ = ok;
    dirty_ = true;
    if (!ok)
        for (int w = 2000; w <= 2008; ++w)
            words_.setWord(w, 0); // «Нет ответа от БП»
}

void Plc::imposeMode(int code) {
    imposedMode_ = code >= 0 && code <= 7 ? code : -1;
    modeImposedOnce_ = modeImposedOnce_ || imposedMode_ >= 0;
    dirty_ = true;
}

void Plc::setStopped(bool stopped) {
    if (stopped == stopped_)
        return;
    stopped_ = stopped;
    dirty_ = true;
    if (!stopped) {
        // RUN again: a warm restart, as after power-on — nothing the program
        // had latched (drives on, a spindle request, an M in progress, a
        // remembered alarm) comes back by itself; the operator starts again.
        for (std::size_t i = 0; i < latch_.size(); ++i)
            if (latch_[i]) {
                latch_[i] = 0;
                if (!driven_[i])
                    sig_[i] = 0;
            }
        std::fill(interlockLatched_.begin(), interlockLatched_.end(), 0);
        pulses_.clear();
        mActive_ = mAcked_ = mTimedOut_ = mUnknownAlarm_ = false;
        keysPending_ = keysTaken_ = 0;
        sig_[firstScanSig_] = 1;
        wakeMs_ = 0;
        return;
    }
    {
        std::fill(outputs_.begin(), outputs_.end(), 0);
        for (int a = 1000; a <= 1013; ++a)
            words_.setWord(a, 0);
        for (int a = 1900; a <= 1907; ++a)
            words_.setWord(a, 0);
        words_.setWord(engine::z::SystemMessagesWord, 0);
    }
}

// The 16 signals of a word hold its bits, signal b bit b (0 or 1; packing
// reads any non-zero signal as 1). Eight signals at a time in one 64-bit
// word (little-endian: signal b of the eight is byte b): the scan packs and
// unpacks some forty words.
void Plc::unpackWord(int word, std::uint16_t value) {
    std::uint8_t* p = sig_.data() + zSignal(word, 0);
    if constexpr (std::endian::native == std::endian::little) {
        for (int h = 0; h < 2; ++h) {
            // Byte i of bits·0x0101… holds the eight bits; the mask keeps bit
            // i of them in byte i; + 0x7F carries it to bit 7 of its byte
            // (at most 0xFF: no carry on); shifted and masked, it is 0 or 1.
            const std::uint64_t bits = (value >> (8 * h)) & 0xFFu;
            const std::uint64_t v = ((((bits * 0x0101010101010101ull) & 0x8040201008040201ull) +
                                      0x7F7F7F7F7F7F7F7Full) >>
                                     7) &
                                    0x0101010101010101ull;
            std::memcpy(p + 8 * h, &v, sizeof v);
        }
    } else {
        for (int b = 0; b < 16; ++b)
            p[b] = static_cast<std::uint8_t>((value >> b) & 1u);
    }
}

std::uint16_t Plc::packWord(int word) const {
    const std::uint8_t* p = sig_.data() + zSignal(word, 0);
    unsigned v = 0;
    if constexpr (std::endian::native == std::endian::little) {
        for (int h = 0; h < 2; ++h) {
            std::uint64_t x;
            std::memcpy(&x, p + 8 * h, sizeof x);
            // Bit 7 of each byte set when the byte is not 0 (its low seven
            // bits + 0x7F reach bit 7 without a carry out of the byte) ...
            const std::uint64_t nonZero =
                (((x & 0x7F7F7F7F7F7F7F7Full) + 0x7F7F7F7F7F7F7F7Full) | x) & 0x8080808080808080ull;
            // ... and gathered: byte i's bit lands on bit 56 + i of the product.
            v |= static_cast<unsigned>(((nonZero >> 7) * 0x0102040810204080ull) >> 56) << (8 * h);
        }
    } else {
        for (int b = 0; b < 16; ++b)
            v |= static_cast<unsigned>(p[b] != 0) << b;
    }
    return static_cast<std::uint16_t>(v);
}

void Plc::readPositioner(const engine::InterfaceWords& w) {
    if (!linkOk_)
        return;
    // Read every tick: compared as one block, copied on a change.
    if (!words_.sameOutputs(w)) {
        words_.copyOutputs(w);
        dirty_ = true;
    }
    const auto keys = static_cast<std::uint16_t>(w.word(engine::z::KeysWord) & keyMaskBits());
    if ((keys & ~keysPending_) != 0) {
        keysPending_ = static_cast<std::uint16_t>(keysPending_ | keys);
        dirty_ = true;
    }
}

void Plc::writePositioner(engine::InterfaceWords& w) {
    for (int a = 1000; a <= 1013; ++a)
        w.setWord(a, words_.word(a));
    for (int a = 1900; a <= 1907; ++a)
        w.setWord(a, words_.word(a));
    w.setWord(engine::z::SystemMessagesWord, words_.word(engine::z::SystemMessagesWord));
    if (keysTaken_) {
        w.setWord(engine::z::KeysWord,
                  static_cast<std::uint16_t>(w.word(engine::z::KeysWord) & ~keysTaken_));
        keysTaken_ = 0;
    }
}

// ---------------------------------------------------------------------------
// Signal helpers

void Plc::setLatched(std::uint32_t s, bool v) {
    latch_[s] = v ? 1 : 0;
    if (driven_[s])
        return;
    bool pulsing = false;
    if (pulseTarget_[s])
        for (const Pulse& p : pulses_)
            pulsing = pulsing || p.signal == s;
    sig_[s] = static_cast<std::uint8_t>(latch_[s] || pulsing);
}

void Plc::startPulse(std::uint32_t s, std::int64_t endMs) {
    for (Pulse& p : pulses_)
        if (p.signal == s) {
            p.endMs = std::max(p.endMs, endMs);
            return;
        }
    pulses_.push_back({s, endMs});
}

bool Plc::pulseActive(std::uint32_t s, std::int64_t nowMs) const {
    for (const Pulse& p : pulses_)
        if (p.signal == s && nowMs < p.endMs)
            return true;
    return false;
}

// Undriven pulse targets: latch | pulse. Expired pulses are dropped.
void Plc::refreshPulses(std::int64_t nowMs) {
    for (std::size_t i = 0; i < pulses_.size();) {
        const Pulse p = pulses_[i];
        if (nowMs >= p.endMs) {
            if (!driven_[p.signal])
                sig_[p.signal] = latch_[p.signal];
            pulses_.erase(pulses_.begin() + static_cast<std::ptrdiff_t>(i));
            continue;
        }
        if (!driven_[p.signal])
            sig_[p.signal] = 1;
        wake(p.endMs);
        ++i;
    }
}

void Plc::apply(const CompiledActions& a, std::int64_t nowMs, int pulseMs) {
    for (std::uint32_t s : a.set)
        setLatched(s, true);
    for (std::uint32_t s : a.reset)
        setLatched(s, false);
    for (std::uint32_t s : a.toggle)
        setLatched(s, !latch_[s]);
    for (std::uint32_t s : a.pulse) {
        startPulse(s, nowMs + pulseMs);
        sig_[s] = 1;
    }
}

// ---------------------------------------------------------------------------
// The scan

void Plc::scan(std::int64_t nowMs) {
    dirty_ = false;
    nextWake_ = kNever;
    if (stopped_) {
        wakeMs_ = kNever; // «ОТЛАДКА СТОП»: nothing runs until setStopped(false)
        return;
    }
    ++scans_;

    // 1. Inputs with debounce: a new level counts once it has stood for the
    // input's debounce time.
    for (std::size_t i = 0; i < inputSig_.size(); ++i) {
        const std::uint8_t level =
            moduleFailed(d_.inputs[i].module) ? 0 : static_cast<std::uint8_t>(terminal_[i]);
        if (level != candidate_[i]) {
            candidate_[i] = level;
            candidateSince_[i] = nowMs;
        }
        const std::uint32_t s = inputSig_[i];
        if (scans_ == 1) {
            sig_[s] = candidate_[i]; // the filter starts settled on the levels at power-on
            continue;
        }
        if (sig_[s] != candidate_[i]) {
            const std::int64_t due = candidateSince_[i] + d_.inputs[i].debounceMs;
            if (nowMs >= due)
                sig_[s] = candidate_[i];
            else
                wake(due);
        }
    }
    sig_[linkOkSig_] = linkOk_ ? 1 : 0;
    sig_[alarmSig_] = (words_.word(1900) | words_.word(1901)) != 0;
    refreshPulses(nowMs);

    segment0In(nowMs);
    segment1Keys(nowMs);
    segment2(nowMs);
    interlocks(nowMs);
    mAcknowledge(nowMs);
    segment0Out(nowMs);

    // 8. Output terminals.
    for (std::size_t i = 0; i < outputSig_.size(); ++i)
        outputs_[i] = moduleFailed(d_.outputs[i].module) ? 0 : sig_[outputSig_[i]];
    for (int w = 1000; w <= 1013; ++w)
        words_.setWord(w, packWord(w));
    for (int w = 1900; w <= 1907; ++w)
        words_.setWord(w, packWord(w));
    words_.setWord(engine::z::SystemMessagesWord, packWord(engine::z::SystemMessagesWord));

    // Keys are one-scan signals.
    for (int k = 1; k <= 12; ++k)
        sig_[keySig_[k]] = 0;
    sig_[firstScanSig_] = 0;
    // A scan that changed a signal is followed by another (edges, settling);
    // otherwise the next one is due when an input, a word or a timer changes.
    if (std::memcmp(sig_.data(), prev_.data(), sig_.size()) != 0) {
        dirty_ = true;
        std::memcpy(prev_.data(), sig_.data(), sig_.size());
    }
    wakeMs_ = nextWake_;
}

void Plc::segment0In(std::int64_t nowMs) {
    for (int w = 2000; w <= 2008; ++w)
        unpackWord(w, words_.word(w));
    // The keys of Z1300 (2.3, table 4).
    words_.setWord(engine::z::KeysWord, keysPending_);
    unpackWord(engine::z::KeysWord, keysPending_);
    for (int k = 1; k <= 12; ++k)
        sig_[keySig_[k]] = static_cast<std::uint8_t>((keysPending_ >> engine::z::keyBit(k)) & 1u);
    keysTaken_ = static_cast<std::uint16_t>(keysTaken_ | keysPending_);
    keysPending_ = 0;

    // M function: the code on Z2001.0-6, the strobe Z2001.7 (GOST 26642 §6.4).
    const std::uint16_t w2001 = words_.word(engine::z::MCodeWord);
    const int code = w2001 & 0x7F;
    const bool strobe = (w2001 >> 7) & 1u;
    if (code != lastCode_) {
        lastCode_ = code;
        codeSinceMs_ = nowMs;
    }
    if (strobe && !mActive_) {
        mActive_ = true;
        mAcked_ = false;
        mTimedOut_ = false;
        mStartMs_ = nowMs;
        const auto it = mfuncs_.find(code);
        mCurrent_ = it != mfuncs_.end() ? &it->second : nullptr;
        MEvent e;
        e.code = code;
        e.codeMs = codeSinceMs_;
        e.strobeMs = nowMs;
        e.described = mCurrent_ != nullptr;
        mLog_.push_back(e);
        if (mCurrent_)
            apply(mCurrent_->actions, nowMs, std::max(d_.timing.t4Ms, 1));
        else
            mUnknownAlarm_ = !d_.unknownM.acknowledge;
    } else if (!strobe && mActive_) {
        // The positioner took the acknowledgement (or «Сброс» abandoned the hand-over).
        mActive_ = false;
        mCurrent_ = nullptr;
        mTimedOut_ = false;
        mUnknownAlarm_ = false;
        if (!mLog_.empty())
            mLog_.back().dropMs = nowMs;
    }
    sig_[mBusySig_] = mActive_ && !mAcked_;
}

void Plc::segment1Keys(std::int64_t nowMs) {
    for (const Key& k : keys_) {
        if (!sig_[keySig_[k.def->key]])
            continue;
        if (k.when && !k.when->eval(sig_.data(), prev_.data()))
            continue;
        apply(k.actions, nowMs, d_.timing.pulseMs);
    }
}

void Plc::segment2(std::int64_t nowMs) {
    const std::uint8_t* now = sig_.data();
    const std::uint8_t* prev = prev_.data();
    for (Rung& r : rungs_) {
        const bool in = r.when.eval(now, prev);
        switch (r.kind) {
        case RungKind::Coil:
            sig_[r.target] = in ? 1 : 0;
            break;
        case RungKind::Set:
            if (in)
                setLatched(r.target, true);
            break;
        case RungKind::Reset:
            if (in)
                setLatched(r.target, false);
            break;
        case RungKind::OnDelay:
            if (!in) {
                r.running = false;
                sig_[r.target] = 0;
            } else {
                if (!r.running) {
                    r.running = true;
                    r.startMs = nowMs;
                }
                const bool done = nowMs - r.startMs >= r.ms;
                sig_[r.target] = done ? 1 : 0;
                if (!done)
                    wake(r.startMs + r.ms);
            }
            break;
        case RungKind::OffDelay:
            if (in) {
                r.running = false;
                sig_[r.target] = 1;
            } else if (sig_[r.target]) {
                if (!r.running) {
                    r.running = true;
                    r.startMs = nowMs;
                }
                if (nowMs - r.startMs >= r.ms) {
                    sig_[r.target] = 0;
                    r.running = false;
                } else {
                    wake(r.startMs + r.ms);
                }
            }
            break;
        case RungKind::Pulse:
            if (in && !r.lastIn && !r.running) {
                r.running = true;
                r.startMs = nowMs;
            }
            if (r.running) {
                if (nowMs - r.startMs >= r.ms)
                    r.running = false;
                else
                    wake(r.startMs + r.ms);
            }
            sig_[r.target] = r.running ? 1 : 0;
            break;
        }
        r.lastIn = in;
    }
}

void Plc::interlocks(std::int64_t nowMs) {
    ilEstop_ = ilFeedHold_ = ilDataHold_ = ilStartInhibit_ = false;
    ilOverrideMax_ = -1;
    ilAlarms_ = ilWork_ = 0;
    const bool ack = sig_[zSignal(1000, 7)] != 0;
    sig_[ackSig_] = ack;
    for (std::size_t i = 0; i < interlocks_.size(); ++i) {
        const Interlock& il = interlocks_[i];
        const InterlockDef& d = *il.def;
        const bool cause = il.when.eval(sig_.data(), prev_.data());
        bool active = cause;
        if (d.latch) {
            if (cause)
                interlockLatched_[i] = 1;
            else if (ack)
                interlockLatched_[i] = 0;
            active = interlockLatched_[i] != 0;
        }
        const bool was = sig_[il.signal] != 0;
        sig_[il.signal] = active ? 1 : 0;
        if (!active)
            continue;
        if (!was) {
            // «Стоп» / «Сброс» to the positioner when the interlock trips.
            if (d.stopProgram)
                startPulse(zSignal(1000, 4), nowMs + d_.timing.pulseMs);
            if (d.resetProgram)
                startPulse(zSignal(1000, 5), nowMs + d_.timing.pulseMs);
            if (d.stopProgram || d.resetProgram)
                wake(nowMs + d_.timing.pulseMs);
        }
        ilEstop_ = ilEstop_ || d.estop;
        ilFeedHold_ = ilFeedHold_ || d.feedHold;
        ilDataHold_ = ilDataHold_ || d.dataHold;
        ilStartInhibit_ = ilStartInhibit_ || d.startInhibit;
        if (d.overrideMaxCode >= 0)
            ilOverrideMax_ = ilOverrideMax_ < 0 ? d.overrideMaxCode
                                                : std::min(ilOverrideMax_, d.overrideMaxCode);
        if (d.alarm > 0)
            ilAlarms_ |= 1u << (d.alarm - 1);
        if (d.work > 0)
            ilWork_ |= 1u << (d.work - 1);
        for (std::uint32_t s : il.off) {
            latch_[s] = 0;
            sig_[s] = 0;
        }
    }
}

void Plc::mAcknowledge(std::int64_t nowMs) {
    const std::uint32_t ackBit = zSignal(1000, 11);
    if (!mActive_) {
        sig_[ackBit] = 0;
        return;
    }
    if (!mAcked_) {
        bool done = false;
        if (mCurrent_)
            done = !mCurrent_->done || mCurrent_->done->eval(sig_.data(), prev_.data());
        else
            done = d_.unknownM.acknowledge;
        const std::int64_t t3 = mStartMs_ + d_.timing.t3Ms;
        if (done && nowMs >= t3) {
            mAcked_ = true;
            mTimedOut_ = false;
            if (!mLog_.empty())
                mLog_.back().ackMs = nowMs;
        } else if (done) {
            wake(t3);
        }
        if (!mAcked_ && mCurrent_ && mCurrent_->def->timeoutMs > 0) {
            const std::int64_t due = mStartMs_ + mCurrent_->def->timeoutMs;
            if (nowMs >= due) {
                if (!mTimedOut_ && !mLog_.empty())
                    mLog_.back().timedOut = true;
                mTimedOut_ = true;
            } else {
                wake(due);
            }
        }
    }
    sig_[ackBit] = mAcked_ ? 1 : 0;
    sig_[mBusySig_] = !mAcked_;
}

void Plc::segment0Out(std::int64_t nowMs) {
    const std::uint8_t* now = sig_.data();
    const std::uint8_t* prev = prev_.data();
    for (const Slot& s : slots_)
        sig_[s.signal] =
            static_cast<std::uint8_t>(s.when.eval(now, prev) || pulseActive(s.signal, nowMs));
    // Pulses onto the stop/reset bits from the interlocks (not slots' own targets).
    for (int bit : {4, 5}) {
        const std::uint32_t s = zSignal(1000, bit);
        if (pulseActive(s, nowMs))
            sig_[s] = 1;
    }
    // Interlocks act on the GOST 26642 signals.
    if (ilEstop_)
        sig_[zSignal(1000, 0)] = 0;
    if (ilFeedHold_)
        sig_[zSignal(1000, 1)] = 0;
    if (ilStartInhibit_)
        sig_[zSignal(1000, 2)] = 0;
    if (ilDataHold_)
        sig_[zSignal(1000, 6)] = 1;

    // Mode code Z1000.8-10.
    if (!modeRules_.empty() || modeImposedOnce_) {
        int code = imposedMode_ >= 0 ? imposedMode_ : 0;
        for (const ModeRuleC& m : modeRules_)
            if (imposedMode_ < 0 && m.when.eval(now, prev)) {
                code = m.code;
                break;
            }
        for (int b = 0; b < 3; ++b)
            sig_[zSignal(1000, 8 + b)] = static_cast<std::uint8_t>((code >> b) & 1);
    }
    // Override Z1001.11, code Z1001.12-15.
    if (overrideFromPlc_) {
        bool fromPlc = overrideFromPlc_->eval(now, prev);
        int code = 0;
        for (int b = 0; b < 4; ++b)
            code |= (sig_[overrideBits_[static_cast<std::size_t>(b)]] ? 1 : 0) << b;
        if (code > 10)
            code = 10;
        if (ilOverrideMax_ >= 0) {
            if (!fromPlc)
                code = 10; // the panel's choice is not known to the PLC: cap it
            fromPlc = true;
            code = std::min(code, ilOverrideMax_);
        }
        sig_[zSignal(1001, 11)] = fromPlc ? 1 : 0;
        for (int b = 0; b < 4; ++b)
            sig_[zSignal(1001, 12 + b)] = static_cast<std::uint8_t>(fromPlc ? (code >> b) & 1 : 0);
    } else if (ilOverrideMax_ >= 0) {
        sig_[zSignal(1001, 11)] = 1;
        for (int b = 0; b < 4; ++b)
            sig_[zSignal(1001, 12 + b)] = static_cast<std::uint8_t>((ilOverrideMax_ >> b) & 1);
    }

    // Segment 1, out: LEDs (table 4), messages.
    for (int w = 1900; w <= 1907; ++w)
        unpackWord(w, 0);
    for (const Led& l : leds_) {
        const int bit = engine::z::keyBit(l.key);
        if (l.green)
            sig_[zSignal(engine::z::GreenLedsWord, bit)] = l.green->eval(now, prev) ? 1 : 0;
        if (l.red)
            sig_[zSignal(engine::z::RedLedsWord, bit)] = l.red->eval(now, prev) ? 1 : 0;
    }
    std::uint32_t alarms = ilAlarms_, work = ilWork_;
    for (const Message& m : alarms_)
        if (m.when.eval(now, prev))
            alarms |= 1u << (m.k - 1);
    for (const Message& m : work_)
        if (m.when.eval(now, prev))
            work |= 1u << (m.k - 1);
    if (mActive_ && !mAcked_ && mCurrent_) {
        if (mCurrent_->def->waitWork > 0)
            work |= 1u << (mCurrent_->def->waitWork - 1);
        if (mTimedOut_)
            alarms |= 1u << (mCurrent_->def->timeoutAlarm - 1);
    }
    if (mActive_ && mUnknownAlarm_ && d_.unknownM.alarm > 0)
        alarms |= 1u << (d_.unknownM.alarm - 1);
    unpackWord(1900, static_cast<std::uint16_t>(alarms & 0xFFFF));
    unpackWord(1901, static_cast<std::uint16_t>(alarms >> 16));
    unpackWord(1902, static_cast<std::uint16_t>(work & 0xFFFF));
    unpackWord(1903, static_cast<std::uint16_t>(work >> 16));
    // System messages: module failures (table 2, Z1307.n = place n).
    unpackWord(engine::z::SystemMessagesWord, failedModules_);
}

} // namespace k528::plc
