// The desktop UI's language (ru/en, Qt Linguist): chosen on the command line,
// else the saved setting, else the system locale (Russian on a Russian system,
// English elsewhere). Switching at run time retranslates every open window.
#pragma once

#include <QString>

namespace k528::studio {

// "ru" or "en".
QString savedOrSystemLanguage();
// Installs the translator for `language` ("ru"/"en") and saves the choice.
// Returns false if the language is not one of ours.
bool setLanguage(const QString& language);
QString currentLanguage();

} // namespace k528::studio
