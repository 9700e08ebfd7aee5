// The notes of revisions that core and the desktop write (not a user's own):
// an id and its arguments. The revisions table keeps a note as its English
// text (what `k528 db log` prints and older databases hold); readNote() finds
// which note of this catalog a stored text is, so that a display says it in
// its own language (the desktop: app/studio/session/core_texts.cpp). A text
// that is none of them is a user's note, shown as written.
#pragma once

#include "profile/diff.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace k528::db {

struct Note {
    std::string id;                // one of noteTexts()
    std::vector<std::string> args; // %1, %2 …
};

struct NoteText {
    std::string_view id, en;
};
std::span<const NoteText> noteTexts();

// The English text, as stored.
std::string noteText(const Note& n);
// The note `summary` is (its arguments as stored), or nullopt for a user's
// own words. An argument of "set"/"changed" is a list of item keys (C022,
// R12, #3, A01, title, a simulation key): other words are a user's.
std::optional<Note> readNote(std::string_view summary);

// "changed C022, R12" (at most eight keys, then "and N more").
Note changedNote(const std::vector<profile::Change>& changes);

} // namespace k528::db
