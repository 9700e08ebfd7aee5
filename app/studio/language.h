// The desktop UI's language (ru/en, Qt Linguist): chosen on the command line,
// else the saved setting, else the system locale (Russian on a Russian system,
// English elsewhere). Switching at run time retranslates every open window.
// Two translators: ours (k528studio_<lang>.qm) and Qt's own (qtbase_<lang>.qm
// of Debian's qt6-translations-l10n) for file dialogs and standard buttons.
// The libraries' gettext messages (libpq's, the C library's) follow it too
// (LANGUAGE, set before libpq's first use).
#pragma once

#include <QString>

namespace k528::studio {

// "ru" or "en".
QString savedOrSystemLanguage();
// Installs the translator for `language` ("ru"/"en") and saves the choice.
// Returns false if the language is not one of ours.
bool setLanguage(const QString& language);
QString currentLanguage();
// Qt's own translation (qtbase_ru.qm: file dialogs, standard buttons) is
// installed — for Russian; English needs none.
bool qtTranslationsLoaded();

} // namespace k528::studio
