#!/usr/bin/env bash
# Refreshes translations/*.ts from the sources (target update_translations of
# build/release) and fills them from translations/pairs/<area>.{ru,en}.tsv:
# Russian from the pairs only; English from the pairs, else the source itself
# (the sources are English). Prints what is still untranslated.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --build build/release --target update_translations >/dev/null
cat translations/pairs/*.ru.tsv | python3 scripts/ts_apply.py translations/k528studio_ru.ts | sed 's/^/ru /'
cat translations/pairs/*.en.tsv | python3 scripts/ts_apply.py --source-language translations/k528studio_en.ts | sed 's/^/en /'
