#!/bin/sh
# usage: cli_texts_from_catalog.sh CLI_SOURCE_DIR
# The command line says its words from one catalog (cli_texts.cpp: an id,
# its Russian and its English), rendered in the command's --lang. A choice
# written in a command between two texts by the language is a second
# translation system: sentences the catalog's checks (cli.lang) never see,
# which drift from the same sentence said elsewhere. This fails on
#   ru ? "…" : "…",  lang == Lang::Ru ? "…",  russianCommandLine() ? "…",
#   ru ? std::string("…") …,  the condition ending a line and "? "…"" on the
#   next,  a helper choosing between its two text arguments
#   (ru ? russian : english),  and if (ru) printing a Russian literal.
# Naming the language itself (? "ru" : "en", the --lang a helper program is
# given) is not a choice between texts.
set -u
cli=$1
catalog='cli_texts.cpp'
# The language, as the command line's sources test it (POSIX ERE, for grep and awk).
lang='(russian[A-Za-z_]*(\(\))?|(^|[^A-Za-z0-9_.>])ru_?|Lang::Ru|(^|[^A-Za-z0-9_.>])lang)'
text='(std::string(_view)?\(|u8)?"'
status=0
n=0
for path in $(cd "$cli" && find . -name '*.cpp' -o -name '*.h' | sed 's|^\./||' | sort); do
    [ "$path" = "$catalog" ] && continue
    n=$((n + 1))
    hits=$(awk -v lang="$lang" -v text="$text" '
        function report() { print FNR ": " $0 }
        {
            line = $0
            if (line ~ ("\\?[[:space:]]*\"ru\"[[:space:]]*:[[:space:]]*\"en\"")) { prev = line; next }
            if (line ~ (lang "[[:space:]]*\\?[[:space:]]*" text) ||
                line ~ (lang "[[:space:]]*\\?[[:space:]]*$") ||
                line ~ (lang "[[:space:]]*\\?[[:space:]]*russian[[:space:]]*:[[:space:]]*english") ||
                (prev ~ (lang "[[:space:]]*$") && line ~ ("^[[:space:]]*\\?[[:space:]]*" text)) ||
                (prev ~ ("(^|[^A-Za-z0-9_])if[[:space:]]*.*" lang ".*[)][[:space:]]*$") && line ~ /"[^"]*[\320\321]/))  # a Cyrillic letter in UTF-8
                report()
            prev = line
        }' "$cli/$path")
    if [ -n "$hits" ]; then
        echo "FAIL: $path chooses between two texts by the language: give them an id in $catalog (cliText)"
        printf '%s\n' "$hits"
        status=1
    fi
done
[ $status -eq 0 ] && echo "cli texts from the catalog: no choice between two texts by the language in $n files outside $catalog"
exit $status
