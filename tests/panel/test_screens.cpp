// Every screen of manual 2.6 reached by its keys on a freshly powered-on
// training lathe (X on the diameter, Z; discrete 0.001 mm; R10..R13, R220,
// R221 preset), with the four lines written by hand from the layouts of
// docs/panel.md (trailing blanks dropped).
#include "rig/panel_rig.h"

#include <QtTest>

using namespace k528;
using namespace k528::testrig;

class TestScreens : public QObject {
    Q_OBJECT
private slots:
    void screen_data() {
        QTest::addColumn<QString>("keys");
        QTest::addColumn<QStringList>("lines");
        const auto row = [](const char* name, const char* keys,
                            std::initializer_list<const char*> l) {
            QTest::newRow(name) << QString::fromUtf8(keys) << expect(l);
        };
        // --- 2.6.1: power-on in РУЧНОЙ; 2.6.2/2.6.3 screens 1 and 2 -------------
        row("power-on", "",
            {"РУЧ            100%", "", " X    0.000    0.000", " Z    0.000    0.000"});
        row("auto 1", "F1",
            {"АВТ            100%", "", " X    0.000    0.000", " Z    0.000    0.000"});
        row("auto 2", "F1 MODE",
            {"АВТ            100%", "", " X    0.000 F=  0.00", " Z    0.000 F=  0.00"});
        row("auto MODE wraps", "F1 MODE MODE",
            {"АВТ            100%", "", " X    0.000    0.000", " Z    0.000    0.000"});
        row("manual 2", "F2 MODE",
            {"РУЧ            100%", "", " X    0.000 F=  0.00", " Z    0.000 F=  0.00"});
        row("manual 3", "F2 MODE MODE", {"РУЧ            100%", ">R0=0", " R1=0", " R2=0"});
        row("manual MODE wraps", "F2 MODE MODE MODE",
            {"РУЧ            100%", "", " X    0.000    0.000", " Z    0.000    0.000"});
        row("manual 3 scroll", "F2 MODE MODE DOWN DOWN DOWN DOWN",
            {"РУЧ            100%", " R2=0", " R3=0", ">R4=0"});
        row("manual 3 PAR prompt", "F2 MODE MODE PAR 1 0",
            {"РУЧ            100%", "НОМЕР R-ПАРАМЕТРА?", ">10", ""});
        row("manual 3 PAR jump", "F2 MODE MODE PAR 1 0 ENTER",
            {"РУЧ            100%", " R8=0", " R9=0", ">R10=40000"});
        row("manual 3 up", "F2 MODE MODE PAR 1 3 ENTER UP UP UP",
            {"РУЧ            100%", ">R10=40000", " R11=36000", " R12=1000"});
        row("manual 3 shift", "F2 MODE MODE PAR 1 3 ENTER SHIFT+UP",
            {"РУЧ            100%", ">R10=40000", " R11=36000", " R12=1000"});
        row("manual 3 typing", "F2 MODE MODE DOWN - 1 2",
            {"РУЧ            100%", " R0=0", ">R1=-12", " R2=0"});
        row("manual 3 no such R", "F2 MODE MODE PAR 3 0 0 ENTER",
            {"РУЧ            100%", "ОШИБКА ВВОДА", " R1=0", " R2=0"});
        row("ACK typing", "F1 ACK 7",
            {"АВТ    7       100%", "", " X    0.000    0.000", " Z    0.000    0.000"});
        row("ACK program", "F1 ACK 7 ENTER",
            {"АВТ     7      100%", "", " X    0.000    0.000", " Z    0.000    0.000"});
        row("ACK program 12", "F1 ACK 1 2 ENTER",
            {"АВТ    12      100%", "", " X    0.000    0.000", " Z    0.000    0.000"});
        row("ACK program 0", "F1 ACK 0 ENTER",
            {"АВТ            100%", "ОШИБКА ВВОДА", " X    0.000    0.000",
             " Z    0.000    0.000"});
        row("L1 0%", "F1 L1",
            {"АВТ              0%", "", " X    0.000    0.000", " Z    0.000    0.000"});
        row("L2 20%", "F1 L2",
            {"АВТ             20%", "", " X    0.000    0.000", " Z    0.000    0.000"});
        row("L3 50%", "L3",
            {"РУЧ             50%", "", " X    0.000    0.000", " Z    0.000    0.000"});

        // --- 2.6.4 ----------------------------------------------------------------
        row("reference", "F3",
            {"ПБТ            100%", "", " X    0.000#0.000", " Z    0.000#0.000"});

        // --- 2.6.5 ----------------------------------------------------------------
        row("presets menu", "F4",
            {"УСТ ПРЕДУСТАНОВКИ", ">1-КООРД.И СМЕЩЕНИЯ", " 2-ИСХОДНОЕ", " 3-ПОДНАЛАДКА"});
        row("presets menu down", "F4 DOWN DOWN DOWN",
            {"УСТ ПРЕДУСТАНОВКИ", " 2-ИСХОДНОЕ", " 3-ПОДНАЛАДКА", ">4-ПРАВКА"});
        row("presets menu by 3", "F4 SHIFT+DOWN SHIFT+DOWN SHIFT+DOWN",
            {"УСТ ПРЕДУСТАНОВКИ", " 7-ОСЦИЛЛЯЦИЯ", " 8-СКОРОСТИ", ">9-ОСЕВАЯ"});
        row("presets menu SHIFT key", "F4 SHIFT DOWN",
            {"УСТ ПРЕДУСТАНОВКИ", " 2-ИСХОДНОЕ", " 3-ПОДНАЛАДКА", ">4-ПРАВКА"});
        row("presets ENTER", "F4 DOWN ENTER",
            {"УСТ2 ИСХОДНОЕ     X", "MX: 0.000", ">R220=200.000", " R221=180.000"});
        row("group 1 X", "F4 1",
            {"УСТ1 КООРД.И СМЕЩ.X", "ТЕКУЩАЯ КООРДИНАТА", ">   X=0.000", " R224=0.000"});
        row("group 1 marker", "F4 1 DOWN DOWN",
            {"УСТ1 КООРД.И СМЕЩ.X", "КОРРЕКЦИЯ", " R224=0.000", ">R226=0.000"});
        row("group 1 end", "F4 1 DOWN DOWN DOWN DOWN DOWN",
            {"УСТ1 КООРД.И СМЕЩ.X", "СМЕЩЕНИЕ МАХОВИКОМ", " R228=0.000", ">R230=0.000"});
        row("group 1 Z", "F4 1 RIGHT",
            {"УСТ1 КООРД.И СМЕЩ.Z", "ТЕКУЩАЯ КООРДИНАТА", ">   Z=0.000", " R225=0.000"});
        row("group 1 Z marker", "F4 1 DOWN DOWN DOWN LEFT",
            {"УСТ1 КООРД.И СМЕЩ.Z", "СМЕЩЕНИЕ НУЛЯ", " R227=0.000", ">R229=0.000"});
        row("group 2 X", "F4 2",
            {"УСТ2 ИСХОДНОЕ     X", "MX: 0.000", ">R220=200.000", " R221=180.000"});
        row("group 2 Z", "F4 2 DOWN",
            {"УСТ2 ИСХОДНОЕ     Z", "MZ: 0.000", " R220=200.000", ">R221=180.000"});
        row("group 3", "F4 3", {"УСТ3 ПОДНАЛАДКА   X", ">R218=0", " R219=0", ""});
        row("group 3 Z", "F4 3 DOWN", {"УСТ3 ПОДНАЛАДКА   Z", " R218=0", ">R219=0", ""});
        row("group 4", "F4 4",
            {"УСТ4 ПРАВКА ПЕРИФ.", "DX ЧЕРН.ПРАВКИ", ">R210=0.000", " R211=0.000"});
        row("group 4 feed", "F4 4 DOWN DOWN",
            {"УСТ4 ПРАВКА ПЕРИФ.", "FZ ЧЕРН.ПРАВКИ", " R211=0.000", ">R212=0.00"});
        row("group 4 face", "F4 4 RIGHT",
            {"УСТ4 ПРАВКА ТОРЦА", "DZ ЧЕРН.ПРАВКИ", ">R214=0.000", " R215=0.000"});
        row("group 4 face end", "F4 4 LEFT DOWN DOWN DOWN",
            {"УСТ4 ПРАВКА ТОРЦА", "FX ЧИСТ.ПРАВКИ", " R216=0.00", ">R217=0.00"});
        row("group 5", "F4 5",
            {"УСТ5 ШЛИФ.КРУГ", "ДИАМЕТР НОВ.КРУГА", ">R204=0.000", " R205=0.000"});
        row("group 5 end", "F4 5 SHIFT+DOWN",
            {"УСТ5 ШЛИФ.КРУГ", "ТЕК.ДИАМЕТР КРУГА", " R206=0.000", ">R207=0.000"});
        row("group 6", "F4 6", {"УСТ6 АЛМАЗ", "MX: 0.000", ">R200=0.000", " R201=0.000"});
        row("group 6 NZ", "F4 6 DOWN DOWN",
            {"УСТ6 АЛМАЗ", "NZ АЛМАЗА", " R201=0.000", ">R202=0.00"});
        row("group 7 X", "F4 7",
            {"УСТ7 ОСЦИЛЛЯЦИЯ   X", "-MX: 0.000", ">R184=0.000", " R185=0.000"});
        row("group 7 delay", "F4 7 DOWN DOWN DOWN",
            {"УСТ7 ОСЦИЛЛЯЦИЯ   X", "ЗАДЕРЖКА РЕВЕРСА,СЕК", " R186=0.00", ">R187=0.000"});
        row("group 7 end", "F4 7 SHIFT+DOWN SHIFT+DOWN SHIFT+DOWN",
            {"УСТ7 ОСЦИЛЛЯЦИЯ   X", "ХОДЫ ВЫХАЖИВАНИЯ", " R190=0", ">R191=0"});
        row("group 7 Z", "F4 7 LEFT",
            {"УСТ7 ОСЦИЛЛЯЦИЯ   Z", "-MZ: 0.000", ">R192=0.000", " R193=0.000"});
        row("group 7 Z marker", "F4 7 DOWN DOWN RIGHT",
            {"УСТ7 ОСЦИЛЛЯЦИЯ   Z", "СКОРОСТЬ ОСЦИЛЛЯЦИИ", " R193=0.000", ">R194=0.00"});
        row("group 8 X", "F4 8",
            {"УСТ8 ДОП.СКОРОСТИ X", "ДОП.СКОРОСТЬ 1", ">R174=0.00", " R175=0.00"});
        row("group 8 Z", "F4 8 DOWN DOWN DOWN RIGHT",
            {"УСТ8 ДОП.СКОРОСТИ Z", "ДОП.СКОРОСТЬ 4", " R181=0.00", ">R182=0.00"});
        row("group 9", "F4 9",
            {"УСТ9 ОСЕВ.ОРИЕНТАЦИЯ", "РАССТОЯНИЕ КРУГ-ЩУП", ">R164=0.000", " R165=0"});
        row("group 9 end", "F4 9 SHIFT+DOWN SHIFT+DOWN SHIFT+DOWN",
            {"УСТ9 ОСЕВ.ОРИЕНТАЦИЯ", "Z-ПОЗИЦИЯ", " R170=0.000", ">R171=0.000"});
        row("group MODE back", "F4 9 MODE",
            {"УСТ ПРЕДУСТАНОВКИ", " 7-ОСЦИЛЛЯЦИЯ", " 8-СКОРОСТИ", ">9-ОСЕВАЯ"});
        row("group F4 back", "F4 5 F4",
            {"УСТ ПРЕДУСТАНОВКИ", " 3-ПОДНАЛАДКА", " 4-ПРАВКА", ">5-ШЛИФ.КРУГ"});
        row("group remembered", "F4 6 F1 F4",
            {"УСТ ПРЕДУСТАНОВКИ", " 4-ПРАВКА", " 5-ШЛИФ.КРУГ", ">6-АЛМАЗ"});
        row("group typing", "F4 2 1 2 . 3",
            {"УСТ2 ИСХОДНОЕ     X", "MX: 0.000", ">R220=12.3", " R221=180.000"});

        // --- password (2.6) -----------------------------------------------------------
        row("password", "F5", {"ПАРОЛЬ?", ">", "", ""});
        row("password typing", "F5 1 2 3", {"ПАРОЛЬ?", ">***", "", ""});
        row("password DEL", "F5 1 2 3 DEL", {"ПАРОЛЬ?", ">**", "", ""});
        row("password five digits", "F5 1 2 3 4 5", {"ПАРОЛЬ?", ">****", "", ""}); // four taken
        row("password ESC", "F1 F5 ESC ESC",
            {"АВТ            100%", "", " X    0.000    0.000", " Z    0.000    0.000"});
        row("F6 wrong", "F6 1 2 3 4 ENTER", {"ПАРОЛЬ?", ">", "ДОСТУП ЗАКРЫТ", ""});
        row("F7 wrong", "F7 1 1 1 2 ENTER", {"ПАРОЛЬ?", ">", "ДОСТУП ЗАКРЫТ", ""});
        row("F6 wrong retry", "F6 1 2 3 4 ENTER 1 1 1 1 ENTER",
            {"РЕДАКТИРОВАНИЕ УП", " ПРОГРАММА 1", ">КАТАЛОГ", " ОЧИСТИТЬ УП"});

        // --- 2.6.6 ----------------------------------------------------------------
        row("cparams", "F5 1 1 1 1 ENTER",
            {"ПАРАМЕТРЫ СТАНКА", "НАЛИЧ.ОСИ", "N001>X=1", "N053 Z=1"});
        row("cparams view only", "F5 2 2 2 2 ENTER",
            {"ПАРАМЕТРЫ СТАНКА", "НАЛИЧ.ОСИ", "N001>X=1", "N053 Z=1"});
        row("cparams down", "F5 1 1 1 1 ENTER DOWN",
            {"ПАРАМЕТРЫ СТАНКА", "ЗНАК ДОС", "N002>X=0", "N054 Z=0"});
        row("cparams up stops", "F5 1 1 1 1 ENTER UP",
            {"ПАРАМЕТРЫ СТАНКА", "НАЛИЧ.ОСИ", "N001>X=1", "N053 Z=1"});
        row("cparams other axis", "F5 1 1 1 1 ENTER DOWN DOWN DOWN DOWN DOWN DOWN LEFT",
            {"ПАРАМЕТРЫ СТАНКА", "ИНД.ДИАМЕТР", "N007 X=1", "N059>Z=0"});
        row("cparams Z steps", "F5 1 1 1 1 ENTER LEFT DOWN",
            {"ПАРАМЕТРЫ СТАНКА", "ЗНАК ДОС", "N002 X=0", "N054>Z=0"});
        row("cparams common", "F5 1 1 1 1 ENTER RIGHT", {"ПАРАМЕТРЫ СТАНКА", "N М1", "№105 2", ""});
        row("cparams common back", "F5 1 1 1 1 ENTER DOWN LEFT RIGHT DOWN LEFT",
            {"ПАРАМЕТРЫ СТАНКА", "ЗНАК ДОС", "N002 X=0", "N054>Z=0"});
        row("cparams PAR prompt", "F5 1 1 1 1 ENTER PAR 4",
            {"ПАРАМЕТРЫ СТАНКА", "НОМЕР ПАРАМЕТРА?", ">4", ""});
        row("cparams PAR X", "F5 1 1 1 1 ENTER PAR 4 0 ENTER",
            {"ПАРАМЕТРЫ СТАНКА", "F ОБЫЧНАЯ", "N040>X=150000", "N092 Z=200000"});
        row("cparams PAR Z", "F5 1 1 1 1 ENTER PAR 9 2 ENTER",
            {"ПАРАМЕТРЫ СТАНКА", "F ОБЫЧНАЯ", "N040 X=150000", "N092>Z=200000"});
        row("cparams PAR common", "F5 1 1 1 1 ENTER PAR 1 2 3 ENTER",
            {"ПАРАМЕТРЫ СТАНКА", "ESC=сброс в исх.сост", "№123 1", ""});
        row("cparams PAR bad", "F5 1 1 1 1 ENTER PAR 1 5 3 ENTER",
            {"ПАРАМЕТРЫ СТАНКА", "ОШИБКА ВВОДА", "N001>X=1", "N053 Z=1"});
        row("cparams last pair", "F5 1 1 1 1 ENTER RIGHT UP",
            {"ПАРАМЕТРЫ СТАНКА", "Резерв", "N052>X=0", "N104 Z=0"});
        row("cparams last pair down", "F5 1 1 1 1 ENTER PAR 5 2 ENTER DOWN",
            {"ПАРАМЕТРЫ СТАНКА", "N М1", "№105 2", ""});
        row("cparams last", "F5 1 1 1 1 ENTER PAR 1 5 2 ENTER DOWN",
            {"ПАРАМЕТРЫ СТАНКА", "Резерв", "№152 0", ""});
        row("cparams typing", "F5 1 1 1 1 ENTER PAR 2 1 ENTER 2 5 0 0",
            {"ПАРАМЕТРЫ СТАНКА", "T контроля ДОС", "N021>X=2500", "N073 Z=1000"});
        row("cparams view only typing", "F5 0 0 0 0 ENTER PAR 2 1 ENTER 2 5 0 0",
            {"ПАРАМЕТРЫ СТАНКА", "T контроля ДОС", "N021>X=1000", "N073 Z=1000"});
        row("cparams re-entry", "F5 1 1 1 1 ENTER PAR 2 6 ENTER F2 F5 1 1 1 1 ENTER",
            {"ПАРАМЕТРЫ СТАНКА", "К(СКОР)", "N026>X=262", "N078 Z=174"});

        // --- 2.6.7 ----------------------------------------------------------------
        row("program menu", "F6 1 1 1 1 ENTER",
            {"РЕДАКТИРОВАНИЕ УП", " ПРОГРАММА 1", ">КАТАЛОГ", " ОЧИСТИТЬ УП"});
        row("program menu number", "F6 1 1 1 1 ENTER UP 4 2",
            {"РЕДАКТИРОВАНИЕ УП", ">ПРОГРАММА 42", " КАТАЛОГ", " ОЧИСТИТЬ УП"});
        row("catalog", "F6 1 1 1 1 ENTER ENTER", {"РЕДАКТИРОВАНИЕ УП", ">L1", " L90", " L91"});
        row("catalog down", "F6 1 1 1 1 ENTER ENTER DOWN RIGHT",
            {"РЕДАКТИРОВАНИЕ УП", " L1", " L90", ">L91"});
        row("catalog ESC", "F6 1 1 1 1 ENTER ENTER ESC",
            {"РЕДАКТИРОВАНИЕ УП", " ПРОГРАММА 1", ">КАТАЛОГ", " ОЧИСТИТЬ УП"});
        row("catalog DEL", "F6 1 1 1 1 ENTER ENTER DOWN DEL",
            {"РЕДАКТИРОВАНИЕ УП", "УДАЛИТЬ L90?", "", "ENTER-ДА  ESC-НЕТ"});
        row("catalog DEL done", "F6 1 1 1 1 ENTER ENTER DOWN DEL ENTER",
            {"РЕДАКТИРОВАНИЕ УП", " L1", ">L91", ""});
        row("catalog DEL no", "F6 1 1 1 1 ENTER ENTER DOWN DEL ESC",
            {"РЕДАКТИРОВАНИЕ УП", " L1", ">L90", " L91"});
        row("clear programs", "F6 1 1 1 1 ENTER DOWN ENTER",
            {"РЕДАКТИРОВАНИЕ УП", "ОЧИСТИТЬ УП?", "", "ENTER-ДА  ESC-НЕТ"});
        row("clear programs done", "F6 1 1 1 1 ENTER DOWN ENTER ENTER",
            {"РЕДАКТИРОВАНИЕ УП", " ПРОГРАММА 0", " КАТАЛОГ", ">ОЧИСТИТЬ УП"});
        row("clear programs catalog", "F6 1 1 1 1 ENTER DOWN ENTER ENTER UP ENTER",
            {"РЕДАКТИРОВАНИЕ УП", "", "", ""});
        row("frame ISO", "F6 1 1 1 1 ENTER UP ENTER",
            {" N1  G90 G0  G   #1", " M3  M8  M       L", "X42.000    F=", "Z2.000     F="});
        row("frame next", "F6 1 1 1 1 ENTER UP ENTER SHIFT+DOWN",
            {" N2  G1  G   G   #2", " M   M   M       L", "X          F=", "Z0.000     F=200.00"});
        row("frame computational",
            "F6 1 1 1 1 ENTER UP ENTER SHIFT+DOWN SHIFT+DOWN SHIFT+DOWN SHIFT+DOWN SHIFT+DOWN",
            {" N6  R1", "     =R10", "     -R12", ""});
        row("frame PAR ignored", "F6 1 1 1 1 ENTER UP ENTER PAR",
            {" N1  G90 G0  G   #1", " M3  M8  M       L", "X42.000    F=", "Z2.000     F="});
        row("frame new program", "F6 1 1 1 1 ENTER UP 5 ENTER",
            {" N   G   G   G   #", " M   M   M       L", "X          F=", "Z          F="});
        row("frame type menu", "F6 1 1 1 1 ENTER UP 5 ENTER ACK",
            {"Укажите тип кадра", "1-вычислит.кадр", "2-кадр усл.перехода", "3-кадр безусл.перех"});
        row("frame new computational", "F6 1 1 1 1 ENTER UP 5 ENTER ACK 1",
            {" N   R", "     =", "", ""});
        row("frame new conditional", "F6 1 1 1 1 ENTER UP 5 ENTER ACK 2",
            {" N   IF R>0", "     GOTO", "", ""});
        row("frame new unconditional", "F6 1 1 1 1 ENTER UP 5 ENTER ACK 3",
            {" N   GOTO", "", "", ""});
        row("frame type menu ESC", "F6 1 1 1 1 ENTER UP 5 ENTER ACK ESC",
            {" N   G   G   G   #", " M   M   M       L", "X          F=", "Z          F="});
        row("frame manual's ISO",
            "F6 1 1 1 1 ENTER UP 5 ENTER 1 2 DOWN DOWN 5 . 3 4 2 RIGHT 5 0 RIGHT - 1 2 3 4 . 6 7 8 "
            "RIGHT 1 0 0 0 ENTER",
            {" N12 G   G   G   #", " M   M   M       L", "X5.342     F=50.00",
             "Z-1234.678 F=1000.00"});
        row("frame manual's computational",
            "F6 1 1 1 1 ENTER UP 5 ENTER ACK 1 1 2 RIGHT 1 2 3 = % 1 + 1 2 ENTER",
            {" N12 R123", "     =R1", "     +12", ""});
        row("frame manual's conditional",
            "F6 1 1 1 1 ENTER UP 5 ENTER ACK 2 2 0 2 RIGHT 1 DOWN 3 0 1 ENTER",
            {" N202IF R1>0", "     GOTO 301", "", ""});
        row("frame manual's unconditional",
            "F6 1 1 1 1 ENTER UP 5 ENTER ACK 3 2 0 7 RIGHT 3 3 ENTER",
            {" N207GOTO 33", "", "", ""});
        row("frame skip", "F6 1 1 1 1 ENTER UP 5 ENTER ACK 3 2 0 7 RIGHT 3 3 ENTER !",
            {"/N207GOTO 33", "", "", ""});
        row("frame skip off", "F6 1 1 1 1 ENTER UP 5 ENTER ACK 3 2 0 7 RIGHT 3 3 ENTER ! !",
            {" N207GOTO 33", "", "", ""});
        row("frame MODE to catalog", "F6 1 1 1 1 ENTER UP 5 ENTER 1 ENTER MODE",
            {"РЕДАКТИРОВАНИЕ УП", " L1", ">L5", " L90"});
        row("frame MODE to menu", "F6 1 1 1 1 ENTER UP 5 ENTER 1 ENTER MODE MODE",
            {"РЕДАКТИРОВАНИЕ УП", ">ПРОГРАММА 5", " КАТАЛОГ", " ОЧИСТИТЬ УП"});

        // --- 2.6.8 ----------------------------------------------------------------
        row("data control", "F7 1 1 1 1 ENTER",
            {"УПРАВЛЕНИЕ ДАННЫМИ", ">ОЧИСТКА С-ПАРАМ", " ОЧИСТКА Р-ПАРАМ", " РАБОТА С ПЭВМ"});
        row("data control confirm", "F7 1 1 1 1 ENTER ENTER",
            {"УПРАВЛЕНИЕ ДАННЫМИ", "ОЧИСТКА С-ПАРАМ?", "", "ENTER-ДА  ESC-НЕТ"});
        row("data control confirm R", "F7 1 1 1 1 ENTER DOWN ENTER",
            {"УПРАВЛЕНИЕ ДАННЫМИ", "ОЧИСТКА Р-ПАРАМ?", "", "ENTER-ДА  ESC-НЕТ"});
        row("data control no", "F7 1 1 1 1 ENTER DOWN ENTER ESC",
            {"УПРАВЛЕНИЕ ДАННЫМИ", " ОЧИСТКА С-ПАРАМ", ">ОЧИСТКА Р-ПАРАМ", " РАБОТА С ПЭВМ"});
        row("data control PC", "F7 1 1 1 1 ENTER DOWN DOWN ENTER",
            {"УПРАВЛЕНИЕ ДАННЫМИ", "РАБОТА С ПЭВМ", "ГОТОВ К ОБМЕНУ", ""});
        row("data control PC MODE", "F7 1 1 1 1 ENTER DOWN DOWN ENTER MODE",
            {"УПРАВЛЕНИЕ ДАННЫМИ", " ОЧИСТКА С-ПАРАМ", " ОЧИСТКА Р-ПАРАМ", ">РАБОТА С ПЭВМ"});

        // --- HELP (2.6) ----------------------------------------------------------
        row("help", "HELP",
            {">1 - СООБЩЕНИЯ", " 2 - НЕИСПРАВНОСТИ", " 3 - СИСТЕМА", " 4 - ДИАГНОСТИКА"});
        row("help marker", "HELP DOWN DOWN",
            {" 1 - СООБЩЕНИЯ", " 2 - НЕИСПРАВНОСТИ", ">3 - СИСТЕМА", " 4 - ДИАГНОСТИКА"});
        row("help messages empty", "HELP 1", {"СООБЩЕНИЯ", "", "", ""});
        row("help faults empty", "HELP DOWN ENTER", {"НЕИСПРАВНОСТИ", "", "", ""});
        row("help system empty", "HELP 3 DOWN UP", {"СИСТЕМА", "", "", ""});
        row("help list MODE", "HELP 3 MODE",
            {" 1 - СООБЩЕНИЯ", " 2 - НЕИСПРАВНОСТИ", ">3 - СИСТЕМА", " 4 - ДИАГНОСТИКА"});
        row("diagnostics X", "HELP 4", {"ABS_X 0.000", "ERR_X 0.000", "DAC_X 0", "PLS_X 0"});
        row("diagnostics Z", "HELP 4 RIGHT", {"ABS_Z 0.000", "ERR_Z 0.000", "DAC_Z 0", "PLS_Z 0"});
        row("diagnostics back", "HELP 4 RIGHT LEFT",
            {"ABS_X 0.000", "ERR_X 0.000", "DAC_X 0", "PLS_X 0"});
        row("help back", "F4 3 HELP 4 HELP", {"УСТ3 ПОДНАЛАДКА   X", ">R218=0", " R219=0", ""});
        row("help F key", "HELP 2 F1",
            {"АВТ            100%", "", " X    0.000    0.000", " Z    0.000    0.000"});
        row("F8 nothing", "F4 F8",
            {"УСТ ПРЕДУСТАНОВКИ", ">1-КООРД.И СМЕЩЕНИЯ", " 2-ИСХОДНОЕ", " 3-ПОДНАЛАДКА"});
    }
    void screen() {
        QFETCH(QString, keys);
        QFETCH(QStringList, lines);
        PanelRig r;
        r.keys(keys.toStdString());
        QCOMPARE(r.lines(), lines);
    }

    // Every line of every screen above is 20 characters the LCD font has.
    void linesFitTheLcd() {
        const char* sequences[] = {"",
                                   "F1 MODE",
                                   "F2 MODE MODE",
                                   "F3",
                                   "F4 7 DOWN DOWN DOWN",
                                   "F4 9",
                                   "F5 1 1 1 1 ENTER PAR 1 2 5 ENTER",
                                   "F6 1 1 1 1 ENTER UP ENTER",
                                   "F6 1 1 1 1 ENTER UP 5 ENTER ACK",
                                   "F7 1 1 1 1 ENTER",
                                   "HELP",
                                   "HELP 4"};
        for (const char* s : sequences) {
            PanelRig r;
            r.keys(s);
            const panel::Display d = r.display();
            for (const std::string& l : d.lcd.lines) {
                QCOMPARE(utf8::length(l), std::size_t(20));
                QVERIFY2(!panel::lcdFirstUnsupported(l).has_value(), l.c_str());
            }
        }
    }
};

QTEST_APPLESS_MAIN(TestScreens)
#include "test_screens.moc"
