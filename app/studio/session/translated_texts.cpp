#include "session/translated_texts.h"

#include "util/text_pattern.h"

#include <QCoreApplication>

namespace k528::studio {

const TranslatedText* TranslatedTexts::find(std::string_view id) const {
    for (const TranslatedText& t : table_)
        if (id == t.id)
            return &t;
    return nullptr;
}

QString TranslatedTexts::pattern(std::string_view id) const {
    const TranslatedText* t = find(id);
    return t ? QCoreApplication::translate(context_, t->english) : QString();
}

std::optional<QString> TranslatedTexts::text(std::string_view id, std::span<const std::string> args) const {
    const TranslatedText* t = find(id);
    if (!t)
        return std::nullopt;
    return QString::fromStdString(util::fillPattern(QCoreApplication::translate(context_, t->english).toStdString(), args));
}

} // namespace k528::studio
