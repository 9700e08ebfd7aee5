#include "util/text_catalog.h"

#include "util/text_pattern.h"

namespace k528::util {

const CatalogText* TextCatalog::find(std::string_view id) const {
    for (const CatalogText& t : texts_)
        if (t.id == id)
            return &t;
    return nullptr;
}

std::string TextCatalog::render(std::string_view id, std::span<const std::string> args, bool russian) const {
    if (id.empty())
        return {};
    if (const CatalogText* t = find(id))
        return fillPattern(t->in(russian), args);
    std::string s(id);
    for (const std::string& a : args)
        s += " " + a;
    return s;
}

} // namespace k528::util
