<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>k528::studio::MainWindow</name>
    <message>
        <source>About K528 Studio</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;h3&gt;K528 Studio %1&lt;/h3&gt;&lt;p&gt;Workstation for the Konstar K528-05 two-axis positioning controller and its K923 operator panel.&lt;/p&gt;&lt;p&gt;Licence: GNU GPL version 3 or later.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>K528 Studio</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About K528 Studio</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>K923 operator panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine control panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Messages</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axes and signals</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The K923 panel: 4×20 LCD, 26 keys, 17 LEDs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The machine&apos;s push-buttons, handwheel, override and lamps.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alarms and messages of the controller and the machine.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis positions, following error, DAC and interface signals.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ready</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
