#include "panel/keys.h"

#include <array>
#include <cctype>

namespace k528::panel {

namespace {
constexpr std::array<std::string_view, kKeyCount> kNames = {
    "F1", "F2", "F3", "F4", "F5", "F6", "F7", "F8",
    "K1", "K2", "K3", "K4", "K5", "K6", "K7", "K8", "K9", "K10", "K11", "K12",
    "L1", "L2", "L3", "L4",
    "UP", "DOWN", "LEFT", "RIGHT",
    "MODE", "HELP", "ESC", "SHIFT", "PAR", "ACK", "INS", "DEL", "ENTER",
    "0", "1", "2", "3", "4", "5", "6", "7", "8", "9",
    ".", "+", "-", "*", "/", "=", "%", "!",
};

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(a[i])) != std::toupper(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}
} // namespace

std::string_view keyName(Key k) { return kNames[static_cast<std::size_t>(k)]; }

std::optional<Key> keyFromName(std::string_view name) {
    for (int i = 0; i < kKeyCount; ++i)
        if (equalsIgnoreCase(kNames[static_cast<std::size_t>(i)], name))
            return static_cast<Key>(i);
    return std::nullopt;
}

std::string formatKey(const KeyPress& k) {
    return (k.shift ? "SHIFT+" : "") + std::string(keyName(k.key));
}

std::optional<KeyPress> parseKey(std::string_view text) {
    bool shift = false;
    if (text.size() > 6 && equalsIgnoreCase(text.substr(0, 6), "SHIFT+")) {
        shift = true;
        text.remove_prefix(6);
    }
    const auto k = keyFromName(text);
    if (!k)
        return std::nullopt;
    return KeyPress{*k, shift};
}

std::vector<std::string> splitKeys(std::string_view keys) {
    std::vector<std::string> out;
    std::size_t i = 0;
    while (i < keys.size()) {
        while (i < keys.size() && std::isspace(static_cast<unsigned char>(keys[i])))
            ++i;
        const std::size_t start = i;
        while (i < keys.size() && !std::isspace(static_cast<unsigned char>(keys[i])))
            ++i;
        if (i > start)
            out.emplace_back(keys.substr(start, i - start));
    }
    return out;
}

int digitOf(Key k) {
    const int v = static_cast<int>(k) - static_cast<int>(Key::D0);
    return v >= 0 && v <= 9 ? v : -1;
}

int functionNumber(Key k) {
    const int i = static_cast<int>(k);
    if (k >= Key::F1 && k <= Key::F8)
        return i - static_cast<int>(Key::F1) + 1;
    if (k >= Key::K1 && k <= Key::K12)
        return i - static_cast<int>(Key::K1) + 1;
    if (k >= Key::L1 && k <= Key::L4)
        return i - static_cast<int>(Key::L1) + 1;
    return 0;
}

bool isFunctionKey(Key k) { return k >= Key::F1 && k <= Key::F8; }
bool isKKey(Key k) { return k >= Key::K1 && k <= Key::K12; }
bool isLKey(Key k) { return k >= Key::L1 && k <= Key::L4; }

} // namespace k528::panel
