<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ru">
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
        <source>K528 Studio</source>
        <translation>K528 Studio</translation>
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
        <source>The machine's push-buttons, handwheel, override and lamps.</source>
        <translation>Кнопки пульта станка, маховик, корректор и лампы.</translation>
    </message>
    <message>
        <source>Alarms and messages of the controller and the machine.</source>
        <translation>Аварийные и рабочие сообщения УЧПУ и станка.</translation>
    </message>
    <message>
        <source>Axis positions, following error, DAC and interface signals.</source>
        <translation>Положение осей, рассогласование, ЦАП и сигналы интерфейса.</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Готово</translation>
    </message>
</context>
</TS>