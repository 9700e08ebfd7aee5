#include "panel/text.h"

#include "util/utf8.h"

#include <cinttypes>
#include <cstdio>
#include <cstdlib>

namespace k528::panel {

__extension__ typedef __int128 Wide; // exact products of scaled values

// ---------------------------------------------------------------------------
// Canvas

Canvas::Canvas() {
    for (auto& row : cells_)
        row.fill(U' ');
}

void Canvas::put(int row, int col, std::string_view text) {
    if (row < 0 || row >= kLcdRows)
        return;
    int c = col;
    for (const char32_t cp : utf8::decode(text)) {
        if (c >= 1 && c <= kLcdColumns)
            cells_[static_cast<std::size_t>(row)][static_cast<std::size_t>(c - 1)] = cp;
        ++c;
    }
}

void Canvas::putRight(int row, int lastCol, std::string_view text) {
    put(row, lastCol - textWidth(text) + 1, text);
}

void Canvas::clearRow(int row) {
    if (row >= 0 && row < kLcdRows)
        cells_[static_cast<std::size_t>(row)].fill(U' ');
}

void Canvas::blink(int row, int col, int len) {
    if (col < 1) {
        len -= 1 - col;
        col = 1;
    }
    if (col + len - 1 > kLcdColumns)
        len = kLcdColumns - col + 1;
    blinkRow_ = row;
    blinkCol_ = col;
    blinkLen_ = len > 0 ? len : 0;
}

char32_t Canvas::at(int row, int col) const {
    if (row < 0 || row >= kLcdRows || col < 1 || col > kLcdColumns)
        return U' ';
    return cells_[static_cast<std::size_t>(row)][static_cast<std::size_t>(col - 1)];
}

std::string Canvas::line(int row) const {
    std::string s;
    for (const char32_t cp : cells_[static_cast<std::size_t>(row)])
        utf8::append(s, cp);
    return s;
}

Lcd Canvas::lcd() const {
    Lcd l;
    for (int r = 0; r < kLcdRows; ++r)
        l.lines[static_cast<std::size_t>(r)] = line(r);
    if (blinkLen_ > 0) {
        l.blinkRow = blinkRow_;
        l.blinkColumn = blinkCol_ - 1;
        l.blinkLength = blinkLen_;
    }
    return l;
}

// ---------------------------------------------------------------------------
// Text

int textWidth(std::string_view s) {
    return static_cast<int>(utf8::length(s));
}

std::string padLeft(std::string_view s, int width) {
    const int w = textWidth(s);
    return w >= width ? std::string(s)
                      : std::string(static_cast<std::size_t>(width - w), ' ') + std::string(s);
}

std::vector<std::string> wrapText(std::string_view text, int width) {
    std::vector<char32_t> cps = utf8::decode(text);
    std::vector<std::string> lines;
    std::size_t i = 0;
    while (i < cps.size()) {
        while (i < cps.size() && cps[i] == U' ')
            ++i;
        if (i >= cps.size())
            break;
        const std::size_t rest = cps.size() - i;
        std::size_t take =
            rest <= static_cast<std::size_t>(width) ? rest : static_cast<std::size_t>(width);
        std::size_t next = i + take;
        if (take < rest) {
            // Prefer a break at a blank (the blank is dropped) or after a
            // '/', '.', ',' or '-' — whichever keeps more on this line.
            std::size_t best = 0;
            for (std::size_t k = 1; k <= take; ++k) {
                const char32_t c = cps[i + k - 1];
                if (k < take + 1 && i + k < cps.size() && cps[i + k] == U' ')
                    best = k; // break before the blank that follows
                if (c == U'/' || c == U'.' || c == U',' || c == U'-')
                    best = k;
            }
            if (best > 0) {
                take = best;
                next = i + take;
            }
        }
        std::vector<char32_t> part(cps.begin() + static_cast<std::ptrdiff_t>(i),
                                   cps.begin() + static_cast<std::ptrdiff_t>(i + take));
        while (!part.empty() && part.back() == U' ')
            part.pop_back();
        lines.push_back(utf8::encode(part));
        i = next;
    }
    return lines;
}

// ---------------------------------------------------------------------------
// Numbers

std::string formatCoordinate(std::int64_t disc, const units::AxisScale& s) {
    return units::formatDisc(disc, s);
}

namespace {

// |v| * num / den rounded half away from zero, with v's sign.
std::int64_t scaleRound(std::int64_t v, std::int64_t num, std::int64_t den) {
    const Wide mag = static_cast<Wide>(v < 0 ? -static_cast<Wide>(v) : static_cast<Wide>(v)) * num;
    const Wide q = (mag + den / 2) / den;
    return static_cast<std::int64_t>(v < 0 ? -q : q);
}

Wide pow10(int n) {
    Wide p = 1;
    for (int i = 0; i < n; ++i)
        p *= 10;
    return p;
}

} // namespace

std::string formatScaled(std::int64_t scaled, int decimals) {
    if (decimals <= 0)
        return std::to_string(scaled);
    const std::uint64_t mag =
        scaled < 0 ? 0 - static_cast<std::uint64_t>(scaled) : static_cast<std::uint64_t>(scaled);
    const auto per = static_cast<std::uint64_t>(pow10(decimals));
    const std::string frac = std::to_string(mag % per);
    std::string s;
    if (scaled < 0)
        s.push_back('-');
    s.append(std::to_string(mag / per));
    s.push_back('.');
    s.append(static_cast<std::size_t>(decimals) - frac.size(), '0');
    s.append(frac);
    return s;
}

std::string formatFeed(std::int64_t discPerMin, const units::AxisScale& s, int maxWidth) {
    const std::int64_t dpm = s.discretesPerMm();
    for (int decimals = 2; decimals >= 0; --decimals) {
        const std::int64_t scaled =
            scaleRound(discPerMin, static_cast<std::int64_t>(pow10(decimals)), dpm);
        std::string t = formatScaled(scaled, decimals);
        if (maxWidth <= 0 || textWidth(t) <= maxWidth || decimals == 0)
            return t;
    }
    return {};
}

std::string formatSeconds(std::int64_t ms) {
    return formatScaled(ms, 3);
}

std::optional<std::int64_t> evaluateEntry(std::string_view text, int decimals) {
    if (decimals < 0 || decimals > 6 || text.empty())
        return std::nullopt;
    const Wide scale = pow10(decimals);
    const Wide limit = static_cast<Wide>(INT64_MAX);
    std::size_t i = 0;
    // One number with an optional sign: "-12.5" -> scaled.
    const auto number = [&](Wide& out) {
        bool neg = false;
        if (i < text.size() && text[i] == '-') {
            neg = true;
            ++i;
        }
        Wide v = 0;
        int digits = 0, frac = -1;
        for (; i < text.size(); ++i) {
            const char c = text[i];
            if (c >= '0' && c <= '9') {
                if (frac >= 0) {
                    if (++frac > decimals)
                        return false;
                }
                v = v * 10 + (c - '0');
                if (v > limit)
                    return false;
                ++digits;
            } else if (c == '.' && frac < 0) {
                frac = 0;
            } else {
                break;
            }
        }
        if (digits == 0)
            return false;
        v *= pow10(decimals - (frac < 0 ? 0 : frac));
        out = neg ? -v : v;
        return out <= limit && out >= -limit;
    };
    Wide acc = 0;
    if (!number(acc))
        return std::nullopt;
    while (i < text.size()) {
        const char op = text[i++];
        Wide b = 0;
        if (!number(b))
            return std::nullopt;
        switch (op) {
        case '+':
            acc += b;
            break;
        case '-':
            acc -= b;
            break;
        case '*': {
            const Wide p = acc * b;
            const Wide mag = p < 0 ? -p : p;
            const Wide q = (mag + scale / 2) / scale;
            acc = p < 0 ? -q : q;
            break;
        }
        case '/': {
            if (b == 0)
                return std::nullopt;
            const Wide n = acc * scale;
            const Wide an = n < 0 ? -n : n, ab = b < 0 ? -b : b;
            const Wide q = (an + ab / 2) / ab;
            acc = (n < 0) != (b < 0) ? -q : q;
            break;
        }
        default:
            return std::nullopt;
        }
        if (acc > limit || acc < -limit)
            return std::nullopt;
    }
    return static_cast<std::int64_t>(acc);
}

// ---------------------------------------------------------------------------
// Entry

char typedChar(Key k) {
    const int d = digitOf(k);
    if (d >= 0)
        return static_cast<char>('0' + d);
    switch (k) {
    case Key::Point:
        return '.';
    case Key::Plus:
        return '+';
    case Key::Minus:
        return '-';
    case Key::Multiply:
        return '*';
    case Key::Divide:
        return '/';
    case Key::Equals:
        return '=';
    case Key::Percent:
        return 'R';
    default:
        return 0;
    }
}

void Entry::start(Kind kind, int maxChars, int decimals) {
    kind_ = kind;
    max_ = maxChars;
    decimals_ = decimals;
    active_ = true;
    text_.clear();
}

namespace {
bool isOp(char c) {
    return c == '+' || c == '-' || c == '*' || c == '/';
}
bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
} // namespace

bool Entry::type(Key k) {
    const char c = typedChar(k);
    if (c == 0 || c == '=')
        return false;
    const bool empty = text_.empty();
    const char last = empty ? 0 : text_.back();
    bool ok = false;
    switch (kind_) {
    case Kind::Digits:
        ok = isDigit(c);
        break;
    case Kind::Calculator:
        if (isDigit(c))
            ok = true;
        else if (c == '.')
            ok = true; // more decimals than the field has fail at ENTER (ОШИБКА ВВОДА)
        else if (c == '-')
            ok = true; // a sign or a subtraction; malformed texts fail at ENTER
        else if (isOp(c))
            ok = !empty;
        break;
    case Kind::Frame:
        if (c == 'R')
            ok = empty;
        else if (c == '-')
            ok = empty;
        else if (c == '.')
            ok = text_.find('.') == std::string::npos && text_.find('R') == std::string::npos;
        else
            ok = isDigit(c);
        break;
    case Kind::Operand:
        if (c == 'R' || c == '-')
            ok = empty;
        else
            ok = isDigit(c);
        break;
    case Kind::OpOperand:
        if (empty)
            ok = isOp(c);
        else if (c == 'R' || c == '-')
            ok = text_.size() == 1 && c != last;
        else
            ok = isDigit(c);
        break;
    }
    if (!ok)
        return false;
    if (static_cast<int>(text_.size()) < max_)
        text_.push_back(c);
    return true;
}

bool Entry::begin(Key k, Kind kind, int maxChars, int decimals) {
    if (!active_)
        start(kind, maxChars, decimals);
    const bool typed = type(k);
    if (text_.empty())
        stop();
    return typed;
}

bool Entry::assignResult() {
    const auto v = evaluateEntry(text_, decimals_);
    if (!v)
        return false;
    text_ = formatScaled(*v, decimals_);
    return true;
}

void Entry::backspace() {
    if (!text_.empty())
        text_.pop_back();
}

Entry::Answer Entry::answer(Key k, std::string& given) {
    if (k == Key::Enter) {
        given = text_;
        stop();
        return Answer::Given;
    }
    if (k == Key::Par) {
        stop();
        return Answer::Withdrawn;
    }
    if (k == Key::Del)
        backspace();
    else
        type(k);
    return Answer::Typing;
}

} // namespace k528::panel
