// The K923 LCD's character generator: the glyph table and its lookup.
//
// Each glyph is written as seven (or, for the block, eight) rows of five
// dots, top to bottom: '#' a lit dot, '.' a dark one. Row 7, the cursor line,
// is empty unless written. The forms follow the HD44780U ROM A02 for Latin
// and the Cyrillic ROMs of the HD44780-compatible KS0066 / Winstar modules for
// Cyrillic: capitals as on a 5×7 matrix, small letters mostly as small
// capitals; Cyrillic letters that look like Latin ones use the Latin glyph
// (sameAs), exactly as those ROMs do. The table is checked when compiling.
#include "panel/lcd_font.h"

#include "util/utf8.h"

#include <algorithm>
#include <bit>
#include <vector>

namespace k528::panel {

namespace {

struct GlyphSource {
    char32_t cp;
    std::string_view dots; // 35 or 40 of '#' / '.', row after row
    char32_t sameAs;       // 0, or the character whose glyph this one uses
};

constexpr GlyphSource glyph(char32_t cp, std::string_view dots) {
    return {cp, dots, 0};
}
constexpr GlyphSource sameAs(char32_t cp, char32_t other) {
    return {cp, {}, other};
}

// clang-format off
constexpr GlyphSource kGlyphs[] = {
    // ---- ASCII 0x20..0x7E, HD44780 style. The descenders of g j p q y are
    //      folded into the seven rows, as in the 5×8 ROM fonts.
    glyph(U' ', "....."
                "....."
                "....."
                "....."
                "....."
                "....."
                "....."),
    glyph(U'!', "..#.."
                "..#.."
                "..#.."
                "..#.."
                "..#.."
                "....."
                "..#.."),
    glyph(U'"', ".#.#."
                ".#.#."
                ".#.#."
                "....."
                "....."
                "....."
                "....."),
    glyph(U'#', ".#.#."
                ".#.#."
                "#####"
                ".#.#."
                "#####"
                ".#.#."
                ".#.#."),
    glyph(U'$', "..#.."
                ".####"
                "#.#.."
                ".###."
                "..#.#"
                "####."
                "..#.."),
    glyph(U'%', "##..."
                "##..#"
                "...#."
                "..#.."
                ".#..."
                "#..##"
                "...##"),
    glyph(U'&', ".##.."
                "#..#."
                "#.#.."
                ".#..."
                "#.#.#"
                "#..#."
                ".##.#"),
    glyph(U'\'', ".##.."
                 "..#.."
                 ".#..."
                 "....."
                 "....."
                 "....."
                 "....."),
    glyph(U'(', "...#."
                "..#.."
                ".#..."
                ".#..."
                ".#..."
                "..#.."
                "...#."),
    glyph(U')', ".#..."
                "..#.."
                "...#."
                "...#."
                "...#."
                "..#.."
                ".#..."),
    glyph(U'*', "....."
                "..#.."
                "#.#.#"
                ".###."
                "#.#.#"
                "..#.."
                "....."),
    glyph(U'+', "....."
                "..#.."
                "..#.."
                "#####"
                "..#.."
                "..#.."
                "....."),
    glyph(U',', "....."
                "....."
                "....."
                "....."
                ".##.."
                "..#.."
                ".#..."),
    glyph(U'-', "....."
                "....."
                "....."
                "#####"
                "....."
                "....."
                "....."),
    glyph(U'.', "....."
                "....."
                "....."
                "....."
                "....."
                ".##.."
                ".##.."),
    glyph(U'/', "....."
                "....#"
                "...#."
                "..#.."
                ".#..."
                "#...."
                "....."),
    glyph(U'0', ".###."
                "#...#"
                "#..##"
                "#.#.#"
                "##..#"
                "#...#"
                ".###."),
    glyph(U'1', "..#.."
                ".##.."
                "..#.."
                "..#.."
                "..#.."
                "..#.."
                ".###."),
    glyph(U'2', ".###."
                "#...#"
                "....#"
                "...#."
                "..#.."
                ".#..."
                "#####"),
    glyph(U'3', "#####"
                "...#."
                "..#.."
                "...#."
                "....#"
                "#...#"
                ".###."),
    glyph(U'4', "...#."
                "..##."
                ".#.#."
                "#..#."
                "#####"
                "...#."
                "...#."),
    glyph(U'5', "#####"
                "#...."
                "####."
                "....#"
                "....#"
                "#...#"
                ".###."),
    glyph(U'6', "..##."
                ".#..."
                "#...."
                "####."
                "#...#"
                "#...#"
                ".###."),
    glyph(U'7', "#####"
                "....#"
                "...#."
                "..#.."
                ".#..."
                ".#..."
                ".#..."),
    glyph(U'8', ".###."
                "#...#"
                "#...#"
                ".###."
                "#...#"
                "#...#"
                ".###."),
    glyph(U'9', ".###."
                "#...#"
                "#...#"
                ".####"
                "....#"
                "...#."
                ".##.."),
    glyph(U':', "....."
                ".##.."
                ".##.."
                "....."
                ".##.."
                ".##.."
                "....."),
    glyph(U';', "....."
                ".##.."
                ".##.."
                "....."
                ".##.."
                "..#.."
                ".#..."),
    glyph(U'<', "...#."
                "..#.."
                ".#..."
                "#...."
                ".#..."
                "..#.."
                "...#."),
    glyph(U'=', "....."
                "....."
                "#####"
                "....."
                "#####"
                "....."
                "....."),
    glyph(U'>', ".#..."
                "..#.."
                "...#."
                "....#"
                "...#."
                "..#.."
                ".#..."),
    glyph(U'?', ".###."
                "#...#"
                "....#"
                "...#."
                "..#.."
                "....."
                "..#.."),
    glyph(U'@', ".###."
                "#...#"
                "....#"
                ".##.#"
                "#.#.#"
                "#.#.#"
                ".###."),
    glyph(U'A', ".###."
                "#...#"
                "#...#"
                "#...#"
                "#####"
                "#...#"
                "#...#"),
    glyph(U'B', "####."
                "#...#"
                "#...#"
                "####."
                "#...#"
                "#...#"
                "####."),
    glyph(U'C', ".###."
                "#...#"
                "#...."
                "#...."
                "#...."
                "#...#"
                ".###."),
    glyph(U'D', "###.."
                "#..#."
                "#...#"
                "#...#"
                "#...#"
                "#..#."
                "###.."),
    glyph(U'E', "#####"
                "#...."
                "#...."
                "####."
                "#...."
                "#...."
                "#####"),
    glyph(U'F', "#####"
                "#...."
                "#...."
                "####."
                "#...."
                "#...."
                "#...."),
    glyph(U'G', ".###."
                "#...#"
                "#...."
                "#.###"
                "#...#"
                "#...#"
                ".####"),
    glyph(U'H', "#...#"
                "#...#"
                "#...#"
                "#####"
                "#...#"
                "#...#"
                "#...#"),
    glyph(U'I', ".###."
                "..#.."
                "..#.."
                "..#.."
                "..#.."
                "..#.."
                ".###."),
    glyph(U'J', "..###"
                "...#."
                "...#."
                "...#."
                "...#."
                "#..#."
                ".##.."),
    glyph(U'K', "#...#"
                "#..#."
                "#.#.."
                "##..."
                "#.#.."
                "#..#."
                "#...#"),
    glyph(U'L', "#...."
                "#...."
                "#...."
                "#...."
                "#...."
                "#...."
                "#####"),
    glyph(U'M', "#...#"
                "##.##"
                "#.#.#"
                "#.#.#"
                "#...#"
                "#...#"
                "#...#"),
    glyph(U'N', "#...#"
                "#...#"
                "##..#"
                "#.#.#"
                "#..##"
                "#...#"
                "#...#"),
    glyph(U'O', ".###."
                "#...#"
                "#...#"
                "#...#"
                "#...#"
                "#...#"
                ".###."),
    glyph(U'P', "####."
                "#...#"
                "#...#"
                "####."
                "#...."
                "#...."
                "#...."),
    glyph(U'Q', ".###."
                "#...#"
                "#...#"
                "#...#"
                "#.#.#"
                "#..#."
                ".##.#"),
    glyph(U'R', "####."
                "#...#"
                "#...#"
                "####."
                "#.#.."
                "#..#."
                "#...#"),
    glyph(U'S', ".####"
                "#...."
                "#...."
                ".###."
                "....#"
                "....#"
                "####."),
    glyph(U'T', "#####"
                "..#.."
                "..#.."
                "..#.."
                "..#.."
                "..#.."
                "..#.."),
    glyph(U'U', "#...#"
                "#...#"
                "#...#"
                "#...#"
                "#...#"
                "#...#"
                ".###."),
    glyph(U'V', "#...#"
                "#...#"
                "#...#"
                "#...#"
                "#...#"
                ".#.#."
                "..#.."),
    glyph(U'W', "#...#"
                "#...#"
                "#...#"
                "#.#.#"
                "#.#.#"
                "#.#.#"
                ".#.#."),
    glyph(U'X', "#...#"
                "#...#"
                ".#.#."
                "..#.."
                ".#.#."
                "#...#"
                "#...#"),
    glyph(U'Y', "#...#"
                "#...#"
                "#...#"
                ".#.#."
                "..#.."
                "..#.."
                "..#.."),
    glyph(U'Z', "#####"
                "....#"
                "...#."
                "..#.."
                ".#..."
                "#...."
                "#####"),
    glyph(U'[', ".###."
                ".#..."
                ".#..."
                ".#..."
                ".#..."
                ".#..."
                ".###."),
    glyph(U'\\', "....."
                 "#...."
                 ".#..."
                 "..#.."
                 "...#."
                 "....#"
                 "....."),
    glyph(U']', ".###."
                "...#."
                "...#."
                "...#."
                "...#."
                "...#."
                ".###."),
    glyph(U'^', "..#.."
                ".#.#."
                "#...#"
                "....."
                "....."
                "....."
                "....."),
    glyph(U'_', "....."
                "....."
                "....."
                "....."
                "....."
                "....."
                "#####"),
    glyph(U'`', ".#..."
                "..#.."
                "...#."
                "....."
                "....."
                "....."
                "....."),
    glyph(U'a', "....."
                "....."
                ".###."
                "....#"
                ".####"
                "#...#"
                ".####"),
    glyph(U'b', "#...."
                "#...."
                "#.##."
                "##..#"
                "#...#"
                "#...#"
                "####."),
    glyph(U'c', "....."
                "....."
                ".###."
                "#...."
                "#...."
                "#...#"
                ".###."),
    glyph(U'd', "....#"
                "....#"
                ".##.#"
                "#..##"
                "#...#"
                "#...#"
                ".####"),
    glyph(U'e', "....."
                "....."
                ".###."
                "#...#"
                "#####"
                "#...."
                ".###."),
    glyph(U'f', "..##."
                ".#..#"
                ".#..."
                "###.."
                ".#..."
                ".#..."
                ".#..."),
    glyph(U'g', "....."
                ".####"
                "#...#"
                "#...#"
                ".####"
                "....#"
                ".###."),
    glyph(U'h', "#...."
                "#...."
                "#.##."
                "##..#"
                "#...#"
                "#...#"
                "#...#"),
    glyph(U'i', "..#.."
                "....."
                ".##.."
                "..#.."
                "..#.."
                "..#.."
                ".###."),
    glyph(U'j', "...#."
                "....."
                "..##."
                "...#."
                "...#."
                "#..#."
                ".##.."),
    glyph(U'k', "#...."
                "#...."
                "#..#."
                "#.#.."
                "##..."
                "#.#.."
                "#..#."),
    glyph(U'l', ".##.."
                "..#.."
                "..#.."
                "..#.."
                "..#.."
                "..#.."
                ".###."),
    glyph(U'm', "....."
                "....."
                "##.#."
                "#.#.#"
                "#.#.#"
                "#...#"
                "#...#"),
    glyph(U'n', "....."
                "....."
                "#.##."
                "##..#"
                "#...#"
                "#...#"
                "#...#"),
    glyph(U'o', "....."
                "....."
                ".###."
                "#...#"
                "#...#"
                "#...#"
                ".###."),
    glyph(U'p', "....."
                "....."
                "####."
                "#...#"
                "####."
                "#...."
                "#...."),
    glyph(U'q', "....."
                "....."
                ".##.#"
                "#..##"
                ".####"
                "....#"
                "....#"),
    glyph(U'r', "....."
                "....."
                "#.##."
                "##..#"
                "#...."
                "#...."
                "#...."),
    glyph(U's', "....."
                "....."
                ".###."
                "#...."
                ".###."
                "....#"
                "####."),
    glyph(U't', ".#..."
                ".#..."
                "###.."
                ".#..."
                ".#..."
                ".#..#"
                "..##."),
    glyph(U'u', "....."
                "....."
                "#...#"
                "#...#"
                "#...#"
                "#..##"
                ".##.#"),
    glyph(U'v', "....."
                "....."
                "#...#"
                "#...#"
                "#...#"
                ".#.#."
                "..#.."),
    glyph(U'w', "....."
                "....."
                "#...#"
                "#...#"
                "#.#.#"
                "#.#.#"
                ".#.#."),
    glyph(U'x', "....."
                "....."
                "#...#"
                ".#.#."
                "..#.."
                ".#.#."
                "#...#"),
    glyph(U'y', "....."
                "....."
                "#...#"
                "#...#"
                ".####"
                "....#"
                ".###."),
    glyph(U'z', "....."
                "....."
                "#####"
                "...#."
                "..#.."
                ".#..."
                "#####"),
    glyph(U'{', "...#."
                "..#.."
                "..#.."
                ".#..."
                "..#.."
                "..#.."
                "...#."),
    glyph(U'|', "..#.."
                "..#.."
                "..#.."
                "..#.."
                "..#.."
                "..#.."
                "..#.."),
    glyph(U'}', ".#..."
                "..#.."
                "..#.."
                "...#."
                "..#.."
                "..#.."
                ".#..."),
    glyph(U'~', "....."
                "....."
                "....."
                ".##.#"
                "#..#."
                "....."
                "....."),
    // ---- Cyrillic capitals. Letters that look like Latin ones are the same
    //      glyph (sameAs), as in the HD44780 Cyrillic ROMs.
    sameAs(U'А', U'A'),
    glyph(U'Б', "#####"
                "#...."
                "#...."
                "####."
                "#...#"
                "#...#"
                "####."),
    sameAs(U'В', U'B'),
    glyph(U'Г', "#####"
                "#...."
                "#...."
                "#...."
                "#...."
                "#...."
                "#...."),
    glyph(U'Д', "..###"
                ".#..#"
                ".#..#"
                ".#..#"
                ".#..#"
                "#####"
                "#...#"),
    sameAs(U'Е', U'E'),
    glyph(U'Ё', ".#.#."
                "....."
                "#####"
                "#...."
                "####."
                "#...."
                "#####"),
    glyph(U'Ж', "#.#.#"
                "#.#.#"
                "#.#.#"
                ".###."
                "#.#.#"
                "#.#.#"
                "#.#.#"),
    glyph(U'З', ".###."
                "#...#"
                "....#"
                "..##."
                "....#"
                "#...#"
                ".###."),
    glyph(U'И', "#...#"
                "#...#"
                "#..##"
                "#.#.#"
                "##..#"
                "#...#"
                "#...#"),
    glyph(U'Й', ".#.#."
                "#...#"
                "#..##"
                "#.#.#"
                "##..#"
                "#...#"
                "#...#"),
    sameAs(U'К', U'K'),
    glyph(U'Л', "..###"
                ".#..#"
                ".#..#"
                ".#..#"
                ".#..#"
                ".#..#"
                "#...#"),
    sameAs(U'М', U'M'),
    sameAs(U'Н', U'H'),
    sameAs(U'О', U'O'),
    glyph(U'П', "#####"
                "#...#"
                "#...#"
                "#...#"
                "#...#"
                "#...#"
                "#...#"),
    sameAs(U'Р', U'P'),
    sameAs(U'С', U'C'),
    sameAs(U'Т', U'T'),
    glyph(U'У', "#...#"
                "#...#"
                "#...#"
                ".####"
                "....#"
                "#...#"
                ".###."),
    glyph(U'Ф', "..#.."
                ".###."
                "#.#.#"
                "#.#.#"
                "#.#.#"
                ".###."
                "..#.."),
    sameAs(U'Х', U'X'),
    glyph(U'Ц', "#..#."
                "#..#."
                "#..#."
                "#..#."
                "#..#."
                "#####"
                "....#"),
    glyph(U'Ч', "#...#"
                "#...#"
                "#...#"
                ".####"
                "....#"
                "....#"
                "....#"),
    glyph(U'Ш', "#.#.#"
                "#.#.#"
                "#.#.#"
                "#.#.#"
                "#.#.#"
                "#.#.#"
                "#####"),
    glyph(U'Щ', "#.#.#"
                "#.#.#"
                "#.#.#"
                "#.#.#"
                "#.#.#"
                "#####"
                "....#"),
    glyph(U'Ъ', "##..."
                ".#..."
                ".#..."
                ".###."
                ".#..#"
                ".#..#"
                ".###."),
    glyph(U'Ы', "#...#"
                "#...#"
                "#...#"
                "###.#"
                "#.#.#"
                "#.#.#"
                "###.#"),
    glyph(U'Ь', "#...."
                "#...."
                "#...."
                "####."
                "#...#"
                "#...#"
                "####."),
    glyph(U'Э', ".###."
                "#...#"
                "....#"
                "..###"
                "....#"
                "#...#"
                ".###."),
    glyph(U'Ю', "#..#."
                "#.#.#"
                "#.#.#"
                "###.#"
                "#.#.#"
                "#.#.#"
                "#..#."),
    glyph(U'Я', ".####"
                "#...#"
                "#...#"
                ".####"
                "..#.#"
                ".#..#"
                "#...#"),
    // ---- Cyrillic small letters: small capitals on the x-height (rows 2..6), as
    //      in the KS0066 / HD44780-compatible Cyrillic ROMs; б, ё, й and ф rise
    //      above it.
    sameAs(U'а', U'a'),
    glyph(U'б', "...##"
                ".##.."
                "#...."
                "####."
                "#...#"
                "#...#"
                ".###."),
    glyph(U'в', "....."
                "....."
                "####."
                "#...#"
                "####."
                "#...#"
                "####."),
    glyph(U'г', "....."
                "....."
                "#####"
                "#...."
                "#...."
                "#...."
                "#...."),
    glyph(U'д', "....."
                "....."
                "..##."
                ".#.#."
                ".#.#."
                "#####"
                "#...#"),
    sameAs(U'е', U'e'),
    glyph(U'ё', ".#.#."
                "....."
                ".###."
                "#...#"
                "#####"
                "#...."
                ".###."),
    glyph(U'ж', "....."
                "....."
                "#.#.#"
                "#.#.#"
                ".###."
                "#.#.#"
                "#.#.#"),
    glyph(U'з', "....."
                "....."
                "####."
                "....#"
                ".###."
                "....#"
                "####."),
    glyph(U'и', "....."
                "....."
                "#...#"
                "#..##"
                "#.#.#"
                "##..#"
                "#...#"),
    glyph(U'й', ".#.#."
                "..#.."
                "#...#"
                "#..##"
                "#.#.#"
                "##..#"
                "#...#"),
    glyph(U'к', "....."
                "....."
                "#..#."
                "#.#.."
                "##..."
                "#.#.."
                "#..#."),
    glyph(U'л', "....."
                "....."
                "..###"
                ".#..#"
                ".#..#"
                ".#..#"
                "#...#"),
    glyph(U'м', "....."
                "....."
                "#...#"
                "##.##"
                "#.#.#"
                "#...#"
                "#...#"),
    glyph(U'н', "....."
                "....."
                "#...#"
                "#...#"
                "#####"
                "#...#"
                "#...#"),
    sameAs(U'о', U'o'),
    glyph(U'п', "....."
                "....."
                "#####"
                "#...#"
                "#...#"
                "#...#"
                "#...#"),
    sameAs(U'р', U'p'),
    sameAs(U'с', U'c'),
    glyph(U'т', "....."
                "....."
                "#####"
                "..#.."
                "..#.."
                "..#.."
                "..#.."),
    sameAs(U'у', U'y'),
    glyph(U'ф', "..#.."
                "..#.."
                ".###."
                "#.#.#"
                "#.#.#"
                ".###."
                "..#.."),
    sameAs(U'х', U'x'),
    glyph(U'ц', "....."
                "....."
                "#..#."
                "#..#."
                "#..#."
                "#####"
                "....#"),
    glyph(U'ч', "....."
                "....."
                "#...#"
                "#...#"
                ".####"
                "....#"
                "....#"),
    glyph(U'ш', "....."
                "....."
                "#.#.#"
                "#.#.#"
                "#.#.#"
                "#.#.#"
                "#####"),
    glyph(U'щ', "....."
                "....."
                "#.#.#"
                "#.#.#"
                "#.#.#"
                "#####"
                "....#"),
    glyph(U'ъ', "....."
                "....."
                "##..."
                ".#..."
                ".###."
                ".#..#"
                ".###."),
    glyph(U'ы', "....."
                "....."
                "#...#"
                "#...#"
                "###.#"
                "#.#.#"
                "###.#"),
    glyph(U'ь', "....."
                "....."
                "#...."
                "#...."
                "####."
                "#...#"
                "####."),
    glyph(U'э', "....."
                "....."
                ".###."
                "#...#"
                "..###"
                "#...#"
                ".###."),
    glyph(U'ю', "....."
                "....."
                "#..#."
                "#.#.#"
                "###.#"
                "#.#.#"
                "#..#."),
    glyph(U'я', "....."
                "....."
                ".####"
                "#...#"
                ".####"
                ".#..#"
                "#...#"),
    // ---- Symbols of the screens and of the manual's texts.
    glyph(U'▲', "....."
                "....."
                "..#.."
                ".###."
                "#####"
                "....."
                "....."),
    glyph(U'▼', "....."
                "....."
                "#####"
                ".###."
                "..#.."
                "....."
                "....."),
    glyph(U'◀', "....."
                "...#."
                "..##."
                ".###."
                "..##."
                "...#."
                "....."),
    glyph(U'►', "....."
                ".#..."
                ".##.."
                ".###."
                ".##.."
                ".#..."
                "....."),
    glyph(U'→', "....."
                "..#.."
                "...#."
                "#####"
                "...#."
                "..#.."
                "....."),
    glyph(U'←', "....."
                "..#.."
                ".#..."
                "#####"
                ".#..."
                "..#.."
                "....."),
    glyph(U'↑', "..#.."
                ".###."
                "#.#.#"
                "..#.."
                "..#.."
                "..#.."
                "..#.."),
    glyph(U'↓', "..#.."
                "..#.."
                "..#.."
                "..#.."
                "#.#.#"
                ".###."
                "..#.."),
    glyph(U'№', "#..#."
                "##.#."
                "#.##."
                "#..#."
                "#..#."
                "....."
                "....."),
    glyph(U'°', ".##.."
                "#..#."
                "#..#."
                ".##.."
                "....."
                "....."
                "....."),
    glyph(U'«', "....."
                "..#.#"
                ".#.#."
                "#.#.."
                ".#.#."
                "..#.#"
                "....."),
    glyph(U'»', "....."
                "#.#.."
                ".#.#."
                "..#.#"
                ".#.#."
                "#.#.."
                "....."),
    glyph(U'±', "..#.."
                "..#.."
                "#####"
                "..#.."
                "..#.."
                "....."
                "#####"),
    glyph(U'½', "#...."
                "#...."
                "#..#."
                "..#.."
                ".#.##"
                "....#"
                "...##"),
    glyph(U'█', "#####"
                "#####"
                "#####"
                "#####"
                "#####"
                "#####"
                "#####"
                "#####"),

};
// clang-format on

// The compile-time check of the table: well-formed rows, no code point twice,
// every sameAs names a glyph drawn in the table.
constexpr bool tableIsValid() {
    for (const GlyphSource& g : kGlyphs) {
        if (g.sameAs == 0) {
            if (g.dots.size() != 35 && g.dots.size() != 40)
                return false;
            for (char c : g.dots)
                if (c != '#' && c != '.')
                    return false;
        } else {
            if (!g.dots.empty())
                return false;
            bool found = false;
            for (const GlyphSource& o : kGlyphs)
                found = found || (o.cp == g.sameAs && o.sameAs == 0);
            if (!found)
                return false;
        }
        int count = 0;
        for (const GlyphSource& o : kGlyphs)
            count += o.cp == g.cp ? 1 : 0;
        if (count != 1)
            return false;
    }
    return true;
}
static_assert(tableIsValid(),
              "K923 LCD font: a glyph has a bad row, a repeated code point or a bad sameAs");

constexpr Glyph parse(std::string_view dots) {
    Glyph g;
    for (std::size_t i = 0; i < dots.size(); ++i)
        if (dots[i] == '#')
            g.rows[i / kGlyphColumns] |=
                static_cast<std::uint8_t>(1u << (kGlyphColumns - 1 - i % kGlyphColumns));
    return g;
}

constexpr Glyph drawnGlyph(const GlyphSource& g) {
    if (g.sameAs == 0)
        return parse(g.dots);
    for (const GlyphSource& o : kGlyphs)
        if (o.cp == g.sameAs)
            return parse(o.dots);
    return {};
}

struct Entry {
    char32_t cp;
    Glyph glyph;
};

struct Tables {
    std::vector<Entry> sorted; // by code point, for lookup
    std::vector<char32_t> characters;
    std::vector<std::pair<char32_t, char32_t>> lookAlikes;

    Tables() {
        for (const GlyphSource& g : kGlyphs) {
            sorted.push_back({g.cp, drawnGlyph(g)});
            characters.push_back(g.cp);
            if (g.sameAs != 0)
                lookAlikes.emplace_back(g.cp, g.sameAs);
        }
        std::sort(sorted.begin(), sorted.end(),
                  [](const Entry& a, const Entry& b) { return a.cp < b.cp; });
    }
};

const Tables& tables() {
    static const Tables t;
    return t;
}

} // namespace

int Glyph::litDots() const {
    int n = 0;
    for (std::uint8_t r : rows)
        n += std::popcount(static_cast<unsigned>(r & 0x1Fu));
    return n;
}

char32_t lcdCanonical(char32_t cp) {
    switch (cp) {
    case U'\u25C4':
        return U'◀'; // ◄ black left-pointing pointer
    case U'\u25B6':
        return U'►'; // ▶ black right-pointing triangle
    case U'\u2013':  // – en dash
    case U'\u2014':  // — em dash
    case U'\u2212':
        return U'-'; // − minus sign
    case U'\u201C':  // “
    case U'\u201D':  // ”
    case U'\u201E':
        return U'"'; // „
    case U'\u2018':  // ‘
    case U'\u2019':
        return U'\''; // ’
    case U'\u00A0':
        return U' '; // no-break space
    default:
        return cp;
    }
}

std::optional<Glyph> lcdGlyph(char32_t cp) {
    cp = lcdCanonical(cp);
    const auto& s = tables().sorted;
    const auto it = std::lower_bound(s.begin(), s.end(), cp,
                                     [](const Entry& e, char32_t c) { return e.cp < c; });
    if (it == s.end() || it->cp != cp)
        return std::nullopt;
    return it->glyph;
}

Glyph lcdGlyphOrPlaceholder(char32_t cp) {
    const auto g = lcdGlyph(cp);
    return g ? *g : lcdPlaceholderGlyph();
}

bool lcdCanShow(char32_t cp) {
    return lcdGlyph(cp).has_value();
}

Glyph lcdPlaceholderGlyph() {
    return parse("#####"
                 "#...#"
                 "#...#"
                 "#...#"
                 "#...#"
                 "#...#"
                 "#####");
}

Glyph lcdBlockGlyph() {
    Glyph g;
    g.rows.fill(0x1F);
    return g;
}

std::span<const char32_t> lcdCharacters() {
    return tables().characters;
}

std::span<const std::pair<char32_t, char32_t>> lcdLookAlikes() {
    return tables().lookAlikes;
}

std::optional<char32_t> lcdFirstUnsupported(std::string_view text) {
    for (char32_t cp : utf8::decode(text))
        if (!lcdCanShow(cp))
            return cp;
    return std::nullopt;
}

} // namespace k528::panel
