// The texts of a training grade: one entry per id, the Russian and the
// English template, %1..%9 the arguments, %% a per cent sign. One entry a
// line, plain literals.
#include "catalog/training_texts.h"

namespace k528::catalog {

namespace {

constexpr util::CatalogText kTexts[] = {
    // --- the file -----------------------------------------------------------------------
    {"program-errors", "Программа не принята станком: %1 ошибок, первая в строке %2: %3", "the machine does not take the program: %1 errors, the first on line %2: %3"},
    {"no-program", "В файле нет программы: станку нечего выполнять", "the file holds no program: the machine has nothing to run"},
    {"procedure-error", "Строка %1: действие оператора «%2» не понято: %3", "line %1: the operator's step '%2' is not understood: %3"},
    {"procedure.hold", "HOLD:КНОПКА:С — держать кнопку С секунд (0..3600)", "HOLD:BUTTON:S holds a button for S seconds (0..3600)"},
    {"procedure.estop", "аварийная кнопка фиксируется: PUSH:ESTOP, PULL:ESTOP", "the E-stop latches: PUSH:ESTOP, PULL:ESTOP"},
    {"procedure.button", "нет такой кнопки; кнопки станка: DRIVES_ON START STOP RESET X+ X- Z+ Z- RAPID CHUCK ESTOP", "no such button; the machine's buttons: DRIVES_ON START STOP RESET X+ X- Z+ Z- RAPID CHUCK ESTOP"},
    {"procedure.wait", "WAIT:С — подождать С секунд (0..36000)", "WAIT:S waits S seconds (0..36000)"},
    {"procedure.program", "PROGRAM:N — номер программы 1..99", "PROGRAM:N takes a program number 1..99"},
    {"procedure.handwheel", "HANDWHEEL:X, HANDWHEEL:Z или HANDWHEEL:OFF", "HANDWHEEL:X, HANDWHEEL:Z or HANDWHEEL:OFF"},
    {"procedure.step", "STEP:1, STEP:10 или STEP:100 — множитель маховика", "STEP:1, STEP:10 or STEP:100: the handwheel's multiplier"},
    {"procedure.turn", "TURN:N — повернуть маховик на N делений (±1..100000)", "TURN:N turns the handwheel by N detents (±1..100000)"},
    {"procedure.override", "OVERRIDE:П — положение корректора: 0 1 2 5 10 20 35 50 75 90 100", "OVERRIDE:P takes a step of the override: 0 1 2 5 10 20 35 50 75 90 100"},
    {"procedure.preset", "R<n>=<значение> — записываемый R-параметр 0..231 и целое значение", "R<n>=<value>: a writable R-parameter 0..231 and a whole value"},
    {"procedure.unknown", "ожидается одно из: %2", "expected one of: %2"},
    // --- what a step of the procedure did not do -------------------------------------------
    {"note.program-refused", "программа L%1 не выбрана (ACK, номер, ENTER в режиме АВТОМАТ)", "program L%1 was not selected (ACK, number, ENTER in АВТОМАТ)"},
    {"note.override-refused", "корректор %1 %% не установлен: на станке нет такого положения", "the override %1 %% was not set: the machine has no such step"},
    {"note.new-wheel-refused", "круг не заменён: сначала остановите шпиндель круга", "the wheel was not changed: stop the wheel spindle first"},
    {"note.door-refused", "дверь не открылась: она заблокирована", "the door did not open: it is locked"},
    {"note.home-failed", "привязка к базовой точке не выполнена: %1", "the reference-point cycle did not complete: %1"},
    {"note.preset-refused", "%1 = %2 не записано (РУЧНОЙ, экран 3; во время программы запись запрещена)", "%1 = %2 was not written (РУЧНОЙ, screen 3; not while a program runs)"},
    {"note.not-started", "программа не запустилась после «Пуск»", "the program did not start after CYCLE START"},
    // --- the part ---------------------------------------------------------------------------
    {"overcut", "Перерез: металл снят на %1 мкм глубже допуска (площадь %2 мм²) на Ø%3 у Z%4 — кадр %5, строка %6", "over-cut: metal removed %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4 — frame %5, line %6"},
    {"overcut.manual", "Перерез ручным перемещением: металл снят на %1 мкм глубже допуска (площадь %2 мм²) на Ø%3 у Z%4", "over-cut by a manual move: metal removed %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4"},
    {"overcut.unknown", "Перерез: металла нет на %1 мкм глубже допуска (площадь %2 мм²) на Ø%3 у Z%4", "over-cut: metal missing %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4"},
    {"undercut", "Недорез: оставлено %1 мкм сверх допуска (площадь %2 мм²) на Ø%3 у Z%4; ближайший проход — кадр %5, строка %6", "under-cut: %1 µm of metal left beyond the tolerance (area %2 mm²) at Ø%3 near Z%4; the nearest pass is frame %5, line %6"},
    {"undercut.untouched", "Недорез: оставлено %1 мкм сверх допуска (площадь %2 мм²) на Ø%3 у Z%4 — здесь не прошёл ни один проход", "under-cut: %1 µm of metal left beyond the tolerance (area %2 mm²) at Ø%3 near Z%4: no pass came here"},
    // --- collisions -------------------------------------------------------------------------
    {"collision.rapid-into-material", "Ускоренное перемещение (G00) в металл на X%1 Z%2, на %3 мм в заготовку — кадр %4, строка %5: инструмент сломан", "a rapid (G00) into the metal at X%1 Z%2, %3 mm into the blank — frame %4, line %5: the tool is broken"},
    {"collision.manual-into-material", "Ручное перемещение в металл на X%1 Z%2, на %3 мм в заготовку: инструмент сломан", "a manual move into the metal at X%1 Z%2, %3 mm into the blank: the tool is broken"},
    {"collision.feed-spindle-stopped", "Резание при остановленном шпинделе на X%1 Z%2 — кадр %4, строка %5: включите шпиндель (M3) до подачи", "cutting with the spindle stopped at X%1 Z%2 — frame %4, line %5: start the spindle (M3) before the feed"},
    {"collision.feed-wheel-stopped", "Подача круга в кольцо при остановленном круге: кромка Ø%1 у Z%2 — кадр %4, строка %5: включите круг до подачи", "a feed of the wheel into the ring with the wheel stopped: its edge at Ø%1 near Z%2 — frame %4, line %5: start the wheel before the feed"},
    {"collision.tool-into-chuck.jaws", "Инструмент в кулачки патрона на X%1 Z%2 — кадр %4, строка %5", "the tool into the chuck's jaws at X%1 Z%2 — frame %4, line %5"},
    {"collision.tool-into-chuck.body", "Инструмент в корпус патрона на X%1 Z%2 — кадр %4, строка %5", "the tool into the chuck's body at X%1 Z%2 — frame %4, line %5"},
    {"collision.tool-into-chuck", "Инструмент в патрон или кулачки на X%1 Z%2 — кадр %4, строка %5", "the tool into the chuck or its jaws at X%1 Z%2 — frame %4, line %5"},
    {"collision.tool-into-chuck.manual", "Инструмент в патрон или кулачки ручным перемещением на X%1 Z%2", "the tool into the chuck or its jaws by a manual move at X%1 Z%2"},
    {"collision.rapid-into-material.ring", "Круг на ускоренном ходу в кольцо: кромка Ø%1 у Z%2, на %3 мм в стенку — кадр %4, строка %5", "the wheel into the ring at rapid: its edge at Ø%1 near Z%2, %3 mm into the wall — frame %4, line %5"},
    // --- messages and the run ----------------------------------------------------------------
    {"message", "Сообщение %1 «%2» — кадр %3, строка %4: в этом упражнении его быть не должно", "message %1 «%2» — frame %3, line %4: it must not come in this exercise"},
    {"message.machine", "Сообщение %1 «%2»: в этом упражнении его быть не должно", "message %1 «%2»: it must not come in this exercise"},
    {"not-started", "Программа не запускалась", "the program was never started"},
    {"not-started.why", "Программа не запустилась: %1", "the program did not start: %1"},
    {"not-completed.alarm", "Программа остановлена сообщением и не выполнена до конца — кадр %1, строка %2", "a message stopped the program before its end — frame %1, line %2"},
    {"not-completed.interrupted", "Программа прервана и не выполнена до конца — кадр %1, строка %2", "the program was interrupted before its end — frame %1, line %2"},
    {"not-completed.timeout", "Программа не закончилась за отведённое время — кадр %1, строка %2", "the program did not end in the time given — frame %1, line %2"},
    {"cycle-time", "Время цикла %1 с больше нормы %2 с", "cycle time %1 s is over the limit of %2 s"},
    // --- the operator's steps -----------------------------------------------------------------
    {"step.home", "Привязка к базовой точке (ПБТ) по X и Z не выполнена до пуска программы", "the reference-point cycle (ПБТ) of X and Z was not done before the program started"},
    {"step.preset", "R%1 при пуске программы = %2, а по заданию должно быть %3 (РУЧНОЙ, экран 3)", "R%1 was %2 when the program started; the task asks for %3 (РУЧНОЙ, screen 3)"},
    {"step.acknowledge", "Сообщения не квитированы (ESC): %1", "messages not acknowledged (ESC): %1"},
    {"step.position", "Инструмент остановлен на X%1 Z%2, а по заданию — X%3 Z%4 (±%5 мм)", "the tool stopped at X%1 Z%2; the task asks for X%3 Z%4 (±%5 mm)"},
    {"step.new_wheel", "Изношенный круг не заменён (НОВЫЙ КРУГ)", "the worn wheel was not changed (NEW WHEEL)"},
    {"step.completed", "Программа не выполнена до конца", "the program did not run to its end"},
    // --- the machine as it is left ---------------------------------------------------------------
    {"end.spindle_stopped", "После программы шпиндель не остановлен (M5)", "the spindle still turns after the program (M5)"},
    {"end.coolant_off", "После программы не выключена СОЖ (M9)", "the coolant is still on after the program (M9)"},
    {"end.gauge_out", "После программы прибор активного контроля не отведён (M21)", "the in-process gauge is still in the bore after the program (M21)"},
    {"end.r", "R%1 после программы = %2, ожидалось %3", "R%1 is %2 after the program; %3 was expected"},
};

} // namespace

util::TextCatalog trainingTexts() { return util::TextCatalog(kTexts); }

} // namespace k528::catalog
