// The controller link's texts (core/link/link_texts.h: an id and its
// arguments) in the window's language, through its translators; the
// command line says the same ids from core's catalog (studio.ui_language
// fails on an id this table lacks or says differently).
#pragma once

#include <QString>

#include <string_view>

namespace k528::link {
struct Said;
struct LinkError;
} // namespace k528::link

namespace k528::studio {

// E.g. «чтение регистров 6000..6031: контроллер не отвечает (попыток: 4, последняя: время ожидания истекло)».
QString linkText(const link::Said& s);
QString linkErrorText(const link::LinkError& e);
// A link plugin's error (a line failure of core's catalog, «соединение
// отклонено», else the system's own words).
QString lineErrorText(const QString& error);
bool hasLinkText(std::string_view id);

} // namespace k528::studio
