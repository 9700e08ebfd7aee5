<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ru">
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
        <source>The K923 panel: 4×20 LCD, 26 keys, 17 LEDs.</source>
        <translation>Панель K923: индикатор 4×20, 26 клавиш, 17 светодиодов.</translation>
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