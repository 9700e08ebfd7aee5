#include "training/procedure.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>

namespace k528::training {

namespace {

std::string upper(std::string_view s) {
    std::string u(s);
    for (char& c : u)
        if (c >= 'a' && c <= 'z')
            c = static_cast<char>(c - 'a' + 'A');
    return u;
}

std::optional<double> number(std::string_view s) {
    if (s.empty() || s.size() > 24)
        return std::nullopt;
    const std::string t(s);
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (end != t.c_str() + t.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::optional<std::int64_t> whole(std::string_view s) {
    const auto v = number(s);
    if (!v || *v != std::floor(*v) || std::fabs(*v) > 2147483647.0)
        return std::nullopt;
    return static_cast<std::int64_t>(*v);
}

// The text after "; OPERATOR:" / "; ОПЕРАТОР:" on a line, if it is one.
std::optional<std::string_view> operatorLine(std::string_view line) {
    std::size_t i = 0;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
        ++i;
    if (i >= line.size() || line[i] != ';')
        return std::nullopt;
    ++i;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
        ++i;
    const std::string_view rest = line.substr(i);
    for (std::string_view word : {std::string_view("OPERATOR:"), std::string_view("ОПЕРАТОР:")}) {
        if (rest.size() >= word.size() && upper(rest.substr(0, word.size())) == upper(word))
            return rest.substr(word.size());
        // «оператор:» in lower case (UTF-8 Cyrillic is not folded by upper()).
        if (word == "ОПЕРАТОР:" && rest.substr(0, std::string_view("оператор:").size()) == "оператор:")
            return rest.substr(std::string_view("оператор:").size());
    }
    return std::nullopt;
}

const std::string_view kTokens =
    "K923 keys (F1..F8 K1..K12 L1..L4 UP DOWN LEFT RIGHT MODE HELP ESC SHIFT PAR ACK INS DEL "
    "ENTER 0..9 . + - * / = % !, SHIFT+KEY), PUSH:BUTTON, HOLD:BUTTON:S, PUSH:ESTOP, PULL:ESTOP, "
    "WAIT:S, HOME, RUN, PROGRAM:N, R<n>=<v>, HANDWHEEL:X|Z|OFF, STEP:1|10|100, TURN:N, "
    "OVERRIDE:PCT, NEWWHEEL, DOOR:OPEN, DOOR:CLOSE";

// One token; false with `why` set when it is not a step.
bool parseToken(const std::string& token, ProcedureStep& st, Text& why) {
    const std::string t = upper(token);
    const auto bad = [&](std::string id, std::vector<TextArg> args = {}) {
        why = Text{std::move(id), std::move(args)};
        return false;
    };
    st.token = token;
    const auto colon = t.find(':');
    const std::string head = t.substr(0, colon);
    const std::string rest = colon == std::string::npos ? std::string() : t.substr(colon + 1);
    if (colon != std::string::npos) {
        if (head == "PUSH" || head == "HOLD" || head == "PULL") {
            std::string name = rest;
            if (head == "HOLD") {
                const auto c2 = rest.rfind(':');
                const auto s = c2 == std::string::npos ? std::nullopt : number(rest.substr(c2 + 1));
                if (!s || *s <= 0 || *s > 3600)
                    return bad("procedure.hold", {token});
                st.ms = std::max<std::int64_t>(1, std::llround(*s * 1000.0));
                name = rest.substr(0, c2);
            }
            if (name == "ESTOP") {
                if (head == "HOLD")
                    return bad("procedure.estop", {token});
                st.kind = head == "PULL" ? ProcedureStep::Kind::EstopPull
                                         : ProcedureStep::Kind::EstopPush;
                return true;
            }
            if (head == "PULL")
                return bad("procedure.estop", {token});
            const auto b = machine::buttonFromName(name);
            if (!b)
                return bad("procedure.button", {token});
            st.button = *b;
            st.kind = head == "HOLD" ? ProcedureStep::Kind::Hold : ProcedureStep::Kind::Push;
            if (head == "PUSH")
                st.ms = 100;
            return true;
        }
        if (head == "WAIT") {
            const auto s = number(rest);
            if (!s || *s < 0 || *s > 36000)
                return bad("procedure.wait", {token});
            st.kind = ProcedureStep::Kind::Wait;
            st.ms = std::llround(*s * 1000.0);
            return true;
        }
        if (head == "PROGRAM") {
            const auto n = whole(rest);
            if (!n || *n < 1 || *n > 99)
                return bad("procedure.program", {token});
            st.kind = ProcedureStep::Kind::Program;
            st.value = *n;
            return true;
        }
        if (head == "HANDWHEEL") {
            st.kind = ProcedureStep::Kind::Handwheel;
            if (rest == "OFF")
                st.value = 0;
            else if (rest == "X")
                st.value = 1;
            else if (rest == "Z")
                st.value = 2;
            else
                return bad("procedure.handwheel", {token});
            return true;
        }
        if (head == "STEP") {
            st.kind = ProcedureStep::Kind::HandwheelStep;
            if (rest == "1")
                st.value = 0;
            else if (rest == "10")
                st.value = 1;
            else if (rest == "100")
                st.value = 2;
            else
                return bad("procedure.step", {token});
            return true;
        }
        if (head == "TURN") {
            const auto n = whole(rest);
            if (!n || *n == 0 || std::llabs(*n) > 100000)
                return bad("procedure.turn", {token});
            st.kind = ProcedureStep::Kind::Turn;
            st.value = *n;
            return true;
        }
        if (head == "OVERRIDE") {
            const auto n = whole(rest);
            static constexpr int steps[] = {0, 1, 2, 5, 10, 20, 35, 50, 75, 90, 100};
            bool ok = false;
            for (int s : steps)
                ok = ok || (n && *n == s);
            if (!ok)
                return bad("procedure.override", {token});
            st.kind = ProcedureStep::Kind::Override;
            st.value = *n;
            return true;
        }
        if (head == "DOOR" && (rest == "OPEN" || rest == "CLOSE")) {
            st.kind = rest == "OPEN" ? ProcedureStep::Kind::DoorOpen : ProcedureStep::Kind::DoorClose;
            return true;
        }
    }
    if (t == "HOME") {
        st.kind = ProcedureStep::Kind::Home;
        return true;
    }
    if (t == "RUN") {
        st.kind = ProcedureStep::Kind::Run;
        return true;
    }
    if (t == "NEWWHEEL") {
        st.kind = ProcedureStep::Kind::NewWheel;
        return true;
    }
    // R<n>=<v>
    if (t.size() > 3 && t[0] == 'R' && std::isdigit(static_cast<unsigned char>(t[1]))) {
        const auto eq = t.find('=');
        const auto n = eq == std::string::npos ? std::nullopt : whole(t.substr(1, eq - 1));
        const auto v = eq == std::string::npos ? std::nullopt : whole(t.substr(eq + 1));
        if (!n || !v || *n < 0 || *n > 231)
            return bad("procedure.preset", {token});
        st.kind = ProcedureStep::Kind::Preset;
        st.r = static_cast<int>(*n);
        st.value = *v;
        return true;
    }
    if (const auto k = panel::parseKey(token)) {
        st.kind = ProcedureStep::Kind::Key;
        st.key = *k;
        return true;
    }
    return bad("procedure.unknown", {token, std::string(kTokens)});
}

} // namespace

Procedure standardProcedure(int program) {
    Procedure p;
    std::vector<ProcedureError> none;
    const std::string text = "; OPERATOR: PULL:ESTOP PUSH:DRIVES_ON WAIT:1 HOME PROGRAM:" +
                             std::to_string(program) + " PUSH:START RUN\n";
    p = readProcedure(text, program, none);
    for (ProcedureStep& s : p.steps)
        s.line = 0;
    p.standard = true;
    return p;
}

Procedure readProcedure(std::string_view text, int program, std::vector<ProcedureError>& errors) {
    Procedure p;
    p.standard = false;
    int lineNo = 0;
    bool any = false;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        const std::size_t end = text.find('\n', pos);
        std::string_view line =
            text.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos);
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        ++lineNo;
        if (const auto ops = operatorLine(line)) {
            any = true;
            std::string tok;
            const auto flush = [&] {
                if (tok.empty())
                    return;
                ProcedureStep st;
                st.line = lineNo;
                Text why;
                if (parseToken(tok, st, why))
                    p.steps.push_back(st);
                else
                    errors.push_back({lineNo, tok, why});
                tok.clear();
            };
            for (char c : *ops) {
                if (c == ' ' || c == '\t')
                    flush();
                else
                    tok += c;
            }
            flush();
        }
        if (end == std::string_view::npos)
            break;
        pos = end + 1;
    }
    if (!any)
        return standardProcedure(program);
    return p;
}

std::string formatProcedure(const Procedure& p) {
    std::string out;
    for (const ProcedureStep& s : p.steps)
        out += (out.empty() ? "" : " ") + s.token;
    return out;
}

} // namespace k528::training
