#include "db/notes.h"

#include "db/revisions.h"
#include "profile/problem.h"

#include <array>

namespace k528::db {

namespace {

constexpr std::array kNotes = {
    NoteText{"seed", "built-in profile %1 (first start)"},
    NoteText{"created", "created"},
    NoteText{"set", "set %1"},
    NoteText{"changed", "changed %1"},
    NoteText{"changed-more", "changed %1 and %2 more"},
    NoteText{"changed-order", "changed order of simulation settings"},
    NoteText{"import", "import %1"},
    NoteText{"studio.import", "import %1 (K528 Studio)"},
    NoteText{"studio.loaded", "the machine as K528 Studio loaded it"},
    NoteText{"studio.kept", "kept from the simulated controller's memory (K528 Studio)"},
    NoteText{"studio.editor", "programs and messages from the editor (K528 Studio)"},
    NoteText{"studio.set", "set %1 = %2 (K528 Studio)"},
    NoteText{"studio.undo", "undo: %1"}, // %1: the note of the change undone, as stored
    NoteText{"studio.presets", "presets %1 (K528 Studio)"},
    // the trainer's lock of the machine constants for a class (the desktop's training course)
    NoteText{"studio.lock", "constants locked for the class %1 (trainer)"},
    NoteText{"studio.unlock", "constants unlocked (trainer; were locked for %1)"},
    // a trial part's correction of a tool's offset (k528 db trial, the desktop's dialog)
    NoteText{"trial", "trial part: T%1 %2 measured %3 for %4: R%5 %6 -> %7"},
};

// A key of an item a revision changes: C022, R12, #3, A01/W01/S01, title,
// name, a simulation key (a-z, 0-9, '_', '.').
bool itemKey(std::string_view k) {
    if (k.empty())
        return false;
    const auto digits = [](std::string_view s) {
        return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
    };
    if ((k[0] == 'C' || k[0] == 'R' || k[0] == '#' || k[0] == 'A' || k[0] == 'W' || k[0] == 'S' ||
         k[0] == 'L') &&
        digits(k.substr(1)))
        return true;
    if (k == "title" || k == "name")
        return true;
    // A simulation key has a '.' or '_' (x.kv, tick_ms): one English word alone is a user's.
    if (k.find_first_of("._") == std::string_view::npos)
        return false;
    for (char c : k)
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.'))
            return false;
    return true;
}

bool keyList(std::string_view s) {
    std::size_t i = 0;
    bool any = false;
    while (i < s.size()) {
        std::size_t j = s.find_first_of(" ,", i);
        if (j == std::string_view::npos)
            j = s.size();
        if (j > i) {
            if (!itemKey(s.substr(i, j - i)))
                return false;
            any = true;
        }
        i = j + 1;
    }
    return any;
}

// `s` as `pattern` with %1, %2 standing for any text; the texts in `args`.
bool match(std::string_view pattern, std::string_view s, std::vector<std::string>& args) {
    args.clear();
    const std::size_t p = pattern.find('%');
    if (p == std::string_view::npos)
        return s == pattern;
    if (s.substr(0, p) != pattern.substr(0, p))
        return false;
    const std::string_view restPattern = pattern.substr(p + 2);
    const std::size_t next = restPattern.find('%');
    const std::string_view literal = restPattern.substr(0, next);
    // The argument is followed by `literal`: the last occurrence when it ends the pattern.
    std::size_t at;
    if (next == std::string_view::npos) {
        if (s.size() < p + literal.size() || s.substr(s.size() - literal.size()) != literal)
            return false;
        at = s.size() - literal.size();
    } else {
        at = literal.empty() ? std::string_view::npos : s.find(literal, p);
        if (at == std::string_view::npos)
            return false;
    }
    if (at < p)
        return false;
    args.emplace_back(s.substr(p, at - p));
    if (args.back().empty())
        return false;
    if (next == std::string_view::npos)
        return true;
    std::vector<std::string> more;
    if (!match(restPattern.substr(next), s.substr(at + literal.size()), more))
        return false;
    args.insert(args.end(), more.begin(), more.end());
    return true;
}

} // namespace

std::span<const NoteText> noteTexts() { return kNotes; }

std::string noteText(const Note& n) {
    for (const NoteText& t : kNotes)
        if (t.id == n.id)
            return profile::fillPattern(t.en, n.args);
    return n.id;
}

std::optional<Note> readNote(std::string_view summary) {
    std::vector<std::string> args;
    for (const NoteText& t : kNotes) {
        if (!match(t.en, summary, args))
            continue;
        const std::string_view id = t.id;
        if ((id == "set" || id == "changed" || id == "changed-more" || id == "studio.set") && !keyList(args[0]))
            continue;
        if (id == "changed-more" && args[1].find_first_not_of("0123456789") != std::string::npos)
            continue;
        if ((id == "import" || id == "seed") && args[0].find(' ') != std::string::npos)
            continue; // a file's or a machine's name, not a sentence
        return Note{std::string(id), args};
    }
    return std::nullopt;
}

Note changedNote(const std::vector<profile::Change>& changes) {
    std::string s;
    std::size_t shown = 0;
    for (const auto& c : changes) {
        if (c.key == revision::kOrderKey)
            continue;
        if (shown == 8)
            return Note{"changed-more", {s, std::to_string(changes.size() - shown)}};
        s += (shown ? ", " : "") + c.key;
        ++shown;
    }
    if (s.empty())
        return Note{"changed-order", {}};
    return Note{"changed", {s}};
}

} // namespace k528::db
