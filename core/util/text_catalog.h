// A catalog of core's texts: ids with their Russian and English, patterns
// with %1..%9 for the arguments (util/text_pattern.h). Each area keeps one
// catalog (program diagnostics, PLC description problems, operator
// refusals, training texts, profile problems, link and database errors);
// the command line renders from it, the desktop renders the same ids
// through its translators (studio.ui_language fails on an id the desktop
// lacks or says differently).
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace k528::util {

// One text of a catalog.
struct CatalogText {
    std::string_view id, ru, en;
    constexpr std::string_view in(bool russian) const { return russian ? ru : en; }
};

// A view of a catalog's texts (a constexpr array of CatalogText).
class TextCatalog {
public:
    constexpr explicit TextCatalog(std::span<const CatalogText> texts) : texts_(texts) {}

    std::span<const CatalogText> texts() const { return texts_; }
    // The text `id`, or nullptr.
    const CatalogText* find(std::string_view id) const;
    // The text `id` in a language, its %1..%9 filled with `args`; an id the
    // catalog lacks says the id and its arguments ("id a b": never thrown
    // away), "" for an empty id.
    std::string render(std::string_view id, std::span<const std::string> args, bool russian) const;

private:
    std::span<const CatalogText> texts_;
};

} // namespace k528::util
