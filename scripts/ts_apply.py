#!/usr/bin/env python3
"""Fills translations into a Qt Linguist .ts file.

usage: scripts/ts_apply.py [--source-language] translations/k528studio_ru.ts < pairs.tsv

Each input line is "source<TAB>translation" (\\n for a line break, \\\\ for
a backslash, \\# for a "#" that starts a source: a line starting with "#" is a
comment). Every
message of the .ts file whose source matches gets the translation and loses
its "unfinished" mark. Prints the sources still untranslated. Run the
update_translations target first so the .ts file lists the current sources.

--source-language: the file is in the sources' own language (English): a
message without a pair is translated as its source, unless the source holds
Cyrillic (a text of the manual), which must come from a pair.
"""
import re
import sys
import xml.etree.ElementTree as ET


def unescape(field: str) -> str:
    return re.sub(r"\\\\|\\n|\\#", lambda m: {"\\\\": "\\", "\\n": "\n", "\\#": "#"}[m.group(0)], field)


def main() -> int:
    args = sys.argv[1:]
    identity = "--source-language" in args
    path = [a for a in args if a != "--source-language"][0]
    pairs = {}
    for line in sys.stdin:
        line = line.rstrip("\n")
        if not line or line.startswith("#"):
            continue
        src, _, dst = line.partition("\t")
        pairs[unescape(src)] = unescape(dst)
    tree = ET.parse(path)
    missing = []
    for msg in tree.iter("message"):
        src = msg.findtext("source")
        tr = msg.find("translation")
        if src in pairs:
            tr.text = pairs[src]
            tr.attrib.pop("type", None)
        elif tr.get("type") == "unfinished" or not tr.text:
            if identity and not re.search("[\u0400-\u04FF]", src):
                tr.text = src
                tr.attrib.pop("type", None)
            else:
                missing.append(src)
    tree.write(path, encoding="utf-8", xml_declaration=True)
    with open(path, encoding="utf-8") as f:
        text = f.read()
    with open(path, "w", encoding="utf-8") as f:
        f.write(text.replace("<?xml version='1.0' encoding='utf-8'?>", '<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>', 1))
    for m in missing:
        print("untranslated:", m.replace("\n", "\\n"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
