<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ru">
<context>
    <name>CloseButton</name>
    <message>
        <source>Close Tab</source>
        <translation>Закрыть вкладку</translation>
    </message>
</context>
<context>
    <name>FaultTexts</name>
    <message>
        <source>spindle</source>
        <translation>шпиндель</translation>
    </message>
    <message>
        <source>wheel spindle</source>
        <translation>шпиндель круга</translation>
    </message>
    <message>
        <source>work spindle</source>
        <translation>шпиндель изделия</translation>
    </message>
    <message>
        <source>coolant pump</source>
        <translation>насос СОЖ</translation>
    </message>
    <message>
        <source>lubrication pump</source>
        <translation>насос смазки</translation>
    </message>
    <message>
        <source>hydraulic pump</source>
        <translation>гидронасос</translation>
    </message>
    <message>
        <source>Encoder %1: channel %2 broken</source>
        <translation>ДОС %1: обрыв канала %2</translation>
    </message>
    <message>
        <source>Feed drive %1 not ready</source>
        <translation>Нет готовности привода подачи %1</translation>
    </message>
    <message>
        <source>Limit switch %1%2 hit</source>
        <translation>Наезд на конечник %1%2</translation>
    </message>
    <message>
        <source>Emergency stop circuit open</source>
        <translation>Обрыв цепи аварийного останова</translation>
    </message>
    <message>
        <source>Interference on encoder %1 (DAC limit)</source>
        <translation>Помеха в линиях ДОС %1 (предел ЦАП)</translation>
    </message>
    <message>
        <source>PLC I/O module failure, place %1</source>
        <translation>Отказ модуля ввода-вывода ПЛК, место %1</translation>
    </message>
    <message>
        <source>PLC - positioner link lost</source>
        <translation>Нет связи ПЛК и БП</translation>
    </message>
    <message>
        <source>Drive not ready: %1</source>
        <translation>Нет готовности привода: %1</translation>
    </message>
    <message>
        <source>Motor overheat: %1</source>
        <translation>Перегрев двигателя: %1</translation>
    </message>
    <message>
        <source>Motor overload: %1</source>
        <translation>Перегрузка двигателя: %1</translation>
    </message>
    <message>
        <source>Chuck loses its clamping pressure</source>
        <translation>Патрон теряет давление зажима</translation>
    </message>
    <message>
        <source>Turret jammed</source>
        <translation>Резцедержатель заклинило</translation>
    </message>
    <message>
        <source>In-process gauge fault</source>
        <translation>Неисправность прибора активного контроля</translation>
    </message>
    <message>
        <source>Positioner: encoder module CP34.23, place 0, failed</source>
        <translation>БП: отказ модуля ДОС CP34.23, место 0</translation>
    </message>
    <message>
        <source>Positioner: encoder module CP34.23, place 1, failed</source>
        <translation>БП: отказ модуля ДОС CP34.23, место 1</translation>
    </message>
    <message>
        <source>Positioner: DAC module CM32.03 failed</source>
        <translation>БП: отказ модуля ЦАП CM32.03</translation>
    </message>
    <message>
        <source>Positioner: communication module CP52.05 failed</source>
        <translation>БП: отказ модуля связи CP52.05</translation>
    </message>
    <message>
        <source>Positioner: link to the K923 unstable</source>
        <translation>БП: неустойчивая связь с K923</translation>
    </message>
    <message>
        <source>Positioner: RAM/ROM test fails</source>
        <translation>БП: ошибка теста ОЗУ/ПЗУ</translation>
    </message>
    <message>
        <source>K923: no link to the PLC</source>
        <translation>K923: нет связи с ПЛК</translation>
    </message>
    <message>
        <source>K923: no link to the positioner</source>
        <translation>K923: нет связи с БП</translation>
    </message>
    <message>
        <source>K923: RAM fault</source>
        <translation>K923: неисправно ОЗУ</translation>
    </message>
    <message>
        <source>K923: resident software corrupt</source>
        <translation>K923: нарушен резидент</translation>
    </message>
    <message>
        <source>PLC in debug stop</source>
        <translation>ПЛК в режиме «ОТЛАДКА СТОП»</translation>
    </message>
</context>
<context>
    <name>QDialog</name>
    <message>
        <source>%1 to the controller</source>
        <translation>%1 в контроллер</translation>
    </message>
    <message>
        <source>The controller already holds what %1 has: nothing changes.</source>
        <translation>Контроллер уже хранит то, что есть в %1: ничего не изменится.</translation>
    </message>
    <message>
        <source>Changes in the controller's memory: %1. Each part is committed all or nothing and read back; a controller on the line must be in F7 «РАБОТА С ПЭВМ».</source>
        <translation>Изменений в памяти контроллера: %1. Каждая часть записывается целиком или никак и считывается обратно; контроллер на линии должен быть в F7 «РАБОТА С ПЭВМ».</translation>
    </message>
    <message>
        <source>Not sent as they are (a push takes released programs only; the machine's setting push.unreleased allows drafts):</source>
        <translation>Не передаются как есть (передаются только выпущенные программы; черновики разрешает настройка станка push.unreleased):</translation>
    </message>
</context>
<context>
    <name>QsciScintilla</name>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Отменить</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Повторить</translation>
    </message>
    <message>
        <source>Cu&amp;t</source>
        <translation>&amp;Вырезать</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Копировать</translation>
    </message>
    <message>
        <source>&amp;Paste</source>
        <translation>Вст&amp;авить</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Удалить</translation>
    </message>
    <message>
        <source>Select All</source>
        <translation>Выделить всё</translation>
    </message>
</context>
<context>
    <name>TrainingTexts</name>
    <message>
        <source>the machine does not take the program: %1 errors, the first on line %2: %3</source>
        <translation>Программа не принята станком: %1 ошибок, первая в строке %2: %3</translation>
    </message>
    <message>
        <source>the file holds no program: the machine has nothing to run</source>
        <translation>В файле нет программы: станку нечего выполнять</translation>
    </message>
    <message>
        <source>line %1: the operator's step '%2' is not understood: %3</source>
        <translation>Строка %1: действие оператора «%2» не понято: %3</translation>
    </message>
    <message>
        <source>HOLD:BUTTON:S holds a button for S seconds (0..3600)</source>
        <translation>HOLD:КНОПКА:С — держать кнопку С секунд (0..3600)</translation>
    </message>
    <message>
        <source>the E-stop latches: PUSH:ESTOP, PULL:ESTOP</source>
        <translation>аварийная кнопка фиксируется: PUSH:ESTOP, PULL:ESTOP</translation>
    </message>
    <message>
        <source>no such button; the machine's buttons: DRIVES_ON START STOP RESET X+ X- Z+ Z- RAPID CHUCK ESTOP</source>
        <translation>нет такой кнопки; кнопки станка: DRIVES_ON START STOP RESET X+ X- Z+ Z- RAPID CHUCK ESTOP</translation>
    </message>
    <message>
        <source>WAIT:S waits S seconds (0..36000)</source>
        <translation>WAIT:С — подождать С секунд (0..36000)</translation>
    </message>
    <message>
        <source>PROGRAM:N takes a program number 1..99</source>
        <translation>PROGRAM:N — номер программы 1..99</translation>
    </message>
    <message>
        <source>HANDWHEEL:X, HANDWHEEL:Z or HANDWHEEL:OFF</source>
        <translation>HANDWHEEL:X, HANDWHEEL:Z или HANDWHEEL:OFF</translation>
    </message>
    <message>
        <source>STEP:1, STEP:10 or STEP:100: the handwheel's multiplier</source>
        <translation>STEP:1, STEP:10 или STEP:100 — множитель маховика</translation>
    </message>
    <message>
        <source>TURN:N turns the handwheel by N detents (±1..100000)</source>
        <translation>TURN:N — повернуть маховик на N делений (±1..100000)</translation>
    </message>
    <message>
        <source>OVERRIDE:P takes a step of the override: 0 1 2 5 10 20 35 50 75 90 100</source>
        <translation>OVERRIDE:П — положение корректора: 0 1 2 5 10 20 35 50 75 90 100</translation>
    </message>
    <message>
        <source>R&lt;n&gt;=&lt;value&gt;: a writable R-parameter 0..231 and a whole value</source>
        <translation>R&lt;n&gt;=&lt;значение&gt; — записываемый R-параметр 0..231 и целое значение</translation>
    </message>
    <message>
        <source>expected one of: %2</source>
        <translation>ожидается одно из: %2</translation>
    </message>
    <message>
        <source>program L%1 was not selected (ACK, number, ENTER in АВТОМАТ)</source>
        <translation>программа L%1 не выбрана (ACK, номер, ENTER в режиме АВТОМАТ)</translation>
    </message>
    <message>
        <source>the override %1 %% was not set: the machine has no such step</source>
        <translation>корректор %1 %% не установлен: на станке нет такого положения</translation>
    </message>
    <message>
        <source>the wheel was not changed: stop the wheel spindle first</source>
        <translation>круг не заменён: сначала остановите шпиндель круга</translation>
    </message>
    <message>
        <source>the door did not open: it is locked</source>
        <translation>дверь не открылась: она заблокирована</translation>
    </message>
    <message>
        <source>the reference-point cycle did not complete: %1</source>
        <translation>привязка к базовой точке не выполнена: %1</translation>
    </message>
    <message>
        <source>%1 = %2 was not written (РУЧНОЙ, screen 3; not while a program runs)</source>
        <translation>%1 = %2 не записано (РУЧНОЙ, экран 3; во время программы запись запрещена)</translation>
    </message>
    <message>
        <source>over-cut: metal removed %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4 — frame %5, line %6</source>
        <translation>Перерез: металл снят на %1 мкм глубже допуска (площадь %2 мм²) на Ø%3 у Z%4 — кадр %5, строка %6</translation>
    </message>
    <message>
        <source>over-cut by a manual move: metal removed %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4</source>
        <translation>Перерез ручным перемещением: металл снят на %1 мкм глубже допуска (площадь %2 мм²) на Ø%3 у Z%4</translation>
    </message>
    <message>
        <source>over-cut: metal missing %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4</source>
        <translation>Перерез: металла нет на %1 мкм глубже допуска (площадь %2 мм²) на Ø%3 у Z%4</translation>
    </message>
    <message>
        <source>under-cut: %1 µm of metal left beyond the tolerance (area %2 mm²) at Ø%3 near Z%4; the nearest pass is frame %5, line %6</source>
        <translation>Недорез: оставлено %1 мкм сверх допуска (площадь %2 мм²) на Ø%3 у Z%4; ближайший проход — кадр %5, строка %6</translation>
    </message>
    <message>
        <source>under-cut: %1 µm of metal left beyond the tolerance (area %2 mm²) at Ø%3 near Z%4: no pass came here</source>
        <translation>Недорез: оставлено %1 мкм сверх допуска (площадь %2 мм²) на Ø%3 у Z%4 — здесь не прошёл ни один проход</translation>
    </message>
    <message>
        <source>a rapid (G00) into the metal at X%1 Z%2, %3 mm into the blank — frame %4, line %5: the tool is broken</source>
        <translation>Ускоренное перемещение (G00) в металл на X%1 Z%2, на %3 мм в заготовку — кадр %4, строка %5: инструмент сломан</translation>
    </message>
    <message>
        <source>a manual move into the metal at X%1 Z%2, %3 mm into the blank: the tool is broken</source>
        <translation>Ручное перемещение в металл на X%1 Z%2, на %3 мм в заготовку: инструмент сломан</translation>
    </message>
    <message>
        <source>cutting with the spindle stopped at X%1 Z%2 — frame %4, line %5: start the spindle (M3) before the feed</source>
        <translation>Резание при остановленном шпинделе на X%1 Z%2 — кадр %4, строка %5: включите шпиндель (M3) до подачи</translation>
    </message>
    <message>
        <source>a feed of the wheel into the ring with the wheel stopped: its edge at Ø%1 near Z%2 — frame %4, line %5: start the wheel before the feed</source>
        <translation>Подача круга в кольцо при остановленном круге: кромка Ø%1 у Z%2 — кадр %4, строка %5: включите круг до подачи</translation>
    </message>
    <message>
        <source>the tool into the chuck's jaws at X%1 Z%2 — frame %4, line %5</source>
        <translation>Инструмент в кулачки патрона на X%1 Z%2 — кадр %4, строка %5</translation>
    </message>
    <message>
        <source>the tool into the chuck's body at X%1 Z%2 — frame %4, line %5</source>
        <translation>Инструмент в корпус патрона на X%1 Z%2 — кадр %4, строка %5</translation>
    </message>
    <message>
        <source>the tool into the chuck or its jaws by a manual move at X%1 Z%2</source>
        <translation>Инструмент в патрон или кулачки ручным перемещением на X%1 Z%2</translation>
    </message>
    <message>
        <source>the wheel into the ring at rapid: its edge at Ø%1 near Z%2, %3 mm into the wall — frame %4, line %5</source>
        <translation>Круг на ускоренном ходу в кольцо: кромка Ø%1 у Z%2, на %3 мм в стенку — кадр %4, строка %5</translation>
    </message>
    <message>
        <source>message %1 «%2» — frame %3, line %4: it must not come in this exercise</source>
        <translation>Сообщение %1 «%2» — кадр %3, строка %4: в этом упражнении его быть не должно</translation>
    </message>
    <message>
        <source>message %1 «%2»: it must not come in this exercise</source>
        <translation>Сообщение %1 «%2»: в этом упражнении его быть не должно</translation>
    </message>
    <message>
        <source>the program was never started</source>
        <translation>Программа не запускалась</translation>
    </message>
    <message>
        <source>the program did not start: %1</source>
        <translation>Программа не запустилась: %1</translation>
    </message>
    <message>
        <source>a message stopped the program before its end — frame %1, line %2</source>
        <translation>Программа остановлена сообщением и не выполнена до конца — кадр %1, строка %2</translation>
    </message>
    <message>
        <source>the program was interrupted before its end — frame %1, line %2</source>
        <translation>Программа прервана и не выполнена до конца — кадр %1, строка %2</translation>
    </message>
    <message>
        <source>the program did not end in the time given — frame %1, line %2</source>
        <translation>Программа не закончилась за отведённое время — кадр %1, строка %2</translation>
    </message>
    <message>
        <source>cycle time %1 s is over the limit of %2 s</source>
        <translation>Время цикла %1 с больше нормы %2 с</translation>
    </message>
    <message>
        <source>the reference-point cycle (ПБТ) of X and Z was not done before the program started</source>
        <translation>Привязка к базовой точке (ПБТ) по X и Z не выполнена до пуска программы</translation>
    </message>
    <message>
        <source>R%1 was %2 when the program started; the task asks for %3 (РУЧНОЙ, screen 3)</source>
        <translation>R%1 при пуске программы = %2, а по заданию должно быть %3 (РУЧНОЙ, экран 3)</translation>
    </message>
    <message>
        <source>messages not acknowledged (ESC): %1</source>
        <translation>Сообщения не квитированы (ESC): %1</translation>
    </message>
    <message>
        <source>the tool stopped at X%1 Z%2; the task asks for X%3 Z%4 (±%5 mm)</source>
        <translation>Инструмент остановлен на X%1 Z%2, а по заданию — X%3 Z%4 (±%5 мм)</translation>
    </message>
    <message>
        <source>the worn wheel was not changed (NEW WHEEL)</source>
        <translation>Изношенный круг не заменён (НОВЫЙ КРУГ)</translation>
    </message>
    <message>
        <source>the program did not run to its end</source>
        <translation>Программа не выполнена до конца</translation>
    </message>
    <message>
        <source>the spindle still turns after the program (M5)</source>
        <translation>После программы шпиндель не остановлен (M5)</translation>
    </message>
    <message>
        <source>the coolant is still on after the program (M9)</source>
        <translation>После программы не выключена СОЖ (M9)</translation>
    </message>
    <message>
        <source>the in-process gauge is still in the bore after the program (M21)</source>
        <translation>После программы прибор активного контроля не отведён (M21)</translation>
    </message>
    <message>
        <source>R%1 is %2 after the program; %3 was expected</source>
        <translation>R%1 после программы = %2, ожидалось %3</translation>
    </message>
    <message>
        <source>the tool into the chuck or its jaws at X%1 Z%2 — frame %4, line %5</source>
        <translation>Инструмент в патрон или кулачки на X%1 Z%2 — кадр %4, строка %5</translation>
    </message>
    <message>
        <source>the program did not start after CYCLE START</source>
        <translation>программа не запустилась после «Пуск»</translation>
    </message>
</context>
<context>
    <name>k528::studio</name>
    <message>
        <source>%1 has errors: nothing was loaded.</source>
        <translation>В %1 есть ошибки: ничего не загружено.</translation>
    </message>
    <message>
        <source>%1 holds no program.</source>
        <translation>В %1 нет программ.</translation>
    </message>
    <message>
        <source>A program is running: stop it (RESET) before loading programs.</source>
        <translation>Выполняется программа: остановите её («Сброс») перед загрузкой.</translation>
    </message>
    <message>
        <source>Fix the syntax errors first: %1</source>
        <translation>Сначала исправьте синтаксические ошибки: %1</translation>
    </message>
    <message>
        <source>The file has no program L%1</source>
        <translation>В файле нет программы L%1</translation>
    </message>
    <message>
        <source>error</source>
        <translation>ошибка</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>предупреждение</translation>
    </message>
    <message>
        <source>none (the language only)</source>
        <translation>нет (только язык)</translation>
    </message>
    <message>
        <source>File: %1</source>
        <translation>Файл: %1</translation>
    </message>
    <message>
        <source>Machine: %1    Date: %2</source>
        <translation>Станок: %1    Дата: %2</translation>
    </message>
    <message>
        <source>Errors: %1, warnings: %2    Page %3 of %4</source>
        <translation>Ошибок: %1, предупреждений: %2    Лист %3 из %4</translation>
    </message>
    <message>
        <source>%1 cannot be written: %2</source>
        <translation>%1 не записывается: %2</translation>
    </message>
    <message>
        <source>%1 cannot be written</source>
        <translation>%1 не записывается</translation>
    </message>
    <message>
        <source>The database has no machine %1</source>
        <translation>В базе нет станка %1</translation>
    </message>
    <message>
        <source>Not saved: fix the syntax errors first: %1</source>
        <translation>Не сохранено: сначала исправьте синтаксические ошибки: %1</translation>
    </message>
    <message>
        <source>Not saved: every program needs its %L header in the machine's memory</source>
        <translation>Не сохранено: в памяти станка каждой программе нужен заголовок %L</translation>
    </message>
    <message>
        <source>Not saved: %1 was changed in the database since revision %2 was opened (%3)</source>
        <translation>Не сохранено: %1 изменён в базе после того, как была открыта ревизия %2 (%3)</translation>
    </message>
    <message>
        <source>%1 is the database this window uses: it is not read as a program</source>
        <translation>%1 — база данных, с которой работает это окно: как программа она не читается</translation>
    </message>
</context>
<context>
    <name>k528::studio::AxesView</name>
    <message>
        <source>Axis</source>
        <translation>Ось</translation>
    </message>
    <message>
        <source>Current, mm</source>
        <translation>Текущая, мм</translation>
    </message>
    <message>
        <source>Machine, mm</source>
        <translation>Станка, мм</translation>
    </message>
    <message>
        <source>Rest, mm</source>
        <translation>Остаток, мм</translation>
    </message>
    <message>
        <source>Feed, mm/min</source>
        <translation>Подача, мм/мин</translation>
    </message>
    <message>
        <source>Error, µm</source>
        <translation>Ошибка, мкм</translation>
    </message>
    <message>
        <source>DAC</source>
        <translation>ЦАП</translation>
    </message>
    <message>
        <source>Volts</source>
        <translation>Вольт</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Состояние</translation>
    </message>
    <message>
        <source> (dia.)</source>
        <translation> (диам.)</translation>
    </message>
    <message>
        <source>absent</source>
        <translation>нет оси</translation>
    </message>
    <message>
        <source>homing</source>
        <translation>привязка</translation>
    </message>
    <message>
        <source>homed</source>
        <translation>привязана</translation>
    </message>
    <message>
        <source>not homed</source>
        <translation>не привязана</translation>
    </message>
    <message>
        <source>loop closed</source>
        <translation>контур замкнут</translation>
    </message>
    <message>
        <source>loop open</source>
        <translation>контур разомкнут</translation>
    </message>
    <message>
        <source>moving</source>
        <translation>движение</translation>
    </message>
    <message>
        <source>in position</source>
        <translation>в позиции</translation>
    </message>
    <message>
        <source>cam</source>
        <translation>конечник торможения</translation>
    </message>
    <message>
        <source>limit +</source>
        <translation>конечник +</translation>
    </message>
    <message>
        <source>limit -</source>
        <translation>конечник -</translation>
    </message>
    <message>
        <source>fault %1</source>
        <translation>ошибка %1</translation>
    </message>
    <message>
        <source>Z1000 PLC→</source>
        <translation>Z1000 ПЛК→</translation>
    </message>
    <message>
        <source>E-stop released</source>
        <translation>нет аварийного стопа</translation>
    </message>
    <message>
        <source>feed enable</source>
        <translation>деблокировка подачи</translation>
    </message>
    <message>
        <source>start enable</source>
        <translation>деблокировка пуска</translation>
    </message>
    <message>
        <source>start</source>
        <translation>пуск</translation>
    </message>
    <message>
        <source>stop</source>
        <translation>стоп</translation>
    </message>
    <message>
        <source>reset</source>
        <translation>сброс</translation>
    </message>
    <message>
        <source>data hold</source>
        <translation>блокировка ввода</translation>
    </message>
    <message>
        <source>acknowledge</source>
        <translation>квитирование</translation>
    </message>
    <message>
        <source>M done</source>
        <translation>M выполнена</translation>
    </message>
    <message>
        <source>mode %1</source>
        <translation>режим %1</translation>
    </message>
    <message>
        <source>Z2000 →PLC</source>
        <translation>Z2000 →ПЛК</translation>
    </message>
    <message>
        <source>ready</source>
        <translation>готова</translation>
    </message>
    <message>
        <source>running</source>
        <translation>выполняется</translation>
    </message>
    <message>
        <source>interrupted</source>
        <translation>прервано</translation>
    </message>
    <message>
        <source>end/reset</source>
        <translation>конец/сброс</translation>
    </message>
    <message>
        <source>dwell</source>
        <translation>выдержка</translation>
    </message>
    <message>
        <source>M00</source>
        <translation>M00</translation>
    </message>
    <message>
        <source>override 0%</source>
        <translation>корректор 0%</translation>
    </message>
    <message>
        <source>change wheel</source>
        <translation>смена круга</translation>
    </message>
    <message>
        <source>Z2001</source>
        <translation>Z2001</translation>
    </message>
    <message>
        <source>M strobe</source>
        <translation>строб M</translation>
    </message>
    <message>
        <source>M code %1</source>
        <translation>код M %1</translation>
    </message>
    <message>
        <source>cycle %1</source>
        <translation>цикл %1</translation>
    </message>
    <message>
        <source>regulator</source>
        <translation>регулятор</translation>
    </message>
    <message>
        <source>feed</source>
        <translation>подача</translation>
    </message>
    <message>
        <source>jog +</source>
        <translation>перемещение +</translation>
    </message>
    <message>
        <source>jog -</source>
        <translation>перемещение -</translation>
    </message>
    <message>
        <source>rapid</source>
        <translation>ускоренно</translation>
    </message>
    <message>
        <source>loop</source>
        <translation>контур</translation>
    </message>
    <message>
        <source>loop error</source>
        <translation>ошибка контура</translation>
    </message>
    <message>
        <source>fast inputs </source>
        <translation>быстрые входы </translation>
    </message>
</context>
<context>
    <name>k528::studio::CalculatorDialog</name>
    <message>
        <source>C-constant calculator: acceleration (parameter 22)</source>
        <translation>Калькулятор С-параметров: ускорение (параметр 22)</translation>
    </message>
    <message>
        <source>Axis X (C22)</source>
        <translation>Ось X (C22)</translation>
    </message>
    <message>
        <source>Axis Z (C74)</source>
        <translation>Ось Z (C74)</translation>
    </message>
    <message>
        <source>Formula 2: braking from Vmax over S</source>
        <translation>Формула 2: торможение с Vmax на пути S</translation>
    </message>
    <message>
        <source>Formula 3: acceleration A</source>
        <translation>Формула 3: ускорение A</translation>
    </message>
    <message>
        <source>Vmax, mm/min</source>
        <translation>Vmax, мм/мин</translation>
    </message>
    <message>
        <source>S, mm of braking</source>
        <translation>S, мм торможения</translation>
    </message>
    <message>
        <source>A, m/s²</source>
        <translation>A, м/с²</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Ось</translation>
    </message>
    <message>
        <source>Formula</source>
        <translation>Формула</translation>
    </message>
    <message>
        <source>Formula 2 as printed: C = 3.556·10⁻⁶ · Vmax² / S, Vmax in discretes/min, S in discretes: 3.556·10⁻⁶ · %1² / %2 = %3.</source>
        <translation>Формула 2, как напечатана: C = 3.556·10⁻⁶ · Vmax² / S, Vmax в дискретах/мин, S в дискретах: 3.556·10⁻⁶ · %1² / %2 = %3.</translation>
    </message>
    <message>
        <source>Formula 3: C = 25600 · A / Kd, A in m/s², Kd = %1 (the discrete in µm): 25600 · %2 / %1 = %3.</source>
        <translation>Формула 3: C = 25600 · A / Kд, A в м/с², Kд = %1 (дискрета в мкм): 25600 · %2 / %1 = %3.</translation>
    </message>
    <message>
        <source>The motion described: A = %1 m/s². The value as printed: &lt;b&gt;%2&lt;/b&gt;, which means %3 m/s² in K528 Studio's unit (factor %4).</source>
        <translation>Описанное движение: A = %1 м/с². Значение по напечатанной формуле: &lt;b&gt;%2&lt;/b&gt;, в единице K528 Studio это %3 м/с² (множитель %4).</translation>
    </message>
    <message>
        <source>The value that gives this motion: &lt;b&gt;%1&lt;/b&gt; (25600 · A / Kd = %2, integer part). Enter this one in C%3.</source>
        <translation>Значение, дающее это движение: &lt;b&gt;%1&lt;/b&gt; (25600 · A / Kд = %2, целая часть). Его и вводите в C%3.</translation>
    </message>
    <message>
        <source>Why formula 1 gives twice the value</source>
        <translation>Почему формула 1 даёт вдвое большее значение</translation>
    </message>
    <message>
        <source>Set C%1 to %2</source>
        <translation>Записать C%1 = %2</translation>
    </message>
    <message>
        <source>calculator: %1 → C%2 = %3</source>
        <translation>калькулятор: %1 → C%2 = %3</translation>
    </message>
    <message>
        <source>Formula 1: run-up from 0 to Vmax in Tacc</source>
        <translation>Формула 1: разгон от 0 до Vmax за Tразг</translation>
    </message>
    <message>
        <source>Tacc, ms</source>
        <translation>Tразг, мс</translation>
    </message>
    <message>
        <source>Formula 1 as printed: C = 0.8533 · Vmax / Tacc, Vmax in discretes/min, Tacc in ms: 0.8533 · %1 / %2 = %3.</source>
        <translation>Формула 1, как напечатана: C = 0.8533 · Vmax / Tразг, Vmax в дискретах/мин, Tразг в мс: 0.8533 · %1 / %2 = %3.</translation>
    </message>
    <message>
        <source>Table E.1 prints three formulas for parameter 22. Formula 3 defines the unit: C = 25600·A/Kd. Braking from V to 0 over S needs A = V²/(2S); put into formula 3 this is 25600/7200·10⁻⁶·V²/S = 3.5556·10⁻⁶·V²/S — formula 2's 3.556 rounded. A run-up from 0 to V in T needs A = V/T, that is 25600/60000·V/T = 0.4267·V/T; formula 1 prints 0.8533, twice as much.</source>
        <translation>Таблица Е.1 приводит для параметра 22 три формулы. Формула 3 задаёт единицу: C = 25600·A/Kд. Торможение с V до 0 на пути S требует A = V²/(2S); по формуле 3 это 25600/7200·10⁻⁶·V²/S = 3.5556·10⁻⁶·V²/S — коэффициент 3.556 формулы 2, округлённый. Разгон от 0 до V за T требует A = V/T, то есть 25600/60000·V/T = 0.4267·V/T; в формуле 1 напечатано 0.8533 — вдвое больше.</translation>
    </message>
    <message>
        <source>Two formulas against one: K528 Studio takes the unit of formulas 2 and 3 (docs/machine-constants.md). A value computed by formula 1 as printed makes the axis accelerate twice as fast as described (appendix Zh's 2000 for «2 s to 5000 mm/min» runs up in 1.07 s here). Apply the consistent value.</source>
        <translation>Две формулы против одной: K528 Studio принимает единицу формул 2 и 3 (docs/machine-constants.md). Значение по формуле 1, как она напечатана, разгоняет ось вдвое быстрее описанного (2000 из приложения Ж для «2 с до 5000 мм/мин» здесь разгоняет за 1.07 с). Вводите согласованное значение.</translation>
    </message>
</context>
<context>
    <name>k528::studio::CatalogTexts</name>
    <message>
        <source>No regulator enable X</source>
        <translation>Нет деблокировки регулятора X</translation>
    </message>
    <message>
        <source>No answer from encoder slot 0</source>
        <translation>Нет ответа от ДОС 0-место</translation>
    </message>
    <message>
        <source>No answer from DAC</source>
        <translation>Нет ответа от ЦАП</translation>
    </message>
    <message>
        <source>Encoder channel 1 broken (X)</source>
        <translation>Обрыв канала 1 ДОС (ось X)</translation>
    </message>
    <message>
        <source>Encoder channel 2 broken (X)</source>
        <translation>Обрыв канала 2 ДОС (ось X)</translation>
    </message>
    <message>
        <source>DAC limit exceeded (X)</source>
        <translation>Превышен предел ЦАП (ось X)</translation>
    </message>
    <message>
        <source>Max. following error X in motion</source>
        <translation>Макс.рассогл.по X при движении</translation>
    </message>
    <message>
        <source>Position/clamp check X</source>
        <translation>Контроль полож/зажима оси X</translation>
    </message>
    <message>
        <source>Emergency "STOP" from PLC</source>
        <translation>Аварийный «СТОП» от ПЛК</translation>
    </message>
    <message>
        <source>Limit switch X "-"</source>
        <translation>Конечник оси X в «-»</translation>
    </message>
    <message>
        <source>Limit switch X "+"</source>
        <translation>Конечник оси X в «+»</translation>
    </message>
    <message>
        <source>Software limit switch (X)</source>
        <translation>Программный конечный выключ.(X)</translation>
    </message>
    <message>
        <source>Encoder ratio error (X)</source>
        <translation>Ошибка коэфф.преобразования ДОС (X)</translation>
    </message>
    <message>
        <source>CP52.05 failure in positioner</source>
        <translation>Отказ СР52.05 в БП</translation>
    </message>
    <message>
        <source>C-parameters destroyed</source>
        <translation>Разрушены С-параметры</translation>
    </message>
    <message>
        <source>Drive X not ready</source>
        <translation>Нет готовности привода оси X</translation>
    </message>
    <message>
        <source>No regulator enable Z</source>
        <translation>Нет деблокировки регулятора Z</translation>
    </message>
    <message>
        <source>No answer from encoder slot 1</source>
        <translation>Нет ответа от ДОС 1-место</translation>
    </message>
    <message>
        <source>No link with PLC</source>
        <translation>Нет связи с ПЛК</translation>
    </message>
    <message>
        <source>Encoder channel 1 broken (Z)</source>
        <translation>Обрыв канала 1 ДОС (ось Z)</translation>
    </message>
    <message>
        <source>Encoder channel 2 broken (Z)</source>
        <translation>Обрыв канала 2 ДОС (ось Z)</translation>
    </message>
    <message>
        <source>DAC limit exceeded (Z)</source>
        <translation>Превышен предел ЦАП (ось Z)</translation>
    </message>
    <message>
        <source>Max. following error Z in motion</source>
        <translation>Макс.рассогл.по Z при движении</translation>
    </message>
    <message>
        <source>Position/clamp check Z</source>
        <translation>Контроль полож/зажима оси Z</translation>
    </message>
    <message>
        <source>No link with panel</source>
        <translation>Нет связи с панелью</translation>
    </message>
    <message>
        <source>Limit switch Z "-"</source>
        <translation>Конечник оси Z в "-"</translation>
    </message>
    <message>
        <source>Limit switch Z "+"</source>
        <translation>Конечник оси Z в "+"</translation>
    </message>
    <message>
        <source>Software limit switch (Z)</source>
        <translation>Программный конечный выключ.(Z)</translation>
    </message>
    <message>
        <source>Encoder ratio error (Z)</source>
        <translation>Ошибка коэфф.преобразования ДОС (Z)</translation>
    </message>
    <message>
        <source>Positioner RAM/ROM failure</source>
        <translation>Отказ ОЗУ/ПЗУ позиционера</translation>
    </message>
    <message>
        <source>Control program destroyed</source>
        <translation>Разрушена управляющая программа</translation>
    </message>
    <message>
        <source>Drive Z not ready</source>
        <translation>Нет готовности привода оси Z</translation>
    </message>
    <message>
        <source>X coordinate setting</source>
        <translation>Задание координаты X</translation>
    </message>
    <message>
        <source>X/L</source>
        <translation>X/L</translation>
    </message>
    <message>
        <source>X/M17</source>
        <translation>X/M17</translation>
    </message>
    <message>
        <source>X/end of L</source>
        <translation>X/конец L</translation>
    </message>
    <message>
        <source>N encoder error</source>
        <translation>Ошибка N ДОС</translation>
    </message>
    <message>
        <source>N DAC error</source>
        <translation>Ошибка N ЦАП</translation>
    </message>
    <message>
        <source>N handwheel error</source>
        <translation>Ошибка N маховика</translation>
    </message>
    <message>
        <source>Home switch not left</source>
        <translation>Нет съезда с конечника "0"</translation>
    </message>
    <message>
        <source>No "0" mark</source>
        <translation>Нет "0"-метки</translation>
    </message>
    <message>
        <source>Not homed</source>
        <translation>Нет привязки к базовой точке</translation>
    </message>
    <message>
        <source>Wheel D &gt; Dmax</source>
        <translation>D круга &gt; Dmax</translation>
    </message>
    <message>
        <source>Wheel D &lt; Dmin</source>
        <translation>D круга &lt; Dmin</translation>
    </message>
    <message>
        <source>L missing</source>
        <translation>L отсутствует</translation>
    </message>
    <message>
        <source>Overflow</source>
        <translation>Переполнение</translation>
    </message>
    <message>
        <source>G?</source>
        <translation>G?</translation>
    </message>
    <message>
        <source>Nesting depth L</source>
        <translation>Глубина вложения L</translation>
    </message>
    <message>
        <source>Z coordinate setting</source>
        <translation>Задание координаты Z</translation>
    </message>
    <message>
        <source>Z/L</source>
        <translation>Z/L</translation>
    </message>
    <message>
        <source>Z/M17</source>
        <translation>Z/M17</translation>
    </message>
    <message>
        <source>Z/end of L</source>
        <translation>Z/конец L</translation>
    </message>
    <message>
        <source>Jump error</source>
        <translation>Ошибка перехода</translation>
    </message>
    <message>
        <source>Duplicate frame numbers</source>
        <translation>Дублирование номеров кадров</translation>
    </message>
    <message>
        <source>PLC I/O module failure</source>
        <translation>Отказ модулей ввода/вывода в ПЛК</translation>
    </message>
    <message>
        <source>Encoder check X</source>
        <translation>Контроль ДОС оси X</translation>
    </message>
    <message>
        <source>Encoder check Z</source>
        <translation>Контроль ДОС оси Z</translation>
    </message>
    <message>
        <source>M30/L</source>
        <translation>M30/L</translation>
    </message>
    <message>
        <source>M2/L</source>
        <translation>M2/L</translation>
    </message>
    <message>
        <source>M17/L</source>
        <translation>M17/L</translation>
    </message>
    <message>
        <source>M30/M17</source>
        <translation>M30/M17</translation>
    </message>
    <message>
        <source>M2/M17</source>
        <translation>M2/M17</translation>
    </message>
    <message>
        <source>G04/X/Z</source>
        <translation>G04/X/Z</translation>
    </message>
    <message>
        <source>G04/L</source>
        <translation>G04/L</translation>
    </message>
    <message>
        <source>automatic</source>
        <translation>АВТОМАТ</translation>
    </message>
    <message>
        <source>manual</source>
        <translation>РУЧНОЙ</translation>
    </message>
    <message>
        <source>reference point</source>
        <translation>ПРИВЯЗКА К БАЗОВОЙ ТОЧКЕ</translation>
    </message>
    <message>
        <source>presets</source>
        <translation>ПРЕДУСТАНОВКИ</translation>
    </message>
    <message>
        <source>machine constants</source>
        <translation>РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ</translation>
    </message>
    <message>
        <source>program editing</source>
        <translation>РЕДАКТИРОВАНИЕ УП</translation>
    </message>
    <message>
        <source>data control</source>
        <translation>УПРАВЛЕНИЕ ДАННЫМИ</translation>
    </message>
    <message>
        <source>turning</source>
        <translation>проходной</translation>
    </message>
    <message>
        <source>facing</source>
        <translation>подрезной</translation>
    </message>
    <message>
        <source>grooving</source>
        <translation>канавочный</translation>
    </message>
    <message>
        <source>boring</source>
        <translation>расточной</translation>
    </message>
    <message>
        <source>drill</source>
        <translation>сверло</translation>
    </message>
    <message>
        <source>threading</source>
        <translation>резьбовой</translation>
    </message>
    <message>
        <source>coordinates and offsets</source>
        <translation>КООРД.И СМЕЩЕНИЯ</translation>
    </message>
    <message>
        <source>initial position</source>
        <translation>ИСХОДНОЕ</translation>
    </message>
    <message>
        <source>adjustment</source>
        <translation>ПОДНАЛАДКА</translation>
    </message>
    <message>
        <source>dressing</source>
        <translation>ПРАВКА</translation>
    </message>
    <message>
        <source>grinding wheel</source>
        <translation>ШЛИФ.КРУГ</translation>
    </message>
    <message>
        <source>diamond</source>
        <translation>АЛМАЗ</translation>
    </message>
    <message>
        <source>oscillation</source>
        <translation>ОСЦИЛЛЯЦИЯ</translation>
    </message>
    <message>
        <source>speeds</source>
        <translation>СКОРОСТИ</translation>
    </message>
    <message>
        <source>axial orientation</source>
        <translation>ОСЕВАЯ</translation>
    </message>
</context>
<context>
    <name>k528::studio::CompletionTexts</name>
    <message>
        <source>%1 (axis %2)</source>
        <translation>%1 (ось %2)</translation>
    </message>
    <message>
        <source>end of program</source>
        <translation>конец программы</translation>
    </message>
    <message>
        <source>end of subprogram</source>
        <translation>конец подпрограммы</translation>
    </message>
    <message>
        <source>user parameter</source>
        <translation>параметр пользователя</translation>
    </message>
    <message>
        <source>reserved</source>
        <translation>резерв</translation>
    </message>
    <message>
        <source>reserved (read only)</source>
        <translation>резерв (только чтение)</translation>
    </message>
    <message>
        <source>%1 (read only)</source>
        <translation>%1 (только чтение)</translation>
    </message>
    <message>
        <source>program %1</source>
        <translation>программа %1</translation>
    </message>
    <message>
        <source>stop until CYCLE START</source>
        <translation>останов до «Пуск»</translation>
    </message>
</context>
<context>
    <name>k528::studio::ConflictDialog</name>
    <message>
        <source>Changed on another PC — %1</source>
        <translation>Изменено на другом ПК — %1</translation>
    </message>
    <message>
        <source>C%1 = %2 was applied to the controller but not kept in the database: %3

Your change was based on revision %4; revision %5 is the newest now.</source>
        <translation>C%1 = %2 передано в контроллер, но не сохранено в базе данных: %3

Ваше изменение сделано от ревизии %4; последняя ревизия теперь %5.</translation>
    </message>
    <message>
        <source>Show the differences</source>
        <translation>Показать различия</translation>
    </message>
    <message>
        <source>Apply my change on top</source>
        <translation>Применить моё изменение поверх</translation>
    </message>
    <message>
        <source>Do not keep it</source>
        <translation>Не сохранять</translation>
    </message>
</context>
<context>
    <name>k528::studio::ConstantsEditor</name>
    <message>
        <source>No C-parameter %1 (1..152)</source>
        <translation>Нет С-параметра %1 (1..152)</translation>
    </message>
</context>
<context>
    <name>k528::studio::ConstantsFollow</name>
    <message>
        <source>Not kept in the database: %1</source>
        <translation>Не сохранено в базе данных: %1</translation>
    </message>
    <message>
        <source>the controller on the link keeps its own constants until they are pushed to it</source>
        <translation>контроллер на линии хранит свои константы, пока в него не передадут новые</translation>
    </message>
    <message>
        <source>the simulated controller did not take it now: %1</source>
        <translation>модель контроллера сейчас её не приняла: %1</translation>
    </message>
    <message>
        <source>the constants shown are this revision's</source>
        <translation>показаны константы этой ревизии</translation>
    </message>
    <message>
        <source>Database %1: the machine %2 is not read from it: %3</source>
        <translation>База данных %1: станок %2 из неё не прочитан: %3</translation>
    </message>
    <message>
        <source>Database %1 has no machine %2: the constants shown stay as they were; the first change kept creates the machine there</source>
        <translation>В базе данных %1 нет станка %2: показанные параметры остаются прежними; первое сохранённое изменение создаст станок в ней</translation>
    </message>
    <message>
        <source>Database %1: %2 is at revision %3 there; the controller on the link keeps its own constants until they are pushed to it</source>
        <translation>База данных %1: %2 в ней на ревизии %3; контроллер на линии сохраняет свои параметры, пока их не передадут в него</translation>
    </message>
    <message>
        <source>Database %1: the constants shown are those of revision %2 of %3</source>
        <translation>База данных %1: показаны параметры ревизии %2 станка %3</translation>
    </message>
    <message>
        <source>Database %1: revision %2 of %3 has other constants; the simulated controller did not take them now: %4</source>
        <translation>База данных %1: в ревизии %2 станка %3 другие параметры; модель контроллера сейчас их не приняла: %4</translation>
    </message>
</context>
<context>
    <name>k528::studio::ConstantsLock</name>
    <message>
        <source>Name the class the constants are locked for</source>
        <translation>Укажите группу, для которой блокируются константы</translation>
    </message>
    <message>
        <source>The machine constants are locked by the trainer for the class «%1»: they cannot be changed until the trainer unlocks them (Training course, Class tab)</source>
        <translation>Константы станка заблокированы преподавателем для группы «%1»: изменить их нельзя, пока преподаватель не снимет блокировку (Учебный курс, вкладка «Группа»)</translation>
    </message>
</context>
<context>
    <name>k528::studio::ConstantsModel</name>
    <message>
        <source>No.</source>
        <translation>№</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Ось</translation>
    </message>
    <message>
        <source>Panel name</source>
        <translation>Имя на пульте</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Назначение</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Единица</translation>
    </message>
    <message>
        <source>Range</source>
        <translation>Диапазон</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Значение</translation>
    </message>
    <message>
        <source>The value means</source>
        <translation>Что значит значение</translation>
    </message>
    <message>
        <source>C%1: «%2» is not a whole number</source>
        <translation>C%1: «%2» — не целое число</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Адрес</translation>
    </message>
    <message>
        <source>Where the constant lives in the positioner's memory, as table E.1 prints it: the word Z…, its bit or byte</source>
        <translation>Где параметр лежит в памяти БП, как в таблице Е.1: слово Z…, его бит или байт</translation>
    </message>
</context>
<context>
    <name>k528::studio::ConstantsPane</name>
    <message>
        <source>«%1» is not a whole number</source>
        <translation>«%1» — не целое число</translation>
    </message>
    <message>
        <source>Machine constants</source>
        <translation>Параметры станка</translation>
    </message>
    <message>
        <source>Applied to the controller, but not kept in the database: %1</source>
        <translation>Введено в контроллер, но не сохранено в базе: %1</translation>
    </message>
    <message>
        <source>%1 — kept as revision %2 of %3</source>
        <translation>%1 — сохранено как ревизия %2 станка %3</translation>
    </message>
    <message>
        <source>Search: number, panel name, meaning, unit, address</source>
        <translation>Поиск: номер, имя на пульте, назначение, единица, адрес</translation>
    </message>
    <message>
        <source>All axes</source>
        <translation>Все оси</translation>
    </message>
    <message>
        <source>Axis X</source>
        <translation>Ось X</translation>
    </message>
    <message>
        <source>Axis Z</source>
        <translation>Ось Z</translation>
    </message>
    <message>
        <source>Common</source>
        <translation>Общие</translation>
    </message>
    <message>
        <source>Hide reserved</source>
        <translation>Скрыть резерв</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Отменить</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Повторить</translation>
    </message>
    <message>
        <source>History...</source>
        <translation>История...</translation>
    </message>
    <message>
        <source>Every revision that changed the selected constant</source>
        <translation>Все ревизии, менявшие выбранный параметр</translation>
    </message>
    <message>
        <source>Compare revisions...</source>
        <translation>Сравнить ревизии...</translation>
    </message>
    <message>
        <source>Import...</source>
        <translation>Импорт...</translation>
    </message>
    <message>
        <source>A machine file (.k528m) or the constants as CSV, checked as «k528 db import» checks them</source>
        <translation>Файл станка (.k528m) или параметры в CSV; проверяется, как в «k528 db import»</translation>
    </message>
    <message>
        <source>Export...</source>
        <translation>Экспорт...</translation>
    </message>
    <message>
        <source>Calculator...</source>
        <translation>Калькулятор...</translation>
    </message>
    <message>
        <source>why the next change is made (kept with its revision)</source>
        <translation>зачем вносится следующее изменение (сохраняется с ревизией)</translation>
    </message>
    <message>
        <source>Select a constant first</source>
        <translation>Сначала выберите параметр</translation>
    </message>
    <message>
        <source>Import machine constants</source>
        <translation>Импорт параметров станка</translation>
    </message>
    <message>
        <source>Machine files (*.k528m);;Constants as CSV (*.csv);;All files (*)</source>
        <translation>Файлы станка (*.k528m);;Параметры в CSV (*.csv);;Все файлы (*)</translation>
    </message>
    <message>
        <source>Export machine constants</source>
        <translation>Экспорт параметров станка</translation>
    </message>
    <message>
        <source>Machine files (*.k528m);;Constants as CSV (*.csv)</source>
        <translation>Файлы станка (*.k528m);;Параметры в CSV (*.csv)</translation>
    </message>
    <message>
        <source>Another operation is under way</source>
        <translation>Уже выполняется другая операция</translation>
    </message>
    <message>
        <source>interrupted</source>
        <translation>прервано</translation>
    </message>
    <message>
        <source>Importing %1</source>
        <translation>Импорт %1</translation>
    </message>
    <message>
        <source>%1 imported: revision %2 of %3 (%4 changes)</source>
        <translation>%1 импортирован: ревизия %2 станка %3 (изменений: %4)</translation>
    </message>
    <message>
        <source>Nothing was imported: %1</source>
        <translation>Ничего не импортировано: %1</translation>
    </message>
    <message>
        <source>the controller did not take them: %1</source>
        <translation>контроллер их не принял: %1</translation>
    </message>
    <message>
        <source>Exporting %1</source>
        <translation>Экспорт %1</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>не удаётся записать %1: %2</translation>
    </message>
    <message>
        <source>The constants written to %1</source>
        <translation>Параметры записаны в %1</translation>
    </message>
    <message>
        <source>Nothing was exported: %1</source>
        <translation>Ничего не экспортировано: %1</translation>
    </message>
    <message>
        <source>Changes: %1</source>
        <translation>Изменений: %1</translation>
    </message>
    <message>
        <source>sending them to the controller...</source>
        <translation>передача в контроллер...</translation>
    </message>
    <message>
        <source>The trainer has unlocked the machine constants</source>
        <translation>Преподаватель снял блокировку констант станка</translation>
    </message>
    <message>
        <source>Cutting data...</source>
        <translation>Режимы резания...</translation>
    </message>
    <message>
        <source>Spindle speed from the cutting speed and the diameter, feed per minute, the grinding wheel's surface speed from R207</source>
        <translation>Частота вращения шпинделя по скорости резания и диаметру, минутная подача, окружная скорость шлифовального круга по R207</translation>
    </message>
    <message>
        <source>The constants of the controller on the line, read every 10 s.</source>
        <translation>Константы контроллера на линии, считываются каждые 10 с.</translation>
    </message>
    <message>
        <source>A change is written to it at once and kept in the database.</source>
        <translation>Изменение сразу записывается в него и сохраняется в базе данных.</translation>
    </message>
</context>
<context>
    <name>k528::studio::Controller</name>
    <message>
        <source>The controller has not answered since %1: the values shown are its last, stale; the line is tried again by itself</source>
        <translation>Контроллер не отвечает с %1: показаны его последние, устаревшие значения; связь восстанавливается автоматически</translation>
    </message>
</context>
<context>
    <name>k528::studio::ControllerDock</name>
    <message>
        <source>Controller</source>
        <translation>Контроллер</translation>
    </message>
    <message>
        <source>&amp;Controller</source>
        <translation>&amp;Контроллер</translation>
    </message>
    <message>
        <source>&amp;Connect to the controller</source>
        <translation>&amp;Подключиться к контроллеру</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Отключиться</translation>
    </message>
    <message>
        <source>&amp;Pull into the database</source>
        <translation>&amp;Считать в базу данных</translation>
    </message>
    <message>
        <source>Push a &amp;file...</source>
        <translation>Передать &amp;файл...</translation>
    </message>
    <message>
        <source>Push a database &amp;machine</source>
        <translation>Передать станок из &amp;базы данных</translation>
    </message>
    <message>
        <source>Line (RS485, Modbus RTU)</source>
        <translation>Линия (RS485, Modbus RTU)</translation>
    </message>
    <message>
        <source>Live monitor</source>
        <translation>Монитор</translation>
    </message>
    <message>
        <source>Plugin</source>
        <translation>Модуль</translation>
    </message>
    <message>
        <source>Port</source>
        <translation>Порт</translation>
    </message>
    <message>
        <source>Baud</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <source>Parity</source>
        <translation>Чётность</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Адрес</translation>
    </message>
    <message>
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message>
        <source>even</source>
        <translation>чёт</translation>
    </message>
    <message>
        <source>odd</source>
        <translation>нечёт</translation>
    </message>
    <message>
        <source>Ports</source>
        <translation>Порты</translation>
    </message>
    <message>
        <source>Pull into the database</source>
        <translation>Считать в базу данных</translation>
    </message>
    <message>
        <source>Push a file...</source>
        <translation>Передать файл...</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Отключиться</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Подключиться</translation>
    </message>
    <message>
        <source>No controller-link plugin was found (searched: %1). %2</source>
        <translation>Модуль связи с контроллером не найден (искали: %1). %2</translation>
    </message>
    <message>
        <source>Choose the serial port the controller is on.</source>
        <translation>Выберите последовательный порт контроллера.</translation>
    </message>
    <message>
        <source>No connection on %1: %2</source>
        <translation>Нет связи по %1: %2</translation>
    </message>
    <message>
        <source>Connected: %1</source>
        <translation>Подключено: %1</translation>
    </message>
    <message>
        <source>memory read</source>
        <translation>память считана</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>остановлено</translation>
    </message>
    <message>
        <source>The push did not start: the controller's memory could not be read (%1); nothing was sent</source>
        <translation>Передача не начата: память контроллера не считана (%1); ничего не передано</translation>
    </message>
    <message>
        <source>Pull failed: %1</source>
        <translation>Считывание не удалось: %1</translation>
    </message>
    <message>
        <source>Pulled, but not kept in the database: %1</source>
        <translation>Считано, но не сохранено в базе данных: %1</translation>
    </message>
    <message>
        <source>Pulled %1 programs; the database already holds this memory of %2 (revision %3)</source>
        <translation>Считано программ: %1; база данных уже хранит эту память станка %2 (ревизия %3)</translation>
    </message>
    <message>
        <source>Pulled %1 programs into %2, revision %3 (%4 changes)</source>
        <translation>Считано программ: %1 в станок %2, ревизия %3 (изменений: %4)</translation>
    </message>
    <message>
        <source>pushed</source>
        <translation>передано</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>ничего</translation>
    </message>
    <message>
        <source>Pushed %1: written and verified %2</source>
        <translation>Передан %1: записано и проверено %2</translation>
    </message>
    <message>
        <source>Push of %1 stopped: %2. Written and verified before: %3</source>
        <translation>Передача %1 остановлена: %2. Записано и проверено до этого: %3</translation>
    </message>
    <message>
        <source>Connecting to %1...</source>
        <translation>Подключение к %1...</translation>
    </message>
    <message>
        <source>Disconnected</source>
        <translation>Отключено</translation>
    </message>
    <message>
        <source>Pulling the controller's memory...</source>
        <translation>Считывание памяти контроллера...</translation>
    </message>
    <message>
        <source>Push a machine file</source>
        <translation>Передать файл станка</translation>
    </message>
    <message>
        <source>Machine files (*.k528m *.txt);;All files (*)</source>
        <translation>Файлы станка (*.k528m *.txt);;Все файлы (*)</translation>
    </message>
    <message>
        <source>%1 cannot be pushed: %2; nothing was sent</source>
        <translation>%1 нельзя передать: %2; ничего не передано</translation>
    </message>
    <message>
        <source>The machine %1 cannot be loaded: %2</source>
        <translation>Станок %1 не загружается: %2</translation>
    </message>
    <message>
        <source>Reading the controller's memory to show what %1 changes...</source>
        <translation>Считывание памяти контроллера, чтобы показать, что изменит %1...</translation>
    </message>
    <message>
        <source>Push</source>
        <translation>Передать</translation>
    </message>
    <message>
        <source>Pushing %1...</source>
        <translation>Передача %1...</translation>
    </message>
    <message>
        <source>Push of %1 not started; nothing was sent</source>
        <translation>Передача %1 не начата; ничего не передано</translation>
    </message>
    <message>
        <source>Check what %1 changes, then push.</source>
        <translation>Проверьте, что изменит %1, затем передайте.</translation>
    </message>
    <message>
        <source>Cancelling at the next exchange...</source>
        <translation>Отмена при следующем обмене...</translation>
    </message>
    <message>
        <source>power-on</source>
        <translation>включение</translation>
    </message>
    <message>
        <source>, running</source>
        <translation>, выполнение</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Режим</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Программа</translation>
    </message>
    <message>
        <source>L%1, frame N%2</source>
        <translation>L%1, кадр N%2</translation>
    </message>
    <message>
        <source>Override</source>
        <translation>Коррекция</translation>
    </message>
    <message>
        <source>%1 mm (machine %2), following error %3 mm, %4</source>
        <translation>%1 мм (станок %2), ошибка слежения %3 мм, %4</translation>
    </message>
    <message>
        <source>homed</source>
        <translation>привязана</translation>
    </message>
    <message>
        <source>not homed</source>
        <translation>не привязана</translation>
    </message>
    <message>
        <source>Alarms</source>
        <translation>Аварийные сообщения</translation>
    </message>
    <message>
        <source>K LEDs</source>
        <translation>Светодиоды K</translation>
    </message>
    <message>
        <source>Machine messages</source>
        <translation>Сообщения станка</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Сообщение</translation>
    </message>
    <message>
        <source>Programs</source>
        <translation>Программы</translation>
    </message>
    <message>
        <source>Clear the C area (all constants 0)...</source>
        <translation>Очистить область C (все константы 0)...</translation>
    </message>
    <message>
        <source>Clear the R area (all R-parameters 0)...</source>
        <translation>Очистить область R (все R-параметры 0)...</translation>
    </message>
    <message>
        <source>Frame log...</source>
        <translation>Журнал кадров...</translation>
    </message>
    <message>
        <source>Save every frame of the line (time, direction, bytes, CRC) to a file</source>
        <translation>Сохранить каждый кадр линии (время, направление, байты, CRC) в файл</translation>
    </message>
    <message>
        <source>Show it on every view of the window</source>
        <translation>Показывать его во всех панелях окна</translation>
    </message>
    <message>
        <source>Push %1</source>
        <translation>Записать %1</translation>
    </message>
    <message>
        <source>Save the frame log</source>
        <translation>Сохранение журнала кадров</translation>
    </message>
    <message>
        <source>Text (*.txt);;All files (*)</source>
        <translation>Текст (*.txt);;Все файлы (*)</translation>
    </message>
    <message>
        <source>The frame log was not saved: %1</source>
        <translation>Журнал кадров не сохранён: %1</translation>
    </message>
    <message>
        <source>The frame log saved to %1 (%2 frames)</source>
        <translation>Журнал кадров сохранён в %1 (кадров: %2)</translation>
    </message>
    <message>
        <source>the C area</source>
        <translation>область C</translation>
    </message>
    <message>
        <source>the R area</source>
        <translation>область R</translation>
    </message>
    <message>
        <source>%1 was not cleared: %2</source>
        <translation>%1 не очищена: %2</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Очистка</translation>
    </message>
    <message>
        <source>Clear %1 of %2? Every value becomes 0; the database keeps what it had.</source>
        <translation>Очистить %1 контроллера %2? Все значения станут 0; база данных сохранит то, что в ней было.</translation>
    </message>
    <message>
        <source>%1 cleared</source>
        <translation>%1 очищена</translation>
    </message>
    <message>
        <source>%1: %2 answers, %3 timeouts, %4 CRC errors, %5 bad replies, %6 exceptions%7, %8 retries; round trip median %9 ms, p95 %10 ms; line busy %11 %</source>
        <translation>%1: ответов %2, тайм-аутов %3, ошибок CRC %4, неверных ответов %5, исключений %6%7, повторов %8; время обмена: медиана %9 мс, p95 %10 мс; загрузка линии %11 %</translation>
    </message>
    <message>
        <source>Why: %1</source>
        <translation>Причина: %1</translation>
    </message>
    <message>
        <source>No machine of the database has a line</source>
        <translation>Ни у одного станка базы данных нет линии</translation>
    </message>
    <message>
        <source>Connect to a database &amp;machine</source>
        <translation>Подключиться к &amp;станку базы данных</translation>
    </message>
    <message>
        <source>Line (Modbus TCP)</source>
        <translation>Линия (Modbus TCP)</translation>
    </message>
    <message>
        <source>Host:port</source>
        <translation>Узел:порт</translation>
    </message>
    <message>
        <source>Unit id</source>
        <translation>Номер устройства</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Станок</translation>
    </message>
    <message>
        <source>(the line below)</source>
        <translation>(линия ниже)</translation>
    </message>
    <message>
        <source>The machines of the database that keep their controller's line</source>
        <translation>Станки базы данных, у которых задана линия их УЧПУ</translation>
    </message>
    <message>
        <source>List the system's serial ports and the database's machines again</source>
        <translation>Заново получить последовательные порты системы и станки базы данных</translation>
    </message>
    <message>
        <source>Enter the gateway's HOST:PORT.</source>
        <translation>Введите УЗЕЛ:ПОРТ шлюза.</translation>
    </message>
    <message>
        <source>Choose a machine of the database, or the controller's port (or HOST:PORT for Modbus TCP), speed, parity and address, then Connect.</source>
        <translation>Выберите станок базы данных или порт УЧПУ (или УЗЕЛ:ПОРТ для Modbus TCP), скорость, чётность и адрес, затем нажмите «Подключиться».</translation>
    </message>
</context>
<context>
    <name>k528::studio::CoreTexts</name>
    <message>
        <source>cannot read the file: %1</source>
        <translation>файл нельзя прочитать: %1</translation>
    </message>
    <message>
        <source>cannot create the file</source>
        <translation>файл нельзя создать</translation>
    </message>
    <message>
        <source>cannot write the file</source>
        <translation>файл нельзя записать</translation>
    </message>
    <message>
        <source>not valid UTF-8</source>
        <translation>текст не в кодировке UTF-8</translation>
    </message>
    <message>
        <source>column %1: U+FEFF (byte-order mark), an invisible character; a byte-order mark may stand only at the very start of the file (files joined with `cat`?) — remove it</source>
        <translation>позиция %1: U+FEFF (метка порядка байтов) — невидимый символ; такая метка может стоять только в самом начале файла (файлы склеены командой cat?) — удалите её</translation>
    </message>
    <message>
        <source>%1 is given twice (first on line %2)</source>
        <translation>%1 задан дважды (впервые в строке %2)</translation>
    </message>
    <message>
        <source>section header without ']': %1</source>
        <translation>заголовок раздела без «]»: %1</translation>
    </message>
    <message>
        <source>[end program] without [program N]</source>
        <translation>[end program] без [program N]</translation>
    </message>
    <message>
        <source>unknown section [%1] (known: machine, c, r, program N, messages, plc-messages, simulation)</source>
        <translation>неизвестный раздел [%1] (известны: machine, c, r, program N, messages, plc-messages, simulation)</translation>
    </message>
    <message>
        <source>[program N]: N must be a number 1..99, not '%1'</source>
        <translation>[program N]: N должно быть числом 1..99, а не «%1»</translation>
    </message>
    <message>
        <source>program %1 is empty</source>
        <translation>программа %1 пуста</translation>
    </message>
    <message>
        <source>a program line may not start with '[' (missing [end program] for program %1 of line %2?)</source>
        <translation>строка программы не может начинаться с «[» (нет [end program] у программы %1 из строки %2?)</translation>
    </message>
    <message>
        <source>program %1 has no [end program]</source>
        <translation>у программы %1 нет [end program]</translation>
    </message>
    <message>
        <source>line outside any section: %1</source>
        <translation>строка вне разделов: %1</translation>
    </message>
    <message>
        <source>expected key=value: %1</source>
        <translation>ожидалось «ключ=значение»: %1</translation>
    </message>
    <message>
        <source>unknown key '%1' in [machine] (format, name, title)</source>
        <translation>неизвестный ключ «%1» в разделе [machine] (format, name, title)</translation>
    </message>
    <message>
        <source>format: '%1' is not a number</source>
        <translation>format: «%1» — не число</translation>
    </message>
    <message>
        <source>format %1 is not one this program reads (%2)</source>
        <translation>формат %1 эта программа не читает (читает %2)</translation>
    </message>
    <message>
        <source>unknown key '%1' in [c] (C001..C152)</source>
        <translation>неизвестный ключ «%1» в разделе [c] (C001..C152)</translation>
    </message>
    <message>
        <source>unknown key '%1' in [r] (R0..R299)</source>
        <translation>неизвестный ключ «%1» в разделе [r] (R0..R299)</translation>
    </message>
    <message>
        <source>%1: '%2' is not a whole number</source>
        <translation>%1: «%2» — не целое число</translation>
    </message>
    <message>
        <source>expected #k=text in [messages], not '%1'</source>
        <translation>в разделе [messages] ожидалось #k=текст, а не «%1»</translation>
    </message>
    <message>
        <source>message number %1 is outside #1..#99</source>
        <translation>номер сообщения %1 вне #1..#99</translation>
    </message>
    <message>
        <source>expected A01..A32, W01..W32 or S01..S16 in [plc-messages], not '%1'</source>
        <translation>в разделе [plc-messages] ожидалось A01..A32, W01..W32 или S01..S16, а не «%1»</translation>
    </message>
    <message>
        <source>PLC message '%1': the number must be 1..%2</source>
        <translation>сообщение ПЛК «%1»: номер должен быть 1..%2</translation>
    </message>
    <message>
        <source>no [machine] section</source>
        <translation>нет раздела [machine]</translation>
    </message>
    <message>
        <source>[machine] has no format=%1</source>
        <translation>в разделе [machine] нет format=%1</translation>
    </message>
    <message>
        <source>[machine] has no name=</source>
        <translation>в разделе [machine] нет name=</translation>
    </message>
    <message>
        <source>no [c] section (the 152 machine constants)</source>
        <translation>нет раздела [c] (152 константы станка)</translation>
    </message>
    <message>
        <source>[c] lacks %1 (all 152 are required)</source>
        <translation>в разделе [c] нет %1 (нужны все 152)</translation>
    </message>
    <message>
        <source>[c] lacks %1 and %2 more (all 152 are required)</source>
        <translation>в разделе [c] нет %1 и ещё %2 (нужны все 152)</translation>
    </message>
    <message>
        <source>no built-in profile of this name (built-in: %1)</source>
        <translation>встроенного профиля с таким именем нет (встроенные: %1)</translation>
    </message>
    <message>
        <source>no profile given (built-in: %1)</source>
        <translation>профиль не указан (встроенные: %1)</translation>
    </message>
    <message>
        <source>neither a built-in profile (%1) nor a machine file</source>
        <translation>это не встроенный профиль (%1) и не файл станка</translation>
    </message>
    <message>
        <source>the first line must be the header '%1'</source>
        <translation>первая строка должна быть заголовком «%1»</translation>
    </message>
    <message>
        <source>expected 5 fields (number;axis;name;value;unit), found %1</source>
        <translation>ожидалось 5 полей (номер;ось;имя;значение;единица), найдено %1</translation>
    </message>
    <message>
        <source>number '%1' is not a C-parameter 1..152</source>
        <translation>номер «%1» — не C-параметр 1..152</translation>
    </message>
    <message>
        <source>%1 belongs to axis '%2', the row says '%3'</source>
        <translation>%1 относится к оси «%2», а в строке — «%3»</translation>
    </message>
    <message>
        <source>%1 is given twice</source>
        <translation>%1 задан дважды</translation>
    </message>
    <message>
        <source>%1: value '%2' is not a whole number</source>
        <translation>%1: значение «%2» — не целое число</translation>
    </message>
    <message>
        <source>empty: no header line</source>
        <translation>файл пуст: нет строки заголовка</translation>
    </message>
    <message>
        <source>%1 is missing (all 152 are required)</source>
        <translation>нет %1 (нужны все 152)</translation>
    </message>
    <message>
        <source>a quoted field is not closed</source>
        <translation>поле в кавычках не закрыто</translation>
    </message>
    <message>
        <source>text after a closing quote</source>
        <translation>текст после закрывающей кавычки</translation>
    </message>
    <message>
        <source>name is empty</source>
        <translation>имя пусто</translation>
    </message>
    <message>
        <source>name longer than 64 characters</source>
        <translation>имя длиннее 64 символов</translation>
    </message>
    <message>
        <source>name '%1' does not start with a-z or 0-9</source>
        <translation>имя «%1» начинается не с a-z и не с 0-9</translation>
    </message>
    <message>
        <source>name '%1' has a character other than a-z, 0-9, '-', '_', '.'</source>
        <translation>в имени «%1» есть символ, кроме a-z, 0-9, «-», «_», «.»</translation>
    </message>
    <message>
        <source>title: %1</source>
        <translation>название: %1</translation>
    </message>
    <message>
        <source>text is empty</source>
        <translation>текст пуст</translation>
    </message>
    <message>
        <source>text is not valid UTF-8</source>
        <translation>текст не в кодировке UTF-8</translation>
    </message>
    <message>
        <source>text has a control character or line break</source>
        <translation>в тексте управляющий символ или перевод строки</translation>
    </message>
    <message>
        <source>text has %1 characters, more than %2</source>
        <translation>в тексте %1 символов, больше %2</translation>
    </message>
    <message>
        <source>text ends with a blank</source>
        <translation>текст кончается пробелом</translation>
    </message>
    <message>
        <source>text starts with a blank</source>
        <translation>текст начинается с пробела</translation>
    </message>
    <message>
        <source>no C-parameter %1 (1..152)</source>
        <translation>C-параметра %1 нет (1..152)</translation>
    </message>
    <message>
        <source>%1 = %2 is outside the range %3 of «%4»</source>
        <translation>%1 = %2 вне диапазона %3 константы «%4»</translation>
    </message>
    <message>
        <source>no R-parameter %1 (0..299)</source>
        <translation>R-параметра %1 нет (0..299)</translation>
    </message>
    <message>
        <source>R%1 is read-only (R232..R262): it cannot be preset</source>
        <translation>R%1 только для чтения (R232..R262): его нельзя задать заранее</translation>
    </message>
    <message>
        <source>R%1 = %2 is outside the 32-bit range</source>
        <translation>R%1 = %2 вне 32-разрядного диапазона</translation>
    </message>
    <message>
        <source>program number %1 is outside 1..99</source>
        <translation>номер программы %1 вне 1..99</translation>
    </message>
    <message>
        <source>program L%1: empty</source>
        <translation>программа L%1: пуста</translation>
    </message>
    <message>
        <source>program L%1: not valid UTF-8</source>
        <translation>программа L%1: текст не в кодировке UTF-8</translation>
    </message>
    <message>
        <source>program L%1: the text does not end with a line break</source>
        <translation>программа L%1: текст не кончается переводом строки</translation>
    </message>
    <message>
        <source>program L%1: carriage return in the text (lines end with LF)</source>
        <translation>программа L%1: в тексте возврат каретки (строки кончаются символом LF)</translation>
    </message>
    <message>
        <source>program L%1: line %2 starts with '[' (reserved for machine-file sections)</source>
        <translation>программа L%1: строка %2 начинается с «[» (так начинаются разделы файла станка)</translation>
    </message>
    <message>
        <source>program L%1: line %2 is the header of program L%3 (one program per entry)</source>
        <translation>программа L%1: строка %2 — заголовок программы L%3 (одна программа в записи)</translation>
    </message>
    <message>
        <source>program L%1: line %2: %MESSAGES belongs to the machine file's [messages] section</source>
        <translation>программа L%1: строка %2: %MESSAGES место в разделе [messages] файла станка</translation>
    </message>
    <message>
        <source>program L%1: only blank lines</source>
        <translation>программа L%1: только пустые строки</translation>
    </message>
    <message>
        <source>technological message number %1 is outside 1..99</source>
        <translation>номер технологического сообщения %1 вне 1..99</translation>
    </message>
    <message>
        <source>message #%1: %2</source>
        <translation>сообщение #%1: %2</translation>
    </message>
    <message>
        <source>PLC message %1 is outside 1..%2</source>
        <translation>сообщение ПЛК %1 вне 1..%2</translation>
    </message>
    <message>
        <source>PLC message %1: %2</source>
        <translation>сообщение ПЛК %1: %2</translation>
    </message>
    <message>
        <source>simulation: %1</source>
        <translation>моделирование: %1</translation>
    </message>
    <message>
        <source>simulation %1: %2</source>
        <translation>моделирование, %1: %2</translation>
    </message>
    <message>
        <source>empty key</source>
        <translation>пустой ключ</translation>
    </message>
    <message>
        <source>key longer than 64 characters</source>
        <translation>ключ длиннее 64 символов</translation>
    </message>
    <message>
        <source>key '%1' does not start with a letter a-z</source>
        <translation>ключ «%1» начинается не с буквы a-z</translation>
    </message>
    <message>
        <source>key '%1' has a character other than a-z, 0-9, '_', '.'</source>
        <translation>в ключе «%1» есть символ, кроме a-z, 0-9, «_», «.»</translation>
    </message>
    <message>
        <source>value is not valid UTF-8</source>
        <translation>значение не в кодировке UTF-8</translation>
    </message>
    <message>
        <source>value longer than 200 characters</source>
        <translation>значение длиннее 200 символов</translation>
    </message>
    <message>
        <source>value spans lines</source>
        <translation>значение занимает несколько строк</translation>
    </message>
    <message>
        <source>value has a control character</source>
        <translation>в значении управляющий символ</translation>
    </message>
    <message>
        <source>value has a ';' (starts a comment in machine files)</source>
        <translation>в значении есть «;» (в файлах станков с неё начинается комментарий)</translation>
    </message>
    <message>
        <source>value starts or ends with a blank</source>
        <translation>значение начинается или кончается пробелом</translation>
    </message>
    <message>
        <source>value %1 is outside %2..%3</source>
        <translation>значение %1 вне %2..%3</translation>
    </message>
    <message>
        <source>value '%1' is not a whole number</source>
        <translation>значение «%1» — не целое число</translation>
    </message>
    <message>
        <source>value '%1' is not a number</source>
        <translation>значение «%1» — не число</translation>
    </message>
    <message>
        <source>value '%1' is not true/false</source>
        <translation>значение «%1» — не true/false</translation>
    </message>
    <message>
        <source>%1</source>
        <translation>%1</translation>
    </message>
    <message>
        <source>'%1' is not a tool kind (turning, facing, grooving, boring, drill, threading)</source>
        <translation>«%1» — не вид инструмента (turning, facing, grooving, boring, drill, threading)</translation>
    </message>
    <message>
        <source>'%1' is not one of +z+x, -z+x, +z-x, -z-x</source>
        <translation>«%1» — не одно из +z+x, -z+x, +z-x, -z-x</translation>
    </message>
    <message>
        <source>needs 0..50 mm</source>
        <translation>нужно 0..50 мм</translation>
    </message>
    <message>
        <source>needs more than 0, at most 1000 mm</source>
        <translation>нужно больше 0, не больше 1000 мм</translation>
    </message>
    <message>
        <source>needs 0..100 mm (0: no limit)</source>
        <translation>нужно 0..100 мм (0 — без предела)</translation>
    </message>
    <message>
        <source>needs a user R-parameter 0..148 (X there, Z in the next)</source>
        <translation>нужен пользовательский R-параметр 0..148 (в нём X, в следующем Z)</translation>
    </message>
    <message>
        <source>a tool key is tool.&lt;station 1..8&gt;.&lt;key&gt;</source>
        <translation>ключ инструмента — tool.&lt;позиция 1..8&gt;.&lt;ключ&gt;</translation>
    </message>
    <message>
        <source>'%1' is not a key of a tool</source>
        <translation>«%1» — не ключ инструмента</translation>
    </message>
    <message>
        <source>the tool of station %1 has no kind (tool.%1.kind)</source>
        <translation>у инструмента позиции %1 не задан вид (tool.%1.kind)</translation>
    </message>
    <message>
        <source>%1, line %2: %3</source>
        <translation>%1, строка %2: %3</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source> (message %1)</source>
        <translation> (сообщение %1)</translation>
    </message>
    <message>
        <source>%1 cannot be read: %2</source>
        <translation>%1 не читается: %2</translation>
    </message>
    <message>
        <source>Vmax must be a positive number</source>
        <translation>Vmax должна быть положительным числом</translation>
    </message>
    <message>
        <source>the run-up time must be a positive number</source>
        <translation>время разгона должно быть положительным числом</translation>
    </message>
    <message>
        <source>the braking distance must be a positive number</source>
        <translation>путь торможения должен быть положительным числом</translation>
    </message>
    <message>
        <source>the acceleration must be a positive number</source>
        <translation>ускорение должно быть положительным числом</translation>
    </message>
    <message>
        <source>Umax must be a positive number</source>
        <translation>Umax должно быть положительным числом</translation>
    </message>
    <message>
        <source>Kv must be a positive number</source>
        <translation>Kv должен быть положительным числом</translation>
    </message>
    <message>
        <source>the screw lead must be a positive number</source>
        <translation>шаг винта должен быть положительным числом</translation>
    </message>
    <message>
        <source>the gear ratio must be a positive number</source>
        <translation>передаточное отношение должно быть положительным числом</translation>
    </message>
    <message>
        <source>the encoder must have at least one line</source>
        <translation>у датчика должен быть хотя бы один штрих</translation>
    </message>
    <message>
        <source>the screw lead %1 mm is not a whole number of discretes (%2 mm)</source>
        <translation>шаг винта %1 мм — не целое число дискрет (%2 мм)</translation>
    </message>
    <message>
        <source>the gear ratio %1 is not a fraction with a denominator up to 100000</source>
        <translation>передаточное отношение %1 — не дробь со знаменателем до 100000</translation>
    </message>
    <message>
        <source>a speed must be zero or positive</source>
        <translation>скорость должна быть нулевой или положительной</translation>
    </message>
    <message>
        <source>the fastest feed %1 mm/min is above what the drive reaches at DAC MAX (%2 mm/min)</source>
        <translation>наибольшая подача %1 мм/мин больше той, что привод даёт при МАКС.ЦАП (%2 мм/мин)</translation>
    </message>
    <message>
        <source>the cutting speed must be a positive number</source>
        <translation>скорость резания должна быть положительным числом</translation>
    </message>
    <message>
        <source>the diameter must be a positive number</source>
        <translation>диаметр должен быть положительным числом</translation>
    </message>
    <message>
        <source>the spindle speed must be a positive number</source>
        <translation>частота вращения шпинделя должна быть положительным числом</translation>
    </message>
    <message>
        <source>the feed per revolution must be a positive number</source>
        <translation>подача на оборот должна быть положительным числом</translation>
    </message>
    <message>
        <source>the wheel's diameter must be a positive number</source>
        <translation>диаметр круга должен быть положительным числом</translation>
    </message>
    <message>
        <source>the wheel's speed must be a positive number</source>
        <translation>частота вращения круга должна быть положительным числом</translation>
    </message>
    <message>
        <source>the machine presets no R207 (the wheel's diameter)</source>
        <translation>станок не задаёт R207 (диаметр круга)</translation>
    </message>
    <message>
        <source>tool %1 has no offset R-parameters (tool.%1.offset_r)</source>
        <translation>у инструмента %1 нет R-параметров коррекции (tool.%1.offset_r)</translation>
    </message>
    <message>
        <source>the measured size and the drawing's must be numbers</source>
        <translation>измеренный размер и размер по чертежу должны быть числами</translation>
    </message>
    <message>
        <source>R%1 would leave the R-parameter range</source>
        <translation>R%1 вышел бы за диапазон R-параметров</translation>
    </message>
    <message>
        <source>no tool at station %1</source>
        <translation>нет инструмента в позиции %1</translation>
    </message>
    <message>
        <source>%1 without its Russian %2 (an English text stands beside its Russian)</source>
        <translation>%1 без русского текста %2 (английский даётся рядом с русским)</translation>
    </message>
    <message>
        <source>%1 is written beside its Russian text: %2=</source>
        <translation>%1 пишется рядом с русским текстом: %2=</translation>
    </message>
    <message>
        <source>line '%1' is not tcp://HOST:PORT/UNIT or serial:DEVICE?baud=115200&amp;parity=none&amp;address=1</source>
        <translation>линия «%1» — не tcp://ХОСТ:ПОРТ/УСТРОЙСТВО и не serial:УСТРОЙСТВО?baud=115200&amp;parity=none&amp;address=1</translation>
    </message>
    <message>
        <source>line '%1': the unit id after '/' is a station address 1..247</source>
        <translation>линия «%1»: после «/» — адрес станции 1..247</translation>
    </message>
    <message>
        <source>line '%1': no HOST:PORT after tcp:// (tcp://HOST:PORT/UNIT)</source>
        <translation>линия «%1»: после tcp:// нет ХОСТ:ПОРТ (tcp://ХОСТ:ПОРТ/УСТРОЙСТВО)</translation>
    </message>
    <message>
        <source>line '%1': the port after the host is 1..65535</source>
        <translation>линия «%1»: порт после хоста — 1..65535</translation>
    </message>
    <message>
        <source>line '%1': '%2' is not a host name or address</source>
        <translation>линия «%1»: «%2» — не имя и не адрес хоста</translation>
    </message>
    <message>
        <source>line '%1': no device after serial: (serial:DEVICE?baud=115200&amp;parity=none&amp;address=1)</source>
        <translation>линия «%1»: после serial: нет устройства (serial:УСТРОЙСТВО?baud=115200&amp;parity=none&amp;address=1)</translation>
    </message>
    <message>
        <source>line '%1': baud is a rate in bit/s, 1200..4000000</source>
        <translation>линия «%1»: baud — скорость в бит/с, 1200..4000000</translation>
    </message>
    <message>
        <source>line '%1': parity is none, even or odd</source>
        <translation>линия «%1»: parity — none, even или odd</translation>
    </message>
    <message>
        <source>line '%1': stop_bits is 1 or 2</source>
        <translation>линия «%1»: stop_bits — 1 или 2</translation>
    </message>
    <message>
        <source>line '%1': address is a station address 1..247</source>
        <translation>линия «%1»: address — адрес станции 1..247</translation>
    </message>
    <message>
        <source>line '%1': '%2' is not a setting of a serial line (baud, parity, stop_bits, address)</source>
        <translation>линия «%1»: «%2» — не настройка последовательной линии (baud, parity, stop_bits, address)</translation>
    </message>
    <message>
        <source>Incomplete set of C-parameters</source>
        <translation>Неполный набор С-параметров</translation>
    </message>
    <message>
        <source>%1 %5 = %3 is outside %4</source>
        <translation>%1 «%2» = %3 вне диапазона %4</translation>
    </message>
    <message>
        <source>Axis %1: exactly one display discrete must be set (%2), %3 set</source>
        <translation>Ось %1: должна быть задана ровно одна дискрета (%2), задано %3</translation>
    </message>
    <message>
        <source>Axis %1: L/N = %2/%3 is above 1: one encoder pulse is more than a discrete, the axis cannot position finer than a pulse</source>
        <translation>Ось %1: L/N = %2/%3 больше 1: один импульс ДОС больше дискреты, ось не позиционируется точнее импульса</translation>
    </message>
    <message>
        <source>Axis %1: DAC MAX = 0: the drive gets no voltage</source>
        <translation>Ось %1: МАКС.ЦАП = 0: привод не получит напряжения</translation>
    </message>
    <message>
        <source>Axis %1: DAC LIMIT %2 is below DAC MAX %3: message %4 at full speed</source>
        <translation>Ось %1: ПРЕДЕЛ ЦАП %2 меньше МАКС.ЦАП %3: на максимальной скорости будет сообщение %4</translation>
    </message>
    <message>
        <source>Axis %1: DAC LIMIT %2 is not 15-20 %% above DAC MAX %3 (recommended %4...%5)</source>
        <translation>Ось %1: ПРЕДЕЛ ЦАП %2 не на 15-20 %% выше МАКС.ЦАП %3 (рекомендуется %4...%5)</translation>
    </message>
    <message>
        <source>Axis %1: ACCELERATION 1 = 0</source>
        <translation>Ось %1: УСКОРЕНИЕ 1 = 0</translation>
    </message>
    <message>
        <source>Axis %1: %3 = 0: the axis will not move</source>
        <translation>Ось %1: %2 = 0: ось не будет двигаться</translation>
    </message>
    <message>
        <source>Axis %1: a homing speed is zero, yet programs need the axis homed</source>
        <translation>Ось %1: нулевая скорость привязки к базовой точке, а пуск программы требует привязки</translation>
    </message>
    <message>
        <source>Axis %1: F HOME CREEP is above F HOME START</source>
        <translation>Ось %1: F ОТКЛ.БТ больше F СТАРТ БТ</translation>
    </message>
    <message>
        <source>Axis %1: -LIMIT %2 is not below +LIMIT %3</source>
        <translation>Ось %1: -ОГРАНИЧЕН %2 не меньше +ОГРАНИЧЕН %3</translation>
    </message>
    <message>
        <source>Axis %1: HOME VALUE %2 is outside the soft limits %3...%4</source>
        <translation>Ось %1: ЗНАЧЕНИЕ БТ %2 вне программных конечников %3...%4</translation>
    </message>
    <message>
        <source>Axis %1: function %2 is assigned to two fast inputs</source>
        <translation>Ось %1: функция %2 назначена двум быстрым входам</translation>
    </message>
    <message>
        <source>No axis is present (AXIS PRESENT = 0)</source>
        <translation>Нет ни одной оси (НАЛИЧ.ОСИ = 0)</translation>
    </message>
    <message>
        <source>Both encoders are on channel %1 (%4)</source>
        <translation>Оба ДОС подключены к одному каналу %1 (%2, %3)</translation>
    </message>
    <message>
        <source>A handwheel and an encoder are on channel %1 (%4)</source>
        <translation>Маховик и ДОС подключены к одному каналу %1 (%2, %3)</translation>
    </message>
    <message>
        <source>Both drives are on DAC channel %1 (%4)</source>
        <translation>Оба привода подключены к одному каналу ЦАП %1 (%2, %3)</translation>
    </message>
    <message>
        <source>Both handwheels are on channel %1</source>
        <translation>Оба маховика подключены к одному каналу %1</translation>
    </message>
    <message>
        <source>Manual cycle %1: program L%2 does not exist</source>
        <translation>Ручной цикл %1: программы L%2 нет</translation>
    </message>
    <message>
        <source>Simulation setting %1 is not in the registry (a typo?)</source>
        <translation>Параметр моделирования %1 не из реестра (опечатка?)</translation>
    </message>
</context>
<context>
    <name>k528::studio::CuttingDataDialog</name>
    <message>
        <source>Cutting data</source>
        <translation>Режимы резания</translation>
    </message>
    <message>
        <source>Spindle speed: n = 1000·v / (π·D)</source>
        <translation>Частота вращения шпинделя: n = 1000·v / (π·D)</translation>
    </message>
    <message>
        <source>Cutting speed v, m/min</source>
        <translation>Скорость резания v, м/мин</translation>
    </message>
    <message>
        <source>Diameter D, mm</source>
        <translation>Диаметр D, мм</translation>
    </message>
    <message>
        <source>Spindle speed n</source>
        <translation>Частота вращения n</translation>
    </message>
    <message>
        <source>Feed per minute: F = f·n</source>
        <translation>Минутная подача: F = f·n</translation>
    </message>
    <message>
        <source>Feed per revolution f, mm/rev</source>
        <translation>Подача на оборот f, мм/об</translation>
    </message>
    <message>
        <source>Feed F</source>
        <translation>Подача F</translation>
    </message>
    <message>
        <source>Grinding wheel: v = π·D·n / 60000</source>
        <translation>Шлифовальный круг: v = π·D·n / 60000</translation>
    </message>
    <message>
        <source>R207 wheel diameter, discretes of X</source>
        <translation>R207 диаметр круга, дискреты X</translation>
    </message>
    <message>
        <source>Wheel speed, rev/min</source>
        <translation>Частота вращения круга, об/мин</translation>
    </message>
    <message>
        <source>Surface speed</source>
        <translation>Окружная скорость</translation>
    </message>
    <message>
        <source>%1 rev/min</source>
        <translation>%1 об/мин</translation>
    </message>
    <message>
        <source>%1 mm/min at n = %2 rev/min</source>
        <translation>%1 мм/мин при n = %2 об/мин</translation>
    </message>
    <message>
        <source>%1 m/s (wheel Ø%2 mm)</source>
        <translation>%1 м/с (круг Ø%2 мм)</translation>
    </message>
    <message>
        <source>— (no wheel diameter in R207)</source>
        <translation>— (в R207 нет диаметра круга)</translation>
    </message>
</context>
<context>
    <name>k528::studio::CycleTimeLabel</name>
    <message>
        <source>%1 min %2 s</source>
        <translation>%1 мин %2 с</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 с</translation>
    </message>
    <message>
        <source>Cycle time: none while the file has errors</source>
        <translation>Время цикла: нет, пока в файле есть ошибки</translation>
    </message>
    <message>
        <source>Cycle time: choose the machine the file is for</source>
        <translation>Время цикла: выберите станок для файла</translation>
    </message>
    <message>
        <source>Cycle time: measuring on the simulated machine…</source>
        <translation>Время цикла: измеряется на модели станка…</translation>
    </message>
    <message>
        <source>the run ends in an alarm</source>
        <translation>прогон заканчивается аварией</translation>
    </message>
    <message>
        <source>the run does not end within an hour</source>
        <translation>прогон не заканчивается за час</translation>
    </message>
    <message>
        <source>the program cannot be started on this machine</source>
        <translation>программу нельзя запустить на этом станке</translation>
    </message>
    <message>
        <source>Cycle time of L%1: %2 (%3)</source>
        <translation>Время цикла L%1: %2 (%3)</translation>
    </message>
    <message>
        <source>Cycle time of L%1: none, %2 (%3)</source>
        <translation>Время цикла L%1: нет, %2 (%3)</translation>
    </message>
</context>
<context>
    <name>k528::studio::DatabaseTexts</name>
    <message>
        <source>no machine "%1" in %2 (machines: %3)</source>
        <translation>нет станка «%1» в %2 (станки: %3)</translation>
    </message>
    <message>
        <source>no machine "%1" in %2 (machines: none)</source>
        <translation>нет станка «%1» в %2 (станков нет)</translation>
    </message>
    <message>
        <source>a machine named %1 already exists in %2</source>
        <translation>станок с именем %1 уже есть в %2</translation>
    </message>
    <message>
        <source>cannot rename %1 to %2: a machine of that name exists</source>
        <translation>нельзя переименовать %1 в %2: станок с таким именем уже есть</translation>
    </message>
    <message>
        <source>machine %1: the machine constants are locked by the trainer for the class «%2» (setting %3): %4 not changed; nothing was written (the trainer unlocks them first: k528 db set %1 %3=)</source>
        <translation>станок %1: константы станка заблокированы преподавателем для группы «%2» (параметр %3): %4 не изменены; ничего не записано (сначала преподаватель снимает блокировку: k528 db set %1 %3=)</translation>
    </message>
    <message>
        <source>machine %1 has revisions 1..%2; there is no revision %3</source>
        <translation>у станка %1 ревизии 1..%2; ревизии %3 нет</translation>
    </message>
    <message>
        <source>machine %1 is at revision %2, not %3</source>
        <translation>станок %1 — на ревизии %2, а не %3</translation>
    </message>
    <message>
        <source>machine %1 is at revision %2 (changed by %3 at %4), not %5 as read: load it again and repeat the change</source>
        <translation>станок %1 — на ревизии %2 (изменил %3, %4), а не %5, как было прочитано: загрузите его снова и повторите изменение</translation>
    </message>
    <message>
        <source>the author's name is %1 bytes long; a name has at most %2 (UTF-8); nothing was written</source>
        <translation>имя автора длиной %1 байт; имя — не длиннее %2 байт (UTF-8); ничего не записано</translation>
    </message>
    <message>
        <source>machine %1 revision %2 in %3: history entry %4 %5 of revision %6 cannot be read</source>
        <translation>станок %1, ревизия %2 в %3: запись истории %4 %5 ревизии %6 не читается</translation>
    </message>
    <message>
        <source>machine %1 revision %2 in %3: the revision is missing from the revision table</source>
        <translation>станок %1, ревизия %2 в %3: ревизии нет в таблице ревизий</translation>
    </message>
    <message>
        <source>machine %1 revision %2 in %3: program L%4 of revision %5 does not match its SHA-256 checksum</source>
        <translation>станок %1, ревизия %2 в %3: программа L%4 ревизии %5 не совпадает со своей контрольной суммой SHA-256</translation>
    </message>
    <message>
        <source>machine %1: history has an unknown section %2</source>
        <translation>станок %1: в истории неизвестный раздел %2</translation>
    </message>
    <message>
        <source>machine %1: program L%2 does not match its SHA-256 checksum</source>
        <translation>станок %1: программа L%2 не совпадает со своей контрольной суммой SHA-256</translation>
    </message>
    <message>
        <source>%1: the database has no message history (schema version %2 below %3: open it once with write access to upgrade it)</source>
        <translation>%1: в базе данных нет истории сообщений (версия схемы %2 ниже %3: откройте её один раз с правом записи, чтобы обновить)</translation>
    </message>
    <message>
        <source>%1: the database has no training attempts (schema version %2 below %3: open it once with write access to upgrade it)</source>
        <translation>%1: в базе данных нет учебных попыток (версия схемы %2 ниже %3: откройте её один раз с правом записи, чтобы обновить)</translation>
    </message>
    <message>
        <source>%1: the database has no time in each state of the shop's machines (schema version %2 below %3: open it once with write access to upgrade it)</source>
        <translation>%1: в базе данных нет времени станков цеха в каждом состоянии (версия схемы %2 ниже %3: откройте её один раз с правом записи, чтобы обновить)</translation>
    </message>
    <message>
        <source>an attempt needs its student's name; nothing was written</source>
        <translation>у попытки должно быть имя учащегося; ничего не записано</translation>
    </message>
    <message>
        <source>an attempt needs its exercise; nothing was written</source>
        <translation>у попытки должно быть упражнение; ничего не записано</translation>
    </message>
    <message>
        <source>the attempt of "%1" at "%2": a score is 0..100, not %3; nothing was written</source>
        <translation>попытка «%1» в «%2»: оценка — 0..100, а не %3; ничего не записано</translation>
    </message>
    <message>
        <source>the attempt of "%1" at "%2": a negative cycle time; nothing was written</source>
        <translation>попытка «%1» в «%2»: отрицательное время цикла; ничего не записано</translation>
    </message>
    <message>
        <source>a transfer is a push or a pull, not "%1"</source>
        <translation>передача — это push или pull, а не «%1»</translation>
    </message>
    <message>
        <source>a transfer's result is ok, partial or failed, not "%1"</source>
        <translation>результат передачи — ok, partial или failed, а не «%1»</translation>
    </message>
    <message>
        <source>a time in a state needs a machine, a day (YYYY-MM-DD), run, idle, alarm or offline and 0 ms or more, not '%1' '%2' '%3' %4 ms; nothing was written</source>
        <translation>для времени в состоянии нужны станок, день (ГГГГ-ММ-ДД), run, idle, alarm или offline и 0 мс или больше, а не '%1' '%2' '%3' %4 мс; ничего не записано</translation>
    </message>
    <message>
        <source>machine %1 has no program L%2 (at revision %3); nothing was released</source>
        <translation>у станка %1 нет программы L%2 (на ревизии %3); ничего не выпущено</translation>
    </message>
    <message>
        <source>program L%2 of machine %1 was never released; nothing was written</source>
        <translation>программа L%2 станка %1 ни разу не выпускалась; ничего не записано</translation>
    </message>
    <message>
        <source>program L%2 of machine %1 is withdrawn already; nothing was written</source>
        <translation>программа L%2 станка %1 уже отозвана; ничего не записано</translation>
    </message>
    <message>
        <source>%1: an SQLite database has one user, who may do everything; the roles are PostgreSQL's</source>
        <translation>%1: у базы данных SQLite один пользователь, которому можно всё; роли есть только у PostgreSQL</translation>
    </message>
    <message>
        <source>no database location: set K528_DB, XDG_DATA_HOME or HOME</source>
        <translation>место базы данных не задано: задайте K528_DB, XDG_DATA_HOME или HOME</translation>
    </message>
    <message>
        <source>K528_DB names a PostgreSQL database (%1), not a file</source>
        <translation>K528_DB называет базу данных PostgreSQL (%1), а не файл</translation>
    </message>
    <message>
        <source>no database at %1</source>
        <translation>нет базы данных %1</translation>
    </message>
    <message>
        <source>no database at %1 (create one with: k528 db init --db %1)</source>
        <translation>нет базы данных %1 (создать её: k528 db init --db %1)</translation>
    </message>
    <message>
        <source>cannot create the database %1: the folder %2 does not exist</source>
        <translation>нельзя создать базу данных %1: папки %2 нет</translation>
    </message>
    <message>
        <source>%1: is a directory, not a database file</source>
        <translation>%1: это папка, а не файл базы данных</translation>
    </message>
    <message>
        <source>%1: not an empty database (schema version %2); a copy goes only into a new or empty one</source>
        <translation>%1: база данных не пуста (версия схемы %2); копия записывается только в новую или пустую</translation>
    </message>
    <message>
        <source>not a K528 Studio database: the file has only %1 bytes, too few for an SQLite database</source>
        <translation>это не база данных K528 Studio: в файле всего %1 байт, слишком мало для базы данных SQLite</translation>
    </message>
    <message>
        <source>not a K528 Studio database: the file does not start with the SQLite header (another kind of file, or a database whose first page is damaged)</source>
        <translation>это не база данных K528 Studio: файл не начинается с заголовка SQLite (файл другого рода или база данных с повреждённой первой страницей)</translation>
    </message>
    <message>
        <source>not a K528 Studio database: it is another program's SQLite database (application_id %1, ours is %2)</source>
        <translation>это не база данных K528 Studio: это база данных SQLite другой программы (application_id %1, у нас %2)</translation>
    </message>
    <message>
        <source>not a K528 Studio database: it is another program's SQLite database (application_id %1, %2 schema objects)</source>
        <translation>это не база данных K528 Studio: это база данных SQLite другой программы (application_id %1, объектов схемы: %2)</translation>
    </message>
    <message>
        <source>the database has schema version %1, written by a newer K528 Studio; this program knows versions up to %2. Use the newer program</source>
        <translation>версия схемы базы данных — %1, её записала более новая K528 Studio; эта программа знает версии до %2. Откройте её более новой программой</translation>
    </message>
    <message>
        <source>; the file was left untouched</source>
        <translation>; файл не изменён</translation>
    </message>
    <message>
        <source>; only the unfinished transaction in %1 was rolled back (SQLite's crash recovery of a K528 Studio database), nothing else was changed</source>
        <translation>; откачена только незавершённая транзакция в %1 (восстановление SQLite после сбоя базы данных K528 Studio), больше ничего не изменено</translation>
    </message>
    <message>
        <source>%1: another process is writing to the database and kept it locked longer than the busy timeout; nothing was written, try again</source>
        <translation>%1: другой процесс пишет в базу данных и держит её заблокированной дольше времени ожидания; ничего не записано, повторите</translation>
    </message>
    <message>
        <source>%1 has schema version %2; a copy needs version %3 (open it once with write access to upgrade it)</source>
        <translation>у %1 версия схемы %2; для копии нужна версия %3 (откройте её один раз с правом записи, чтобы обновить)</translation>
    </message>
    <message>
        <source>a database cannot be copied into itself</source>
        <translation>базу данных нельзя скопировать в неё саму</translation>
    </message>
    <message>
        <source>'%1' is not ITEM=VALUE (e.g. C022=2133, R12=5, #3=TEXT, A01=TEXT)</source>
        <translation>«%1» — не ПУНКТ=ЗНАЧЕНИЕ (например, C022=2133, R12=5, #3=ТЕКСТ, A01=ТЕКСТ)</translation>
    </message>
    <message>
        <source>%1: no such C-parameter (1..152)</source>
        <translation>%1: такого C-параметра нет (1..152)</translation>
    </message>
    <message>
        <source>%1: no such R-parameter (0..299)</source>
        <translation>%1: такого R-параметра нет (0..299)</translation>
    </message>
    <message>
        <source>%1: no such technological message (#1..#99)</source>
        <translation>%1: такого технологического сообщения нет (#1..#99)</translation>
    </message>
    <message>
        <source>%1: no such PLC message (%2..%3)</source>
        <translation>%1: такого сообщения ПЛК нет (%2..%3)</translation>
    </message>
    <message>
        <source>%1: '%2' is not a whole number</source>
        <translation>%1: «%2» — не целое число</translation>
    </message>
    <message>
        <source>'%1' is not an item: C&lt;n&gt;, R&lt;n&gt;, #&lt;n&gt;, A&lt;nn&gt;, W&lt;nn&gt;, S&lt;nn&gt;, title or a simulation key</source>
        <translation>«%1» — не пункт: C&lt;n&gt;, R&lt;n&gt;, #&lt;n&gt;, A&lt;nn&gt;, W&lt;nn&gt;, S&lt;nn&gt;, title или параметр моделирования</translation>
    </message>
    <message>
        <source>%1 is given twice ('%2' and '%3'); give each item once</source>
        <translation>%1 задан дважды («%2» и «%3»); задайте каждый пункт один раз</translation>
    </message>
    <message>
        <source>'%1' is not a known simulation key; nothing was saved. The keys are listed in docs/profile-format.md; --allow-unknown stores it anyway</source>
        <translation>«%1» — неизвестный параметр моделирования; ничего не сохранено. Параметры перечислены в docs/profile-format.md; с --allow-unknown он сохраняется всё равно</translation>
    </message>
    <message>
        <source>'%1' is not a known simulation key; nothing was saved (did you mean %2?). The keys are listed in docs/profile-format.md; --allow-unknown stores it anyway</source>
        <translation>«%1» — неизвестный параметр моделирования; ничего не сохранено (может быть, %2?). Параметры перечислены в docs/profile-format.md; с --allow-unknown он сохраняется всё равно</translation>
    </message>
    <message>
        <source>%1 or %2</source>
        <translation>%1 или %2</translation>
    </message>
    <message>
        <source>database location "%1": empty; give a file path or a postgresql:// URI</source>
        <translation>место базы данных «%1»: пусто; укажите путь к файлу или URI postgresql://</translation>
    </message>
    <message>
        <source>database location "%1": a password does not go into a database location (every user of this PC can read a command line, and shells keep it): put it in ~/.pgpass (PGPASSFILE) or a service file (PGSERVICEFILE, postgresql://?service=NAME), or log in without one</source>
        <translation>место базы данных «%1»: пароль в место базы данных не пишется (командную строку видит любой пользователь этого ПК, и оболочки её сохраняют): запишите его в ~/.pgpass (PGPASSFILE) или в файл служб (PGSERVICEFILE, postgresql://?service=ИМЯ) либо входите без пароля</translation>
    </message>
    <message>
        <source>database location "%1": sqlite: needs a file path (sqlite:/srv/k528/shop.db)</source>
        <translation>место базы данных «%1»: после sqlite: нужен путь к файлу (sqlite:/srv/k528/shop.db)</translation>
    </message>
    <message>
        <source>database location "%1": unknown kind of database "%2"; K528 Studio keeps its database in SQLite (a file path or sqlite:PATH) or PostgreSQL (postgresql://…)</source>
        <translation>место базы данных «%1»: неизвестный вид базы данных «%2»; K528 Studio хранит базу данных в SQLite (путь к файлу или sqlite:ПУТЬ) или в PostgreSQL (postgresql://…)</translation>
    </message>
    <message>
        <source>cannot connect to the database %1: %2</source>
        <translation>нет подключения к базе данных %1: «%2»</translation>
    </message>
    <message>
        <source>the connection to the server was lost and cannot be made again</source>
        <translation>связь с сервером потеряна и не восстанавливается</translation>
    </message>
    <message>
        <source>cannot open: %1</source>
        <translation>файл не открывается: «%1»</translation>
    </message>
    <message>
        <source>cannot be read: %1</source>
        <translation>файл не читается: «%1»</translation>
    </message>
    <message>
        <source>%1: is not a regular file (a character device); a database is a regular file — give another --db path</source>
        <translation>%1: это не обычный файл (символьное устройство); база данных — обычный файл: укажите другой путь --db</translation>
    </message>
    <message>
        <source>%1: is not a regular file (a block device); a database is a regular file — give another --db path</source>
        <translation>%1: это не обычный файл (блочное устройство); база данных — обычный файл: укажите другой путь --db</translation>
    </message>
    <message>
        <source>%1: is not a regular file (a FIFO); a database is a regular file — give another --db path</source>
        <translation>%1: это не обычный файл (именованный канал); база данных — обычный файл: укажите другой путь --db</translation>
    </message>
    <message>
        <source>%1: is not a regular file (a socket); a database is a regular file — give another --db path</source>
        <translation>%1: это не обычный файл (сокет); база данных — обычный файл: укажите другой путь --db</translation>
    </message>
    <message>
        <source>%1: is not a regular file (not a file); a database is a regular file — give another --db path</source>
        <translation>%1: это не обычный файл (не файл); база данных — обычный файл: укажите другой путь --db</translation>
    </message>
    <message>
        <source>cannot be read: SQLite did not open the file</source>
        <translation>файл не читается: SQLite не открыла его</translation>
    </message>
    <message>
        <source>another program kept the database locked longer than the busy timeout (%1)</source>
        <translation>другая программа держала базу данных заблокированной дольше времени ожидания (SQLite: «%1»)</translation>
    </message>
    <message>
        <source>cannot be read as a database (%1)</source>
        <translation>файл не читается как база данных (SQLite: «%1»)</translation>
    </message>
    <message>
        <source>the database is damaged (integrity check: %1)</source>
        <translation>база данных повреждена (проверка целостности, SQLite: «%1»)</translation>
    </message>
    <message>
        <source>the database is damaged (integrity check: %1 rows break foreign keys (first: %2 row %3 -&gt; %4))</source>
        <translation>база данных повреждена (проверка целостности: %1 строк нарушают внешние ключи; первая — %2, строка %3 -&gt; %4)</translation>
    </message>
    <message>
        <source>K528 Studio database without a schema version</source>
        <translation>база данных K528 Studio без версии схемы</translation>
    </message>
    <message>
        <source>not a K528 Studio database: an SQLite database without K528 Studio's application_id, with an unfinished transaction of another program (the hot journal %1, begun on a file of %2 pages), which is not ours to roll back: let that program open it first</source>
        <translation>это не база данных K528 Studio: база данных SQLite без application_id K528 Studio, с незавершённой транзакцией другой программы (горячий журнал %1, начат на файле из %2 страниц), откатывать её не нам: пусть сначала её откроет та программа</translation>
    </message>
    <message>
        <source>not a K528 Studio database: an SQLite database without K528 Studio's application_id, with an unfinished transaction of another program (the hot journal %1, begun on a file of unknown size), which is not ours to roll back: let that program open it first</source>
        <translation>это не база данных K528 Studio: база данных SQLite без application_id K528 Studio, с незавершённой транзакцией другой программы (горячий журнал %1, начат на файле неизвестного размера), откатывать её не нам: пусть сначала её откроет та программа</translation>
    </message>
    <message>
        <source>another program wrote into the file while it was being created</source>
        <translation>пока файл создавался, в него записала другая программа</translation>
    </message>
    <message>
        <source>cannot switch to WAL journal mode (mode "%1"): another process kept the database busy longer than the busy timeout</source>
        <translation>не переключается в режим журнала WAL (режим «%1»): другой процесс держал базу данных занятой дольше времени ожидания</translation>
    </message>
    <message>
        <source>the search path names no schema that exists; create it or set search_path (options=-csearch_path=…)</source>
        <translation>путь поиска не называет ни одной существующей схемы; создайте её или задайте search_path (options=-csearch_path=…)</translation>
    </message>
    <message>
        <source>not a K528 Studio database: it holds %1 tables or views of another program (no k528_schema); nothing was changed</source>
        <translation>это не база данных K528 Studio: в ней %1 таблиц или представлений другой программы (нет k528_schema); ничего не изменено</translation>
    </message>
    <message>
        <source>not a K528 Studio database (k528_schema says "%1"); nothing was changed</source>
        <translation>это не база данных K528 Studio (в k528_schema — «%1»); ничего не изменено</translation>
    </message>
    <message>
        <source>the table k528_schema is empty</source>
        <translation>таблица k528_schema пуста</translation>
    </message>
    <message>
        <source>no K528 Studio database at %1 (the database is empty; create one with: k528 db init --db %1)</source>
        <translation>нет базы данных K528 Studio в %1 (база данных пуста; создать её: k528 db init --db %1)</translation>
    </message>
    <message>
        <source>%1: not an empty database (schema version %2); a copy goes only into an empty one</source>
        <translation>%1: база данных не пуста (версия схемы %2); копия записывается только в пустую</translation>
    </message>
    <message>
        <source>PostgreSQL %1 is too old; K528 Studio needs version 11 or newer</source>
        <translation>PostgreSQL %1 слишком стар; K528 Studio нужна версия 11 или новее</translation>
    </message>
    <message>
        <source>the database's encoding is %1; K528 Studio keeps Russian texts and needs UTF8 (createdb --encoding=UTF8 --template=template0)</source>
        <translation>кодировка базы данных — %1; K528 Studio хранит русские тексты, ей нужна UTF8 (createdb --encoding=UTF8 --template=template0)</translation>
    </message>
    <message>
        <source>%1: another session is writing to the database and kept it locked longer than the busy timeout; nothing was written, try again</source>
        <translation>%1: другой сеанс пишет в базу данных и держит её заблокированной дольше времени ожидания; ничего не записано, повторите</translation>
    </message>
    <message>
        <source>no role "%1": the roles are trainer, technologist, operator and viewer</source>
        <translation>нет роли «%1»: роли — trainer, technologist, operator и viewer</translation>
    </message>
    <message>
        <source>no message run %1; nothing was written</source>
        <translation>нет прогона сообщений %1; ничего не записано</translation>
    </message>
    <message>
        <source>the new run has no id</source>
        <translation>у нового прогона нет номера</translation>
    </message>
    <message>
        <source>another process kept the database locked longer than the busy timeout; the messages were not written</source>
        <translation>другой процесс держал базу данных заблокированной дольше времени ожидания; сообщения не записаны</translation>
    </message>
    <message>
        <source>message event %1 of run %2: acknowledged without saying how</source>
        <translation>событие сообщения %1 прогона %2: квитировано без указания, как</translation>
    </message>
    <message>
        <source>message event %1 of run %2: no such message was raised</source>
        <translation>событие сообщения %1 прогона %2: такое сообщение не выдавалось</translation>
    </message>
    <message>
        <source>message history row %1: unknown source "%2"</source>
        <translation>строка истории сообщений %1: неизвестный источник «%2»</translation>
    </message>
    <message>
        <source>; none of the batch's %1 events was written</source>
        <translation>; ни одно из %1 событий пакета не записано</translation>
    </message>
    <message>
        <source>machine %1: a push takes released programs only; not released as they are:</source>
        <translation>станок %1: передаются только выпущенные программы; не выпущены в этом виде:</translation>
    </message>
    <message>
        <source>L%1: not in the database, nothing of it released</source>
        <translation>L%1: нет в базе данных, ничего из неё не выпущено</translation>
    </message>
    <message>
        <source>L%1: draft, nothing of it released</source>
        <translation>L%1: черновик, ничего из неё не выпущено</translation>
    </message>
    <message>
        <source>L%1: withdrawn, nothing of it released</source>
        <translation>L%1: отозвана, ничего из неё не выпущено</translation>
    </message>
    <message>
        <source>L%1: not the released version (revision %2)</source>
        <translation>L%1: не выпущенная версия (ревизия %2)</translation>
    </message>
    <message>
        <source>release them (k528 db release %1 L&lt;n&gt;), or let technologists push drafts: k528 db set %1 push.unreleased=true</source>
        <translation>выпустите их (k528 db release %1 L&lt;n&gt;) или разрешите технологам передавать черновики: k528 db set %1 push.unreleased=true</translation>
    </message>
    <message>
        <source>release them (k528 db release %1 L&lt;n&gt;), or push as a technologist (the machine allows drafts: push.unreleased)</source>
        <translation>выпустите их (k528 db release %1 L&lt;n&gt;) или передайте их как технолог (станок разрешает черновики: push.unreleased)</translation>
    </message>
    <message>
        <source>column %1 holds a value that is neither an integer nor a text (query: %2)</source>
        <translation>столбец %1 содержит значение, которое не является ни целым числом, ни текстом (запрос «%2»)</translation>
    </message>
    <message>
        <source>column %1 holds a value where an integer belongs: %2</source>
        <translation>столбец %1 содержит значение там, где должно быть целое число: «%2»</translation>
    </message>
    <message>
        <source>; the migration to schema version %1 failed, nothing was changed</source>
        <translation>; переход на версию схемы %1 не удался, ничего не изменено</translation>
    </message>
    <message>
        <source>an unexpected database error (please report it): %1</source>
        <translation>непредвиденная ошибка базы данных (пожалуйста, сообщите о ней): «%1»</translation>
    </message>
    <message>
        <source>machine %1: rejected, nothing was written (%2 error):</source>
        <translation>станок %1: отклонено, ничего не записано (ошибок: %2):</translation>
    </message>
    <message>
        <source>machine %1: rejected, nothing was written (%2 errors):</source>
        <translation>станок %1: отклонено, ничего не записано (ошибок: %2):</translation>
    </message>
    <message>
        <source>machine %1: rejected, nothing was written:</source>
        <translation>станок %1: отклонено, ничего не записано:</translation>
    </message>
    <message>
        <source>machine %1 revision %2 in %3: simulation key %4 of the stored order has no value</source>
        <translation>станок %1, ревизия %2 в %3: у ключа моделирования %4 из сохранённого порядка нет значения</translation>
    </message>
    <message>
        <source>machine %1 revision %2 in %3: the stored order of the simulation settings does not list every key</source>
        <translation>станок %1, ревизия %2 в %3: сохранённый порядок настроек моделирования перечисляет не все ключи</translation>
    </message>
    <message>
        <source>machine %1 in %2: C values: "%3" where integer pairs belong</source>
        <translation>станок %1 в %2: значения C-параметров: «%3» там, где должны быть пары целых чисел</translation>
    </message>
    <message>
        <source>machine %1 in %2: C values: a number without its value</source>
        <translation>станок %1 в %2: значения C-параметров: номер без значения</translation>
    </message>
    <message>
        <source>machine %1 in %2: R presets: "%3" where integer pairs belong</source>
        <translation>станок %1 в %2: предустановки R-параметров: «%3» там, где должны быть пары целых чисел</translation>
    </message>
    <message>
        <source>machine %1 in %2: R presets: a number without its value</source>
        <translation>станок %1 в %2: предустановки R-параметров: номер без значения</translation>
    </message>
    <message>
        <source>machine %1 in %2: C-parameter number %3 is not 1..152</source>
        <translation>станок %1 в %2: номер C-параметра %3 — не из 1..152</translation>
    </message>
    <message>
        <source>machine %1 in %2: %3 of the 152 C-parameter values are stored</source>
        <translation>станок %1 в %2: хранится значений C-параметров: %3 из 152</translation>
    </message>
    <message>
        <source>machine %1 in %2: program L%3 of revision %4 does not match its SHA-256 checksum (the text was altered outside K528 Studio)</source>
        <translation>станок %1 в %2: программа L%3 ревизии %4 не совпадает со своей контрольной суммой SHA-256 (текст изменён не в K528 Studio)</translation>
    </message>
    <message>
        <source>machine %1 in %2: unknown PLC message group %3</source>
        <translation>станок %1 в %2: неизвестная группа сообщений ПЛК %3</translation>
    </message>
    <message>
        <source>machine %1 in %2: the simulation setting %3=%4 cannot be read</source>
        <translation>станок %1 в %2: настройку моделирования %3=%4 прочитать нельзя</translation>
    </message>
    <message>
        <source>the database is read-only: %1 (%2); nothing was written</source>
        <translation>база данных доступна только для чтения: %1 (%2); ничего не записано</translation>
    </message>
    <message>
        <source>the database is read-only: %1 (%2); a new database cannot be created there</source>
        <translation>база данных доступна только для чтения: %1 (%2); создать там новую базу данных нельзя</translation>
    </message>
    <message>
        <source>the database is read-only: %1 (%2); its schema is older than this program's and cannot be upgraded</source>
        <translation>база данных доступна только для чтения: %1 (%2); её схема старше схемы этой программы, и обновить её нельзя</translation>
    </message>
    <message>
        <source>the database is read-only: %1 (%2); it has an unfinished transaction (a hot -journal) that only a user who may write the file can roll back; the file was left untouched</source>
        <translation>база данных доступна только для чтения: %1 (%2); в ней незавершённая транзакция (горячий журнал -journal), откатить которую может только пользователь с правом записи; файл не изменён</translation>
    </message>
    <message>
        <source>permission denied</source>
        <translation>нет права на запись</translation>
    </message>
    <message>
        <source>no permission to create files in its folder</source>
        <translation>нет права создавать файлы в её папке</translation>
    </message>
    <message>
        <source>read-only file system</source>
        <translation>файловая система только для чтения</translation>
    </message>
    <message>
        <source>opened read-only</source>
        <translation>открыта только для чтения</translation>
    </message>
    <message>
        <source>the database %1 refused the user %2: %4 needs %5; the user has %3; nothing was written</source>
        <translation>база данных %1 отказала пользователю %2: для действия «%4» требуется %5; у пользователя: %3; ничего не записано</translation>
    </message>
    <message>
        <source>the database %1 refused the user %2: %3 needs %4; the user has no K528 Studio role; nothing was written</source>
        <translation>база данных %1 отказала пользователю %2: для действия «%3» требуется %4; у пользователя нет ни одной роли K528 Studio; ничего не записано</translation>
    </message>
    <message>
        <source>creating a machine</source>
        <translation>создание станка</translation>
    </message>
    <message>
        <source>changing a machine</source>
        <translation>изменение станка</translation>
    </message>
    <message>
        <source>deleting a machine</source>
        <translation>удаление станка</translation>
    </message>
    <message>
        <source>releasing a program</source>
        <translation>выпуск программы</translation>
    </message>
    <message>
        <source>withdrawing a program</source>
        <translation>отзыв программы</translation>
    </message>
    <message>
        <source>recording a transfer</source>
        <translation>запись передачи в журнал</translation>
    </message>
    <message>
        <source>recording messages</source>
        <translation>запись сообщений</translation>
    </message>
    <message>
        <source>recording a training attempt</source>
        <translation>запись учебной попытки</translation>
    </message>
    <message>
        <source>creating the database's tables</source>
        <translation>создание таблиц базы данных</translation>
    </message>
    <message>
        <source>setting up the roles</source>
        <translation>настройка ролей</translation>
    </message>
    <message>
        <source>granting a role</source>
        <translation>выдача роли</translation>
    </message>
    <message>
        <source>setting or clearing the constants lock</source>
        <translation>установка или снятие блокировки констант</translation>
    </message>
    <message>
        <source>recording the machines' time in each state</source>
        <translation>запись времени станков в каждом состоянии</translation>
    </message>
    <message>
        <source>the role %1</source>
        <translation>роль %1</translation>
    </message>
    <message>
        <source>the owner of the database</source>
        <translation>владелец базы данных</translation>
    </message>
    <message>
        <source>the owner of the database's tables with CREATEROLE</source>
        <translation>владелец таблиц базы данных с правом CREATEROLE</translation>
    </message>
    <message>
        <source>the role's admin (its creator, or CREATEROLE)</source>
        <translation>администратор роли (её создатель или CREATEROLE)</translation>
    </message>
    <message>
        <source>machine %1: %2</source>
        <translation>станок %1: %2</translation>
    </message>
</context>
<context>
    <name>k528::studio::DatabaseUi</name>
    <message>
        <source>Database: %1</source>
        <translation>База данных: %1</translation>
    </message>
    <message>
        <source>The database %1 cannot be opened: %2</source>
        <translation>Базу данных %1 открыть нельзя: %2</translation>
    </message>
    <message>
        <source>this is not a database location (a file path, sqlite:PATH or postgresql://HOST/NAME; a password is never written in it: use ~/.pgpass or a service file)</source>
        <translation>это не адрес базы данных (путь к файлу, sqlite:ПУТЬ или postgresql://СЕРВЕР/ИМЯ; пароль в нём не пишется: он берётся из ~/.pgpass или файла служб)</translation>
    </message>
    <message>
        <source>it cannot be reached, read or created</source>
        <translation>к ней нет доступа, её нельзя прочитать или создать</translation>
    </message>
    <message>
        <source>it is not a K528 Studio database</source>
        <translation>это не база данных K528 Studio</translation>
    </message>
    <message>
        <source>it is damaged (nothing in it was changed)</source>
        <translation>она повреждена (в ней ничего не изменено)</translation>
    </message>
    <message>
        <source>it was written by a newer K528 Studio</source>
        <translation>она записана более новой версией K528 Studio</translation>
    </message>
    <message>
        <source>another program holds it too long</source>
        <translation>другая программа слишком долго держит её занятой</translation>
    </message>
    <message>
        <source>the server refused this user</source>
        <translation>сервер отказал этому пользователю</translation>
    </message>
    <message>
        <source>an unexpected database error</source>
        <translation>непредвиденная ошибка базы данных</translation>
    </message>
    <message>
        <source>The database %1 cannot be opened: %2.
Details: %3</source>
        <translation>Базу данных %1 открыть нельзя: %2.
Подробности: %3</translation>
    </message>
    <message>
        <source>Name a database: a file path, sqlite:PATH or postgresql://HOST/NAME.</source>
        <translation>Укажите базу данных: путь к файлу, sqlite:ПУТЬ или postgresql://СЕРВЕР/ИМЯ.</translation>
    </message>
    <message>
        <source>K528 Studio — %1</source>
        <translation>K528 Studio — %1</translation>
    </message>
    <message>
        <source>Database</source>
        <translation>База данных</translation>
    </message>
    <message>
        <source>The database of machines, programs and their history: a file on this PC (a path, or sqlite:PATH), or the shop's PostgreSQL server (postgresql://HOST/NAME, postgresql:///NAME, postgresql://?service=shop). The password is never written here: the server's password is read from ~/.pgpass (PGPASSFILE) or a service file.</source>
        <translation>База данных станков, программ и их истории: файл на этом ПК (путь или sqlite:ПУТЬ) или сервер PostgreSQL цеха (postgresql://СЕРВЕР/ИМЯ, postgresql:///ИМЯ, postgresql://?service=shop). Пароль здесь не пишется: пароль сервера берётся из ~/.pgpass (PGPASSFILE) или файла служб.</translation>
    </message>
    <message>
        <source>File...</source>
        <translation>Файл...</translation>
    </message>
    <message>
        <source>Database file</source>
        <translation>Файл базы данных</translation>
    </message>
    <message>
        <source>K528 Studio databases (*.db *.sqlite);;All files (*)</source>
        <translation>Базы данных K528 Studio (*.db *.sqlite);;Все файлы (*)</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Открыть</translation>
    </message>
    <message>
        <source>%1 changed on another PC: revision %2 by %3 at %4 (%5)</source>
        <translation>%1 изменён на другом ПК: ревизия %2, автор %3, %4 (%5)</translation>
    </message>
    <message>
        <source>&amp;Database...</source>
        <translation>&amp;База данных...</translation>
    </message>
    <message>
        <source>Database %1 open</source>
        <translation>Открыта база данных %1</translation>
    </message>
    <message>
        <source>Transfers</source>
        <translation>Передачи</translation>
    </message>
    <message>
        <source>every machine</source>
        <translation>все станки</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Время</translation>
    </message>
    <message>
        <source>User</source>
        <translation>Пользователь</translation>
    </message>
    <message>
        <source>PC</source>
        <translation>ПК</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Станок</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Контроллер</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Направление</translation>
    </message>
    <message>
        <source>What moved</source>
        <translation>Что передано</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Итог</translation>
    </message>
    <message>
        <source>Machine:</source>
        <translation>Станок:</translation>
    </message>
    <message>
        <source>push</source>
        <translation>в УЧПУ</translation>
    </message>
    <message>
        <source>pull</source>
        <translation>из УЧПУ</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>успешно</translation>
    </message>
    <message>
        <source>partial</source>
        <translation>частично</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>не удалось</translation>
    </message>
    <message>
        <source>%1 transfers</source>
        <translation>передач: %1</translation>
    </message>
    <message>
        <source>&amp;Transfers...</source>
        <translation>&amp;Передачи...</translation>
    </message>
    <message>
        <source>The database %1 cannot be opened: %2.</source>
        <translation>Базу данных %1 открыть нельзя: %2.</translation>
    </message>
</context>
<context>
    <name>k528::studio::DebugPanel</name>
    <message>
        <source>Type an R-parameter number, R0..R299.</source>
        <translation>Введите номер R-параметра, R0..R299.</translation>
    </message>
    <message>
        <source>A program is under way: stop it first.</source>
        <translation>Программа выполняется: сначала остановите её.</translation>
    </message>
    <message>
        <source>Open a program file first.</source>
        <translation>Сначала откройте файл программы.</translation>
    </message>
    <message>
        <source>The program under way is another file's.</source>
        <translation>Выполняется программа другого файла.</translation>
    </message>
    <message>
        <source>R-parameters are R0..R299, not R%1.</source>
        <translation>R-параметры: R0..R299, а не R%1.</translation>
    </message>
    <message>
        <source>R%1 was not set: %2</source>
        <translation>R%1 не записан: %2</translation>
    </message>
    <message>
        <source>R%1: «%2» is not a whole number.</source>
        <translation>R%1: «%2» — не целое число.</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Выполнить</translation>
    </message>
    <message>
        <source>Send the file and run its first program (homing as the operator would), or continue</source>
        <translation>Передать файл и выполнить его первую программу (с привязкой к базовой точке, как оператор) или продолжить</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Стоп</translation>
    </message>
    <message>
        <source>Continue</source>
        <translation>Продолжить</translation>
    </message>
    <message>
        <source>Single frame</source>
        <translation>Покадрово</translation>
    </message>
    <message>
        <source>Run to cursor</source>
        <translation>До курсора</translation>
    </message>
    <message>
        <source>Run until the frame at the cursor, stopping before it</source>
        <translation>Выполнять до кадра у курсора и остановиться перед ним</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Прервать</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Сброс</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <source>fastest</source>
        <translation>максимально</translation>
    </message>
    <message>
        <source>real time</source>
        <translation>реальное время</translation>
    </message>
    <message>
        <source>Call stack</source>
        <translation>Стек вызовов</translation>
    </message>
    <message>
        <source>R158</source>
        <translation>R158</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Программа</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation>Кадр</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Строка</translation>
    </message>
    <message>
        <source>Watch</source>
        <translation>Наблюдение</translation>
    </message>
    <message>
        <source>Add an R-parameter: R12, Enter</source>
        <translation>Добавить R-параметр: R12, Enter</translation>
    </message>
    <message>
        <source>R</source>
        <translation>R</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Значение</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Назначение</translation>
    </message>
    <message>
        <source>Like STOP on the machine's panel: the motion stops, CYCLE START continues</source>
        <translation>«Стоп»: перемещение останавливается, «Пуск» продолжает</translation>
    </message>
    <message>
        <source>Like CYCLE START: continue the held program</source>
        <translation>«Пуск»: продолжить остановленную программу</translation>
    </message>
    <message>
        <source>Stop after each frame; CYCLE START runs the next one</source>
        <translation>Останов после каждого кадра; «Пуск» выполняет следующий</translation>
    </message>
    <message>
        <source>Like RESET: the program ends without continuation</source>
        <translation>«Сброс»: программа прерывается без возможности продолжения</translation>
    </message>
    <message>
        <source>RESET and ESC: end the program and acknowledge the messages</source>
        <translation>«Сброс» и ESC: прервать программу и квитировать сообщения</translation>
    </message>
    <message>
        <source>the file</source>
        <translation>файл</translation>
    </message>
    <message>
        <source>There is no frame at or after line %1.</source>
        <translation>В строке %1 и после неё нет кадра.</translation>
    </message>
    <message>
        <source>L%1 never reaches line %2: nothing to start there.</source>
        <translation>L%1 не доходит до строки %2: начать там нечего.</translation>
    </message>
    <message>
        <source>Line %1 runs while %2 oscillates (Gx81 up to its Gx80): start from the frame of the Gx81 or after the Gx80.</source>
        <translation>Строка %1 выполняется во время осцилляции %2 (от Gx81 до её Gx80): начните с кадра Gx81 или после Gx80.</translation>
    </message>
    <message>
        <source>Start here</source>
        <translation>Начать отсюда</translation>
    </message>
    <message>
        <source>L%1 N%2 (line %3)</source>
        <translation>L%1 N%2 (строка %3)</translation>
    </message>
    <message>
        <source>L%1 (line %2)</source>
        <translation>L%1 (строка %2)</translation>
    </message>
    <message>
        <source>L%1 starts before %2 with the state the preview rebuilt. The axes go there first: X to its reference point, then Z, then X, at the rapid speed.</source>
        <translation>L%1 начнётся перед %2 с состоянием, восстановленным просмотром. Сначала оси подходят туда: X в базовую точку, затем Z, затем X, на ускоренной подаче.</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Состояние</translation>
    </message>
    <message>
        <source>Modal functions</source>
        <translation>Модальные функции</translation>
    </message>
    <message>
        <source>Feeds</source>
        <translation>Подачи</translation>
    </message>
    <message>
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message>
        <source>R224..R231 (coordinate components)</source>
        <translation>R224..R231 (составляющие координат)</translation>
    </message>
    <message>
        <source>R-parameters the program set</source>
        <translation>R-параметры, заданные программой</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Сообщение</translation>
    </message>
    <message>
        <source>M functions handed to the PLC again</source>
        <translation>M-функции, повторно переданные в ПЛК</translation>
    </message>
    <message>
        <source>Start point %1</source>
        <translation>Точка начала %1</translation>
    </message>
    <message>
        <source>%1 (machine %2)</source>
        <translation>%1 (станок %2)</translation>
    </message>
    <message>
        <source>Safe path</source>
        <translation>Безопасный путь</translation>
    </message>
    <message>
        <source>X %1, Z %2, X %3 (machine system)</source>
        <translation>X %1, Z %2, X %3 (система станка)</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Предупреждение</translation>
    </message>
    <message>
        <source>line %1 moves %2 until a signal or by handwheel: the start point takes its programmed end</source>
        <translation>строка %1 перемещает %2 до сигнала или маховиком: точка начала берёт её запрограммированный конец</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Начать</translation>
    </message>
    <message>
        <source>Start the program before the frame at the cursor, with its state rebuilt (modal functions, R-parameters, call stack) and shown first</source>
        <translation>Запустить программу перед кадром под курсором с восстановленным состоянием (модальные функции, R-параметры, стек вызовов), показав его сначала</translation>
    </message>
</context>
<context>
    <name>k528::studio::DebugSession</name>
    <message>
        <source>There is no frame at or after line %1.</source>
        <translation>В строке %1 и после неё нет кадра.</translation>
    </message>
    <message>
        <source>A program is under way: stop it first.</source>
        <translation>Программа выполняется: сначала остановите её.</translation>
    </message>
    <message>
        <source>The controller holds no program L%1.</source>
        <translation>В позиционере нет программы L%1.</translation>
    </message>
    <message>
        <source>The emergency stop is pressed: pull it out on the machine's panel.</source>
        <translation>Нажат аварийный стоп: отпустите его на пульте станка.</translation>
    </message>
    <message>
        <source>Switching the drives on…</source>
        <translation>Включение приводов…</translation>
    </message>
    <message>
        <source>The reference-point mode was refused: %1</source>
        <translation>Режим привязки к базовой точке не принят: %1</translation>
    </message>
    <message>
        <source>Reference point of %1…</source>
        <translation>Привязка к базовой точке по %1…</translation>
    </message>
    <message>
        <source>Program L%1 was refused: %2</source>
        <translation>Программа L%1 не принята: %2</translation>
    </message>
    <message>
        <source>The machine did not get ready: the drives are off (see the machine's messages).</source>
        <translation>Станок не готов: приводы не включены (см. сообщения станка).</translation>
    </message>
    <message>
        <source>The reference-point cycle of %1 stopped with a message.</source>
        <translation>Привязка к базовой точке по %1 прервана сообщением.</translation>
    </message>
    <message>
        <source>The reference-point cycle of %1 ended without the reference point.</source>
        <translation>Привязка к базовой точке по %1 закончилась без базовой точки.</translation>
    </message>
    <message>
        <source>The reference-point cycle of %1 did not start.</source>
        <translation>Привязка к базовой точке по %1 не началась.</translation>
    </message>
    <message>
        <source>L%1 runs.</source>
        <translation>L%1 выполняется.</translation>
    </message>
    <message>
        <source>L%1 ended.</source>
        <translation>L%1 закончена.</translation>
    </message>
    <message>
        <source>The program stopped with a message: %1</source>
        <translation>Программа остановлена сообщением: %1</translation>
    </message>
    <message>
        <source>No machine</source>
        <translation>Нет станка</translation>
    </message>
    <message>
        <source>Starting L%1…</source>
        <translation>Пуск L%1…</translation>
    </message>
    <message>
        <source>L%1 N%2 (line %3)</source>
        <translation>L%1 N%2 (строка %3)</translation>
    </message>
    <message>
        <source>L%1 (line %2)</source>
        <translation>L%1 (строка %2)</translation>
    </message>
    <message>
        <source>No program</source>
        <translation>Нет программы</translation>
    </message>
    <message>
        <source>Running %1</source>
        <translation>Выполняется %1</translation>
    </message>
    <message>
        <source>Breakpoint: before %1</source>
        <translation>Точка останова: перед %1</translation>
    </message>
    <message>
        <source>Single frame: before %1</source>
        <translation>Покадрово: перед %1</translation>
    </message>
    <message>
        <source>Run to cursor: before %1</source>
        <translation>До курсора: перед %1</translation>
    </message>
    <message>
        <source>Ended at %1</source>
        <translation>Закончена в %1</translation>
    </message>
    <message>
        <source>Stopped by a message at %1</source>
        <translation>Остановлена сообщением в %1</translation>
    </message>
    <message>
        <source>the emergency stop is pressed on the machine's panel</source>
        <translation>на пульте станка нажат аварийный стоп</translation>
    </message>
    <message>
        <source>the positioner shows message %1: %2</source>
        <translation>позиционер выдаёт сообщение %1: %2</translation>
    </message>
    <message>
        <source>the PLC did not pass it on (start enable, the machine's messages)</source>
        <translation>ПЛК его не передал (деблокировка пуска, сообщения станка)</translation>
    </message>
    <message>
        <source>The machine is paused (Simulation &gt; Pause the machine): the run goes on when it runs.</source>
        <translation>Станок на паузе (Станок &gt; Пауза): запуск продолжится, когда станок пойдёт.</translation>
    </message>
    <message>
        <source>The machine is paused (Simulation &gt; Pause the machine): the program goes on when it runs.</source>
        <translation>Станок на паузе (Станок &gt; Пауза): программа продолжится, когда станок пойдёт.</translation>
    </message>
    <message>
        <source>the K923 is in %1, not in automatic mode</source>
        <translation>K923 в режиме %1, а не АВТОМАТ</translation>
    </message>
    <message>
        <source>Automatic mode was refused: %1</source>
        <translation>АВТОМАТ не принят: %1</translation>
    </message>
    <message>
        <source>CYCLE START is held down on the machine's panel: release it, then Run again.</source>
        <translation>Кнопка «Пуск» на пульте станка нажата: отпустите её и снова нажмите «Выполнить».</translation>
    </message>
    <message>
        <source>CYCLE START was not taken: %1.</source>
        <translation>«Пуск» не принят: %1.</translation>
    </message>
    <message>
        <source>M00 at %1: CYCLE START continues</source>
        <translation>M00 в %1: «Пуск» продолжает</translation>
    </message>
    <message>
        <source>Held at %1: CYCLE START continues</source>
        <translation>Остановлена в %1: «Пуск» продолжает</translation>
    </message>
</context>
<context>
    <name>k528::studio::DescriptionTexts</name>
    <message>
        <source>appears twice</source>
        <translation>встречается дважды</translation>
    </message>
    <message>
        <source>JSON syntax error: line %2, column %3</source>
        <translation>ошибка синтаксиса JSON: строка %2, столбец %3</translation>
    </message>
    <message>
        <source>expected an object, found %1</source>
        <translation>ожидается объект, а здесь %1</translation>
    </message>
    <message>
        <source>unknown key (known here: %1)</source>
        <translation>неизвестный ключ (здесь известны: %1)</translation>
    </message>
    <message>
        <source>is missing</source>
        <translation>отсутствует</translation>
    </message>
    <message>
        <source>expected an array, found %1</source>
        <translation>ожидается массив, а здесь %1</translation>
    </message>
    <message>
        <source>expected a string, found %1</source>
        <translation>ожидается строка, а здесь %1</translation>
    </message>
    <message>
        <source>expected a whole number, found %1</source>
        <translation>ожидается целое число, а здесь %1</translation>
    </message>
    <message>
        <source>%1 is outside %2..%3</source>
        <translation>%1 вне диапазона %2..%3</translation>
    </message>
    <message>
        <source>expected a number, found %1</source>
        <translation>ожидается число, а здесь %1</translation>
    </message>
    <message>
        <source>expected true or false, found %1</source>
        <translation>ожидается true или false, а здесь %1</translation>
    </message>
    <message>
        <source>null</source>
        <translation>null</translation>
    </message>
    <message>
        <source>true/false</source>
        <translation>true/false</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>число</translation>
    </message>
    <message>
        <source>a string</source>
        <translation>строка</translation>
    </message>
    <message>
        <source>an array</source>
        <translation>массив</translation>
    </message>
    <message>
        <source>an object</source>
        <translation>объект</translation>
    </message>
    <message>
        <source>?</source>
        <translation>?</translation>
    </message>
    <message>
        <source>'%1' is not a valid name (letters, digits and '_', starting with a letter or '_', at most 40)</source>
        <translation>«%1» — недопустимое имя (буквы, цифры и «_», начинается с буквы или «_», не длиннее 40 знаков)</translation>
    </message>
    <message>
        <source>'%1' is reserved (a keyword or a built-in signal)</source>
        <translation>имя «%1» занято (ключевое слово или встроенный сигнал)</translation>
    </message>
    <message>
        <source>'%1' is reserved for the K923 keys K1..K12</source>
        <translation>имя «%1» оставлено клавишам K923 K1..K12</translation>
    </message>
    <message>
        <source>'%1' looks like an interface address (Z&lt;word&gt;.&lt;bit&gt;)</source>
        <translation>имя «%1» похоже на адрес интерфейса (Z&lt;слово&gt;.&lt;бит&gt;)</translation>
    </message>
    <message>
        <source>this program reads format 1</source>
        <translation>эта программа читает формат 1</translation>
    </message>
    <message>
        <source>is empty</source>
        <translation>пусто</translation>
    </message>
    <message>
        <source>module place %1 appears twice</source>
        <translation>место модуля %1 встречается дважды</translation>
    </message>
    <message>
        <source>no module at place %1 in "modules"</source>
        <translation>в "modules" нет модуля на месте %1</translation>
    </message>
    <message>
        <source>'%1': use "no" (normally open) or "nc" (normally closed)</source>
        <translation>«%1»: нужно "no" (замыкающий контакт) или "nc" (размыкающий)</translation>
    </message>
    <message>
        <source>a timer needs exactly one of on_delay_ms, off_delay_ms, pulse_ms</source>
        <translation>у таймера должно быть ровно одно из on_delay_ms, off_delay_ms, pulse_ms</translation>
    </message>
    <message>
        <source>a delay belongs to a timer: {"timer": "name", "on_delay_ms": ..., "when": ...}</source>
        <translation>задержка бывает только у таймера: {"timer": "имя", "on_delay_ms": ..., "when": ...}</translation>
    </message>
    <message>
        <source>a rung has exactly one of "out", "set", "reset", "timer"</source>
        <translation>у ступени логики ровно одно из "out", "set", "reset", "timer"</translation>
    </message>
    <message>
        <source>M%1 is described twice</source>
        <translation>M%1 описана дважды</translation>
    </message>
    <message>
        <source>timeout_ms and timeout_alarm go together</source>
        <translation>timeout_ms и timeout_alarm задаются вместе</translation>
    </message>
    <message>
        <source>give either "acknowledge": true or "alarm": k (hold the frame, raise alarm k)</source>
        <translation>задайте либо "acknowledge": true, либо "alarm": k (задержать кадр и выдать аварийное сообщение k)</translation>
    </message>
    <message>
        <source>%1 % is not an override step (0 1 2 5 10 20 35 50 75 90 100)</source>
        <translation>%1 % — не ступень коррекции (0 1 2 5 10 20 35 50 75 90 100)</translation>
    </message>
    <message>
        <source>K%1 is bound twice</source>
        <translation>клавиша K%1 назначена дважды</translation>
    </message>
    <message>
        <source>a key needs an action: set, reset, toggle or pulse</source>
        <translation>клавише нужно действие: set, reset, toggle или pulse</translation>
    </message>
    <message>
        <source>the LEDs of K%1 are described twice</source>
        <translation>светодиоды K%1 описаны дважды</translation>
    </message>
    <message>
        <source>message %1 has two conditions here</source>
        <translation>у сообщения %1 здесь два условия</translation>
    </message>
    <message>
        <source>not a signal of the positioner interface (known: %1, mode, override, bits)</source>
        <translation>не сигнал интерфейса с БП (известны: %1, mode, override, bits)</translation>
    </message>
    <message>
        <source>needs the four code bits, least significant first</source>
        <translation>нужны четыре бита кода, младший первым</translation>
    </message>
    <message>
        <source>only the free words Z1011..Z1013 are written here; the bits of Z1000..Z1010 have names (see slot keys)</source>
        <translation>здесь пишутся только свободные слова Z1011..Z1013; у битов Z1000..Z1010 есть имена (ключи сигналов БП)</translation>
    </message>
    <message>
        <source>writes the same bit as %1</source>
        <translation>пишет тот же бит, что и %1</translation>
    </message>
    <message>
        <source>cannot read the file</source>
        <translation>файл нельзя прочитать</translation>
    </message>
    <message>
        <source>no such machine description (built in: %1; or give a .json file)</source>
        <translation>нет такого описания станка (встроенные: %1; или укажите файл .json)</translation>
    </message>
    <message>
        <source>the name '%1' is already used (%2)</source>
        <translation>имя «%1» уже занято (%2)</translation>
    </message>
    <message>
        <source>built in</source>
        <translation>встроенный сигнал</translation>
    </message>
    <message>
        <source>unknown signal '%1'</source>
        <translation>неизвестный сигнал «%1»</translation>
    </message>
    <message>
        <source>%1 is not written by the logic (only Z1000..Z1013 are; messages, LEDs and keys have their own sections)</source>
        <translation>%1 не пишется логикой (пишутся только Z1000..Z1013; у сообщений, светодиодов и клавиш свои разделы)</translation>
    </message>
    <message>
        <source>Z1000.11 (M acknowledged) is written by segment 0</source>
        <translation>Z1000.11 (M квитирована) пишет сегмент 0</translation>
    </message>
    <message>
        <source>%1 is the mode code, written by positioner.mode</source>
        <translation>%1 — бит кода режима, его пишет positioner.mode</translation>
    </message>
    <message>
        <source>%1 belongs to the override code, written by positioner.override</source>
        <translation>%1 — бит кода коррекции, его пишет positioner.override</translation>
    </message>
    <message>
        <source>'%1' cannot be written: only outputs, flags and bits Z1000..Z1013 can (it is declared at %2)</source>
        <translation>«%1» нельзя писать: пишутся только выходы, флаги и биты Z1000..Z1013 (объявлен: %2)</translation>
    </message>
    <message>
        <source>'%1' already has a coil (each signal has one)</source>
        <translation>у «%1» уже есть катушка (у каждого сигнала одна)</translation>
    </message>
    <message>
        <source>%1 already has a coil in the logic</source>
        <translation>у %1 уже есть катушка в логике</translation>
    </message>
    <message>
        <source>'%1' is pulsed by an action and also has a coil</source>
        <translation>«%1» получает импульс от действия и при этом имеет катушку</translation>
    </message>
    <message>
        <source>column %1: %3 in "%2"</source>
        <translation>столбец %1: %3 в "%2"</translation>
    </message>
    <message>
        <source>empty condition</source>
        <translation>пустое условие</translation>
    </message>
    <message>
        <source>unexpected '%1'</source>
        <translation>неожиданный знак «%1»</translation>
    </message>
    <message>
        <source>condition nested too deeply (more than %1 levels)</source>
        <translation>условие вложено слишком глубоко (больше %1 уровней)</translation>
    </message>
    <message>
        <source>'%1' is a keyword, not a signal</source>
        <translation>«%1» — ключевое слово, а не сигнал</translation>
    </message>
    <message>
        <source>missing ')'</source>
        <translation>не хватает «)»</translation>
    </message>
    <message>
        <source>the condition ends too early</source>
        <translation>условие обрывается слишком рано</translation>
    </message>
    <message>
        <source>missing ')' after the signal of %1</source>
        <translation>не хватает «)» после сигнала %1</translation>
    </message>
    <message>
        <source>needs three values: x1, x10, x100 positions</source>
        <translation>нужны три значения: положения x1, x10, x100</translation>
    </message>
    <message>
        <source>'%1': a spindle is "spindle", "wheel" or "work"</source>
        <translation>«%1»: шпиндель — это "spindle", "wheel" или "work"</translation>
    </message>
    <message>
        <source>spindle '%1' appears twice</source>
        <translation>шпиндель «%1» встречается дважды</translation>
    </message>
    <message>
        <source>'%1': a pump is "coolant", "lube", "hydraulics" or "air"</source>
        <translation>«%1»: насос — это "coolant", "lube", "hydraulics" или "air"</translation>
    </message>
    <message>
        <source>pump '%1' appears twice</source>
        <translation>насос «%1» встречается дважды</translation>
    </message>
    <message>
        <source>the size must be larger than the blank's bore (internal grinding)</source>
        <translation>размер должен быть больше отверстия заготовки (внутреннее шлифование)</translation>
    </message>
    <message>
        <source>grinding needs the spindles "wheel" and "work"</source>
        <translation>для шлифования нужны шпиндели "wheel" и "work"</translation>
    </message>
    <message>
        <source>grinding needs a chuck (the ring is changed while it is open)</source>
        <translation>для шлифования нужен патрон (кольцо меняют, пока он разжат)</translation>
    </message>
    <message>
        <source>unknown machine signal '%1'</source>
        <translation>неизвестный сигнал станка «%1»</translation>
    </message>
    <message>
        <source>'%1' is not a sensor of this machine (%2)</source>
        <translation>«%1» — не датчик этого станка (%2)</translation>
    </message>
    <message>
        <source>'%1' is not an actuator of this machine (%2)</source>
        <translation>«%1» — не исполнительный механизм этого станка (%2)</translation>
    </message>
    <message>
        <source>'%1' is driven by another output too</source>
        <translation>«%1» управляется ещё и другим выходом</translation>
    </message>
    <message>
        <source>M%1 is not one of the description's m_functions</source>
        <translation>M%1 нет среди m_functions описания</translation>
    </message>
    <message>
        <source>'%1' is not a spindle of the equipment</source>
        <translation>«%1» — не шпиндель из equipment</translation>
    </message>
    <message>
        <source>M%1 both starts and stops the spindle</source>
        <translation>M%1 и пускает, и останавливает шпиндель</translation>
    </message>
    <message>
        <source>'%1' is not one of the spindles listed here</source>
        <translation>«%1» нет среди перечисленных здесь шпинделей</translation>
    </message>
    <message>
        <source>M%1 changes the tool twice</source>
        <translation>M%1 меняет инструмент дважды</translation>
    </message>
    <message>
        <source>the equipment has no turret</source>
        <translation>в оборудовании нет револьверной головки</translation>
    </message>
    <message>
        <source>the turret's box needs z_min_mm &lt; z_max_mm and r_min_mm &lt; r_max_mm</source>
        <translation>габарит револьверной головки требует z_min_mm &lt; z_max_mm и r_min_mm &lt; r_max_mm</translation>
    </message>
    <message>
        <source>a signal name is missing at the end</source>
        <translation>в конце не хватает имени сигнала</translation>
    </message>
    <message>
        <source>expected a signal name, found '%1'</source>
        <translation>ожидается имя сигнала, а здесь «%1»</translation>
    </message>
    <message>
        <source>%1 needs a signal in parentheses: %1(name)</source>
        <translation>%1 требует сигнала в скобках: %1(имя)</translation>
    </message>
    <message>
        <source>%1: %2: %3</source>
        <translation>%1: %2: %3</translation>
    </message>
</context>
<context>
    <name>k528::studio::DiagnosticTexts</name>
    <message>
        <source>comment not closed: no ')' before the end of the line</source>
        <translation>Комментарий не закрыт: нет «)» до конца строки</translation>
    </message>
    <message>
        <source>a CR without LF does not end a line: program text ends its lines with LF or CR LF; convert the file (e.g. tr '\r' '\n')</source>
        <translation>Символ CR без LF не завершает строку: концы строк в тексте программы — LF или CR LF; преобразуйте файл (например, tr '\r' '\n')</translation>
    </message>
    <message>
        <source>invalid byte sequence %1: program text must be UTF-8</source>
        <translation>Недопустимая последовательность байтов %1: текст программы должен быть в UTF-8</translation>
    </message>
    <message>
        <source>frames before the first %L&lt;n&gt; header belong to no program: add a header above them</source>
        <translation>Кадры до первого заголовка %L&lt;n&gt; не принадлежат ни одной программе: добавьте заголовок перед ними</translation>
    </message>
    <message>
        <source>unknown header '%1': expected %L&lt;program number&gt; or %MESSAGES</source>
        <translation>Неизвестный заголовок «%1»: ожидается %L&lt;номер программы&gt; или %MESSAGES</translation>
    </message>
    <message>
        <source>program header without a number: expected %L&lt;1..99&gt;</source>
        <translation>Заголовок программы без номера: ожидается %L&lt;1..99&gt;</translation>
    </message>
    <message>
        <source>program number '%1' is not a whole number 1..99</source>
        <translation>Номер программы «%1» — не целое число 1..99</translation>
    </message>
    <message>
        <source>program number L%1 is outside 1..99</source>
        <translation>Номер программы L%1 вне диапазона 1..99</translation>
    </message>
    <message>
        <source>program L%1 is already defined on line %2</source>
        <translation>Программа L%1 уже определена в строке %2</translation>
    </message>
    <message>
        <source>unexpected text after the program header: '%1'</source>
        <translation>Лишний текст после заголовка программы: «%1»</translation>
    </message>
    <message>
        <source>unexpected text after %MESSAGES: '%1'</source>
        <translation>Лишний текст после %MESSAGES: «%1»</translation>
    </message>
    <message>
        <source>a message table line must read #&lt;1..99&gt;=&lt;text&gt;</source>
        <translation>Строка таблицы сообщений должна иметь вид #&lt;1..99&gt;=&lt;текст&gt;</translation>
    </message>
    <message>
        <source>message number #%1 is outside 1..99</source>
        <translation>Номер сообщения #%1 вне диапазона 1..99</translation>
    </message>
    <message>
        <source>message #%1 is already defined on line %2</source>
        <translation>Сообщение #%1 уже задано в строке %2</translation>
    </message>
    <message>
        <source>only #&lt;1..99&gt;=&lt;text&gt; lines and comments may stand in the %MESSAGES section</source>
        <translation>В разделе %MESSAGES допустимы только строки #&lt;1..99&gt;=&lt;текст&gt; и комментарии</translation>
    </message>
    <message>
        <source>address %1 is not followed by a number</source>
        <translation>После адреса %1 нет числа</translation>
    </message>
    <message>
        <source>%1%2: number too large</source>
        <translation>%1%2: слишком большое число</translation>
    </message>
    <message>
        <source>%1: '%2' is not a whole number without sign or point</source>
        <translation>%1: «%2» — ожидается целое число без знака и точки</translation>
    </message>
    <message>
        <source>address %1 has no value: expected a number or an R-parameter</source>
        <translation>После адреса %1 нет значения: ожидается число или R-параметр</translation>
    </message>
    <message>
        <source>%1: a sign before an R-parameter is not allowed; compute R&lt;i&gt;=0-R&lt;j&gt; in a frame of its own</source>
        <translation>%1: знак перед R-параметром недопустим; вычислите R&lt;i&gt;=0-R&lt;j&gt; отдельным кадром</translation>
    </message>
    <message>
        <source>%2'%1' has more than 18 significant digits</source>
        <translation>%2в числе «%1» больше 18 значащих цифр</translation>
    </message>
    <message>
        <source>%2'%1' has more than 18 digits after the decimal point</source>
        <translation>%2в числе «%1» больше 18 цифр после точки</translation>
    </message>
    <message>
        <source>%2'%1' is not a number</source>
        <translation>%2«%1» — не число</translation>
    </message>
    <message>
        <source>%1 value: </source>
        <translation>Задание координаты %1: </translation>
    </message>
    <message>
        <source>%1: </source>
        <translation>%1: </translation>
    </message>
    <message>
        <source>unexpected character '%1'</source>
        <translation>Неожиданный символ «%1»</translation>
    </message>
    <message>
        <source>Cyrillic letter '%1': frame addresses are Latin letters</source>
        <translation>Кириллическая буква «%1»: адреса кадра пишутся латинскими буквами</translation>
    </message>
    <message>
        <source>Cyrillic letter '%1': frame addresses are Latin letters (%2)</source>
        <translation>Кириллическая буква «%1»: адреса кадра пишутся латинскими буквами (%2)</translation>
    </message>
    <message>
        <source>unknown address '%1': a frame may contain N, G, M, #, L, X, Z, FX, FZ</source>
        <translation>Неизвестный адрес «%1»: в кадре допустимы N, G, M, #, L, X, Z, FX, FZ</translation>
    </message>
    <message>
        <source>%1 is given twice in the frame</source>
        <translation>Адрес %1 задан в кадре дважды</translation>
    </message>
    <message>
        <source>GOTO makes an unconditional jump frame: it holds only [/][N] GOTO &lt;frame number&gt;</source>
        <translation>GOTO — кадр безусловного перехода: в нём может быть только [/][N] GOTO &lt;номер кадра&gt;</translation>
    </message>
    <message>
        <source>more than three G functions in the frame: %1 is one too many</source>
        <translation>Больше трёх G-функций в кадре: %1 лишняя</translation>
    </message>
    <message>
        <source>more than three M functions in the frame: M%1 is one too many</source>
        <translation>Больше трёх M-функций в кадре: M%1 лишняя</translation>
    </message>
    <message>
        <source>the frame number N must come first in the frame</source>
        <translation>Номер кадра N должен стоять в начале кадра</translation>
    </message>
    <message>
        <source>F without an axis: a bare F applies to the X or Z word directly before it; write FX or FZ</source>
        <translation>F без оси: F относится к слову X или Z непосредственно перед ним; напишите FX или FZ</translation>
    </message>
    <message>
        <source>R-parameter outside a computational frame: write R&lt;i&gt;=... as a frame of its own, and in X, Z, FX, FZ as X=R&lt;i&gt;</source>
        <translation>R-параметр вне вычислительного кадра: R&lt;i&gt;=… пишется отдельным кадром, а в X, Z, FX, FZ — как X=R&lt;i&gt;</translation>
    </message>
    <message>
        <source>IF makes a conditional jump frame: it holds only [/][N] IF R&lt;i&gt;&gt;0 GOTO &lt;number&gt;</source>
        <translation>IF — кадр условного перехода: в нём может быть только [/][N] IF R&lt;i&gt;&gt;0 GOTO &lt;номер&gt;</translation>
    </message>
    <message>
        <source>the skip flag '/' may only stand at the start of the frame</source>
        <translation>Признак пропуска «/» может стоять только в начале кадра</translation>
    </message>
    <message>
        <source>expected a whole number or an R-parameter</source>
        <translation>Ожидается целое число или R-параметр</translation>
    </message>
    <message>
        <source>a sign before an R-parameter is not allowed: write 0-R&lt;j&gt; instead of -R&lt;j&gt;</source>
        <translation>Знак перед R-параметром недопустим: вместо -R&lt;j&gt; напишите 0-R&lt;j&gt;</translation>
    </message>
    <message>
        <source>decimal point in a computational frame: R-parameters are whole numbers (discretes), '%1' is not allowed</source>
        <translation>Десятичная точка в вычислительном кадре: R-параметры — целые числа (дискреты), «%1» недопустимо</translation>
    </message>
    <message>
        <source>'%1' is not a number</source>
        <translation>«%1» — не число</translation>
    </message>
    <message>
        <source>number %1 is outside the range of an R-parameter (-2147483648..2147483647)</source>
        <translation>Число %1 вне диапазона R-параметра (-2147483648..2147483647)</translation>
    </message>
    <message>
        <source>unexpected text in a computational frame: '%1'</source>
        <translation>Лишний текст в вычислительном кадре: «%1»</translation>
    </message>
    <message>
        <source>unexpected text in a conditional jump frame: '%1'</source>
        <translation>Лишний текст в кадре условного перехода: «%1»</translation>
    </message>
    <message>
        <source>unexpected text in an unconditional jump frame: '%1'</source>
        <translation>Лишний текст в кадре безусловного перехода: «%1»</translation>
    </message>
    <message>
        <source>computational frame: '=' expected after R%1</source>
        <translation>Вычислительный кадр: после R%1 ожидается «=»</translation>
    </message>
    <message>
        <source>computational frame: expected an operation + - * / or the end of the frame, not '%1'</source>
        <translation>Вычислительный кадр: ожидается знак операции + - * / или конец кадра, а не «%1»</translation>
    </message>
    <message>
        <source>the jump target is written without N: GOTO %1</source>
        <translation>Номер кадра перехода пишется без N: GOTO %1</translation>
    </message>
    <message>
        <source>the jump target is written without N: GOTO &lt;frame number 1..999&gt;</source>
        <translation>Номер кадра перехода пишется без N: GOTO &lt;номер кадра 1..999&gt;</translation>
    </message>
    <message>
        <source>GOTO is not followed by a frame number</source>
        <translation>После GOTO нет номера кадра</translation>
    </message>
    <message>
        <source>jump target '%1' is not a whole number 1..999</source>
        <translation>Номер кадра перехода «%1» — не целое число 1..999</translation>
    </message>
    <message>
        <source>IF must be followed by an R-parameter: IF R&lt;i&gt;&gt;0 GOTO &lt;number&gt;</source>
        <translation>После IF ожидается R-параметр: IF R&lt;i&gt;&gt;0 GOTO &lt;номер&gt;</translation>
    </message>
    <message>
        <source>the only jump condition is %1&gt;0 (manual 2.7.1.3); reduce another condition to it with a computational frame</source>
        <translation>Условие перехода может быть только %1&gt;0 (руководство, 2.7.1.3); другое условие сведите к нему вычислительным кадром</translation>
    </message>
    <message>
        <source>the condition must be followed by GOTO &lt;frame number&gt;</source>
        <translation>После условия ожидается GOTO &lt;номер кадра&gt;</translation>
    </message>
    <message>
        <source>program L%1 has no frames</source>
        <translation>Программа L%1 не содержит кадров</translation>
    </message>
    <message>
        <source>program L%1 has %2 frames: at most 999 are allowed; this is frame 1000</source>
        <translation>В программе L%1 %2 кадров: допускается не более 999; этот кадр — 1000-й</translation>
    </message>
    <message>
        <source>frame number N%1 is outside 1..999</source>
        <translation>Номер кадра N%1 вне диапазона 1..999</translation>
    </message>
    <message>
        <source>duplicate frame numbers: N%1 is already used on line %2</source>
        <translation>Дублирование номеров кадров: N%1 уже есть в строке %2</translation>
    </message>
    <message>
        <source>R-parameter R%1 does not exist: numbers are 0..299</source>
        <translation>R-параметр R%1 не существует: номера 0..299</translation>
    </message>
    <message>
        <source>G?: %1 is outside 0..299</source>
        <translation>G?: номер %1 вне диапазона 0..299</translation>
    </message>
    <message>
        <source>G?: %1 is not a G function of table 5</source>
        <translation>G?: функции %1 нет в таблице 5</translation>
    </message>
    <message>
        <source>G?: %1 and %2 are both of group %3: a frame may hold one function of a group</source>
        <translation>G?: %1 и %2 из одной группы %3: в кадре допустима одна функция группы</translation>
    </message>
    <message>
        <source>X value: the dwell time G04 X%1 is negative</source>
        <translation>Задание координаты X: выдержка времени G04 X%1 отрицательна</translation>
    </message>
    <message>
        <source>X value: the dwell X%1 s is longer than 9999.999 s</source>
        <translation>Задание координаты X: выдержка X%1 с больше 9999.999 с</translation>
    </message>
    <message>
        <source>%1 value: %1%2 is outside ±9999.999 mm</source>
        <translation>Задание координаты %1: %1%2 вне диапазона ±9999.999 мм</translation>
    </message>
    <message>
        <source>feed %1%2 is outside 0.001..10000 mm/min</source>
        <translation>Подача %1%2 вне диапазона 0.001..10000 мм/мин</translation>
    </message>
    <message>
        <source>G04/X/Z: Z is given %2 with the dwell G04; the time goes in X only</source>
        <translation>G04/X/Z: %2 с выдержкой времени G04 задан Z; время задаётся только в X</translation>
    </message>
    <message>
        <source>G04/L: subprogram %1 is called %2 with the dwell G04</source>
        <translation>G04/L: %2 с выдержкой времени G04 вызывается подпрограмма %1</translation>
    </message>
    <message>
        <source>X/L: X is given %2 that calls subprogram %1</source>
        <translation>X/L: %2 с вызовом подпрограммы %1 задана координата X</translation>
    </message>
    <message>
        <source>Z/L: Z is given %2 that calls subprogram %1</source>
        <translation>Z/L: %2 с вызовом подпрограммы %1 задана координата Z</translation>
    </message>
    <message>
        <source>X/M17: X is given %2 that ends the subprogram with M17</source>
        <translation>X/M17: %2 с концом подпрограммы M17 задана координата X</translation>
    </message>
    <message>
        <source>Z/M17: Z is given %2 that ends the subprogram with M17</source>
        <translation>Z/M17: %2 с концом подпрограммы M17 задана координата Z</translation>
    </message>
    <message>
        <source>M30/L: end of program M30 and a call of %1 %2</source>
        <translation>M30/L: конец программы M30 и вызов %1 %2</translation>
    </message>
    <message>
        <source>M2/L: end of program M02 and a call of %1 %2</source>
        <translation>M2/L: конец программы M02 и вызов %1 %2</translation>
    </message>
    <message>
        <source>M17/L: end of subprogram M17 and a call of %1 %2</source>
        <translation>M17/L: конец подпрограммы M17 и вызов %1 %2</translation>
    </message>
    <message>
        <source>M30/M17: end of program M30 and end of subprogram M17 %2</source>
        <translation>M30/M17: конец программы M30 и конец подпрограммы M17 %2</translation>
    </message>
    <message>
        <source>M2/M17: end of program M02 and end of subprogram M17 %2</source>
        <translation>M2/M17: конец программы M02 и конец подпрограммы M17 %2</translation>
    </message>
    <message>
        <source>X/end of L: the last frame of subprogram %1 has no M17 and gives X</source>
        <translation>X/конец L: последний кадр подпрограммы %1 без M17 задаёт координату X</translation>
    </message>
    <message>
        <source>Z/end of L: the last frame of subprogram %1 has no M17 and gives Z</source>
        <translation>Z/конец L: последний кадр подпрограммы %1 без M17 задаёт координату Z</translation>
    </message>
    <message>
        <source>in the frame</source>
        <translation>в кадре</translation>
    </message>
    <message>
        <source>in frame N%1</source>
        <translation>в кадре N%1</translation>
    </message>
    <message>
        <source>G04 without X: no dwell time is given (e.g. G04 X20.5 is 20.5 s)</source>
        <translation>G04 без X: время выдержки не задано (например, G04 X20.5 — 20,5 с)</translation>
    </message>
    <message>
        <source>%1 without %2: no position to set is given (e.g. %1 %212.324)</source>
        <translation>%1 без %2: не задано, какое положение установить (например, %1 %212.324)</translation>
    </message>
    <message>
        <source>%1 without %2: no oscillation stroke is given (e.g. %1 %2=-30.5 F%2=100)</source>
        <translation>%1 без %2: не задан ход осцилляции (например, %1 %2=-30.5 F%2=100)</translation>
    </message>
    <message>
        <source>%1 without %2: there is no motion of axis %2 for signal %3 to interrupt</source>
        <translation>%1 без %2: нет перемещения по оси %2, которое прерывает сигнал %3</translation>
    </message>
    <message>
        <source>M%1: M function number outside 0..99</source>
        <translation>M%1: номер M-функции вне диапазона 0..99</translation>
    </message>
    <message>
        <source>M%1 twice in the frame: the PLC gets it twice</source>
        <translation>M%1 дважды в кадре: ПЛК получит её два раза</translation>
    </message>
    <message>
        <source>#%1: technological message number outside 1..99</source>
        <translation>#%1: номер технологического сообщения вне диапазона 1..99</translation>
    </message>
    <message>
        <source>message #%1 is not in the message table: LCD line 2 will be blank</source>
        <translation>Сообщения #%1 нет в таблице сообщений: строка 2 индикатора будет пустой</translation>
    </message>
    <message>
        <source>L%1: called program number outside 1..99</source>
        <translation>L%1: номер вызываемой программы вне диапазона 1..99</translation>
    </message>
    <message>
        <source>L missing: there is no program L%1</source>
        <translation>L отсутствует: программы L%1 нет</translation>
    </message>
    <message>
        <source>R%1 is read only (R232..R262, appendix Л): it cannot be written</source>
        <translation>R%1 только для чтения (R232..R262, приложение Л): запись в него невозможна</translation>
    </message>
    <message>
        <source>overflow: division by zero</source>
        <translation>Переполнение: деление на ноль</translation>
    </message>
    <message>
        <source>overflow: the result %1 is outside -2147483648..2147483647</source>
        <translation>Переполнение: результат %1 вне диапазона -2147483648..2147483647</translation>
    </message>
    <message>
        <source>jump error: frame number %1 is outside 1..999</source>
        <translation>Ошибка перехода: номер кадра %1 вне диапазона 1..999</translation>
    </message>
    <message>
        <source>jump error: there is no frame N%1 in program L%2</source>
        <translation>Ошибка перехода: кадра N%1 нет в программе L%2</translation>
    </message>
    <message>
        <source>the frame on line %1 is never executed: an unconditional jump or an end of program precedes, and no jump leads here</source>
        <translation>Кадр в строке %1 никогда не выполняется: выше — безусловный переход или конец программы, а перехода сюда нет</translation>
    </message>
    <message>
        <source>the frames on lines %1-%2 are never executed: an unconditional jump or an end of program precedes, and no jump leads here</source>
        <translation>Кадры в строках %1–%2 никогда не выполняются: выше — безусловный переход или конец программы, а перехода сюда нет</translation>
    </message>
    <message>
        <source>subprogram nesting: calls go round in a circle %2; unless a condition breaks it, nesting exceeds the limit of %1</source>
        <translation>Глубина вложения L: вызовы по кругу %2; если цикл не прерывается условием, вложение превысит предел %1</translation>
    </message>
    <message>
        <source>subprogram nesting: the call chain %3 nests %1 levels deep, the limit is %2</source>
        <translation>Глубина вложения L: цепочка вызовов %3 даёт %1 уровней вложения, предел %2</translation>
    </message>
    <message>
        <source>L%1-&gt;%2</source>
        <translation>L%1→%2</translation>
    </message>
    <message>
        <source>L%1</source>
        <translation>L%1</translation>
    </message>
    <message>
        <source>%1: this machine has no %2 axis (C-parameter НАЛИЧ.ОСИ = 0)</source>
        <translation>%1: оси %2 на этом станке нет (НАЛИЧ.ОСИ = 0)</translation>
    </message>
    <message>
        <source>software limit (%2): %2%3%5%6 is beyond the + limit %4 mm</source>
        <translation>%1: %2%3%5%6 за ограничением +ОГРАНИЧЕН %4 мм</translation>
    </message>
    <message>
        <source>software limit (%2): %2%3%5%6 is beyond the - limit %4 mm</source>
        <translation>%1: %2%3%5%6 за ограничением -ОГРАНИЧЕН %4 мм</translation>
    </message>
    <message>
        <source> (diameter)</source>
        <translation> (на диаметр)</translation>
    </message>
    <message>
        <source>, %1 mm in the machine system,</source>
        <translation>, в системе станка %1 мм,</translation>
    </message>
    <message>
        <source>%1%2: the discrete of axis %1 is %3 mm, the value is rounded to %4</source>
        <translation>%1%2: дискрета оси %1 %3 мм, значение будет округлено до %4</translation>
    </message>
    <message>
        <source>F%1%2: the discrete of axis %1 is %3 mm, the feed is rounded to %4</source>
        <translation>F%1%2: дискрета оси %1 %3 мм, подача будет округлена до %4</translation>
    </message>
    <message>
        <source>F%1%2 is above the axis' maximum program feed F УСК.АВТ. (%3 mm/min)</source>
        <translation>F%1%2 больше F УСК.АВТ. оси %1 (%3 мм/мин)</translation>
    </message>
    <message>
        <source>message #%1 is longer than 20 characters (%2): the display shows 20</source>
        <translation>Сообщение #%1 длиннее 20 символов (%2): на индикаторе помещается 20</translation>
    </message>
    <message>
        <source>control character in the text of message #%1</source>
        <translation>Управляющий символ в тексте сообщения #%1</translation>
    </message>
    <message>
        <source>character '%1' in message #%2 may not show on the K923 (Latin, Cyrillic, digits and ASCII signs)</source>
        <translation>Символ «%1» в сообщении #%2 может не отображаться на K923 (латиница, кириллица, цифры и знаки ASCII)</translation>
    </message>
    <message>
        <source>the file holds no program (not a single frame)</source>
        <translation>В файле нет ни одной программы (ни одного кадра)</translation>
    </message>
    <message>
        <source>a jump target is a frame number 1..999, not %1</source>
        <translation>Номер кадра перехода 1..999, а не %1</translation>
    </message>
    <message>
        <source>at most 3 G and 3 M functions in a frame</source>
        <translation>не больше 3 функций G и 3 функций M в кадре</translation>
    </message>
    <message>
        <source>the signal number is 1..4</source>
        <translation>номер сигнала 1..4</translation>
    </message>
    <message>
        <source>%1:%2: %3: %4</source>
        <translation>%1:%2: %3: %4</translation>
    </message>
    <message>
        <source>error</source>
        <translation>ошибка</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>предупреждение</translation>
    </message>
</context>
<context>
    <name>k528::studio::DiffDialog</name>
    <message>
        <source>Compare revisions — %1</source>
        <translation>Сравнение ревизий — %1</translation>
    </message>
    <message>
        <source>the controller now</source>
        <translation>контроллер сейчас</translation>
    </message>
    <message>
        <source>Compare</source>
        <translation>Сравнить</translation>
    </message>
    <message>
        <source>Revision</source>
        <translation>Ревизия</translation>
    </message>
    <message>
        <source>The revisions cannot be compared: %1</source>
        <translation>Ревизии не сравнить: %1</translation>
    </message>
    <message>
        <source>(no difference)</source>
        <translation>(различий нет)</translation>
    </message>
</context>
<context>
    <name>k528::studio::EditorMenu</name>
    <message>
        <source>&amp;Editor</source>
        <translation>&amp;Редактор</translation>
    </message>
    <message>
        <source>Refactor</source>
        <translation>Преобразовать</translation>
    </message>
    <message>
        <source>Renumber frames…</source>
        <translation>Перенумеровать кадры…</translation>
    </message>
    <message>
        <source>Move or copy a program…</source>
        <translation>Перенести или копировать программу…</translation>
    </message>
    <message>
        <source>Format the file</source>
        <translation>Форматировать файл</translation>
    </message>
    <message>
        <source>Listing</source>
        <translation>Листинг</translation>
    </message>
    <message>
        <source>Print…</source>
        <translation>Печать…</translation>
    </message>
    <message>
        <source>Export PDF…</source>
        <translation>Экспорт в PDF…</translation>
    </message>
    <message>
        <source>Setup sheet</source>
        <translation>Карта наладки</translation>
    </message>
    <message>
        <source>Print preview…</source>
        <translation>Предварительный просмотр…</translation>
    </message>
    <message>
        <source>The setup sheet of this file on its machine: the blank, the tools with their offsets, the programs with their cycle times, the R-parameters to preset</source>
        <translation>Карта наладки этого файла на его станке: заготовка, инструмент с коррекциями, программы со временем цикла, предустановки R-параметров</translation>
    </message>
    <message>
        <source>Teach-in</source>
        <translation>Обучение</translation>
    </message>
    <message>
        <source>Insert the controller's position as a frame</source>
        <translation>Вставить положение УЧПУ кадром</translation>
    </message>
    <message>
        <source>The position the viewed controller's axes are at (current coordinates, as its panel shows them) as a frame after the cursor's line</source>
        <translation>Положение осей показываемого УЧПУ (текущие координаты, как на его пульте) кадром после строки курсора</translation>
    </message>
    <message>
        <source>Position into an R-parameter</source>
        <translation>Положение в R-параметр</translation>
    </message>
    <message>
        <source>Machine of this file</source>
        <translation>Станок этого файла</translation>
    </message>
    <message>
        <source>Machine: %1</source>
        <translation>Станок: %1</translation>
    </message>
    <message>
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message>
        <source>The machine this file is checked for: its limits, feeds and axes</source>
        <translation>Станок, для которого проверяется файл: его пределы, подачи и оси</translation>
    </message>
    <message>
        <source>Open from the database…</source>
        <translation>Открыть из базы…</translation>
    </message>
    <message>
        <source>The programs and messages of a machine of the database; saving writes its next revision</source>
        <translation>Программы и сообщения станка из базы; сохранение записывает его следующую ревизию</translation>
    </message>
    <message>
        <source>No file is open</source>
        <translation>Нет открытого файла</translation>
    </message>
    <message>
        <source>The workstation's machine (%1)</source>
        <translation>Станок рабочего места (%1)</translation>
    </message>
    <message>
        <source>The workstation's machine (none)</source>
        <translation>Станок рабочего места (нет)</translation>
    </message>
    <message>
        <source>None: the language only</source>
        <translation>Нет: только язык</translation>
    </message>
</context>
<context>
    <name>k528::studio::EditorTab</name>
    <message>
        <source>Unsaved changes</source>
        <translation>Несохранённые изменения</translation>
    </message>
    <message>
        <source>%1 has unsaved changes. Save them?</source>
        <translation>В %1 есть несохранённые изменения. Сохранить их?</translation>
    </message>
    <message>
        <source>Open program</source>
        <translation>Открыть программу</translation>
    </message>
    <message>
        <source>K528 programs (*.k528 *.txt);;All files (*)</source>
        <translation>Программы K528 (*.k528 *.txt);;Все файлы (*)</translation>
    </message>
    <message>
        <source>%1 cannot be written: %2</source>
        <translation>%1 не записывается: %2</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Сохранён %1</translation>
    </message>
    <message>
        <source>Save program as</source>
        <translation>Сохранить программу как</translation>
    </message>
    <message>
        <source>File changed on disk</source>
        <translation>Файл изменён на диске</translation>
    </message>
    <message>
        <source>%1 was changed on disk. Reload it and lose your changes?</source>
        <translation>%1 изменён на диске. Перечитать его, потеряв ваши изменения?</translation>
    </message>
    <message>
        <source>Reloaded %1</source>
        <translation>Перечитан %1</translation>
    </message>
    <message>
        <source>Sent %1 to the controller</source>
        <translation>%1 переданы в УЧПУ</translation>
    </message>
    <message>
        <source>error</source>
        <translation>ошибка</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>предупреждение</translation>
    </message>
    <message>
        <source>Errors: %1, warnings: %2</source>
        <translation>Ошибок: %1, предупреждений: %2</translation>
    </message>
    <message>
        <source>untitled %1</source>
        <translation>без имени %1</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Новый</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Открыть…</translation>
    </message>
    <message>
        <source>Recent</source>
        <translation>Недавние</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Сохранить</translation>
    </message>
    <message>
        <source>Save as…</source>
        <translation>Сохранить как…</translation>
    </message>
    <message>
        <source>Check for the machine</source>
        <translation>Проверять для станка</translation>
    </message>
    <message>
        <source>Also check the machine's software limits, feeds and axes</source>
        <translation>Проверять также программные ограничения, подачи и оси станка</translation>
    </message>
    <message>
        <source>Send to the controller</source>
        <translation>Передать в УЧПУ</translation>
    </message>
    <message>
        <source>Master…</source>
        <translation>Мастер…</translation>
    </message>
    <message>
        <source>Build or edit the frame at the cursor</source>
        <translation>Построить или изменить кадр под курсором</translation>
    </message>
    <message>
        <source>Programs</source>
        <translation>Программы</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>Важность</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Программа</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Строка</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Сообщение</translation>
    </message>
    <message>
        <source>The machine %1 cannot be loaded: %2</source>
        <translation>Станок %1 не загружается: %2</translation>
    </message>
    <message>
        <source>%1 (database, revision %2)</source>
        <translation>%1 (база, ревизия %2)</translation>
    </message>
    <message>
        <source>Opened the programs of %1, revision %2</source>
        <translation>Открыты программы %1, ревизия %2</translation>
    </message>
    <message>
        <source>The database has no machines</source>
        <translation>В базе нет станков</translation>
    </message>
    <message>
        <source>Open from the database</source>
        <translation>Открыть из базы</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Станок</translation>
    </message>
    <message>
        <source>%1 saved as revision %2</source>
        <translation>%1 сохранён как ревизия %2</translation>
    </message>
    <message>
        <source>%1: the database already holds these programs (revision %2)</source>
        <translation>%1: в базе уже эти программы (ревизия %2)</translation>
    </message>
    <message>
        <source>%1 is the database this window uses: it is not opened as a program</source>
        <translation>%1 — база данных, с которой работает это окно: как программа она не открывается</translation>
    </message>
    <message>
        <source>%1 is the database this window uses: a program is not written over it</source>
        <translation>%1 — база данных, с которой работает это окно: программа поверх неё не записывается</translation>
    </message>
    <message>
        <source>OK replaces line %1: %2</source>
        <translation>ОК заменит строку %1: %2</translation>
    </message>
    <message>
        <source>OK replaces line %1: %2
Its comment stays: %3</source>
        <translation>ОК заменит строку %1: %2
Её комментарий останется: %3</translation>
    </message>
    <message>
        <source>OK inserts a new line after line %1.</source>
        <translation>ОК вставит новую строку после строки %1.</translation>
    </message>
    <message>
        <source>Line %1 replaced by the master</source>
        <translation>Строка %1 заменена мастером</translation>
    </message>
    <message>
        <source>Line %1 replaced by the master; its comment kept</source>
        <translation>Строка %1 заменена мастером; её комментарий сохранён</translation>
    </message>
    <message>
        <source>There is no sample program %1</source>
        <translation>Нет примера программы %1</translation>
    </message>
    <message>
        <source>%1 (sample)</source>
        <translation>%1 (пример)</translation>
    </message>
    <message>
        <source>The controller is busy with a transfer: send again when it has ended</source>
        <translation>Контроллер занят передачей: отправьте снова, когда она закончится</translation>
    </message>
    <message>
        <source>Reading the controller's memory to show what %1 changes...</source>
        <translation>Считывание памяти контроллера, чтобы показать, что изменит %1...</translation>
    </message>
    <message>
        <source>%1 was not sent: the controller's memory could not be read (%2)</source>
        <translation>%1 не отправлен: память контроллера не считана (%2)</translation>
    </message>
    <message>
        <source>Send %1</source>
        <translation>Отправка %1</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Отправить</translation>
    </message>
    <message>
        <source>%1 not sent; nothing changed</source>
        <translation>%1 не отправлен; ничего не изменилось</translation>
    </message>
    <message>
        <source>Sending %1 to the controller...</source>
        <translation>Отправка %1 в контроллер...</translation>
    </message>
    <message>
        <source>Sent %1 to the controller, with warnings: %2</source>
        <translation>%1 отправлен в контроллер, с предупреждениями: %2</translation>
    </message>
    <message>
        <source>%1 was not sent: %2</source>
        <translation>%1 не отправлен: %2</translation>
    </message>
    <message>
        <source>The controller is busy with a transfer: open again when it has ended</source>
        <translation>Контроллер занят передачей: откройте снова, когда она закончится</translation>
    </message>
    <message>
        <source>Reading the programs of the controller...</source>
        <translation>Чтение программ контроллера...</translation>
    </message>
    <message>
        <source>The programs of the controller could not be read: %1</source>
        <translation>Программы контроллера не считаны: %1</translation>
    </message>
    <message>
        <source>Opened the %1 programs of the controller (%2)</source>
        <translation>Открыты программы контроллера (%2): %1</translation>
    </message>
    <message>
        <source>The file's programs and messages into the controller shown, after a preview of what changes</source>
        <translation>Программы и сообщения файла — в показываемый контроллер, после просмотра изменений</translation>
    </message>
    <message>
        <source>Open from the controller</source>
        <translation>Открыть из контроллера</translation>
    </message>
    <message>
        <source>The programs and messages of the controller shown as a new file</source>
        <translation>Программы и сообщения показываемого контроллера — новым файлом</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>Код</translation>
    </message>
</context>
<context>
    <name>k528::studio::FrameMaster</name>
    <message>
        <source>Frame master</source>
        <translation>Мастер кадра</translation>
    </message>
    <message>
        <source>ISO motion frame</source>
        <translation>Кадр ISO (перемещение)</translation>
    </message>
    <message>
        <source>Dwell (G4)</source>
        <translation>Выдержка (G4)</translation>
    </message>
    <message>
        <source>Subprogram call (L)</source>
        <translation>Вызов подпрограммы (L)</translation>
    </message>
    <message>
        <source>Oscillation start/stop</source>
        <translation>Пуск/останов качания</translation>
    </message>
    <message>
        <source>Move until signal</source>
        <translation>Перемещение до сигнала</translation>
    </message>
    <message>
        <source>Computational frame</source>
        <translation>Вычислительный кадр</translation>
    </message>
    <message>
        <source>Conditional jump (IF … GOTO)</source>
        <translation>Условный переход (IF … GOTO)</translation>
    </message>
    <message>
        <source>Unconditional jump (GOTO)</source>
        <translation>Безусловный переход (GOTO)</translation>
    </message>
    <message>
        <source>Technological message</source>
        <translation>Технологическое сообщение</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Вид</translation>
    </message>
    <message>
        <source>Skip flag «/» (the frame is not executed)</source>
        <translation>Пропуск «/» (кадр не обрабатывается)</translation>
    </message>
    <message>
        <source>1..999, empty = none</source>
        <translation>1..999, пусто = нет</translation>
    </message>
    <message>
        <source>Frame number N</source>
        <translation>Номер кадра N</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Ось</translation>
    </message>
    <message>
        <source>Operation</source>
        <translation>Действие</translation>
    </message>
    <message>
        <source>G-functions (up to 3)</source>
        <translation>Функции G (до 3)</translation>
    </message>
    <message>
        <source>M-functions (up to 3)</source>
        <translation>Функции M (до 3)</translation>
    </message>
    <message>
        <source>Message #</source>
        <translation>Сообщение #</translation>
    </message>
    <message>
        <source>Call program L</source>
        <translation>Вызов программы L</translation>
    </message>
    <message>
        <source>X, mm (or R…)</source>
        <translation>X, мм (или R…)</translation>
    </message>
    <message>
        <source>FX, mm/min (or R…)</source>
        <translation>FX, мм/мин (или R…)</translation>
    </message>
    <message>
        <source>Z, mm (or R…)</source>
        <translation>Z, мм (или R…)</translation>
    </message>
    <message>
        <source>FZ, mm/min (or R…)</source>
        <translation>FZ, мм/мин (или R…)</translation>
    </message>
    <message>
        <source>Dwell, s</source>
        <translation>Выдержка, с</translation>
    </message>
    <message>
        <source>Program 1..99</source>
        <translation>Программа 1..99</translation>
    </message>
    <message>
        <source>Start (1) / stop (0)</source>
        <translation>Пуск (1) / останов (0)</translation>
    </message>
    <message>
        <source>Stroke, mm</source>
        <translation>Ход, мм</translation>
    </message>
    <message>
        <source>Speed, mm/min</source>
        <translation>Скорость, мм/мин</translation>
    </message>
    <message>
        <source>Axis (X or Z)</source>
        <translation>Ось (X или Z)</translation>
    </message>
    <message>
        <source>Signal 1..4</source>
        <translation>Сигнал 1..4</translation>
    </message>
    <message>
        <source>Target, mm</source>
        <translation>Цель, мм</translation>
    </message>
    <message>
        <source>Feed, mm/min</source>
        <translation>Подача, мм/мин</translation>
    </message>
    <message>
        <source>Result R</source>
        <translation>Результат R</translation>
    </message>
    <message>
        <source>Condition R (&gt; 0)</source>
        <translation>Условие R (&gt; 0)</translation>
    </message>
    <message>
        <source>Jump to frame N</source>
        <translation>Переход на кадр N</translation>
    </message>
    <message>
        <source>Message number 1..99</source>
        <translation>Номер сообщения 1..99</translation>
    </message>
    <message>
        <source>Text (20 characters)</source>
        <translation>Текст (20 символов)</translation>
    </message>
    <message>
        <source>%1: «%2» is not a number or R-parameter</source>
        <translation>%1: «%2» — не число и не R-параметр</translation>
    </message>
    <message>
        <source>%1: «%2» is not a whole number</source>
        <translation>%1: «%2» — не целое число</translation>
    </message>
    <message>
        <source>N: «%1» is not a whole number</source>
        <translation>N: «%1» — не целое число</translation>
    </message>
    <message>
        <source>G: a list of numbers, e.g. «1 90»</source>
        <translation>G: список номеров, например «1 90»</translation>
    </message>
    <message>
        <source>M: a list of numbers, e.g. «3 8»</source>
        <translation>M: список номеров, например «3 8»</translation>
    </message>
    <message>
        <source>R: the number of the R-parameter tested</source>
        <translation>R: номер проверяемого R-параметра</translation>
    </message>
    <message>
        <source>Operand 1 (number or R…)</source>
        <translation>Операнд 1 (число или R…)</translation>
    </message>
    <message>
        <source>Operand 2 (number or R…)</source>
        <translation>Операнд 2 (число или R…)</translation>
    </message>
    <message>
        <source>Operand 1: a whole number or R…</source>
        <translation>Операнд 1: целое число или R…</translation>
    </message>
    <message>
        <source>Operand 2: a whole number or R…</source>
        <translation>Операнд 2: целое число или R…</translation>
    </message>
    <message>
        <source>Result: the number of the R-parameter written</source>
        <translation>Результат: номер записываемого R-параметра</translation>
    </message>
</context>
<context>
    <name>k528::studio::HistoryDialog</name>
    <message>
        <source>History of %1 %2 — %3</source>
        <translation>История %1 %2 — %3</translation>
    </message>
    <message>
        <source>Revision</source>
        <translation>Ревизия</translation>
    </message>
    <message>
        <source>When</source>
        <translation>Когда</translation>
    </message>
    <message>
        <source>Who</source>
        <translation>Кто</translation>
    </message>
    <message>
        <source>Before</source>
        <translation>Было</translation>
    </message>
    <message>
        <source>After</source>
        <translation>Стало</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Примечание</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(нет)</translation>
    </message>
    <message>
        <source>No revision of %1 changed this constant.</source>
        <translation>Ни одна ревизия %1 не меняла этот параметр.</translation>
    </message>
    <message>
        <source>Revisions that changed this constant: %1 (newest first).</source>
        <translation>Ревизий, менявших параметр: %1 (новые сверху).</translation>
    </message>
    <message>
        <source>The history cannot be read: %1</source>
        <translation>История не читается: %1</translation>
    </message>
</context>
<context>
    <name>k528::studio::HistoryModel</name>
    <message>
        <source>Positioner</source>
        <translation>БП</translation>
    </message>
    <message>
        <source>PLC alarm</source>
        <translation>ПЛК, авария</translation>
    </message>
    <message>
        <source>PLC system</source>
        <translation>ПЛК, системное</translation>
    </message>
    <message>
        <source>PLC work</source>
        <translation>ПЛК, рабочее</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Программа</translation>
    </message>
    <message>
        <source>ESC</source>
        <translation>ESC</translation>
    </message>
    <message>
        <source>ESC from the history dock</source>
        <translation>ESC из журнала сообщений</translation>
    </message>
    <message>
        <source>acknowledge signal Z1000.7</source>
        <translation>сигнал квитирования Z1000.7</translation>
    </message>
    <message>
        <source>reset Z1000.5</source>
        <translation>сброс Z1000.5</translation>
    </message>
    <message>
        <source>L%1, line %2</source>
        <translation>L%1, строка %2</translation>
    </message>
    <message>
        <source>L%1</source>
        <translation>L%1</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>not yet</source>
        <translation>ещё нет</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Время</translation>
    </message>
    <message>
        <source>Machine time</source>
        <translation>Время станка</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Источник</translation>
    </message>
    <message>
        <source>No.</source>
        <translation>№</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Сообщение</translation>
    </message>
    <message>
        <source>Cause gone</source>
        <translation>Причина устранена</translation>
    </message>
    <message>
        <source>Acknowledged</source>
        <translation>Квитировано</translation>
    </message>
</context>
<context>
    <name>k528::studio::HistoryView</name>
    <message>
        <source>Export the message history</source>
        <translation>Экспорт журнала сообщений</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>The messages could not be written (they are kept and written later): %1</source>
        <translation>Сообщения не удалось записать (они сохранены и будут записаны позже): %1</translation>
    </message>
    <message>
        <source>No message history: %1</source>
        <translation>Журнал сообщений недоступен: %1</translation>
    </message>
    <message>
        <source>%1 messages (%2 loaded); %3 waiting for acknowledgement. Database: %4</source>
        <translation>Сообщений: %1 (загружено %2); ждут квитирования: %3. База данных: %4</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Не удаётся записать %1: %2</translation>
    </message>
    <message>
        <source>The export was cancelled; %1 was left as it was.</source>
        <translation>Экспорт отменён; файл %1 не изменён.</translation>
    </message>
    <message>
        <source>Exporting the message history…</source>
        <translation>Экспорт журнала сообщений…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <source>%1 messages exported to %2</source>
        <translation>Сообщений экспортировано: %1, файл %2</translation>
    </message>
    <message>
        <source>Search</source>
        <translation>Поиск</translation>
    </message>
    <message>
        <source>text or number, e.g. 37 or A03</source>
        <translation>текст или номер, например 37 или A03</translation>
    </message>
    <message>
        <source>All sources</source>
        <translation>Все источники</translation>
    </message>
    <message>
        <source>Not acknowledged</source>
        <translation>Не квитированные</translation>
    </message>
    <message>
        <source>All machines</source>
        <translation>Все станки</translation>
    </message>
    <message>
        <source>Acknowledge (ESC)</source>
        <translation>Квитировать (ESC)</translation>
    </message>
    <message>
        <source>Acknowledges the current messages as ESC on the K923 does (C123 reset, C124 faults, C125 system messages)</source>
        <translation>Квитирует текущие сообщения, как ESC на K923 (C123 — сброс, C124 — неисправности, C125 — системные сообщения)</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>Экспорт CSV…</translation>
    </message>
    <message>
        <source>Message history</source>
        <translation>Журнал сообщений</translation>
    </message>
    <message>
        <source>A real controller's messages are acknowledged on its own K923 (ESC): the link carries no keys</source>
        <translation>Сообщения реального контроллера сбрасываются на его собственном K923 (ESC): по линии клавиши не передаются</translation>
    </message>
    <message>
        <source>The messages of the controller on the line, recorded as they are read (every %1 ms) with this PC's time; they are acknowledged on its own K923.</source>
        <translation>Сообщения контроллера на линии, записываются по мере чтения (каждые %1 мс) со временем этой ПЭВМ; сбрасываются на его собственном K923.</translation>
    </message>
    <message>
        <source>Cannot export to %1: %2</source>
        <translation>Не удаётся выгрузить в %1: %2</translation>
    </message>
</context>
<context>
    <name>k528::studio::K923Keys</name>
    <message>
        <source>Mode AUTOMATIC: the machine works by the control program.</source>
        <translation>Режим АВТОМАТ: станок работает по управляющей программе.</translation>
    </message>
    <message>
        <source>Mode MANUAL: the machine's push-buttons and handwheels move the axes; R-parameters can be edited.</source>
        <translation>Режим РУЧНОЙ: оси перемещаются кнопками станочного пульта и маховиками; можно редактировать R-параметры.</translation>
    </message>
    <message>
        <source>Mode REFERENCE POINT: the homing cycle ties the axes to the machine.</source>
        <translation>Режим ПРИВЯЗКА К БАЗОВОЙ ТОЧКЕ: цикл привязки системы отсчёта станка к базовым точкам.</translation>
    </message>
    <message>
        <source>Mode PRESETS: technological parameters of the machine in groups.</source>
        <translation>Режим ПРЕДУСТАНОВКИ: технологические параметры станка по группам.</translation>
    </message>
    <message>
        <source>Mode MACHINE CONSTANTS: editing the C-parameters (password).</source>
        <translation>Режим РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ: станочные параметры (пароль).</translation>
    </message>
    <message>
        <source>Mode PROGRAM EDITING: editing the control programs (password).</source>
        <translation>Режим РЕДАКТИРОВАНИЕ УП: управляющие программы (пароль).</translation>
    </message>
    <message>
        <source>Mode DATA MANAGEMENT: clearing memory and working with the PC (password).</source>
        <translation>Режим УПРАВЛЕНИЕ ДАННЫМИ: очистка памяти и работа с инструментальной ПЭВМ (пароль).</translation>
    </message>
    <message>
        <source>Mode key F8: the K528-05 has no eighth mode.</source>
        <translation>Клавиша режима F8: восьмого режима у K528-05 нет.</translation>
    </message>
    <message>
        <source>The key opens the main screen of the mode.</source>
        <translation>Клавиша открывает основной экран режима.</translation>
    </message>
    <message>
        <source>Machine function key K%1. The PLC program of the machine gives it its function: pressing sets Z1300.%2. Its LED is green by Z1906.%2, red by Z1907.%2, amber by both.</source>
        <translation>Клавиша станка K%1. Её функцию задаёт рабочая программа ПЛК: нажатие устанавливает Z1300.%2. Светодиод зелёный по Z1906.%2, красный по Z1907.%2, жёлтый при обоих.</translation>
    </message>
    <message>
        <source>Feed override key L%1: selects the override whose code machine constant C%2 holds (codes 0–10 = 0…100 %). Its LED shows the override key in effect.</source>
        <translation>Клавиша корректора скорости L%1: включает корректор, код которого задан станочным параметром C%2 (коды 0–10 = 0…100 %). Светодиод показывает действующую клавишу корректора.</translation>
    </message>
    <message>
        <source>Digit %1.</source>
        <translation>Цифра %1.</translation>
    </message>
    <message>
        <source>Moves the marker up to the previous parameter or line.</source>
        <translation>Перемещает маркер вверх, к предыдущему параметру или строке.</translation>
    </message>
    <message>
        <source>Moves the marker down to the next parameter or line.</source>
        <translation>Перемещает маркер вниз, к следующему параметру или строке.</translation>
    </message>
    <message>
        <source>Moves the marker left; in the axis screens, to the other axis.</source>
        <translation>Перемещает маркер влево; в экранах осей — к другой оси.</translation>
    </message>
    <message>
        <source>Moves the marker right; in the axis screens, to the other axis.</source>
        <translation>Перемещает маркер вправо; в экранах осей — к другой оси.</translation>
    </message>
    <message>
        <source>Pages through the screens of the current mode.</source>
        <translation>Перелистывание экранов внутри текущего режима.</translation>
    </message>
    <message>
        <source>Enters the service screens (messages, faults, system, diagnostics) and returns from them.</source>
        <translation>Переход к сервисной индикации (сообщения, неисправности, система, диагностика) и возврат из неё.</translation>
    </message>
    <message>
        <source>As the machine constants set it: cancels editing a parameter, resets the system, acknowledges error and fault messages.</source>
        <translation>По станочным параметрам: отмена редакции параметра, сброс системы в исходное состояние, квитирование сообщений об ошибках и неисправностях.</translation>
    </message>
    <message>
        <source>Switches keys with two functions to their second one: press SHIFT, then the key. The LED shows SHIFT engaged; pressing SHIFT again releases it.</source>
        <translation>Переключение регистра клавиш с двойным назначением: нажмите SHIFT, затем клавишу. Светодиод показывает включённый SHIFT; повторное нажатие SHIFT его снимает.</translation>
    </message>
    <message>
        <source>Goes to choosing a parameter by its number, and back.</source>
        <translation>Переход к выбору параметра по номеру и возврат.</translation>
    </message>
    <message>
        <source>Enters the number of the program for automatic mode; in the program editor, inserts a computing or jump frame.</source>
        <translation>Ввод номера управляющей программы автоматического режима; при редактировании УП — вставка вычислительного кадра или кадра перехода.</translation>
    </message>
    <message>
        <source>Inserts a new standard frame after the current one (program editor).</source>
        <translation>Вставка нового стандартного кадра после текущего (редактирование УП).</translation>
    </message>
    <message>
        <source>Deletes a program, a frame or the value of a parameter.</source>
        <translation>Удаление управляющей программы, кадра или значения параметра.</translation>
    </message>
    <message>
        <source>Enters the typed value.</source>
        <translation>Ввод набранного значения параметра.</translation>
    </message>
    <message>
        <source>Decimal point.</source>
        <translation>Десятичная точка.</translation>
    </message>
    <message>
        <source>Addition.</source>
        <translation>Сложение.</translation>
    </message>
    <message>
        <source>Subtraction; the minus sign.</source>
        <translation>Вычитание; знак минус.</translation>
    </message>
    <message>
        <source>Multiplication.</source>
        <translation>Умножение.</translation>
    </message>
    <message>
        <source>Division.</source>
        <translation>Деление.</translation>
    </message>
    <message>
        <source>Assigns the result.</source>
        <translation>Присвоение результата.</translation>
    </message>
    <message>
        <source>Types the letter R (R-parameters).</source>
        <translation>Ввод символа R (R-параметры).</translation>
    </message>
    <message>
        <source>Sets or clears the skip mark «/» of a frame (program editor).</source>
        <translation>Установка и снятие признака пропуска кадра «/» (редактирование УП).</translation>
    </message>
    <message>
        <source>SHIFT+▲: three lines up; in the program editor, the previous frame.</source>
        <translation>SHIFT+▲: на три строки вверх; при редактировании УП — предыдущий кадр.</translation>
    </message>
    <message>
        <source>SHIFT+▼: three lines down; in the program editor, the next frame.</source>
        <translation>SHIFT+▼: на три строки вниз; при редактировании УП — следующий кадр.</translation>
    </message>
    <message>
        <source>%1 (latches like a click); or hold Shift with the other key</source>
        <translation>%1 (фиксирует SHIFT, как щелчок); или Shift вместе с другой клавишей</translation>
    </message>
    <message>
        <source>PC keyboard:</source>
        <translation>Клавиатура ПК:</translation>
    </message>
</context>
<context>
    <name>k528::studio::K923Widget</name>
    <message>
        <source>Keyboard map…</source>
        <translation>Таблица клавиш ПК…</translation>
    </message>
    <message>
        <source>Copy the LCD text</source>
        <translation>Копировать текст индикатора</translation>
    </message>
    <message>
        <source>LCD: yellow-green backlight</source>
        <translation>Индикатор: жёлто-зелёная подсветка</translation>
    </message>
    <message>
        <source>LCD: blue backlight</source>
        <translation>Индикатор: синяя подсветка</translation>
    </message>
    <message>
        <source>The K923 operator panel. Click it to work it from the PC keyboard too (each key's tooltip names its PC key; Tab leaves the panel). Right-click for the keyboard map.</source>
        <translation>Панель оператора K923. Щёлкните по ней, чтобы работать и с клавиатуры ПК (подсказка каждой клавиши называет клавишу ПК; Tab уводит с панели). Правая кнопка мыши — таблица клавиш.</translation>
    </message>
    <message>
        <source>K923 operator panel</source>
        <translation>Панель оператора K923</translation>
    </message>
</context>
<context>
    <name>k528::studio::KeyboardMapDialog</name>
    <message>
        <source>K923 keyboard map</source>
        <translation>Таблица клавиш ПК для панели K923</translation>
    </message>
    <message>
        <source>The PC keyboard works the panel while the panel has the focus: click the panel (a ring shows round it) or reach it with Tab; Tab leaves it again. Shift held with a PC key that is not a character gives SHIFT+key; S latches the panel's SHIFT for the next key, as a click on SHIFT does. Letters work in the Russian layout too.</source>
        <translation>Клавиатура ПК работает на панель, пока панель в фокусе: щёлкните по панели (вокруг появится рамка) или перейдите на неё клавишей Tab; Tab уводит с неё. Shift вместе с клавишей ПК, не вводящей символ, даёт SHIFT+клавиша; S фиксирует SHIFT панели для следующей клавиши, как щелчок по SHIFT. Буквы работают и в русской раскладке.</translation>
    </message>
    <message>
        <source>Panel key</source>
        <translation>Клавиша панели</translation>
    </message>
    <message>
        <source>PC keyboard</source>
        <translation>Клавиатура ПК</translation>
    </message>
    <message>
        <source>Function</source>
        <translation>Назначение</translation>
    </message>
</context>
<context>
    <name>k528::studio::LinkController</name>
    <message>
        <source>cancelled; nothing was kept</source>
        <translation>отменено; ничего не сохранено</translation>
    </message>
    <message>
        <source>C-parameters</source>
        <translation>C-параметры</translation>
    </message>
    <message>
        <source>messages</source>
        <translation>сообщения</translation>
    </message>
    <message>
        <source>cancelled; the program being sent was not committed</source>
        <translation>отменено; передававшаяся программа не записана</translation>
    </message>
    <message>
        <source>%1, address %2, %3 bit/s</source>
        <translation>%1, адрес %2, %3 бит/с</translation>
    </message>
    <message>
        <source>R-parameters</source>
        <translation>R-параметры</translation>
    </message>
    <message>
        <source>the controller is not connected</source>
        <translation>контроллер не подключён</translation>
    </message>
    <message>
        <source>cancelled; what was not committed is as it was</source>
        <translation>отменено; то, что не было записано, осталось как было</translation>
    </message>
    <message>
        <source>the link's map carries no LCD text, no keys, no DAC or servo-tick data</source>
        <translation>карта линии не содержит текста ЖКИ, клавиш, кодов ЦАП и данных каждого такта</translation>
    </message>
    <message>
        <source>a transfer is under way on the line</source>
        <translation>по линии идёт передача</translation>
    </message>
    <message>
        <source>R%1 is the positioner's own: the PC does not write it (it writes %2)</source>
        <translation>R%1 — собственный параметр позиционера: ПЭВМ его не записывает (она записывает %2)</translation>
    </message>
    <message>
        <source>R%1 is read only over the link: the PC writes %2</source>
        <translation>R%1 по линии только читается: ПЭВМ записывает %2</translation>
    </message>
    <message>
        <source>C%1 has no address in the positioner (table Е.1): it is not written</source>
        <translation>У C%1 нет адреса в позиционере (таблица Е.1): он не записывается</translation>
    </message>
    <message>
        <source>power-on</source>
        <translation>включение</translation>
    </message>
    <message>
        <source>the controller is in F7 УПРАВЛЕНИЕ ДАННЫМИ but not on «РАБОТА С ПЭВМ»: choose it in its menu on the K923</source>
        <translation>контроллер в F7 УПРАВЛЕНИЕ ДАННЫМИ, но не в «РАБОТА С ПЭВМ»: выберите этот пункт в его меню на K923</translation>
    </message>
    <message>
        <source>the controller is not in F7 «РАБОТА С ПЭВМ» (mode %1 now): press F7 (УПРАВЛЕНИЕ ДАННЫМИ) on its K923 and choose «РАБОТА С ПЭВМ»</source>
        <translation>контроллер не в F7 «РАБОТА С ПЭВМ» (сейчас режим %1): нажмите F7 (УПРАВЛЕНИЕ ДАННЫМИ) на его K923 и выберите «РАБОТА С ПЭВМ»</translation>
    </message>
    <message>
        <source>%1: the controller is not connected</source>
        <translation>%1: контроллер не подключён</translation>
    </message>
    <message>
        <source>clear C</source>
        <translation>очистка C</translation>
    </message>
    <message>
        <source>clear R</source>
        <translation>очистка R</translation>
    </message>
    <message>
        <source>On record: transfer %1 in %2</source>
        <translation>Передача записана в журнал: запись %1 в %2</translation>
    </message>
    <message>
        <source>The transfer is not on record: %1</source>
        <translation>Передача не записана в журнал: %1</translation>
    </message>
    <message>
        <source>program %1</source>
        <translation>программа %1</translation>
    </message>
    <message>
        <source>draft</source>
        <translation>черновик</translation>
    </message>
    <message>
        <source>withdrawn</source>
        <translation>отозвана</translation>
    </message>
    <message>
        <source>released</source>
        <translation>выпущена</translation>
    </message>
    <message>
        <source>L%1: %2, not the released version: its released version (revision %3) is sent</source>
        <translation>L%1: %2, не выпущенная версия: передаётся выпущенная версия (ревизия %3)</translation>
    </message>
    <message>
        <source>L%1: %2, never released: not sent</source>
        <translation>L%1: %2, ни разу не выпущена: не передаётся</translation>
    </message>
    <message>
        <source>L%1: not in the database: not sent</source>
        <translation>L%1: нет в базе данных: не передаётся</translation>
    </message>
    <message>
        <source>The push did not start: %1; nothing was sent</source>
        <translation>Передача не начата: %1; ничего не передано</translation>
    </message>
    <message>
        <source>%1, unit %2 (Modbus TCP)</source>
        <translation>%1, устройство %2 (Modbus TCP)</translation>
    </message>
</context>
<context>
    <name>k528::studio::LinkTexts</name>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1; %2</source>
        <translation>%1; %2</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>exception 01: the controller does not know this function</source>
        <translation>исключение 01: контроллер не знает этой функции</translation>
    </message>
    <message>
        <source>exception 02: a register outside the controller's map (or a read-only one written)</source>
        <translation>исключение 02: регистр вне карты контроллера (или запись в регистр только для чтения)</translation>
    </message>
    <message>
        <source>exception 03: a value outside its range; nothing of the request was written</source>
        <translation>исключение 03: значение вне своего диапазона; ничего из запроса не записано</translation>
    </message>
    <message>
        <source>exception 06: the controller is not in F7 «РАБОТА С ПЭВМ» (УПРАВЛЕНИЕ ДАННЫМИ): select it on the K923 to write</source>
        <translation>исключение 06: контроллер не в F7 «РАБОТА С ПЭВМ» (УПРАВЛЕНИЕ ДАННЫМИ): выберите этот пункт на K923, чтобы записывать</translation>
    </message>
    <message>
        <source>exception %1</source>
        <translation>исключение %1</translation>
    </message>
    <message>
        <source>idle (the transfer)</source>
        <translation>свободен</translation>
    </message>
    <message>
        <source>ready (the transfer)</source>
        <translation>готов</translation>
    </message>
    <message>
        <source>committed</source>
        <translation>записано</translation>
    </message>
    <message>
        <source>the controller is not in F7 «РАБОТА С ПЭВМ»</source>
        <translation>контроллер не в F7 «РАБОТА С ПЭВМ»</translation>
    </message>
    <message>
        <source>no such program in the controller</source>
        <translation>такой программы в контроллере нет</translation>
    </message>
    <message>
        <source>the controller refused the text</source>
        <translation>контроллер отклонил текст</translation>
    </message>
    <message>
        <source>CRC or length mismatch: the text arrived damaged and was not stored</source>
        <translation>не совпали CRC или длина: текст пришёл повреждённым и не сохранён</translation>
    </message>
    <message>
        <source>the controller's memory is full</source>
        <translation>память контроллера заполнена</translation>
    </message>
    <message>
        <source>status %1</source>
        <translation>состояние %1</translation>
    </message>
    <message>
        <source>reading registers %1</source>
        <translation>чтение регистров %1</translation>
    </message>
    <message>
        <source>writing registers %1</source>
        <translation>запись регистров %1</translation>
    </message>
    <message>
        <source>echo</source>
        <translation>эхо</translation>
    </message>
    <message>
        <source>diagnostics %1</source>
        <translation>диагностика %1</translation>
    </message>
    <message>
        <source>server id</source>
        <translation>идентификатор сервера</translation>
    </message>
    <message>
        <source>%1: the controller does not answer (%2 attempts)</source>
        <translation>%1: контроллер не отвечает (попыток: %2)</translation>
    </message>
    <message>
        <source>%1: the controller does not answer (1 attempt)</source>
        <translation>%1: контроллер не отвечает (попыток: 1)</translation>
    </message>
    <message>
        <source>%1: the controller does not answer (%2 attempts, last: %3)</source>
        <translation>%1: контроллер не отвечает (попыток: %2, последняя: %3)</translation>
    </message>
    <message>
        <source>%1: the controller does not answer (1 attempt, last: %2)</source>
        <translation>%1: контроллер не отвечает (попыток: 1, последняя: %2)</translation>
    </message>
    <message>
        <source>timeout</source>
        <translation>время ожидания истекло</translation>
    </message>
    <message>
        <source>CRC error</source>
        <translation>ошибка CRC</translation>
    </message>
    <message>
        <source>the port is closed</source>
        <translation>порт закрыт</translation>
    </message>
    <message>
        <source>the connection is closed</source>
        <translation>соединение закрыто</translation>
    </message>
    <message>
        <source>the echo differs</source>
        <translation>эхо не совпадает</translation>
    </message>
    <message>
        <source>an empty answer</source>
        <translation>пустой ответ</translation>
    </message>
    <message>
        <source>the port is closed and does not open again: %1</source>
        <translation>порт закрыт и не открывается снова: %1</translation>
    </message>
    <message>
        <source>the port failed: %1</source>
        <translation>отказ порта: %1</translation>
    </message>
    <message>
        <source>the connection is closed and does not open again: %1</source>
        <translation>соединение закрыто и не открывается снова: %1</translation>
    </message>
    <message>
        <source>the connection failed: %1</source>
        <translation>отказ соединения: %1</translation>
    </message>
    <message>
        <source>%1 (a damaged frame)</source>
        <translation>повреждённый кадр</translation>
    </message>
    <message>
        <source>%1 (an answer that does not fit)</source>
        <translation>ответ не к этому запросу</translation>
    </message>
    <message>
        <source>%1 (no answer)</source>
        <translation>нет ответа</translation>
    </message>
    <message>
        <source>connection refused</source>
        <translation>соединение отклонено</translation>
    </message>
    <message>
        <source>the other end closed the connection</source>
        <translation>другая сторона закрыла соединение</translation>
    </message>
    <message>
        <source>host not found</source>
        <translation>узел не найден</translation>
    </message>
    <message>
        <source>no connection within %1 ms</source>
        <translation>нет соединения за %1 мс</translation>
    </message>
    <message>
        <source>the socket timed out</source>
        <translation>время ожидания сокета истекло</translation>
    </message>
    <message>
        <source>the network is unreachable</source>
        <translation>сеть недоступна</translation>
    </message>
    <message>
        <source>access to the socket denied</source>
        <translation>нет доступа к сокету</translation>
    </message>
    <message>
        <source>the address is in use</source>
        <translation>адрес уже занят</translation>
    </message>
    <message>
        <source>socket error: %1</source>
        <translation>ошибка сокета: %1</translation>
    </message>
    <message>
        <source>no such port</source>
        <translation>порт не найден</translation>
    </message>
    <message>
        <source>permission denied (or another program holds the port)</source>
        <translation>нет доступа к порту (или он занят другой программой)</translation>
    </message>
    <message>
        <source>the port is already open</source>
        <translation>порт уже открыт</translation>
    </message>
    <message>
        <source>the port does not take these settings</source>
        <translation>порт не принимает эти настройки</translation>
    </message>
    <message>
        <source>the port is gone (unplugged?)</source>
        <translation>порт пропал (отключён?)</translation>
    </message>
    <message>
        <source>the port failed to read or write</source>
        <translation>ошибка чтения или записи порта</translation>
    </message>
    <message>
        <source>the port timed out</source>
        <translation>время ожидания порта истекло</translation>
    </message>
    <message>
        <source>the port is not open</source>
        <translation>порт не открыт</translation>
    </message>
    <message>
        <source>port error: %1</source>
        <translation>ошибка порта: %1</translation>
    </message>
    <message>
        <source>'%1' is not HOST:PORT (a port 1..65535)</source>
        <translation>«%1» — не ХОСТ:ПОРТ (порт 1..65535)</translation>
    </message>
    <message>
        <source>the controller is in F7 УПРАВЛЕНИЕ ДАННЫМИ but not on «РАБОТА С ПЭВМ»: choose «РАБОТА С ПЭВМ» in its menu on the K923 (▲ ▼, ENTER), then %1 again; nothing was sent</source>
        <translation>контроллер в F7 УПРАВЛЕНИЕ ДАННЫМИ, но не на «РАБОТА С ПЭВМ»: выберите «РАБОТА С ПЭВМ» в его меню на K923 (▲ ▼, ENTER) и повторите %1; ничего не отправлено</translation>
    </message>
    <message>
        <source>the controller is not in F7 «РАБОТА С ПЭВМ» (mode F%2 now): press F7 (УПРАВЛЕНИЕ ДАННЫМИ) on the K923 and choose «РАБОТА С ПЭВМ», then %1 again; nothing was sent</source>
        <translation>контроллер не в F7 «РАБОТА С ПЭВМ» (сейчас режим F%2): нажмите F7 (УПРАВЛЕНИЕ ДАННЫМИ) на K923, выберите «РАБОТА С ПЭВМ» и повторите %1; ничего не отправлено</translation>
    </message>
    <message>
        <source>the controller is not in F7 «РАБОТА С ПЭВМ» (powering on): press F7 (УПРАВЛЕНИЕ ДАННЫМИ) on the K923 and choose «РАБОТА С ПЭВМ», then %1 again; nothing was sent</source>
        <translation>контроллер не в F7 «РАБОТА С ПЭВМ» (идёт включение): нажмите F7 (УПРАВЛЕНИЕ ДАННЫМИ) на K923, выберите «РАБОТА С ПЭВМ» и повторите %1; ничего не отправлено</translation>
    </message>
    <message>
        <source>push (the action to repeat)</source>
        <translation>передачу</translation>
    </message>
    <message>
        <source>clear C (the action to repeat)</source>
        <translation>очистку C</translation>
    </message>
    <message>
        <source>clear R (the action to repeat)</source>
        <translation>очистку R</translation>
    </message>
    <message>
        <source>set %1 (the action to repeat)</source>
        <translation>запись %1</translation>
    </message>
    <message>
        <source>C-parameters</source>
        <translation>C-параметры</translation>
    </message>
    <message>
        <source>R-parameters</source>
        <translation>R-параметры</translation>
    </message>
    <message>
        <source>R-parameters (%1)</source>
        <translation>R-параметры (%1)</translation>
    </message>
    <message>
        <source>messages</source>
        <translation>сообщения</translation>
    </message>
    <message>
        <source>program %1</source>
        <translation>программа %1</translation>
    </message>
    <message>
        <source>clear C</source>
        <translation>очистка C</translation>
    </message>
    <message>
        <source>clear R</source>
        <translation>очистка R</translation>
    </message>
    <message>
        <source>clear C: the C block does not read back as zeros</source>
        <translation>очистка C: блок C не читается нулями</translation>
    </message>
    <message>
        <source>the controller announces a text of %1 bytes</source>
        <translation>контроллер объявил текст длиной %1 байт</translation>
    </message>
    <message>
        <source>the text read does not match its CRC-32</source>
        <translation>прочитанный текст не совпадает со своей CRC-32</translation>
    </message>
    <message>
        <source>%1 at line %2</source>
        <translation>%1 в строке %2</translation>
    </message>
    <message>
        <source>the map's window does not follow its offset</source>
        <translation>окно карты не следует за своим смещением</translation>
    </message>
    <message>
        <source>%1: the text read back differs from the text sent</source>
        <translation>%1: текст, прочитанный обратно, отличается от отправленного</translation>
    </message>
    <message>
        <source>%1: the controller refused the block</source>
        <translation>%1: контроллер отклонил блок</translation>
    </message>
    <message>
        <source>%1: the controller refused the block at C%2</source>
        <translation>%1: контроллер отклонил блок на C%2</translation>
    </message>
    <message>
        <source>%1: the values read back differ from those sent</source>
        <translation>%1: значения, прочитанные обратно, отличаются от отправленных</translation>
    </message>
    <message>
        <source>C%1 has no address in the positioner (table Е.1): it cannot be written</source>
        <translation>C%1 не имеет адреса в позиционере (таблица Е.1): её нельзя записать</translation>
    </message>
    <message>
        <source>C%1 = %2: the controller refused the value (outside table Е.1)</source>
        <translation>C%1 = %2: контроллер отклонил значение (вне таблицы Е.1)</translation>
    </message>
    <message>
        <source>%1: the controller does not read back what was written</source>
        <translation>%1: контроллер при чтении не возвращает то, что записано</translation>
    </message>
    <message>
        <source>R%1 is read only over the link (the PC writes %2)</source>
        <translation>R%1 по линии только читается (ПЭВМ записывает %2)</translation>
    </message>
    <message>
        <source>R%1 = %2 is outside 32 bits</source>
        <translation>R%1 = %2 не помещается в 32 бита</translation>
    </message>
    <message>
        <source>%1; nothing was sent</source>
        <translation>%1; ничего не отправлено</translation>
    </message>
    <message>
        <source>C%1 (%2): %3 (table Е.1)</source>
        <translation>C%1 (%2): %3 (таблица Е.1)</translation>
    </message>
    <message>
        <source>R%1 is outside the 32-bit range</source>
        <translation>R%1 не помещается в 32 бита</translation>
    </message>
    <message>
        <source>program %1, line %2: %3</source>
        <translation>программа %1, строка %2: %3</translation>
    </message>
    <message>
        <source>program %1 does not hold exactly that program</source>
        <translation>программа %1 содержит не ровно одну эту программу</translation>
    </message>
    <message>
        <source>program %1: %2</source>
        <translation>программа %1: %2</translation>
    </message>
    <message>
        <source>%1:%2: %3</source>
        <translation>%1:%2: %3</translation>
    </message>
    <message>
        <source>%1 holds no program (%L) and no %MESSAGES</source>
        <translation>%1 не содержит ни программы (%L), ни %MESSAGES</translation>
    </message>
    <message>
        <source>%1: the text before the first %L header belongs to no program</source>
        <translation>%1: текст до первого заголовка %L не относится ни к одной программе</translation>
    </message>
    <message>
        <source>%1:%2: %3 (checked against the controller's constants and programs)</source>
        <translation>%1:%2: %3 (проверено по константам и программам контроллера)</translation>
    </message>
    <message>
        <source>new: %1</source>
        <translation>записано: %1</translation>
    </message>
    <message>
        <source>in doubt (the line broke while it was committed; pull to see): %1</source>
        <translation>под вопросом (линия оборвалась во время записи; считайте память, чтобы узнать): %1</translation>
    </message>
    <message>
        <source>as they were: %1</source>
        <translation>как было: %1</translation>
    </message>
    <message>
        <source>%1 answer</source>
        <translation>ответов: %1</translation>
    </message>
    <message>
        <source>%1 answers</source>
        <translation>ответов: %1</translation>
    </message>
    <message>
        <source>%1 timeout</source>
        <translation>тайм-аутов: %1</translation>
    </message>
    <message>
        <source>%1 timeouts</source>
        <translation>тайм-аутов: %1</translation>
    </message>
    <message>
        <source>%1 CRC error</source>
        <translation>ошибок CRC: %1</translation>
    </message>
    <message>
        <source>%1 CRC errors</source>
        <translation>ошибок CRC: %1</translation>
    </message>
    <message>
        <source>%1 bad reply</source>
        <translation>неподходящих ответов: %1</translation>
    </message>
    <message>
        <source>%1 bad replies</source>
        <translation>неподходящих ответов: %1</translation>
    </message>
    <message>
        <source>%1 exception</source>
        <translation>исключений: %1</translation>
    </message>
    <message>
        <source>%1 exceptions</source>
        <translation>исключений: %1</translation>
    </message>
    <message>
        <source>%1 retry</source>
        <translation>повторов: %1</translation>
    </message>
    <message>
        <source>%1 retries</source>
        <translation>повторов: %1</translation>
    </message>
    <message>
        <source>%1 request sent again in halves</source>
        <translation>запросов, посланных снова половинами: %1</translation>
    </message>
    <message>
        <source>%1 requests sent again in halves</source>
        <translation>запросов, посланных снова половинами: %1</translation>
    </message>
    <message>
        <source>; round trip median %1 ms, p95 %2 ms</source>
        <translation>; время отклика: медиана %1 мс, 95-й процентиль %2 мс</translation>
    </message>
    <message>
        <source>cancelled by the user</source>
        <translation>отменено пользователем</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>соединение закрыто</translation>
    </message>
    <message>
        <source>address %1: %2</source>
        <translation>адрес %1: %2</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>нет ответа</translation>
    </message>
    <message>
        <source>a damaged answer (another baud rate or parity?)</source>
        <translation>повреждённый ответ (другая скорость или чётность?)</translation>
    </message>
    <message>
        <source>echo ok</source>
        <translation>эхо в порядке</translation>
    </message>
    <message>
        <source>exception %1 to the echo</source>
        <translation>исключение %1 в ответ на эхо</translation>
    </message>
    <message>
        <source>, running (the server id says)</source>
        <translation>, работает</translation>
    </message>
    <message>
        <source>; no server id (FC 17)</source>
        <translation>; нет идентификатора сервера (функция 17)</translation>
    </message>
    <message>
        <source>; K528-05 map: mode F%1</source>
        <translation>; карта K528-05: режим F%1</translation>
    </message>
    <message>
        <source>, program %1</source>
        <translation>, программа %1</translation>
    </message>
    <message>
        <source>, %1 programs</source>
        <translation>, программ: %1</translation>
    </message>
    <message>
        <source>, alarms</source>
        <translation>, аварии</translation>
    </message>
    <message>
        <source>; round trip %1 ms</source>
        <translation>; время отклика %1 мс</translation>
    </message>
    <message>
        <source>; server id %1</source>
        <translation>; идентификатор сервера %1</translation>
    </message>
    <message>
        <source>cannot connect to %1: %2</source>
        <translation>нет соединения с %1: %2</translation>
    </message>
</context>
<context>
    <name>k528::studio::ListingActions</name>
    <message>
        <source>Listing of %1 pages written to %2</source>
        <translation>Листинг на %1 листах записан в %2</translation>
    </message>
    <message>
        <source>Export the listing</source>
        <translation>Экспорт листинга</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Printed %1 pages</source>
        <translation>Напечатано листов: %1</translation>
    </message>
    <message>
        <source>The listing could not be printed</source>
        <translation>Листинг не напечатан</translation>
    </message>
</context>
<context>
    <name>k528::studio::MachinePanelWidget</name>
    <message>
        <source>SPINDLE</source>
        <translation>ШПИНДЕЛЬ</translation>
    </message>
    <message>
        <source>COOLANT</source>
        <translation>СОЖ</translation>
    </message>
    <message>
        <source>LIMIT</source>
        <translation>КОНЕЧНИК</translation>
    </message>
    <message>
        <source>HOMED</source>
        <translation>ПРИВЯЗКА</translation>
    </message>
    <message>
        <source>DOOR</source>
        <translation>ДВЕРЬ</translation>
    </message>
    <message>
        <source>CLAMPED</source>
        <translation>ЗАЖИМ</translation>
    </message>
    <message>
        <source>ALARM</source>
        <translation>АВАРИЯ</translation>
    </message>
    <message>
        <source>LUBE</source>
        <translation>СМАЗКА</translation>
    </message>
    <message>
        <source>WHEEL</source>
        <translation>КРУГ</translation>
    </message>
    <message>
        <source>GAUGE</source>
        <translation>ПАК</translation>
    </message>
    <message>
        <source>TURRET</source>
        <translation>РЕЗЦЕДЕРЖ.</translation>
    </message>
    <message>
        <source>HYDRAUL.</source>
        <translation>ГИДРАВЛ.</translation>
    </message>
    <message>
        <source>MACHINE CONTROL PANEL</source>
        <translation>ПУЛЬТ СТАНКА</translation>
    </message>
    <message>
        <source>EMERGENCY STOP</source>
        <translation>АВАРИЙНЫЙ СТОП</translation>
    </message>
    <message>
        <source>DRIVES ON</source>
        <translation>ПРИВОДЫ</translation>
    </message>
    <message>
        <source>RESET</source>
        <translation>СБРОС</translation>
    </message>
    <message>
        <source>CYCLE START</source>
        <translation>ПУСК</translation>
    </message>
    <message>
        <source>STOP</source>
        <translation>СТОП</translation>
    </message>
    <message>
        <source>Rapid traverse: hold with a jog button</source>
        <translation>Ускоренное перемещение: держать вместе с кнопкой оси</translation>
    </message>
    <message>
        <source>Jog X+ (hold)</source>
        <translation>Перемещение X+ (держать)</translation>
    </message>
    <message>
        <source>Jog X- (hold)</source>
        <translation>Перемещение X- (держать)</translation>
    </message>
    <message>
        <source>Jog Z+ (hold)</source>
        <translation>Перемещение Z+ (держать)</translation>
    </message>
    <message>
        <source>Jog Z- (hold)</source>
        <translation>Перемещение Z- (держать)</translation>
    </message>
    <message>
        <source>JOG</source>
        <translation>ПЕРЕМЕЩЕНИЕ</translation>
    </message>
    <message>
        <source>HANDWHEEL</source>
        <translation>МАХОВИК</translation>
    </message>
    <message>
        <source>AXIS</source>
        <translation>ОСЬ</translation>
    </message>
    <message>
        <source>STEP</source>
        <translation>ШАГ</translation>
    </message>
    <message>
        <source>Drag round or turn the mouse wheel: one detent is one step</source>
        <translation>Вращайте мышью или колесом мыши: одно деление — один шаг</translation>
    </message>
    <message>
        <source>FEED OVERRIDE %</source>
        <translation>КОРРЕКТОР ПОДАЧИ %</translation>
    </message>
    <message>
        <source>K923: the panel's L1..L4 keys set the override</source>
        <translation>K923: корректор задают клавиши L1..L4 панели</translation>
    </message>
    <message>
        <source>CHUCK</source>
        <translation>ПАТРОН</translation>
    </message>
    <message>
        <source>NEW WHEEL</source>
        <translation>КРУГ НОВЫЙ</translation>
    </message>
    <message>
        <source>Per detent: %1 / %2 / %3 mm</source>
        <translation>На деление: %1 / %2 / %3 мм</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Шпиндель</translation>
    </message>
    <message>
        <source>Wheel</source>
        <translation>Круг</translation>
    </message>
    <message>
        <source>Work</source>
        <translation>Изделие</translation>
    </message>
    <message>
        <source>rpm</source>
        <translation>об/мин</translation>
    </message>
    <message>
        <source>Tool %1</source>
        <translation>Инструмент %1</translation>
    </message>
    <message>
        <source>Gauge: bore %1 / %2 mm, wheel %3 mm</source>
        <translation>ПАК: отверстие %1 / %2 мм, круг %3 мм</translation>
    </message>
    <message>
        <source> in </source>
        <translation> подведён </translation>
    </message>
    <message>
        <source> touch </source>
        <translation> касание </translation>
    </message>
    <message>
        <source> rough </source>
        <translation> черн. </translation>
    </message>
    <message>
        <source> finish </source>
        <translation> чист. </translation>
    </message>
    <message>
        <source> size</source>
        <translation> размер</translation>
    </message>
</context>
<context>
    <name>k528::studio::MachineSource</name>
    <message>
        <source>The machine database is not used: %1</source>
        <translation>База данных станков не используется: %1</translation>
    </message>
    <message>
        <source>database %1</source>
        <translation>база данных %1</translation>
    </message>
    <message>
        <source>built-in</source>
        <translation>встроенный</translation>
    </message>
    <message>
        <source>not in the database %1</source>
        <translation>нет в базе данных %1</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
</context>
<context>
    <name>k528::studio::MachineStore</name>
    <message>
        <source>revision %1 by %2 at %3: %4
</source>
        <translation>ревизия %1, автор %2, %3: %4
</translation>
    </message>
</context>
<context>
    <name>k528::studio::MainWindow</name>
    <message>
        <source>About K528 Studio</source>
        <translation>О программе K528 Studio</translation>
    </message>
    <message>
        <source>&lt;h3&gt;K528 Studio %1&lt;/h3&gt;&lt;p&gt;Workstation for the Konstar K528-05 two-axis positioning controller and its K923 operator panel.&lt;/p&gt;&lt;p&gt;Licence: GNU GPL version 3 or later.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;K528 Studio %1&lt;/h3&gt;&lt;p&gt;Рабочее место для двухкоординатного устройства позиционирования «Констар» К528-05 и его панели оператора K923.&lt;/p&gt;&lt;p&gt;Лицензия: GNU GPL версии 3 или более поздней.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Файл</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>В&amp;ыход</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Вид</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Язык</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Справка</translation>
    </message>
    <message>
        <source>&amp;About K528 Studio</source>
        <translation>&amp;О программе K528 Studio</translation>
    </message>
    <message>
        <source>K923 operator panel</source>
        <translation>Панель оператора K923</translation>
    </message>
    <message>
        <source>Machine control panel</source>
        <translation>Пульт станка</translation>
    </message>
    <message>
        <source>Messages</source>
        <translation>Сообщения</translation>
    </message>
    <message>
        <source>Axes and signals</source>
        <translation>Оси и сигналы</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Готово</translation>
    </message>
    <message>
        <source>Machine time %1:%2:%3</source>
        <translation>Время станка %1:%2:%3</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Станок</translation>
    </message>
    <message>
        <source>&amp;Pause the machine</source>
        <translation>&amp;Пауза</translation>
    </message>
    <message>
        <source>&amp;Speed</source>
        <translation>С&amp;корость</translation>
    </message>
    <message>
        <source>&amp;Faults for training</source>
        <translation>&amp;Неисправности для обучения</translation>
    </message>
    <message>
        <source>&amp;Clear all faults</source>
        <translation>&amp;Убрать все неисправности</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Станок</translation>
    </message>
    <message>
        <source>The machine %1 cannot be loaded: %2</source>
        <translation>Станок %1 не загружается: %2</translation>
    </message>
    <message>
        <source>&amp;Machine</source>
        <translation>&amp;Станок</translation>
    </message>
    <message>
        <source>Machine: %1</source>
        <translation>Станок: %1</translation>
    </message>
    <message>
        <source>Machine: %1 (%2)</source>
        <translation>Станок: %1 (%2)</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Программа</translation>
    </message>
    <message>
        <source>Load programs</source>
        <translation>Загрузка программ</translation>
    </message>
    <message>
        <source>K528 programs (*.k528 *.txt);;All files (*)</source>
        <translation>Программы K528 (*.k528 *.txt);;Все файлы (*)</translation>
    </message>
    <message>
        <source>Loaded %1 from %2</source>
        <translation>Загружены %1 из %2</translation>
    </message>
    <message>
        <source>Loaded %1 from %2, with warnings.</source>
        <translation>Загружены %1 из %2, есть предупреждения.</translation>
    </message>
    <message>
        <source>&amp;Load programs...</source>
        <translation>&amp;Загрузить программы...</translation>
    </message>
    <message>
        <source>Keep in the database</source>
        <translation>Сохранение в базе данных</translation>
    </message>
    <message>
        <source>The memory of %1 was not kept: %2</source>
        <translation>Память %1 не сохранена: %2</translation>
    </message>
    <message>
        <source>%1: the database already holds this memory (revision %2)</source>
        <translation>%1: эта память уже в базе данных (редакция %2)</translation>
    </message>
    <message>
        <source>%1 kept in the database as revision %2 (%3 changes)</source>
        <translation>%1 сохранён в базе данных, редакция %2 (изменений: %3)</translation>
    </message>
    <message>
        <source>&amp;Keep the controller's memory in the database</source>
        <translation>&amp;Сохранить память БП в базе данных</translation>
    </message>
    <message>
        <source>Editor</source>
        <translation>Редактор</translation>
    </message>
    <message>
        <source>The controller on the link takes no keys: press them on its own K923</source>
        <translation>Контроллер на линии не принимает клавиши: нажимайте их на его собственном К923</translation>
    </message>
    <message>
        <source>Debugger</source>
        <translation>Отладчик</translation>
    </message>
    <message>
        <source>This control panel is the simulated machine's: the controller on the line is worked from its own machine's panel (its state is in the other views).</source>
        <translation>Этот пульт — пульт моделируемого станка: контроллером на линии управляют с пульта его собственного станка (его состояние — в других панелях).</translation>
    </message>
    <message>
        <source>The debugger steps programs on the simulated machine; the controller on the line runs them itself. Show the simulation again (Controller dock) to debug.</source>
        <translation>Отладчик выполняет программы по шагам на моделируемом станке; контроллер на линии выполняет их сам. Чтобы отлаживать, снова покажите модель (панель «Контроллер»).</translation>
    </message>
    <message>
        <source>Reading the controller's memory to keep it in the database...</source>
        <translation>Чтение памяти контроллера для сохранения в базе данных...</translation>
    </message>
    <message>
        <source> — stale since %1</source>
        <translation> — устарело с %1</translation>
    </message>
    <message>
        <source>K923: LEDs only (no LCD text or keys over the link)</source>
        <translation>K923: только светодиоды (текста ЖКИ и клавиш по линии нет)</translation>
    </message>
    <message>
        <source>The controller on the line: its K LEDs and override as it shows them; its LCD text and keys are not on the link — use its own K923</source>
        <translation>Контроллер на линии: его светодиоды K и коррекция, как он их показывает; текста ЖКИ и клавиш на линии нет — используйте его собственный K923</translation>
    </message>
    <message>
        <source>The database %1 has no machine %2: it runs as it was loaded; File &gt; Machine offers this database's machines</source>
        <translation>В базе данных %1 нет станка %2: он работает таким, каким был загружен; станки этой базы — в меню Файл &gt; Станок</translation>
    </message>
    <message>
        <source>Shop</source>
        <translation>Цех</translation>
    </message>
</context>
<context>
    <name>k528::studio::MessagesView</name>
    <message>
        <source>Source</source>
        <translation>Источник</translation>
    </message>
    <message>
        <source>No.</source>
        <translation>№</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Сообщение</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Состояние</translation>
    </message>
    <message>
        <source> (L%1, line %2)</source>
        <translation> (L%1, строка %2)</translation>
    </message>
    <message>
        <source>Positioner</source>
        <translation>БП</translation>
    </message>
    <message>
        <source>active</source>
        <translation>есть</translation>
    </message>
    <message>
        <source>PLC system</source>
        <translation>ПЛК, системное</translation>
    </message>
    <message>
        <source>PLC alarm</source>
        <translation>ПЛК, авария</translation>
    </message>
    <message>
        <source>PLC</source>
        <translation>ПЛК</translation>
    </message>
    <message>
        <source>information</source>
        <translation>информация</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Программа</translation>
    </message>
    <message>
        <source>No alarms.</source>
        <translation>Аварийных сообщений нет.</translation>
    </message>
    <message>
        <source>Alarms: %1. Acknowledge with RESET on the machine panel or ESC on the K923 once the cause is gone.</source>
        <translation>Аварийных сообщений: %1. Квитируйте кнопкой СБРОС пульта станка или ESC панели K923, когда причина устранена.</translation>
    </message>
    <message>
        <source>waits for acknowledgement</source>
        <translation>ждёт квитирования</translation>
    </message>
</context>
<context>
    <name>k528::studio::ParameterTablePane</name>
    <message>
        <source>Note:</source>
        <translation>Примечание:</translation>
    </message>
    <message>
        <source>They cannot be changed now: %1.</source>
        <translation>Изменить их сейчас нельзя: %1.</translation>
    </message>
</context>
<context>
    <name>k528::studio::ProblemsModel</name>
    <message>
        <source>The rule of the prove-out the frame breaks (the blank, the chuck, the tools): %1</source>
        <translation>Правило проверки программы, нарушенное кадром (заготовка, патрон, инструменты): %1</translation>
    </message>
</context>
<context>
    <name>k528::studio::ProgramMonitor</name>
    <message>
        <source>ready</source>
        <translation>готова</translation>
    </message>
    <message>
        <source>running</source>
        <translation>выполняется</translation>
    </message>
    <message>
        <source>dwell</source>
        <translation>выдержка</translation>
    </message>
    <message>
        <source>waiting for the PLC (M)</source>
        <translation>ожидание ПЛК (M)</translation>
    </message>
    <message>
        <source>M00: waiting for START</source>
        <translation>M00: ожидание «Пуск»</translation>
    </message>
    <message>
        <source>interrupted: START continues</source>
        <translation>прервана: «Пуск» продолжит</translation>
    </message>
    <message>
        <source>ended</source>
        <translation>закончена</translation>
    </message>
    <message>
        <source>stopped by a message: START begins again</source>
        <translation>остановлена сообщением: «Пуск» — с начала</translation>
    </message>
    <message>
        <source>Follow the controller</source>
        <translation>Следовать за БП</translation>
    </message>
    <message>
        <source>L%1: %2</source>
        <translation>L%1: %2</translation>
    </message>
    <message>
        <source>no program</source>
        <translation>нет программы</translation>
    </message>
    <message>
        <source>, frame N%1</source>
        <translation>, кадр N%1</translation>
    </message>
</context>
<context>
    <name>k528::studio::ProgramReleases</name>
    <message>
        <source>Note (why, what was checked):</source>
        <translation>Примечание (почему, что проверено):</translation>
    </message>
    <message>
        <source>draft</source>
        <translation>черновик</translation>
    </message>
    <message>
        <source>released</source>
        <translation>выпущена</translation>
    </message>
    <message>
        <source>withdrawn</source>
        <translation>отозвана</translation>
    </message>
    <message>
        <source>Release states of %1 cannot be read: %2</source>
        <translation>Состояния программ станка %1 прочитать нельзя: %2</translation>
    </message>
    <message>
        <source>Released as of revision %1 by %2 at %3</source>
        <translation>Выпущена в ревизии %1: %2, %3</translation>
    </message>
    <message>
        <source>Changed since its release: revision %1 is released (by %2 at %3) and a push takes that one</source>
        <translation>Изменена после выпуска: выпущена ревизия %1 (%2, %3), в контроллер передаётся она</translation>
    </message>
    <message>
        <source>Deleted from the machine since its release (by %1 at %2)</source>
        <translation>Удалена из станка после выпуска (%1, %2)</translation>
    </message>
    <message>
        <source>Withdrawn by %1 at %2 (revision %3 was released)</source>
        <translation>Отозвана: %1, %2 (была выпущена ревизия %3)</translation>
    </message>
    <message>
        <source>Note: %1</source>
        <translation>Примечание: %1</translation>
    </message>
    <message>
        <source>Never released: a push to a controller does not take it</source>
        <translation>Не выпускалась: передача в контроллер её не берёт</translation>
    </message>
    <message>
        <source>Release L%1 of %2</source>
        <translation>Выпуск L%1 станка %2</translation>
    </message>
    <message>
        <source>Withdraw L%1 of %2</source>
        <translation>Отзыв L%1 станка %2</translation>
    </message>
    <message>
        <source>L%1 is no longer a program of %2: there is nothing to release</source>
        <translation>L%1 больше нет в станке %2: выпускать нечего</translation>
    </message>
    <message>
        <source>L%1 is released already (revision %2)</source>
        <translation>L%1 уже выпущена (ревизия %2)</translation>
    </message>
    <message>
        <source>Released L%1 of %2 as of revision %3 by %4 at %5</source>
        <translation>L%1 станка %2 выпущена в ревизии %3: %4, %5</translation>
    </message>
    <message>
        <source>L%1 was not released: %2</source>
        <translation>L%1 не выпущена: %2</translation>
    </message>
    <message>
        <source>L%1 was never released: there is nothing to withdraw</source>
        <translation>L%1 не выпускалась: отзывать нечего</translation>
    </message>
    <message>
        <source>L%1 is withdrawn already</source>
        <translation>L%1 уже отозвана</translation>
    </message>
    <message>
        <source>Withdrew L%1 of %2 by %3 at %4</source>
        <translation>L%1 станка %2 отозвана: %3, %4</translation>
    </message>
    <message>
        <source>L%1 was not withdrawn: %2</source>
        <translation>L%1 не отозвана: %2</translation>
    </message>
    <message>
        <source>Programs of %1 for the controllers</source>
        <translation>Программы станка %1 для контроллеров</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Состояние</translation>
    </message>
    <message>
        <source>By</source>
        <translation>Кто</translation>
    </message>
    <message>
        <source>Release...</source>
        <translation>Выпустить...</translation>
    </message>
    <message>
        <source>Makes the program's current version the one a push to a controller takes (k528 db release)</source>
        <translation>Текущая версия программы становится той, которую берёт передача в контроллер</translation>
    </message>
    <message>
        <source>Withdraw...</source>
        <translation>Отозвать...</translation>
    </message>
    <message>
        <source>Withdraws the released version: a push no longer takes it (k528 db withdraw)</source>
        <translation>Выпущенная версия отзывается: передача в контроллер её больше не берёт</translation>
    </message>
    <message>
        <source>No.</source>
        <translation>№</translation>
    </message>
</context>
<context>
    <name>k528::studio::ProveoutPane</name>
    <message>
        <source>The blank: %1</source>
        <translation>Заготовка: %1</translation>
    </message>
    <message>
        <source>The file's blank: %1</source>
        <translation>Заготовка файла: %1</translation>
    </message>
    <message>
        <source>The machine's description: %1</source>
        <translation>Описание станка: %1</translation>
    </message>
    <message>
        <source>The machine's tools: %1</source>
        <translation>Инструменты станка: %1</translation>
    </message>
    <message>
        <source>Open a program file in the editor: it is proved on the machine it is checked for.</source>
        <translation>Откройте файл программ в редакторе: его программы проверяются на станке, выбранном для файла.</translation>
    </message>
    <message>
        <source>The file is checked for no machine: choose one (Editor menu) to prove it.</source>
        <translation>Файл не привязан к станку: выберите станок (меню «Редактор»), чтобы проверить его программы.</translation>
    </message>
    <message>
        <source>The file has errors (Problems): it is proved once they are fixed.</source>
        <translation>В файле есть ошибки (список «Проблемы»): программы проверяются после их исправления.</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Ошибка</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Предупреждение</translation>
    </message>
    <message>
        <source>turning</source>
        <translation>проходной</translation>
    </message>
    <message>
        <source>facing</source>
        <translation>подрезной</translation>
    </message>
    <message>
        <source>grooving</source>
        <translation>канавочный</translation>
    </message>
    <message>
        <source>boring bar</source>
        <translation>расточной</translation>
    </message>
    <message>
        <source>drill</source>
        <translation>сверло</translation>
    </message>
    <message>
        <source>threading</source>
        <translation>резьбовой</translation>
    </message>
    <message>
        <source>Nothing found.</source>
        <translation>Ничего не найдено.</translation>
    </message>
    <message>
        <source>Errors: %1, warnings: %2.</source>
        <translation>Ошибок: %1, предупреждений: %2.</translation>
    </message>
    <message>
        <source>the blank of the file (UCG)</source>
        <translation>заготовка из файла (UCG)</translation>
    </message>
    <message>
        <source>the blank</source>
        <translation>заготовка</translation>
    </message>
    <message>
        <source>the chuck and the turret</source>
        <translation>патрон и резцедержатель</translation>
    </message>
    <message>
        <source>the spindles</source>
        <translation>шпиндели</translation>
    </message>
    <message>
        <source>Proved against: %1.</source>
        <translation>Учтены: %1.</translation>
    </message>
    <message>
        <source>No blank: give one (UCG) to check the rapids against the material.</source>
        <translation>Заготовка не задана: задайте её (UCG), чтобы проверить быстрые ходы по материалу.</translation>
    </message>
    <message>
        <source>Blank (UCG)</source>
        <translation>Заготовка (UCG)</translation>
    </message>
    <message>
        <source>the file's own</source>
        <translation>из файла</translation>
    </message>
    <message>
        <source>The blank as a UCG line (NC-200); empty: the UCG comment of the file</source>
        <translation>Заготовка строкой UCG; пусто — комментарий UCG из файла</translation>
    </message>
    <message>
        <source>Prove</source>
        <translation>Проверить</translation>
    </message>
    <message>
        <source>Run the file's programs in preview against the blank, the chuck, the turret and the tools of the machine</source>
        <translation>Выполнить программы файла в просмотре и проверить их по заготовке, патрону, резцедержателю и инструментам станка</translation>
    </message>
    <message>
        <source>Prove after each change</source>
        <translation>Проверять после каждого изменения</translation>
    </message>
    <message>
        <source>The machine's tools</source>
        <translation>Инструменты станка</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>Важность</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Программа</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation>Кадр</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Строка</translation>
    </message>
    <message>
        <source>Text</source>
        <translation>Текст</translation>
    </message>
    <message>
        <source>Station</source>
        <translation>Позиция</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Инструмент</translation>
    </message>
    <message>
        <source>Radius, mm</source>
        <translation>Радиус, мм</translation>
    </message>
    <message>
        <source>Offset X, mm</source>
        <translation>Корр. X, мм</translation>
    </message>
    <message>
        <source>Offset Z, mm</source>
        <translation>Корр. Z, мм</translation>
    </message>
    <message>
        <source>Offsets in</source>
        <translation>Коррекции в</translation>
    </message>
    <message>
        <source>Max depth, mm</source>
        <translation>Глубина, мм</translation>
    </message>
    <message>
        <source>The tool's nose radius</source>
        <translation>Радиус при вершине резца</translation>
    </message>
    <message>
        <source>The deepest cut the tool takes (its cutting edge)</source>
        <translation>Наибольшая глубина резания инструмента (длина режущей кромки)</translation>
    </message>
    <message>
        <source>Prove-out</source>
        <translation>Проверка программы</translation>
    </message>
    <message>
        <source>expected UCG</source>
        <translation>ожидалось UCG</translation>
    </message>
    <message>
        <source>expected the type N after UCG,</source>
        <translation>после «UCG,» ожидался тип N</translation>
    </message>
    <message>
        <source>expected Z&lt;outer length&gt;Z&lt;bore length&gt;</source>
        <translation>ожидалось Z&lt;длина заготовки&gt;Z&lt;длина отверстия&gt;</translation>
    </message>
    <message>
        <source>expected X&lt;outer diameter&gt;X&lt;bore diameter&gt;</source>
        <translation>ожидалось X&lt;наружный диаметр&gt;X&lt;диаметр отверстия&gt;</translation>
    </message>
    <message>
        <source>expected S&lt;outer angle&gt;S&lt;bore angle&gt;</source>
        <translation>ожидалось S&lt;угол снаружи&gt;S&lt;угол отверстия&gt;</translation>
    </message>
    <message>
        <source>the direction is 0 or 1</source>
        <translation>направление — 0 или 1</translation>
    </message>
    <message>
        <source>the detail is -1..-5</source>
        <translation>детализация — от -1 до -5</translation>
    </message>
    <message>
        <source>the blank is smaller than 0.01 mm</source>
        <translation>заготовка меньше 0,01 мм</translation>
    </message>
    <message>
        <source>the bore length has the sign of the outer length</source>
        <translation>длина отверстия того же знака, что длина заготовки</translation>
    </message>
    <message>
        <source>the bore is longer than the blank</source>
        <translation>отверстие длиннее заготовки</translation>
    </message>
    <message>
        <source>the bore diameter is 0..the outer diameter</source>
        <translation>диаметр отверстия — от 0 до наружного диаметра</translation>
    </message>
    <message>
        <source>cone angles are within ±90°</source>
        <translation>углы конусов в пределах ±90°</translation>
    </message>
    <message>
        <source>no UCG in the file</source>
        <translation>в файле нет UCG</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Вид</translation>
    </message>
</context>
<context>
    <name>k528::studio::ProveoutTexts</name>
    <message>
        <source>A rapid (G00) enters the material of the blank: X%1 Z%2</source>
        <translation>Быстрый ход (G00) входит в материал заготовки: X%1 Z%2</translation>
    </message>
    <message>
        <source>A rapid (G00) enters the material at its dogleg: axis %3 arrives first (X%1 Z%2), although both end points are outside the blank</source>
        <translation>Быстрый ход (G00) входит в материал на изломе: ось %3 приходит первой (X%1 Z%2), хотя обе точки кадра вне заготовки</translation>
    </message>
    <message>
        <source>A rapid (G00) takes the wheel into the ring's material: X%1 Z%2</source>
        <translation>Быстрый ход (G00) вводит круг в материал кольца: X%1 Z%2</translation>
    </message>
    <message>
        <source>Tool T%3 runs into the chuck's jaws: X%1 Z%2</source>
        <translation>Инструмент T%3 задевает кулачки патрона: X%1 Z%2</translation>
    </message>
    <message>
        <source>Tool T%3 runs into the chuck's body: X%1 Z%2</source>
        <translation>Инструмент T%3 задевает корпус патрона: X%1 Z%2</translation>
    </message>
    <message>
        <source>The turret runs into the chuck's jaws (tool T%3 at X%1 Z%2)</source>
        <translation>Резцедержатель задевает кулачки патрона (инструмент T%3 у X%1 Z%2)</translation>
    </message>
    <message>
        <source>The turret runs into the chuck's body (tool T%3 at X%1 Z%2)</source>
        <translation>Резцедержатель задевает корпус патрона (инструмент T%3 у X%1 Z%2)</translation>
    </message>
    <message>
        <source>A feed into the material with the spindle stopped: X%1 Z%2</source>
        <translation>Рабочая подача в материал при остановленном шпинделе: X%1 Z%2</translation>
    </message>
    <message>
        <source>A feed into the ring's material with the wheel stopped: X%1 Z%2</source>
        <translation>Рабочая подача в материал кольца при остановленном круге: X%1 Z%2</translation>
    </message>
    <message>
        <source>A manual move takes the tool into the material of the blank: X%1 Z%2</source>
        <translation>Ручное перемещение вводит инструмент в материал заготовки: X%1 Z%2</translation>
    </message>
    <message>
        <source>A cut %1 mm deep, deeper than tool T%2 takes (%3 mm)</source>
        <translation>Глубина резания %1 мм больше допустимой для инструмента T%2 (%3 мм)</translation>
    </message>
</context>
<context>
    <name>k528::studio::PushPreview</name>
    <message>
        <source>name</source>
        <translation>имя</translation>
    </message>
    <message>
        <source>title</source>
        <translation>название</translation>
    </message>
    <message>
        <source>added</source>
        <translation>добавлена</translation>
    </message>
    <message>
        <source>removed</source>
        <translation>удалена</translation>
    </message>
    <message>
        <source>changed</source>
        <translation>изменена</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(нет)</translation>
    </message>
</context>
<context>
    <name>k528::studio::RParamsModel</name>
    <message>
        <source>%1 mm/min</source>
        <translation>%1 мм/мин</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 с</translation>
    </message>
    <message>
        <source>user</source>
        <translation>пользователя</translation>
    </message>
    <message>
        <source>system</source>
        <translation>системный</translation>
    </message>
    <message>
        <source>read only</source>
        <translation>только чтение</translation>
    </message>
    <message>
        <source>reserved</source>
        <translation>резерв</translation>
    </message>
    <message>
        <source>No.</source>
        <translation>№</translation>
    </message>
    <message>
        <source>Access</source>
        <translation>Доступ</translation>
    </message>
    <message>
        <source>Preset screen</source>
        <translation>Экран УСТ</translation>
    </message>
    <message>
        <source>Discretes</source>
        <translation>Дискреты</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>мм</translation>
    </message>
    <message>
        <source>Preset</source>
        <translation>Предустановка</translation>
    </message>
    <message>
        <source>R%1 is read only: the controller writes R232..R262</source>
        <translation>R%1 только для чтения: R232..R262 пишет контроллер</translation>
    </message>
    <message>
        <source>A program is executing: R-parameters are changed when it stops, as on the K923</source>
        <translation>Выполняется программа: R-параметры меняют, когда она остановлена, как на К923</translation>
    </message>
    <message>
        <source>%1 is outside the R-parameters' range -2147483648..2147483647</source>
        <translation>%1 вне диапазона R-параметров -2147483648..2147483647</translation>
    </message>
    <message>
        <source>R%1: «%2» is not a number</source>
        <translation>R%1: «%2» — не число</translation>
    </message>
    <message>
        <source>Meaning (appendix L)</source>
        <translation>Назначение (приложение Л)</translation>
    </message>
</context>
<context>
    <name>k528::studio::RParamsPane</name>
    <message>
        <source>R-parameters</source>
        <translation>R-параметры</translation>
    </message>
    <message>
        <source>The machine's presets are not read from the database: %1</source>
        <translation>Предустановки станка не прочитаны из базы: %1</translation>
    </message>
    <message>
        <source>Search: number or meaning</source>
        <translation>Поиск: номер или назначение</translation>
    </message>
    <message>
        <source>All R0..R299</source>
        <translation>Все R0..R299</translation>
    </message>
    <message>
        <source>User R0..R149</source>
        <translation>Пользователя R0..R149</translation>
    </message>
    <message>
        <source>System (writable)</source>
        <translation>Системные (запись)</translation>
    </message>
    <message>
        <source>Read only R232..R262</source>
        <translation>Только чтение R232..R262</translation>
    </message>
    <message>
        <source>With a preset</source>
        <translation>С предустановкой</translation>
    </message>
    <message>
        <source>Not zero</source>
        <translation>Не ноль</translation>
    </message>
    <message>
        <source>Keep as preset</source>
        <translation>В предустановку</translation>
    </message>
    <message>
        <source>The selected parameter's value becomes the machine's preset (a new revision)</source>
        <translation>Значение выбранного параметра становится предустановкой станка (новая ревизия)</translation>
    </message>
    <message>
        <source>Remove preset</source>
        <translation>Убрать предустановку</translation>
    </message>
    <message>
        <source>Keep all as presets</source>
        <translation>Все в предустановки</translation>
    </message>
    <message>
        <source>Every writable R-parameter that is not 0 becomes a preset, as «Keep the controller's memory» does</source>
        <translation>Каждый записываемый R-параметр, не равный 0, становится предустановкой, как при «Сохранить память контроллера»</translation>
    </message>
    <message>
        <source>Load the presets</source>
        <translation>Ввести предустановки</translation>
    </message>
    <message>
        <source>The machine's presets into the controller</source>
        <translation>Предустановки станка — в контроллер</translation>
    </message>
    <message>
        <source>why the presets change (kept with the revision)</source>
        <translation>зачем меняются предустановки (сохраняется с ревизией)</translation>
    </message>
    <message>
        <source>No preset changes</source>
        <translation>Предустановки не меняются</translation>
    </message>
    <message>
        <source>The presets were not kept: %1</source>
        <translation>Предустановки не сохранены: %1</translation>
    </message>
    <message>
        <source>%1 — kept as revision %2 of %3</source>
        <translation>%1 — сохранено как ревизия %2 станка %3</translation>
    </message>
    <message>
        <source>Select an R-parameter first</source>
        <translation>Сначала выберите R-параметр</translation>
    </message>
    <message>
        <source>R%1 is read only (R232..R262): it cannot be preset</source>
        <translation>R%1 только для чтения (R232..R262): предустановка невозможна</translation>
    </message>
    <message>
        <source>The selected R-parameter has no preset</source>
        <translation>У выбранного R-параметра нет предустановки</translation>
    </message>
    <message>
        <source>Presets loaded into the controller: %1</source>
        <translation>Предустановок введено в контроллер: %1</translation>
    </message>
    <message>
        <source>Presets loaded into the controller: %1 of %2; R%3 not: %4</source>
        <translation>Предустановки загружены в контроллер: %1 из %2; R%3 — нет: %4</translation>
    </message>
    <message>
        <source>Database %1 has no machine %2: the presets shown are those the window loaded; the first one kept creates the machine there</source>
        <translation>В базе данных %1 нет станка %2: показаны предустановки, загруженные окном; первая сохранённая создаст станок в ней</translation>
    </message>
    <message>
        <source>Database %1: the presets shown are those of revision %2 of %3</source>
        <translation>База данных %1: показаны предустановки ревизии %2 станка %3</translation>
    </message>
    <message>
        <source>Trial part...</source>
        <translation>Пробная деталь...</translation>
    </message>
    <message>
        <source>The size measured on the trial part against the drawing: the change of the tool's offset R-parameter, kept as the machine's preset</source>
        <translation>Размер, измеренный на пробной детали, против чертёжного: изменение R-параметра коррекции инструмента, сохраняемое как предустановка станка</translation>
    </message>
    <message>
        <source>Kept as revision %1; R%2 not set in the controller: %3</source>
        <translation>Сохранено как ревизия %1; R%2 в УЧПУ не записан: %3</translation>
    </message>
    <message>
        <source>The R-parameters of the controller on the line, all read every 2.5 s.</source>
        <translation>R-параметры контроллера на линии, все считываются каждые 2,5 с.</translation>
    </message>
    <message>
        <source>R0..R231 are written to it at once (not R158, R222, R223).</source>
        <translation>R0..R231 сразу записываются в него (кроме R158, R222, R223).</translation>
    </message>
</context>
<context>
    <name>k528::studio::RefactorActions</name>
    <message>
        <source>Renumbered every program from %1 by %2</source>
        <translation>Все программы перенумерованы с %1 с шагом %2</translation>
    </message>
    <message>
        <source>Renumbered L%1 from %2 by %3</source>
        <translation>L%1 перенумерована с %2 с шагом %3</translation>
    </message>
    <message>
        <source>Copied L%1 to L%2</source>
        <translation>L%1 скопирована в L%2</translation>
    </message>
    <message>
        <source>Moved L%1 to L%2</source>
        <translation>L%1 перенесена в L%2</translation>
    </message>
    <message>
        <source>Formatted</source>
        <translation>Отформатировано</translation>
    </message>
    <message>
        <source>Renumber frames</source>
        <translation>Перенумеровать кадры</translation>
    </message>
    <message>
        <source>Every program</source>
        <translation>Все программы</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Программа</translation>
    </message>
    <message>
        <source>First number</source>
        <translation>Первый номер</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Шаг</translation>
    </message>
    <message>
        <source>The file has no program</source>
        <translation>В файле нет программ</translation>
    </message>
    <message>
        <source>Move or copy a program</source>
        <translation>Перенести или копировать программу</translation>
    </message>
    <message>
        <source>Keep the program (copy)</source>
        <translation>Сохранить программу (копия)</translation>
    </message>
    <message>
        <source>New number</source>
        <translation>Новый номер</translation>
    </message>
</context>
<context>
    <name>k528::studio::RefactorTexts</name>
    <message>
        <source>there is no program L%1</source>
        <translation>программы L%1 нет</translation>
    </message>
    <message>
        <source>a program number is 1..99, not %1</source>
        <translation>номер программы 1..99, а не %1</translation>
    </message>
    <message>
        <source>program L%1 exists already</source>
        <translation>программа L%1 уже есть</translation>
    </message>
    <message>
        <source>the start and step of numbering must be at least 1</source>
        <translation>начало и шаг нумерации должны быть не меньше 1</translation>
    </message>
    <message>
        <source>the last frame number would exceed 999 (%1 frames)</source>
        <translation>последний номер кадра превысил бы 999 (%1 кадров)</translation>
    </message>
</context>
<context>
    <name>k528::studio::RefusalTexts</name>
    <message>
        <source>F%1 selects no mode</source>
        <translation>F%1 не выбирает режим</translation>
    </message>
    <message>
        <source>the PLC sets the mode (Z1000.8-10 = %1)</source>
        <translation>режим задан из ПЛК (Z1000.8-10 = %1)</translation>
    </message>
    <message>
        <source>override keys are L1..L4, not L%1</source>
        <translation>клавиши коррекции — L1..L4, а не L%1</translation>
    </message>
    <message>
        <source>program numbers are 1..99, not %1</source>
        <translation>номера программ — 1..99, а не %1</translation>
    </message>
    <message>
        <source>R-parameters are R0..R299, not R%1</source>
        <translation>R-параметры — R0..R299, а не R%1</translation>
    </message>
    <message>
        <source>R%1 is read only (R232..R262)</source>
        <translation>R%1 только для чтения (R232..R262)</translation>
    </message>
    <message>
        <source>%1 is outside -2147483648..2147483647</source>
        <translation>%1 вне диапазона -2147483648..2147483647</translation>
    </message>
    <message>
        <source>a program is executing</source>
        <translation>выполняется программа</translation>
    </message>
    <message>
        <source>a program is active (running or held)</source>
        <translation>программа выполняется или остановлена</translation>
    </message>
    <message>
        <source>C-parameters are 1..152, not %1</source>
        <translation>C-параметры — 1..152, а не %1</translation>
    </message>
    <message>
        <source>%1 = %2 is outside the range %3 of «%4»</source>
        <translation>%1 = %2 вне диапазона %3 константы «%4»</translation>
    </message>
    <message>
        <source>C-parameters are edited in РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ (F5)</source>
        <translation>C-параметры редактируются в режиме РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ (F5)</translation>
    </message>
    <message>
        <source>153 values expected (C1..C152 at 1..152)</source>
        <translation>нужно 153 значения (C1..C152 на местах 1..152)</translation>
    </message>
    <message>
        <source>C-parameters are loaded from the PC in УПРАВЛЕНИЕ ДАННЫМИ (F7)</source>
        <translation>C-параметры загружаются с ЭВМ в режиме УПРАВЛЕНИЕ ДАННЫМИ (F7)</translation>
    </message>
    <message>
        <source>memory is cleared in УПРАВЛЕНИЕ ДАННЫМИ (F7)</source>
        <translation>память стирается в режиме УПРАВЛЕНИЕ ДАННЫМИ (F7)</translation>
    </message>
    <message>
        <source>axis %1 is not present</source>
        <translation>ось %1 отсутствует</translation>
    </message>
    <message>
        <source>the current value is set in ПРЕДУСТАНОВКИ (F4)</source>
        <translation>текущее значение задаётся в режиме ПРЕДУСТАНОВКИ (F4)</translation>
    </message>
    <message>
        <source>the zero offset would leave the 32-bit range</source>
        <translation>смещение нуля вышло бы за 32-разрядный диапазон</translation>
    </message>
    <message>
        <source>the PLC sets the mode</source>
        <translation>режим задан из ПЛК</translation>
    </message>
    <message>
        <source>not in this mode</source>
        <translation>не в этом режиме</translation>
    </message>
    <message>
        <source>a program is active</source>
        <translation>выполняется программа</translation>
    </message>
    <message>
        <source>read-only parameter</source>
        <translation>параметр только для чтения</translation>
    </message>
    <message>
        <source>no such parameter</source>
        <translation>нет такого параметра</translation>
    </message>
    <message>
        <source>value out of range</source>
        <translation>значение вне диапазона</translation>
    </message>
    <message>
        <source>no such program</source>
        <translation>программа отсутствует</translation>
    </message>
    <message>
        <source>the axis is not present</source>
        <translation>ось отсутствует</translation>
    </message>
    <message>
        <source>no such key</source>
        <translation>нет такой клавиши</translation>
    </message>
    <message>
        <source>the controller is off</source>
        <translation>устройство выключено</translation>
    </message>
</context>
<context>
    <name>k528::studio::RevisionNotes</name>
    <message>
        <source>built-in profile %1 (first start)</source>
        <translation>встроенный профиль %1 (первый запуск)</translation>
    </message>
    <message>
        <source>created</source>
        <translation>создан</translation>
    </message>
    <message>
        <source>set %1</source>
        <translation>задано: %1</translation>
    </message>
    <message>
        <source>changed %1</source>
        <translation>изменено: %1</translation>
    </message>
    <message>
        <source>changed %1 and %2 more</source>
        <translation>изменено: %1 и ещё %2</translation>
    </message>
    <message>
        <source>changed order of simulation settings</source>
        <translation>изменён порядок настроек моделирования</translation>
    </message>
    <message>
        <source>import %1</source>
        <translation>импорт %1</translation>
    </message>
    <message>
        <source>import %1 (K528 Studio)</source>
        <translation>импорт %1 (K528 Studio)</translation>
    </message>
    <message>
        <source>the machine as K528 Studio loaded it</source>
        <translation>станок, каким его загрузила K528 Studio</translation>
    </message>
    <message>
        <source>kept from the simulated controller's memory (K528 Studio)</source>
        <translation>сохранено из памяти моделируемого контроллера (K528 Studio)</translation>
    </message>
    <message>
        <source>programs and messages from the editor (K528 Studio)</source>
        <translation>программы и сообщения из редактора (K528 Studio)</translation>
    </message>
    <message>
        <source>set %1 = %2 (K528 Studio)</source>
        <translation>задано: %1 = %2 (K528 Studio)</translation>
    </message>
    <message>
        <source>undo: %1</source>
        <translation>отмена: %1</translation>
    </message>
    <message>
        <source>presets %1 (K528 Studio)</source>
        <translation>предустановки %1 (K528 Studio)</translation>
    </message>
    <message>
        <source>trial part: T%1 %2 measured %3 for %4: R%5 %6 -&gt; %7</source>
        <translation>пробная деталь: T%1 %2 измерено %3 при %4 по чертежу: R%5 %6 -&gt; %7</translation>
    </message>
    <message>
        <source>constants locked for the class %1 (trainer)</source>
        <translation>константы заблокированы для группы %1 (преподаватель)</translation>
    </message>
    <message>
        <source>constants unlocked (trainer; were locked for %1)</source>
        <translation>блокировка констант снята (преподаватель; были заблокированы для группы %1)</translation>
    </message>
</context>
<context>
    <name>k528::studio::RuleNames</name>
    <message>
        <source>not UTF-8</source>
        <translation>не UTF-8</translation>
    </message>
    <message>
        <source>unclosed comment</source>
        <translation>незакрытый комментарий</translation>
    </message>
    <message>
        <source>frame syntax</source>
        <translation>синтаксис кадра</translation>
    </message>
    <message>
        <source>Cyrillic letter</source>
        <translation>кириллическая буква</translation>
    </message>
    <message>
        <source>unknown address</source>
        <translation>неизвестный адрес</translation>
    </message>
    <message>
        <source>word given twice</source>
        <translation>слово дважды</translation>
    </message>
    <message>
        <source>too many G</source>
        <translation>больше трёх G</translation>
    </message>
    <message>
        <source>too many M</source>
        <translation>больше трёх M</translation>
    </message>
    <message>
        <source>F without an axis</source>
        <translation>F без оси</translation>
    </message>
    <message>
        <source>bad number</source>
        <translation>неверное число</translation>
    </message>
    <message>
        <source>point in an R frame</source>
        <translation>точка в R-кадре</translation>
    </message>
    <message>
        <source>number out of range</source>
        <translation>число вне диапазона</translation>
    </message>
    <message>
        <source>jump condition</source>
        <translation>условие перехода</translation>
    </message>
    <message>
        <source>bad header</source>
        <translation>неверный заголовок</translation>
    </message>
    <message>
        <source>program number</source>
        <translation>номер программы</translation>
    </message>
    <message>
        <source>program given twice</source>
        <translation>программа дважды</translation>
    </message>
    <message>
        <source>frame outside a program</source>
        <translation>кадр вне программы</translation>
    </message>
    <message>
        <source>message line</source>
        <translation>строка сообщения</translation>
    </message>
    <message>
        <source>message number</source>
        <translation>номер сообщения</translation>
    </message>
    <message>
        <source>message too long</source>
        <translation>длинное сообщение</translation>
    </message>
    <message>
        <source>message given twice</source>
        <translation>сообщение дважды</translation>
    </message>
    <message>
        <source>control character</source>
        <translation>управляющий символ</translation>
    </message>
    <message>
        <source>K923 characters</source>
        <translation>знаки K923</translation>
    </message>
    <message>
        <source>frame number</source>
        <translation>номер кадра</translation>
    </message>
    <message>
        <source>frame number twice</source>
        <translation>номер кадра дважды</translation>
    </message>
    <message>
        <source>too many frames</source>
        <translation>больше 999 кадров</translation>
    </message>
    <message>
        <source>empty program</source>
        <translation>пустая программа</translation>
    </message>
    <message>
        <source>no program</source>
        <translation>нет программы</translation>
    </message>
    <message>
        <source>coordinate range</source>
        <translation>диапазон координаты</translation>
    </message>
    <message>
        <source>feed range</source>
        <translation>диапазон подачи</translation>
    </message>
    <message>
        <source>unknown G</source>
        <translation>неизвестная G</translation>
    </message>
    <message>
        <source>G of one group</source>
        <translation>G одной группы</translation>
    </message>
    <message>
        <source>M out of range</source>
        <translation>M вне диапазона</translation>
    </message>
    <message>
        <source>M given twice</source>
        <translation>M дважды</translation>
    </message>
    <message>
        <source>message out of range</source>
        <translation>сообщение вне диапазона</translation>
    </message>
    <message>
        <source>message not in the table</source>
        <translation>нет в таблице сообщений</translation>
    </message>
    <message>
        <source>call out of range</source>
        <translation>вызов вне диапазона</translation>
    </message>
    <message>
        <source>called program missing</source>
        <translation>нет вызываемой программы</translation>
    </message>
    <message>
        <source>no such R</source>
        <translation>нет такого R</translation>
    </message>
    <message>
        <source>read-only R</source>
        <translation>R только для чтения</translation>
    </message>
    <message>
        <source>division by zero</source>
        <translation>деление на ноль</translation>
    </message>
    <message>
        <source>R overflow</source>
        <translation>переполнение R</translation>
    </message>
    <message>
        <source>jump target</source>
        <translation>цель перехода</translation>
    </message>
    <message>
        <source>axis with a call</source>
        <translation>ось с вызовом L</translation>
    </message>
    <message>
        <source>axis with M17</source>
        <translation>ось с M17</translation>
    </message>
    <message>
        <source>axis at the end of L</source>
        <translation>ось в конце L</translation>
    </message>
    <message>
        <source>two ends in a frame</source>
        <translation>два конца в кадре</translation>
    </message>
    <message>
        <source>G04 with Z</source>
        <translation>G04 с Z</translation>
    </message>
    <message>
        <source>G04 with a call</source>
        <translation>G04 с вызовом L</translation>
    </message>
    <message>
        <source>negative dwell</source>
        <translation>отрицательная выдержка</translation>
    </message>
    <message>
        <source>G04 without time</source>
        <translation>G04 без времени</translation>
    </message>
    <message>
        <source>G without its axis</source>
        <translation>G без своей оси</translation>
    </message>
    <message>
        <source>unreachable frame</source>
        <translation>недостижимый кадр</translation>
    </message>
    <message>
        <source>calls in a circle</source>
        <translation>вызовы по кругу</translation>
    </message>
    <message>
        <source>nesting too deep</source>
        <translation>глубокое вложение</translation>
    </message>
    <message>
        <source>no such axis</source>
        <translation>нет такой оси</translation>
    </message>
    <message>
        <source>software limit</source>
        <translation>программное ограничение</translation>
    </message>
    <message>
        <source>feed above maximum</source>
        <translation>подача выше предельной</translation>
    </message>
    <message>
        <source>rounded to a discrete</source>
        <translation>округление до дискреты</translation>
    </message>
    <message>
        <source>rapid into material</source>
        <translation>G00 в материал</translation>
    </message>
    <message>
        <source>tool into chuck</source>
        <translation>инструмент в патрон</translation>
    </message>
    <message>
        <source>turret into chuck</source>
        <translation>резцедержатель в патрон</translation>
    </message>
    <message>
        <source>feed, spindle stopped</source>
        <translation>подача без шпинделя</translation>
    </message>
    <message>
        <source>feed, wheel stopped</source>
        <translation>подача без круга</translation>
    </message>
    <message>
        <source>cut too deep</source>
        <translation>слишком глубокий рез</translation>
    </message>
    <message>
        <source>manual move into material</source>
        <translation>ручной ход в материал</translation>
    </message>
</context>
<context>
    <name>k528::studio::ScopeView</name>
    <message>
        <source>Export CSV</source>
        <translation>Экспорт CSV</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Cannot write %1</source>
        <translation>Не удаётся записать %1</translation>
    </message>
    <message>
        <source>Export PNG</source>
        <translation>Экспорт PNG</translation>
    </message>
    <message>
        <source>PNG (*.png)</source>
        <translation>PNG (*.png)</translation>
    </message>
    <message>
        <source>%1  t = %2 s  setpoint %3 mm  position %4 mm  speed %5 mm/min  following error %6 mm  DAC %7</source>
        <translation>%1  t = %2 с  задание %3 мм  положение %4 мм  скорость %5 мм/мин  ошибка рассогласования %6 мм  ЦАП %7</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Пауза</translation>
    </message>
    <message>
        <source>Window, s</source>
        <translation>Окно, с</translation>
    </message>
    <message>
        <source>Fourth trace</source>
        <translation>Четвёртый график</translation>
    </message>
    <message>
        <source>Speed, mm/min</source>
        <translation>Скорость, мм/мин</translation>
    </message>
    <message>
        <source>DAC code</source>
        <translation>Код ЦАП</translation>
    </message>
    <message>
        <source>Trigger</source>
        <translation>Запуск</translation>
    </message>
    <message>
        <source>Free running</source>
        <translation>Непрерывно</translation>
    </message>
    <message>
        <source>Frame start</source>
        <translation>Начало кадра</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>Авария</translation>
    </message>
    <message>
        <source>|Following error| over, mm</source>
        <translation>|Ошибка рассогласования| больше, мм</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>Экспорт CSV…</translation>
    </message>
    <message>
        <source>Export PNG…</source>
        <translation>Экспорт PNG…</translation>
    </message>
    <message>
        <source>Move the mouse over a chart to read the values.</source>
        <translation>Наведите мышь на график, чтобы прочитать значения.</translation>
    </message>
    <message>
        <source>Oscilloscope</source>
        <translation>Осциллограф</translation>
    </message>
    <message>
        <source>Time before the newest sample, s</source>
        <translation>Время до последнего отсчёта, с</translation>
    </message>
    <message>
        <source>Setpoint, mm</source>
        <translation>Задание, мм</translation>
    </message>
    <message>
        <source>Position, mm</source>
        <translation>Положение, мм</translation>
    </message>
    <message>
        <source>Following error, mm (right scale)</source>
        <translation>Ошибка рассогласования, мм (правая шкала)</translation>
    </message>
    <message>
        <source>DAC code (right scale)</source>
        <translation>Код ЦАП (правая шкала)</translation>
    </message>
    <message>
        <source>Speed, mm/min (right scale)</source>
        <translation>Скорость, мм/мин (правая шкала)</translation>
    </message>
    <message>
        <source>Axis X</source>
        <translation>Ось X</translation>
    </message>
    <message>
        <source>Axis Z</source>
        <translation>Ось Z</translation>
    </message>
    <message>
        <source>Live at %1 samples a second: the link's poll of the controller's positions and following errors (the setpoint is position + error; no DAC on the link).</source>
        <translation>В реальном времени, %1 отсчётов в секунду: опрос линией положений и рассогласований контроллера (задание = положение + рассогласование; ЦАП по линии нет).</translation>
    </message>
    <message>
        <source>Every servo tick of the simulated machine (%1 samples a second).</source>
        <translation>Каждый такт сервоцикла моделируемого станка (%1 отсчётов в секунду).</translation>
    </message>
    <message>
        <source>The link's map carries no DAC code: the simulated machine's only</source>
        <translation>Карта линии не содержит кода ЦАП: он есть только у моделируемого станка</translation>
    </message>
</context>
<context>
    <name>k528::studio::SetupSheetActions</name>
    <message>
        <source>Open a program file in the editor: its setup sheet is made on the machine it is checked for.</source>
        <translation>Откройте файл программ в редакторе: карта наладки составляется для станка, к которому он привязан.</translation>
    </message>
    <message>
        <source>The file is checked for no machine: choose one (Editor menu) for its setup sheet.</source>
        <translation>Файл не привязан к станку: выберите станок (меню «Редактор») для карты наладки.</translation>
    </message>
    <message>
        <source>The file has errors (Problems): its setup sheet is made once they are fixed.</source>
        <translation>В файле есть ошибки (список «Проблемы»): карта наладки составляется после их исправления.</translation>
    </message>
    <message>
        <source>The setup sheet cannot be made: %1</source>
        <translation>Карту наладки составить нельзя: %1</translation>
    </message>
    <message>
        <source>Setup sheet written to %1</source>
        <translation>Карта наладки записана в %1</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Не удаётся записать %1: %2</translation>
    </message>
    <message>
        <source>Export the setup sheet</source>
        <translation>Экспорт карты наладки</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Setup sheet</source>
        <translation>Карта наладки</translation>
    </message>
    <message>
        <source>Setup sheet: %1</source>
        <translation>Карта наладки: %1</translation>
    </message>
</context>
<context>
    <name>k528::studio::ShopDatabase</name>
    <message>
        <source>The database %1 failed: %2.</source>
        <translation>Ошибка базы данных %1: %2.</translation>
    </message>
    <message>
        <source>The database %1 failed: %2.
Details: %3</source>
        <translation>Ошибка базы данных %1: %2.
Подробности: %3</translation>
    </message>
</context>
<context>
    <name>k528::studio::ShopTile</name>
    <message>
        <source>Mode %1</source>
        <translation>Режим %1</translation>
    </message>
    <message>
        <source>, running</source>
        <translation>, выполнение</translation>
    </message>
    <message>
        <source>Program L%1, frame N%2</source>
        <translation>Программа L%1, кадр N%2</translation>
    </message>
    <message>
        <source>No program</source>
        <translation>Нет программы</translation>
    </message>
    <message>
        <source>Alarm (no number)</source>
        <translation>Авария (без номера)</translation>
    </message>
    <message>
        <source>The line does not answer</source>
        <translation>Линия не отвечает</translation>
    </message>
    <message>
        <source>Last answer at %1</source>
        <translation>Последний ответ в %1</translation>
    </message>
    <message>
        <source>No answer yet</source>
        <translation>Ответа ещё не было</translation>
    </message>
    <message>
        <source>Polling...</source>
        <translation>Опрос...</translation>
    </message>
    <message>
        <source>No transfer on record</source>
        <translation>Обменов не записано</translation>
    </message>
    <message>
        <source>Last transfer: %1</source>
        <translation>Последний обмен: %1</translation>
    </message>
    <message>
        <source>Click: show this machine's controller on every view of the window</source>
        <translation>Щелчок: показать УЧПУ этого станка во всех видах окна</translation>
    </message>
    <message>
        <source>%1 in this state, since %2</source>
        <translation>%1 в этом состоянии, с %2</translation>
    </message>
</context>
<context>
    <name>k528::studio::ShopView</name>
    <message>
        <source>run</source>
        <translation>работа</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>простой</translation>
    </message>
    <message>
        <source>alarm</source>
        <translation>авария</translation>
    </message>
    <message>
        <source>offline</source>
        <translation>нет связи</translation>
    </message>
    <message>
        <source>%1 d %2:%3</source>
        <translation>%1 сут %2:%3</translation>
    </message>
    <message>
        <source>alarm %1</source>
        <translation>авария %1</translation>
    </message>
    <message>
        <source>power-on</source>
        <translation>включение</translation>
    </message>
    <message>
        <source>Reload</source>
        <translation>Перечитать</translation>
    </message>
    <message>
        <source>Read the database's machines and their lines again</source>
        <translation>Заново прочитать станки базы данных и их линии</translation>
    </message>
    <message>
        <source>Alarms raised and cleared</source>
        <translation>Возникшие и снятые аварии</translation>
    </message>
    <message>
        <source>Today: minutes in each state</source>
        <translation>Сегодня: минуты в каждом состоянии</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Время</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Станок</translation>
    </message>
    <message>
        <source>Event</source>
        <translation>Событие</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>Авария</translation>
    </message>
    <message>
        <source>minutes</source>
        <translation>минуты</translation>
    </message>
    <message>
        <source>The database cannot be read: %1</source>
        <translation>Базу данных нельзя прочитать: %1</translation>
    </message>
    <message>
        <source>No machine of the database %1 keeps its controller's line: set a machine's line (Modbus TCP or serial) in the database to see it here.</source>
        <translation>Ни у одного станка базы данных %1 не задана линия его УЧПУ: задайте линию станка (Modbus TCP или последовательный порт) в базе данных, чтобы видеть его здесь.</translation>
    </message>
    <message>
        <source>Machines of the database %1 on their lines: %2; each line polled every %3 ms</source>
        <translation>Станки базы данных %1 на своих линиях: %2; каждая линия опрашивается каждые %3 мс</translation>
    </message>
    <message>
        <source>push</source>
        <translation>в УЧПУ</translation>
    </message>
    <message>
        <source>pull</source>
        <translation>из УЧПУ</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>успешно</translation>
    </message>
    <message>
        <source>partial</source>
        <translation>частично</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>не удалось</translation>
    </message>
    <message>
        <source>%1 %2, %3</source>
        <translation>%1 %2, %3</translation>
    </message>
    <message>
        <source>The machines cannot be polled: %1</source>
        <translation>Станки нельзя опросить: %1</translation>
    </message>
    <message>
        <source>raised</source>
        <translation>возникла</translation>
    </message>
    <message>
        <source>cleared</source>
        <translation>снята</translation>
    </message>
    <message>
        <source>The controller of %1 cannot be shown now: the Controller dock's line is busy</source>
        <translation>УЧПУ станка %1 сейчас нельзя показать: линия панели «Контроллер» занята</translation>
    </message>
    <message>
        <source>Connecting to the controller of %1...</source>
        <translation>Подключение к УЧПУ станка %1...</translation>
    </message>
    <message>
        <source>Publish to MQTT</source>
        <translation>Публиковать в MQTT</translation>
    </message>
    <message>
        <source>Every machine's state (retained) and each alarm raised or cleared to the MQTT broker, in the topics of k528 shop publish (k528/&lt;machine&gt;/state, k528/&lt;machine&gt;/alarms); the machines are polled while this is on, whatever page is shown</source>
        <translation>Состояние каждого станка (с сохранением на брокере) и каждая возникшая или снятая авария — брокеру MQTT, в темах, описанных в руководстве; пока публикация включена, станки опрашиваются, какая бы страница ни была открыта</translation>
    </message>
    <message>
        <source>Broker</source>
        <translation>Брокер</translation>
    </message>
    <message>
        <source>Connecting to the broker...</source>
        <translation>Подключение к брокеру...</translation>
    </message>
    <message>
        <source>Publishing as %1</source>
        <translation>Публикация под именем %1</translation>
    </message>
    <message>
        <source>Not publishing: the broker cannot be reached (see the tool tip)</source>
        <translation>Публикации нет: брокер недоступен (подробности — во всплывающей подсказке)</translation>
    </message>
</context>
<context>
    <name>k528::studio::SimulatedController</name>
    <message>
        <source>simulated %1</source>
        <translation>имитация %1</translation>
    </message>
</context>
<context>
    <name>k528::studio::SystemTexts</name>
    <message>
        <source>cannot open %1: %2</source>
        <translation>не удаётся открыть %1: %2</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>не удаётся прочитать %1: %2</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>не удаётся записать %1: %2</translation>
    </message>
    <message>
        <source>cannot read standard input: %1</source>
        <translation>не удаётся прочитать стандартный ввод: %1</translation>
    </message>
    <message>
        <source>cannot write standard output: %1</source>
        <translation>не удаётся записать стандартный вывод: %1</translation>
    </message>
    <message>
        <source>it is a directory</source>
        <translation>это папка</translation>
    </message>
    <message>
        <source>it is %1, not a regular file (k528 reads program and machine files only)</source>
        <translation>это %1, а не обычный файл (k528 читает только файлы программ и станков)</translation>
    </message>
    <message>
        <source>a directory</source>
        <translation>папка</translation>
    </message>
    <message>
        <source>a character device</source>
        <translation>символьное устройство</translation>
    </message>
    <message>
        <source>a block device</source>
        <translation>блочное устройство</translation>
    </message>
    <message>
        <source>a FIFO (named pipe)</source>
        <translation>FIFO (именованный канал)</translation>
    </message>
    <message>
        <source>a socket</source>
        <translation>сокет</translation>
    </message>
    <message>
        <source>a special file</source>
        <translation>особый файл</translation>
    </message>
    <message>
        <source>it is larger than %1 MiB, the most k528 reads (a K528-05 holds at most 99 programs of 999 frames, about 3 MB of text)</source>
        <translation>он больше %1 МиБ, а больше k528 не читает (K528-05 хранит не более 99 программ по 999 кадров — около 3 МБ текста)</translation>
    </message>
    <message>
        <source>not enough memory</source>
        <translation>не хватает памяти</translation>
    </message>
    <message>
        <source>it is a directory; give a file name</source>
        <translation>это папка; укажите имя файла</translation>
    </message>
    <message>
        <source>it is not a regular file, a FIFO or a character device</source>
        <translation>это не обычный файл, не FIFO и не символьное устройство</translation>
    </message>
    <message>
        <source>cannot create a file in its folder %1: %2</source>
        <translation>в его папке %1 нельзя создать файл: %2</translation>
    </message>
    <message>
        <source>it is not open</source>
        <translation>он не открыт</translation>
    </message>
    <message>
        <source>a write failed</source>
        <translation>запись не удалась</translation>
    </message>
    <message>
        <source>'%1' is not mqtt://HOST[:PORT] (plain MQTT; TLS is not supported)</source>
        <translation>«%1» — не mqtt://ХОСТ[:ПОРТ] (MQTT без шифрования; TLS не поддерживается)</translation>
    </message>
    <message>
        <source>'%1': the port is 1..65535</source>
        <translation>«%1»: порт — 1..65535</translation>
    </message>
    <message>
        <source>'%1': no host name or address after mqtt://</source>
        <translation>«%1»: после mqtt:// нет имени или адреса хоста</translation>
    </message>
    <message>
        <source>Operation not permitted</source>
        <translation>операция не разрешена</translation>
    </message>
    <message>
        <source>No such file or directory</source>
        <translation>нет такого файла или папки</translation>
    </message>
    <message>
        <source>Interrupted system call</source>
        <translation>системный вызов прерван</translation>
    </message>
    <message>
        <source>Input/output error</source>
        <translation>ошибка ввода-вывода</translation>
    </message>
    <message>
        <source>No such device or address</source>
        <translation>нет такого устройства или адреса</translation>
    </message>
    <message>
        <source>Bad file descriptor</source>
        <translation>неверный дескриптор файла</translation>
    </message>
    <message>
        <source>Resource temporarily unavailable</source>
        <translation>ресурс временно недоступен</translation>
    </message>
    <message>
        <source>Cannot allocate memory</source>
        <translation>не хватает памяти</translation>
    </message>
    <message>
        <source>Permission denied</source>
        <translation>доступ запрещён</translation>
    </message>
    <message>
        <source>Device or resource busy</source>
        <translation>устройство или ресурс занято</translation>
    </message>
    <message>
        <source>File exists</source>
        <translation>файл уже существует</translation>
    </message>
    <message>
        <source>Invalid cross-device link</source>
        <translation>ссылка между файловыми системами невозможна</translation>
    </message>
    <message>
        <source>No such device</source>
        <translation>нет такого устройства</translation>
    </message>
    <message>
        <source>Not a directory</source>
        <translation>это не папка</translation>
    </message>
    <message>
        <source>Is a directory</source>
        <translation>это папка</translation>
    </message>
    <message>
        <source>Invalid argument</source>
        <translation>недопустимый аргумент</translation>
    </message>
    <message>
        <source>Too many open files in system</source>
        <translation>слишком много открытых файлов в системе</translation>
    </message>
    <message>
        <source>Too many open files</source>
        <translation>слишком много открытых файлов</translation>
    </message>
    <message>
        <source>Text file busy</source>
        <translation>текстовый файл занят</translation>
    </message>
    <message>
        <source>File too large</source>
        <translation>файл слишком велик</translation>
    </message>
    <message>
        <source>No space left on device</source>
        <translation>на устройстве не осталось места</translation>
    </message>
    <message>
        <source>Illegal seek</source>
        <translation>недопустимое позиционирование</translation>
    </message>
    <message>
        <source>Read-only file system</source>
        <translation>файловая система только для чтения</translation>
    </message>
    <message>
        <source>Too many links</source>
        <translation>слишком много ссылок</translation>
    </message>
    <message>
        <source>Broken pipe</source>
        <translation>канал разорван</translation>
    </message>
    <message>
        <source>File name too long</source>
        <translation>слишком длинное имя файла</translation>
    </message>
    <message>
        <source>Too many levels of symbolic links</source>
        <translation>слишком много уровней символических ссылок</translation>
    </message>
    <message>
        <source>Directory not empty</source>
        <translation>папка не пуста</translation>
    </message>
    <message>
        <source>Disk quota exceeded</source>
        <translation>превышена дисковая квота</translation>
    </message>
    <message>
        <source>Stale file handle</source>
        <translation>устаревший дескриптор файла</translation>
    </message>
    <message>
        <source>Value too large for defined data type</source>
        <translation>значение слишком велико для типа данных</translation>
    </message>
    <message>
        <source>Operation not supported</source>
        <translation>операция не поддерживается</translation>
    </message>
    <message>
        <source>Connection refused</source>
        <translation>в соединении отказано</translation>
    </message>
    <message>
        <source>Connection timed out</source>
        <translation>время ожидания соединения истекло</translation>
    </message>
    <message>
        <source>%2 (error %1)</source>
        <translation>системная ошибка %1 («%2»)</translation>
    </message>
</context>
<context>
    <name>k528::studio::TeachIn</name>
    <message>
        <source>Open a program file in the editor to teach a position into it</source>
        <translation>Откройте файл программ в редакторе, чтобы записать в него положение</translation>
    </message>
    <message>
        <source>No controller is viewed: no position to teach</source>
        <translation>УЧПУ не показывается: положения для записи нет</translation>
    </message>
    <message>
        <source>The viewed controller has no axes: no position to teach</source>
        <translation>У показываемого УЧПУ нет осей: положения для записи нет</translation>
    </message>
    <message>
        <source>Taught: %1</source>
        <translation>Записано: %1</translation>
    </message>
    <message>
        <source>The viewed controller has no axis %1</source>
        <translation>У показываемого УЧПУ нет оси %1</translation>
    </message>
    <message>
        <source>Taught: %1 (%2 mm)</source>
        <translation>Записано: %1 (%2 мм)</translation>
    </message>
</context>
<context>
    <name>k528::studio::TrainingPane</name>
    <message>
        <source>Nothing is machined in this exercise</source>
        <translation>В этом упражнении деталь не обрабатывается</translation>
    </message>
    <message>
        <source>Exercise:</source>
        <translation>Упражнение:</translation>
    </message>
    <message>
        <source>Student:</source>
        <translation>Ученик:</translation>
    </message>
    <message>
        <source>the student's name</source>
        <translation>фамилия ученика</translation>
    </message>
    <message>
        <source>Grade the editor's program</source>
        <translation>Оценить программу из редактора</translation>
    </message>
    <message>
        <source>Runs the editor's program on a simulated machine of its own as the operator would and grades the part</source>
        <translation>Выполняет программу из редактора на отдельном моделируемом станке так, как это сделал бы оператор, и оценивает деталь</translation>
    </message>
    <message>
        <source>Grade a file…</source>
        <translation>Оценить файл…</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>Экспорт CSV</translation>
    </message>
    <message>
        <source>Task</source>
        <translation>Задание</translation>
    </message>
    <message>
        <source>Attempt</source>
        <translation>Попытка</translation>
    </message>
    <message>
        <source>Class</source>
        <translation>Группа</translation>
    </message>
    <message>
        <source>Student</source>
        <translation>Ученик</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Упражнение</translation>
    </message>
    <message>
        <source>Score</source>
        <translation>Балл</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Итог</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Время</translation>
    </message>
    <message>
        <source>passed</source>
        <translation>зачтено</translation>
    </message>
    <message>
        <source>not passed</source>
        <translation>не зачтено</translation>
    </message>
    <message>
        <source>Cycle time at most %1 s</source>
        <translation>Время цикла не более %1 с</translation>
    </message>
    <message>
        <source>The drawing: the half profile below, black; its tolerance limits dashed</source>
        <translation>Чертёж: полупрофиль ниже — чёрным, границы допуска — штрихом</translation>
    </message>
    <message>
        <source>The drawing: bore Ø%1, %2/%3 mm</source>
        <translation>Чертёж: отверстие Ø%1, %2/%3 мм</translation>
    </message>
    <message>
        <source>The drawing: the part the reference program makes, ±%1 mm</source>
        <translation>Чертёж: деталь эталонной программы, ±%1 мм</translation>
    </message>
    <message>
        <source>Hint:</source>
        <translation>Подсказка:</translation>
    </message>
    <message>
        <source>No attempt graded yet: write the program in the editor, then «Grade the editor's program»</source>
        <translation>Попыток ещё не было: напишите программу в редакторе и нажмите «Оценить программу из редактора»</translation>
    </message>
    <message>
        <source>%1: %2/100, %3</source>
        <translation>%1: %2/100, %3</translation>
    </message>
    <message>
        <source>cycle time %1 s</source>
        <translation>время цикла %1 с</translation>
    </message>
    <message>
        <source>(limit %1 s)</source>
        <translation>(норма %1 с)</translation>
    </message>
    <message>
        <source>line %1 «%2»: %3</source>
        <translation>строка %1 «%2»: %3</translation>
    </message>
    <message>
        <source>No deductions</source>
        <translation>Замечаний нет</translation>
    </message>
    <message>
        <source>The editor holds no program: open the student's file in the editor or use «Grade a file…»</source>
        <translation>В редакторе нет программы: откройте в нём файл ученика или нажмите «Оценить файл…»</translation>
    </message>
    <message>
        <source>the editor's program</source>
        <translation>программа из редактора</translation>
    </message>
    <message>
        <source>The student's program</source>
        <translation>Программа ученика</translation>
    </message>
    <message>
        <source>K528 programs (*.k528 *.txt);;All files (*)</source>
        <translation>Программы K528 (*.k528 *.txt);;Все файлы (*)</translation>
    </message>
    <message>
        <source>Training</source>
        <translation>Обучение</translation>
    </message>
    <message>
        <source>Grading: the program runs on the simulated machine…</source>
        <translation>Оценка: программа выполняется на моделируемом станке…</translation>
    </message>
    <message>
        <source>The attempt could not be graded: %1</source>
        <translation>Попытку оценить не удалось: %1</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Не удаётся записать %1: %2</translation>
    </message>
    <message>
        <source>Training course</source>
        <translation>Учебный курс</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Обновить</translation>
    </message>
    <message>
        <source>Reads the class's attempts from the database again</source>
        <translation>Заново прочитать попытки группы из базы данных</translation>
    </message>
    <message>
        <source>Not kept in the database: %1</source>
        <translation>Не сохранено в базе данных: %1</translation>
    </message>
    <message>
        <source>The database cannot be read: only this session's attempts are listed (%1)</source>
        <translation>База данных недоступна: показаны только попытки этого сеанса (%1)</translation>
    </message>
    <message>
        <source>Export PDF</source>
        <translation>Экспорт PDF</translation>
    </message>
    <message>
        <source>The class report as PDF: each attempt with its score and deductions</source>
        <translation>Отчёт по группе в PDF: каждая попытка с оценкой и снятыми баллами</translation>
    </message>
    <message>
        <source>Training course: class report</source>
        <translation>Учебный курс: отчёт по группе</translation>
    </message>
    <message>
        <source>Attempts: %1; printed %2</source>
        <translation>Попыток: %1; напечатано %2</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Файл</translation>
    </message>
    <message>
        <source>Cycle time, s</source>
        <translation>Время цикла, с</translation>
    </message>
    <message>
        <source>Deductions</source>
        <translation>Снятые баллы</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Lock the constants…</source>
        <translation>Заблокировать константы…</translation>
    </message>
    <message>
        <source>Unlock the constants</source>
        <translation>Снять блокировку констант</translation>
    </message>
    <message>
        <source>Lets the machine constants be changed again</source>
        <translation>Снова разрешает изменять константы станка</translation>
    </message>
    <message>
        <source>The machine constants are locked for the class «%1»</source>
        <translation>Константы станка заблокированы для группы «%1»</translation>
    </message>
    <message>
        <source>Locks the machine constants for a class: the constants dock and the K923 refuse changes until you unlock them (kept in the database)</source>
        <translation>Блокирует константы станка для группы: окно констант и К923 не дают их изменять, пока вы не снимете блокировку (хранится в базе данных)</translation>
    </message>
    <message>
        <source>The machine constants may be changed</source>
        <translation>Константы станка можно изменять</translation>
    </message>
    <message>
        <source>No machine</source>
        <translation>Нет станка</translation>
    </message>
    <message>
        <source>Lock the machine constants</source>
        <translation>Блокировка констант станка</translation>
    </message>
    <message>
        <source>The class the constants are locked for:</source>
        <translation>Группа, для которой блокируются константы:</translation>
    </message>
</context>
<context>
    <name>k528::studio::TrialPartDialog</name>
    <message>
        <source>Trial part: correct a tool's offset</source>
        <translation>Пробная деталь: коррекция инструмента</translation>
    </message>
    <message>
        <source>X: a diameter</source>
        <translation>X: диаметр</translation>
    </message>
    <message>
        <source>Z: a length</source>
        <translation>Z: длина</translation>
    </message>
    <message>
        <source>X of this machine shows a diameter: the offset changes by the diameter's error.</source>
        <translation>Ось X этого станка индицирует диаметр: коррекция меняется на ошибку диаметра.</translation>
    </message>
    <message>
        <source>X of this machine shows a radius: the offset changes by half the diameter's error.</source>
        <translation>Ось X этого станка индицирует радиус: коррекция меняется на половину ошибки диаметра.</translation>
    </message>
    <message>
        <source>A size that came out larger than the drawing's was cut with too large an offset: the new offset is the old one minus the error.</source>
        <translation>Размер больше чертёжного получен с завышенной коррекцией: новая коррекция равна старой минус ошибка.</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Инструмент</translation>
    </message>
    <message>
        <source>Measured on</source>
        <translation>Измерено по</translation>
    </message>
    <message>
        <source>Measured, mm</source>
        <translation>Измерено, мм</translation>
    </message>
    <message>
        <source>Drawing, mm</source>
        <translation>По чертежу, мм</translation>
    </message>
    <message>
        <source>Keep as the preset</source>
        <translation>Сохранить как предустановку</translation>
    </message>
    <message>
        <source>The new offset becomes the machine's preset (its next revision in the database, the measurement as its note) and goes into the controller</source>
        <translation>Новая коррекция становится предустановкой станка (следующая ревизия в базе данных, измерение — в примечании) и записывается в УЧПУ</translation>
    </message>
    <message>
        <source>The machine's tools are not described (tool.N.* of its settings).</source>
        <translation>Инструмент станка не описан (tool.N.* в его настройках).</translation>
    </message>
    <message>
        <source>Error %1 mm: R%2 %3 → %4 (offset %5 mm)</source>
        <translation>Ошибка %1 мм: R%2 %3 → %4 (коррекция %5 мм)</translation>
    </message>
    <message>
        <source>Enter the size measured on the trial part and the drawing's size.</source>
        <translation>Введите размер, измеренный на пробной детали, и размер по чертежу.</translation>
    </message>
</context>
<context>
    <name>k528::studio::Workspaces</name>
    <message>
        <source>&amp;Workspace</source>
        <translation>&amp;Рабочее место</translation>
    </message>
    <message>
        <source>&amp;Reset layout</source>
        <translation>&amp;Исходное расположение</translation>
    </message>
    <message>
        <source>The current workspace's docks where they were at first</source>
        <translation>Панели текущего рабочего места — на исходные места</translation>
    </message>
    <message>
        <source>Workspace: the window arranged for its user</source>
        <translation>Рабочее место: окно, устроенное для своего пользователя</translation>
    </message>
    <message>
        <source>Operator</source>
        <translation>Оператор</translation>
    </message>
    <message>
        <source>At the machine: the K923, the machine's panel, the program being run, the messages and the axes</source>
        <translation>У станка: K923, пульт станка, выполняемая программа, сообщения и оси</translation>
    </message>
    <message>
        <source>Technologist</source>
        <translation>Технолог</translation>
    </message>
    <message>
        <source>Programs: the editor with its problems and outline, the backplot; the debugger and the controller from the View menu</source>
        <translation>Программы: редактор с проблемами и структурой, траектория; отладчик и контроллер — из меню «Вид»</translation>
    </message>
    <message>
        <source>Training</source>
        <translation>Обучение</translation>
    </message>
    <message>
        <source>Learning the machine: the machine's panel, the K923, the backplot and the oscilloscope</source>
        <translation>Обучение на станке: пульт станка, K923, траектория и осциллограф</translation>
    </message>
    <message>
        <source>Shop</source>
        <translation>Цех</translation>
    </message>
    <message>
        <source>The shop floor: a tile per machine of the database on its line, the alarms as they come, today's time in each state; the controller of the machine clicked beside it</source>
        <translation>Цех: плитка на каждый станок базы данных на своей линии, аварии по мере появления, время в каждом состоянии за сегодня; рядом — УЧПУ станка, по которому щёлкнули</translation>
    </message>
</context>
<context>
    <name>k528::studio::backplot::BackplotDock</name>
    <message>
        <source>Backplot</source>
        <translation>Траектория</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Программа</translation>
    </message>
    <message>
        <source>Programmed path</source>
        <translation>Программная траектория</translation>
    </message>
    <message>
        <source>Simulate run</source>
        <translation>Моделировать отработку</translation>
    </message>
    <message>
        <source>Run the program on the simulated machine and overlay the actual path, coloured by following error</source>
        <translation>Отработать программу на модели станка и наложить фактическую траекторию, окрашенную по ошибке рассогласования</translation>
    </message>
    <message>
        <source>Blank (UCG)</source>
        <translation>Заготовка (UCG)</translation>
    </message>
    <message>
        <source>The backplot needs OpenGL (an X display)</source>
        <translation>Для траектории нужен OpenGL (дисплей X)</translation>
    </message>
    <message>
        <source>Follow the machine</source>
        <translation>Следить за станком</translation>
    </message>
    <message>
        <source>The actual path grows from the controller's live positions, read %1 times a second; a program's path once its text is read from the controller.</source>
        <translation>Фактическая траектория строится по текущим положениям контроллера, считываемым %1 раз в секунду; траектория программы — когда её текст считан из контроллера.</translation>
    </message>
    <message>
        <source>Reading L%1 from the controller for its path...</source>
        <translation>Чтение L%1 из контроллера для траектории...</translation>
    </message>
    <message>
        <source>While the controller shown runs a program, its path grows here live</source>
        <translation>Пока показываемый контроллер выполняет программу, её траектория строится здесь в реальном времени</translation>
    </message>
</context>
<context>
    <name>k528::studio::backplot::BackplotWidget</name>
    <message>
        <source>Fit</source>
        <translation>Вписать</translation>
    </message>
    <message>
        <source>Show the whole path (middle button pans, the wheel zooms)</source>
        <translation>Показать всю траекторию (средняя кнопка сдвигает, колесо масштабирует)</translation>
    </message>
    <message>
        <source>XZ view</source>
        <translation>Вид XZ</translation>
    </message>
    <message>
        <source>3D view</source>
        <translation>Вид 3D</translation>
    </message>
    <message>
        <source>fastest</source>
        <translation>максимально</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Пауза</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Воспроизвести</translation>
    </message>
    <message>
        <source>Previous frame</source>
        <translation>Предыдущий кадр</translation>
    </message>
    <message>
        <source>Next frame</source>
        <translation>Следующий кадр</translation>
    </message>
    <message>
        <source>Beyond the software limits</source>
        <translation>За программными ограничениями</translation>
    </message>
    <message>
        <source>Click a segment to find its frame</source>
        <translation>Щёлкните по отрезку, чтобы найти его кадр</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>строка %1</translation>
    </message>
    <message>
        <source>L%1 N%2, line %3</source>
        <translation>L%1 N%2, строка %3</translation>
    </message>
    <message>
        <source>No segment here</source>
        <translation>Здесь нет отрезка</translation>
    </message>
    <message>
        <source>%1 segments</source>
        <translation>отрезков: %1</translation>
    </message>
    <message>
        <source>X ⌀ diameter</source>
        <translation>X ⌀ диаметр</translation>
    </message>
    <message>
        <source>X radius</source>
        <translation>X радиус</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 мм</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <source>Stop computing the path (the view keeps what it shows)</source>
        <translation>Прекратить расчёт траектории (вид остаётся прежним)</translation>
    </message>
    <message>
        <source>L%1: computing the path… %2 frames</source>
        <translation>L%1: расчёт траектории… %2 кадров</translation>
    </message>
    <message>
        <source>L%1: cutting the blank… %2 of %3 moves</source>
        <translation>L%1: съём материала… %2 из %3 перемещений</translation>
    </message>
    <message>
        <source>L%1 does not end within %2 frames (an endless loop?): the path shows those frames</source>
        <translation>L%1 не заканчивается за %2 кадров (бесконечный цикл?): показана траектория этих кадров</translation>
    </message>
    <message>
        <source>L%1: the path was not computed (cancelled)</source>
        <translation>L%1: траектория не рассчитана (отменено)</translation>
    </message>
    <message>
        <source>L%1: simulating the run…</source>
        <translation>L%1: моделирование отработки…</translation>
    </message>
    <message>
        <source>µm</source>
        <translation>мкм</translation>
    </message>
</context>
<context>
    <name>k528::studio::backplot::VtkGlWidget</name>
    <message>
        <source>No OpenGL context for the backplot</source>
        <translation>Нет контекста OpenGL для траектории</translation>
    </message>
</context>
</TS>