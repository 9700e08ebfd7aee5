#!/bin/sh
# usage: cli_texts_from_catalog.sh CLI_SOURCE_DIR
# The command line says its words from one catalog (cli_texts.cpp: an id,
# its Russian and its English), rendered in the command's --lang. A choice
# written in a command between two literal texts by the language —
#   ru ? "…" : "…",  lang == Lang::Ru ? "…" : "…",  russianCommandLine() ? "…",
#   ru ? std::string("…") …, or the condition ending a line and the texts
#   on the next ones, or a helper choosing between its two text arguments
#   (ru ? russian : english) — is a second translation system: a sentence the
#   catalog's checks (cli.lang) never see, and one that drifts from the same
#   sentence said elsewhere. Naming the language itself (? "ru" : "en", the
#   --lang a helper program is given) is not a choice between texts.
set -u
cli=$1
catalog='cli_texts.cpp'
cond='(russian[A-Za-z]*(\(\))?|\<ru|Lang::Ru|\<lang)[[:space:]]*\?[[:space:]]*'
literal="$cond"'(std::string(_view)?\(|u8)?"'
dangling="$cond"'$'
helper="$cond"'russian[[:space:]]*:[[:space:]]*english'
status=0
n=0
for path in $(cd "$cli" && find . -name '*.cpp' -o -name '*.h' | sed 's|^\./||' | sort); do
    [ "$path" = "$catalog" ] && continue
    n=$((n + 1))
    hits=$(grep -nE "$literal|$dangling|$helper" "$cli/$path" | grep -vE '\?[[:space:]]*"ru"[[:space:]]*:[[:space:]]*"en"')
    if [ -n "$hits" ]; then
        echo "FAIL: $path chooses between two texts by the language: give them an id in $catalog (cliText)"
        printf '%s\n' "$hits"
        status=1
    fi
done
[ $status -eq 0 ] && echo "cli texts from the catalog: no choice between two literal texts in $n files outside $catalog"
exit $status
