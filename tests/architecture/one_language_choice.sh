#!/bin/sh
# usage: one_language_choice.sh STUDIO_SOURCE_DIR
# The studio picks between what core gives in both languages in one place
# (window_language.h: inWindowLanguage, coreText). russianWindow() itself
# stays for what is about the language rather than a choice between two
# texts: the language's implementation, the menu that switches it, the
# locale of the backplot's numbers, the language of a setup sheet's PDF.
set -u
studio=$1
. "$(dirname "$0")/allowed_files.sh"
allowed='
window_language.h
language.cpp
main_window.cpp
backplot/backplot_widget.cpp
editor/setup_sheet_actions.cpp
'
only_in "$studio" 'russianWindow[[:space:]]*\(' "$allowed" \
    'calls russianWindow(): choose a text by inWindowLanguage() or coreText() (window_language.h)'
[ $status -eq 0 ] && echo "one language choice: russianWindow() only where the language itself is meant"
exit $status
