// The texts a grade shows a student: an id and its arguments (numbers,
// frame names, coordinates — nothing in a language), rendered in Russian or
// English from core's catalog (catalog/training_texts.h), the way core keeps
// the names of the faults (machine::faultText) and the program diagnostics.
// `k528 grade` renders them from here; the desktop renders the same ids
// through tr() (app/studio/training/training_texts.h). An argument that is itself a text of two languages (a
// message of the positioner, a diagnostic) carries both.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace k528::training {

enum class Language { Ru, En };

// One argument: the same in both languages, or a pair.
struct TextArg {
    TextArg() = default;
    TextArg(std::string both) : ru(both), en(std::move(both)) {}
    TextArg(const char* both) : TextArg(std::string(both)) {}
    TextArg(std::string r, std::string e) : ru(std::move(r)), en(std::move(e)) {}
    std::string ru, en;
    const std::string& in(Language l) const { return l == Language::Ru ? ru : en; }
    bool operator==(const TextArg&) const = default;
};

struct Text {
    std::string id; // an id of the catalog ("overcut")
    std::vector<TextArg> args;
    bool operator==(const Text&) const = default;
};

// The text in a language; an id missing from the catalog renders as the id
// and its arguments (never thrown away).
std::string render(const Text& t, Language l);

// The arguments in language `l`, for a pattern's %1..%9 (profile::fillPattern).
std::vector<std::string> argsIn(std::span<const TextArg> args, Language l);

// Language-neutral formatting of the arguments: a length in mm with up to 3
// decimals ("30", "-40.5", "0.125"), an area in mm² (3 decimals), a whole
// number, and a frame as the panel names it ("L1 N7", or "L1" without N).
std::string mmArg(double mm);
std::string areaArg(double mm2);
std::string intArg(long long v);
std::string frameArg(int program, int n);

} // namespace k528::training
