<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>CloseButton</name>
    <message>
        <source>Close Tab</source>
        <translation>Close Tab</translation>
    </message>
</context>
<context>
    <name>FaultTexts</name>
    <message>
        <source>spindle</source>
        <translation>spindle</translation>
    </message>
    <message>
        <source>wheel spindle</source>
        <translation>wheel spindle</translation>
    </message>
    <message>
        <source>work spindle</source>
        <translation>work spindle</translation>
    </message>
    <message>
        <source>coolant pump</source>
        <translation>coolant pump</translation>
    </message>
    <message>
        <source>lubrication pump</source>
        <translation>lubrication pump</translation>
    </message>
    <message>
        <source>hydraulic pump</source>
        <translation>hydraulic pump</translation>
    </message>
    <message>
        <source>Encoder %1: channel %2 broken</source>
        <translation>Encoder %1: channel %2 broken</translation>
    </message>
    <message>
        <source>Feed drive %1 not ready</source>
        <translation>Feed drive %1 not ready</translation>
    </message>
    <message>
        <source>Limit switch %1%2 hit</source>
        <translation>Limit switch %1%2 hit</translation>
    </message>
    <message>
        <source>Emergency stop circuit open</source>
        <translation>Emergency stop circuit open</translation>
    </message>
    <message>
        <source>Interference on encoder %1 (DAC limit)</source>
        <translation>Interference on encoder %1 (DAC limit)</translation>
    </message>
    <message>
        <source>PLC I/O module failure, place %1</source>
        <translation>PLC I/O module failure, place %1</translation>
    </message>
    <message>
        <source>PLC - positioner link lost</source>
        <translation>PLC - positioner link lost</translation>
    </message>
    <message>
        <source>Drive not ready: %1</source>
        <translation>Drive not ready: %1</translation>
    </message>
    <message>
        <source>Motor overheat: %1</source>
        <translation>Motor overheat: %1</translation>
    </message>
    <message>
        <source>Motor overload: %1</source>
        <translation>Motor overload: %1</translation>
    </message>
    <message>
        <source>Chuck loses its clamping pressure</source>
        <translation>Chuck loses its clamping pressure</translation>
    </message>
    <message>
        <source>Turret jammed</source>
        <translation>Turret jammed</translation>
    </message>
    <message>
        <source>In-process gauge fault</source>
        <translation>In-process gauge fault</translation>
    </message>
    <message>
        <source>Positioner: encoder module CP34.23, place 0, failed</source>
        <translation>Positioner: encoder module CP34.23, place 0, failed</translation>
    </message>
    <message>
        <source>Positioner: encoder module CP34.23, place 1, failed</source>
        <translation>Positioner: encoder module CP34.23, place 1, failed</translation>
    </message>
    <message>
        <source>Positioner: DAC module CM32.03 failed</source>
        <translation>Positioner: DAC module CM32.03 failed</translation>
    </message>
    <message>
        <source>Positioner: communication module CP52.05 failed</source>
        <translation>Positioner: communication module CP52.05 failed</translation>
    </message>
    <message>
        <source>Positioner: link to the K923 unstable</source>
        <translation>Positioner: link to the K923 unstable</translation>
    </message>
    <message>
        <source>Positioner: RAM/ROM test fails</source>
        <translation>Positioner: RAM/ROM test fails</translation>
    </message>
    <message>
        <source>K923: no link to the PLC</source>
        <translation>K923: no link to the PLC</translation>
    </message>
    <message>
        <source>K923: no link to the positioner</source>
        <translation>K923: no link to the positioner</translation>
    </message>
    <message>
        <source>K923: RAM fault</source>
        <translation>K923: RAM fault</translation>
    </message>
    <message>
        <source>K923: resident software corrupt</source>
        <translation>K923: resident software corrupt</translation>
    </message>
    <message>
        <source>PLC in debug stop</source>
        <translation>PLC in debug stop</translation>
    </message>
</context>
<context>
    <name>QDialog</name>
    <message>
        <source>%1 to the controller</source>
        <translation>%1 to the controller</translation>
    </message>
    <message>
        <source>The controller already holds what %1 has: nothing changes.</source>
        <translation>The controller already holds what %1 has: nothing changes.</translation>
    </message>
    <message>
        <source>Changes in the controller's memory: %1. Each part is committed all or nothing and read back; a controller on the line must be in F7 «РАБОТА С ПЭВМ».</source>
        <translation>Changes in the controller's memory: %1. Each part is committed all or nothing and read back; a controller on the line must be in F7 «РАБОТА С ПЭВМ».</translation>
    </message>
    <message>
        <source>Not sent as they are (a push takes released programs only; the machine's setting push.unreleased allows drafts):</source>
        <translation>Not sent as they are (a push takes released programs only; the machine's setting push.unreleased allows drafts):</translation>
    </message>
</context>
<context>
    <name>QsciScintilla</name>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Undo</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Redo</translation>
    </message>
    <message>
        <source>Cu&amp;t</source>
        <translation>Cu&amp;t</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Copy</translation>
    </message>
    <message>
        <source>&amp;Paste</source>
        <translation>&amp;Paste</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Delete</translation>
    </message>
    <message>
        <source>Select All</source>
        <translation>Select All</translation>
    </message>
</context>
<context>
    <name>TrainingTexts</name>
    <message>
        <source>the machine does not take the program: %1 errors, the first on line %2: %3</source>
        <translation>the machine does not take the program: %1 errors, the first on line %2: %3</translation>
    </message>
    <message>
        <source>the file holds no program: the machine has nothing to run</source>
        <translation>the file holds no program: the machine has nothing to run</translation>
    </message>
    <message>
        <source>line %1: the operator's step '%2' is not understood: %3</source>
        <translation>line %1: the operator's step '%2' is not understood: %3</translation>
    </message>
    <message>
        <source>HOLD:BUTTON:S holds a button for S seconds (0..3600)</source>
        <translation>HOLD:BUTTON:S holds a button for S seconds (0..3600)</translation>
    </message>
    <message>
        <source>the E-stop latches: PUSH:ESTOP, PULL:ESTOP</source>
        <translation>the E-stop latches: PUSH:ESTOP, PULL:ESTOP</translation>
    </message>
    <message>
        <source>no such button; the machine's buttons: DRIVES_ON START STOP RESET X+ X- Z+ Z- RAPID CHUCK ESTOP</source>
        <translation>no such button; the machine's buttons: DRIVES_ON START STOP RESET X+ X- Z+ Z- RAPID CHUCK ESTOP</translation>
    </message>
    <message>
        <source>WAIT:S waits S seconds (0..36000)</source>
        <translation>WAIT:S waits S seconds (0..36000)</translation>
    </message>
    <message>
        <source>PROGRAM:N takes a program number 1..99</source>
        <translation>PROGRAM:N takes a program number 1..99</translation>
    </message>
    <message>
        <source>HANDWHEEL:X, HANDWHEEL:Z or HANDWHEEL:OFF</source>
        <translation>HANDWHEEL:X, HANDWHEEL:Z or HANDWHEEL:OFF</translation>
    </message>
    <message>
        <source>STEP:1, STEP:10 or STEP:100: the handwheel's multiplier</source>
        <translation>STEP:1, STEP:10 or STEP:100: the handwheel's multiplier</translation>
    </message>
    <message>
        <source>TURN:N turns the handwheel by N detents (±1..100000)</source>
        <translation>TURN:N turns the handwheel by N detents (±1..100000)</translation>
    </message>
    <message>
        <source>OVERRIDE:P takes a step of the override: 0 1 2 5 10 20 35 50 75 90 100</source>
        <translation>OVERRIDE:P takes a step of the override: 0 1 2 5 10 20 35 50 75 90 100</translation>
    </message>
    <message>
        <source>R&lt;n&gt;=&lt;value&gt;: a writable R-parameter 0..231 and a whole value</source>
        <translation>R&lt;n&gt;=&lt;value&gt;: a writable R-parameter 0..231 and a whole value</translation>
    </message>
    <message>
        <source>expected one of: %2</source>
        <translation>expected one of: %2</translation>
    </message>
    <message>
        <source>program L%1 was not selected (ACK, number, ENTER in АВТОМАТ)</source>
        <translation>program L%1 was not selected (ACK, number, ENTER in АВТОМАТ)</translation>
    </message>
    <message>
        <source>the override %1 %% was not set: the machine has no such step</source>
        <translation>the override %1 %% was not set: the machine has no such step</translation>
    </message>
    <message>
        <source>the wheel was not changed: stop the wheel spindle first</source>
        <translation>the wheel was not changed: stop the wheel spindle first</translation>
    </message>
    <message>
        <source>the door did not open: it is locked</source>
        <translation>the door did not open: it is locked</translation>
    </message>
    <message>
        <source>the reference-point cycle did not complete: %1</source>
        <translation>the reference-point cycle did not complete: %1</translation>
    </message>
    <message>
        <source>%1 = %2 was not written (РУЧНОЙ, screen 3; not while a program runs)</source>
        <translation>%1 = %2 was not written (РУЧНОЙ, screen 3; not while a program runs)</translation>
    </message>
    <message>
        <source>over-cut: metal removed %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4 — frame %5, line %6</source>
        <translation>over-cut: metal removed %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4 — frame %5, line %6</translation>
    </message>
    <message>
        <source>over-cut by a manual move: metal removed %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4</source>
        <translation>over-cut by a manual move: metal removed %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4</translation>
    </message>
    <message>
        <source>over-cut: metal missing %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4</source>
        <translation>over-cut: metal missing %1 µm beyond the tolerance (area %2 mm²) at Ø%3 near Z%4</translation>
    </message>
    <message>
        <source>under-cut: %1 µm of metal left beyond the tolerance (area %2 mm²) at Ø%3 near Z%4; the nearest pass is frame %5, line %6</source>
        <translation>under-cut: %1 µm of metal left beyond the tolerance (area %2 mm²) at Ø%3 near Z%4; the nearest pass is frame %5, line %6</translation>
    </message>
    <message>
        <source>under-cut: %1 µm of metal left beyond the tolerance (area %2 mm²) at Ø%3 near Z%4: no pass came here</source>
        <translation>under-cut: %1 µm of metal left beyond the tolerance (area %2 mm²) at Ø%3 near Z%4: no pass came here</translation>
    </message>
    <message>
        <source>a rapid (G00) into the metal at X%1 Z%2, %3 mm into the blank — frame %4, line %5: the tool is broken</source>
        <translation>a rapid (G00) into the metal at X%1 Z%2, %3 mm into the blank — frame %4, line %5: the tool is broken</translation>
    </message>
    <message>
        <source>a manual move into the metal at X%1 Z%2, %3 mm into the blank: the tool is broken</source>
        <translation>a manual move into the metal at X%1 Z%2, %3 mm into the blank: the tool is broken</translation>
    </message>
    <message>
        <source>cutting with the spindle stopped at X%1 Z%2 — frame %4, line %5: start the spindle (M3) before the feed</source>
        <translation>cutting with the spindle stopped at X%1 Z%2 — frame %4, line %5: start the spindle (M3) before the feed</translation>
    </message>
    <message>
        <source>a feed of the wheel into the ring with the wheel stopped: its edge at Ø%1 near Z%2 — frame %4, line %5: start the wheel before the feed</source>
        <translation>a feed of the wheel into the ring with the wheel stopped: its edge at Ø%1 near Z%2 — frame %4, line %5: start the wheel before the feed</translation>
    </message>
    <message>
        <source>the tool into the chuck's jaws at X%1 Z%2 — frame %4, line %5</source>
        <translation>the tool into the chuck's jaws at X%1 Z%2 — frame %4, line %5</translation>
    </message>
    <message>
        <source>the tool into the chuck's body at X%1 Z%2 — frame %4, line %5</source>
        <translation>the tool into the chuck's body at X%1 Z%2 — frame %4, line %5</translation>
    </message>
    <message>
        <source>the tool into the chuck or its jaws by a manual move at X%1 Z%2</source>
        <translation>the tool into the chuck or its jaws by a manual move at X%1 Z%2</translation>
    </message>
    <message>
        <source>the wheel into the ring at rapid: its edge at Ø%1 near Z%2, %3 mm into the wall — frame %4, line %5</source>
        <translation>the wheel into the ring at rapid: its edge at Ø%1 near Z%2, %3 mm into the wall — frame %4, line %5</translation>
    </message>
    <message>
        <source>message %1 «%2» — frame %3, line %4: it must not come in this exercise</source>
        <translation>message %1 «%2» — frame %3, line %4: it must not come in this exercise</translation>
    </message>
    <message>
        <source>message %1 «%2»: it must not come in this exercise</source>
        <translation>message %1 «%2»: it must not come in this exercise</translation>
    </message>
    <message>
        <source>the program was never started</source>
        <translation>the program was never started</translation>
    </message>
    <message>
        <source>the program did not start: %1</source>
        <translation>the program did not start: %1</translation>
    </message>
    <message>
        <source>a message stopped the program before its end — frame %1, line %2</source>
        <translation>a message stopped the program before its end — frame %1, line %2</translation>
    </message>
    <message>
        <source>the program was interrupted before its end — frame %1, line %2</source>
        <translation>the program was interrupted before its end — frame %1, line %2</translation>
    </message>
    <message>
        <source>the program did not end in the time given — frame %1, line %2</source>
        <translation>the program did not end in the time given — frame %1, line %2</translation>
    </message>
    <message>
        <source>cycle time %1 s is over the limit of %2 s</source>
        <translation>cycle time %1 s is over the limit of %2 s</translation>
    </message>
    <message>
        <source>the reference-point cycle (ПБТ) of X and Z was not done before the program started</source>
        <translation>the reference-point cycle (ПБТ) of X and Z was not done before the program started</translation>
    </message>
    <message>
        <source>R%1 was %2 when the program started; the task asks for %3 (РУЧНОЙ, screen 3)</source>
        <translation>R%1 was %2 when the program started; the task asks for %3 (РУЧНОЙ, screen 3)</translation>
    </message>
    <message>
        <source>messages not acknowledged (ESC): %1</source>
        <translation>messages not acknowledged (ESC): %1</translation>
    </message>
    <message>
        <source>the tool stopped at X%1 Z%2; the task asks for X%3 Z%4 (±%5 mm)</source>
        <translation>the tool stopped at X%1 Z%2; the task asks for X%3 Z%4 (±%5 mm)</translation>
    </message>
    <message>
        <source>the worn wheel was not changed (NEW WHEEL)</source>
        <translation>the worn wheel was not changed (NEW WHEEL)</translation>
    </message>
    <message>
        <source>the program did not run to its end</source>
        <translation>the program did not run to its end</translation>
    </message>
    <message>
        <source>the spindle still turns after the program (M5)</source>
        <translation>the spindle still turns after the program (M5)</translation>
    </message>
    <message>
        <source>the coolant is still on after the program (M9)</source>
        <translation>the coolant is still on after the program (M9)</translation>
    </message>
    <message>
        <source>the in-process gauge is still in the bore after the program (M21)</source>
        <translation>the in-process gauge is still in the bore after the program (M21)</translation>
    </message>
    <message>
        <source>R%1 is %2 after the program; %3 was expected</source>
        <translation>R%1 is %2 after the program; %3 was expected</translation>
    </message>
    <message>
        <source>the tool into the chuck or its jaws at X%1 Z%2 — frame %4, line %5</source>
        <translation>the tool into the chuck or its jaws at X%1 Z%2 — frame %4, line %5</translation>
    </message>
    <message>
        <source>the program did not start after CYCLE START</source>
        <translation>the program did not start after CYCLE START</translation>
    </message>
</context>
<context>
    <name>k528::studio</name>
    <message>
        <source>%1 has errors: nothing was loaded.</source>
        <translation>%1 has errors: nothing was loaded.</translation>
    </message>
    <message>
        <source>%1 holds no program.</source>
        <translation>%1 holds no program.</translation>
    </message>
    <message>
        <source>A program is running: stop it (RESET) before loading programs.</source>
        <translation>A program is running: stop it (RESET) before loading programs.</translation>
    </message>
    <message>
        <source>Fix the syntax errors first: %1</source>
        <translation>Fix the syntax errors first: %1</translation>
    </message>
    <message>
        <source>The file has no program L%1</source>
        <translation>The file has no program L%1</translation>
    </message>
    <message>
        <source>error</source>
        <translation>error</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>warning</translation>
    </message>
    <message>
        <source>none (the language only)</source>
        <translation>none (the language only)</translation>
    </message>
    <message>
        <source>File: %1</source>
        <translation>File: %1</translation>
    </message>
    <message>
        <source>Machine: %1    Date: %2</source>
        <translation>Machine: %1    Date: %2</translation>
    </message>
    <message>
        <source>Errors: %1, warnings: %2    Page %3 of %4</source>
        <translation>Errors: %1, warnings: %2    Page %3 of %4</translation>
    </message>
    <message>
        <source>%1 cannot be written: %2</source>
        <translation>%1 cannot be written: %2</translation>
    </message>
    <message>
        <source>%1 cannot be written</source>
        <translation>%1 cannot be written</translation>
    </message>
    <message>
        <source>The database has no machine %1</source>
        <translation>The database has no machine %1</translation>
    </message>
    <message>
        <source>Not saved: fix the syntax errors first: %1</source>
        <translation>Not saved: fix the syntax errors first: %1</translation>
    </message>
    <message>
        <source>Not saved: every program needs its %L header in the machine's memory</source>
        <translation>Not saved: every program needs its %L header in the machine's memory</translation>
    </message>
    <message>
        <source>Not saved: %1 was changed in the database since revision %2 was opened (%3)</source>
        <translation>Not saved: %1 was changed in the database since revision %2 was opened (%3)</translation>
    </message>
    <message>
        <source>%1 is the database this window uses: it is not read as a program</source>
        <translation>%1 is the database this window uses: it is not read as a program</translation>
    </message>
</context>
<context>
    <name>k528::studio::AxesView</name>
    <message>
        <source>Axis</source>
        <translation>Axis</translation>
    </message>
    <message>
        <source>Current, mm</source>
        <translation>Current, mm</translation>
    </message>
    <message>
        <source>Machine, mm</source>
        <translation>Machine, mm</translation>
    </message>
    <message>
        <source>Rest, mm</source>
        <translation>Rest, mm</translation>
    </message>
    <message>
        <source>Feed, mm/min</source>
        <translation>Feed, mm/min</translation>
    </message>
    <message>
        <source>Error, µm</source>
        <translation>Error, µm</translation>
    </message>
    <message>
        <source>DAC</source>
        <translation>DAC</translation>
    </message>
    <message>
        <source>Volts</source>
        <translation>Volts</translation>
    </message>
    <message>
        <source>State</source>
        <translation>State</translation>
    </message>
    <message>
        <source> (dia.)</source>
        <translation> (dia.)</translation>
    </message>
    <message>
        <source>absent</source>
        <translation>absent</translation>
    </message>
    <message>
        <source>homing</source>
        <translation>homing</translation>
    </message>
    <message>
        <source>homed</source>
        <translation>homed</translation>
    </message>
    <message>
        <source>not homed</source>
        <translation>not homed</translation>
    </message>
    <message>
        <source>loop closed</source>
        <translation>loop closed</translation>
    </message>
    <message>
        <source>loop open</source>
        <translation>loop open</translation>
    </message>
    <message>
        <source>moving</source>
        <translation>moving</translation>
    </message>
    <message>
        <source>in position</source>
        <translation>in position</translation>
    </message>
    <message>
        <source>cam</source>
        <translation>cam</translation>
    </message>
    <message>
        <source>limit +</source>
        <translation>limit +</translation>
    </message>
    <message>
        <source>limit -</source>
        <translation>limit -</translation>
    </message>
    <message>
        <source>fault %1</source>
        <translation>fault %1</translation>
    </message>
    <message>
        <source>Z1000 PLC→</source>
        <translation>Z1000 PLC→</translation>
    </message>
    <message>
        <source>E-stop released</source>
        <translation>E-stop released</translation>
    </message>
    <message>
        <source>feed enable</source>
        <translation>feed enable</translation>
    </message>
    <message>
        <source>start enable</source>
        <translation>start enable</translation>
    </message>
    <message>
        <source>start</source>
        <translation>start</translation>
    </message>
    <message>
        <source>stop</source>
        <translation>stop</translation>
    </message>
    <message>
        <source>reset</source>
        <translation>reset</translation>
    </message>
    <message>
        <source>data hold</source>
        <translation>data hold</translation>
    </message>
    <message>
        <source>acknowledge</source>
        <translation>acknowledge</translation>
    </message>
    <message>
        <source>M done</source>
        <translation>M done</translation>
    </message>
    <message>
        <source>mode %1</source>
        <translation>mode %1</translation>
    </message>
    <message>
        <source>Z2000 →PLC</source>
        <translation>Z2000 →PLC</translation>
    </message>
    <message>
        <source>ready</source>
        <translation>ready</translation>
    </message>
    <message>
        <source>running</source>
        <translation>running</translation>
    </message>
    <message>
        <source>interrupted</source>
        <translation>interrupted</translation>
    </message>
    <message>
        <source>end/reset</source>
        <translation>end/reset</translation>
    </message>
    <message>
        <source>dwell</source>
        <translation>dwell</translation>
    </message>
    <message>
        <source>M00</source>
        <translation>M00</translation>
    </message>
    <message>
        <source>override 0%</source>
        <translation>override 0%</translation>
    </message>
    <message>
        <source>change wheel</source>
        <translation>change wheel</translation>
    </message>
    <message>
        <source>Z2001</source>
        <translation>Z2001</translation>
    </message>
    <message>
        <source>M strobe</source>
        <translation>M strobe</translation>
    </message>
    <message>
        <source>M code %1</source>
        <translation>M code %1</translation>
    </message>
    <message>
        <source>cycle %1</source>
        <translation>cycle %1</translation>
    </message>
    <message>
        <source>regulator</source>
        <translation>regulator</translation>
    </message>
    <message>
        <source>feed</source>
        <translation>feed</translation>
    </message>
    <message>
        <source>jog +</source>
        <translation>jog +</translation>
    </message>
    <message>
        <source>jog -</source>
        <translation>jog -</translation>
    </message>
    <message>
        <source>rapid</source>
        <translation>rapid</translation>
    </message>
    <message>
        <source>loop</source>
        <translation>loop</translation>
    </message>
    <message>
        <source>loop error</source>
        <translation>loop error</translation>
    </message>
    <message>
        <source>fast inputs </source>
        <translation>fast inputs </translation>
    </message>
</context>
<context>
    <name>k528::studio::CalculatorDialog</name>
    <message>
        <source>C-constant calculator: acceleration (parameter 22)</source>
        <translation>C-constant calculator: acceleration (parameter 22)</translation>
    </message>
    <message>
        <source>Axis X (C22)</source>
        <translation>Axis X (C22)</translation>
    </message>
    <message>
        <source>Axis Z (C74)</source>
        <translation>Axis Z (C74)</translation>
    </message>
    <message>
        <source>Formula 2: braking from Vmax over S</source>
        <translation>Formula 2: braking from Vmax over S</translation>
    </message>
    <message>
        <source>Formula 3: acceleration A</source>
        <translation>Formula 3: acceleration A</translation>
    </message>
    <message>
        <source>Vmax, mm/min</source>
        <translation>Vmax, mm/min</translation>
    </message>
    <message>
        <source>S, mm of braking</source>
        <translation>S, mm of braking</translation>
    </message>
    <message>
        <source>A, m/s²</source>
        <translation>A, m/s²</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Axis</translation>
    </message>
    <message>
        <source>Formula</source>
        <translation>Formula</translation>
    </message>
    <message>
        <source>Formula 2 as printed: C = 3.556·10⁻⁶ · Vmax² / S, Vmax in discretes/min, S in discretes: 3.556·10⁻⁶ · %1² / %2 = %3.</source>
        <translation>Formula 2 as printed: C = 3.556·10⁻⁶ · Vmax² / S, Vmax in discretes/min, S in discretes: 3.556·10⁻⁶ · %1² / %2 = %3.</translation>
    </message>
    <message>
        <source>Formula 3: C = 25600 · A / Kd, A in m/s², Kd = %1 (the discrete in µm): 25600 · %2 / %1 = %3.</source>
        <translation>Formula 3: C = 25600 · A / Kd, A in m/s², Kd = %1 (the discrete in µm): 25600 · %2 / %1 = %3.</translation>
    </message>
    <message>
        <source>The motion described: A = %1 m/s². The value as printed: &lt;b&gt;%2&lt;/b&gt;, which means %3 m/s² in K528 Studio's unit (factor %4).</source>
        <translation>The motion described: A = %1 m/s². The value as printed: &lt;b&gt;%2&lt;/b&gt;, which means %3 m/s² in K528 Studio's unit (factor %4).</translation>
    </message>
    <message>
        <source>The value that gives this motion: &lt;b&gt;%1&lt;/b&gt; (25600 · A / Kd = %2, integer part). Enter this one in C%3.</source>
        <translation>The value that gives this motion: &lt;b&gt;%1&lt;/b&gt; (25600 · A / Kd = %2, integer part). Enter this one in C%3.</translation>
    </message>
    <message>
        <source>Why formula 1 gives twice the value</source>
        <translation>Why formula 1 gives twice the value</translation>
    </message>
    <message>
        <source>Set C%1 to %2</source>
        <translation>Set C%1 to %2</translation>
    </message>
    <message>
        <source>calculator: %1 → C%2 = %3</source>
        <translation>calculator: %1 → C%2 = %3</translation>
    </message>
    <message>
        <source>Formula 1: run-up from 0 to Vmax in Tacc</source>
        <translation>Formula 1: run-up from 0 to Vmax in Tacc</translation>
    </message>
    <message>
        <source>Tacc, ms</source>
        <translation>Tacc, ms</translation>
    </message>
    <message>
        <source>Formula 1 as printed: C = 0.8533 · Vmax / Tacc, Vmax in discretes/min, Tacc in ms: 0.8533 · %1 / %2 = %3.</source>
        <translation>Formula 1 as printed: C = 0.8533 · Vmax / Tacc, Vmax in discretes/min, Tacc in ms: 0.8533 · %1 / %2 = %3.</translation>
    </message>
    <message>
        <source>Table E.1 prints three formulas for parameter 22. Formula 3 defines the unit: C = 25600·A/Kd. Braking from V to 0 over S needs A = V²/(2S); put into formula 3 this is 25600/7200·10⁻⁶·V²/S = 3.5556·10⁻⁶·V²/S — formula 2's 3.556 rounded. A run-up from 0 to V in T needs A = V/T, that is 25600/60000·V/T = 0.4267·V/T; formula 1 prints 0.8533, twice as much.</source>
        <translation>Table E.1 prints three formulas for parameter 22. Formula 3 defines the unit: C = 25600·A/Kd. Braking from V to 0 over S needs A = V²/(2S); put into formula 3 this is 25600/7200·10⁻⁶·V²/S = 3.5556·10⁻⁶·V²/S — formula 2's 3.556 rounded. A run-up from 0 to V in T needs A = V/T, that is 25600/60000·V/T = 0.4267·V/T; formula 1 prints 0.8533, twice as much.</translation>
    </message>
    <message>
        <source>Two formulas against one: K528 Studio takes the unit of formulas 2 and 3 (docs/machine-constants.md). A value computed by formula 1 as printed makes the axis accelerate twice as fast as described (appendix Zh's 2000 for «2 s to 5000 mm/min» runs up in 1.07 s here). Apply the consistent value.</source>
        <translation>Two formulas against one: K528 Studio takes the unit of formulas 2 and 3 (docs/machine-constants.md). A value computed by formula 1 as printed makes the axis accelerate twice as fast as described (appendix Zh's 2000 for «2 s to 5000 mm/min» runs up in 1.07 s here). Apply the consistent value.</translation>
    </message>
</context>
<context>
    <name>k528::studio::CatalogTexts</name>
    <message>
        <source>No regulator enable X</source>
        <translation>No regulator enable X</translation>
    </message>
    <message>
        <source>No answer from encoder slot 0</source>
        <translation>No answer from encoder slot 0</translation>
    </message>
    <message>
        <source>No answer from DAC</source>
        <translation>No answer from DAC</translation>
    </message>
    <message>
        <source>Encoder channel 1 broken (X)</source>
        <translation>Encoder channel 1 broken (X)</translation>
    </message>
    <message>
        <source>Encoder channel 2 broken (X)</source>
        <translation>Encoder channel 2 broken (X)</translation>
    </message>
    <message>
        <source>DAC limit exceeded (X)</source>
        <translation>DAC limit exceeded (X)</translation>
    </message>
    <message>
        <source>Max. following error X in motion</source>
        <translation>Max. following error X in motion</translation>
    </message>
    <message>
        <source>Position/clamp check X</source>
        <translation>Position/clamp check X</translation>
    </message>
    <message>
        <source>Emergency "STOP" from PLC</source>
        <translation>Emergency "STOP" from PLC</translation>
    </message>
    <message>
        <source>Limit switch X "-"</source>
        <translation>Limit switch X "-"</translation>
    </message>
    <message>
        <source>Limit switch X "+"</source>
        <translation>Limit switch X "+"</translation>
    </message>
    <message>
        <source>Software limit switch (X)</source>
        <translation>Software limit switch (X)</translation>
    </message>
    <message>
        <source>Encoder ratio error (X)</source>
        <translation>Encoder ratio error (X)</translation>
    </message>
    <message>
        <source>CP52.05 failure in positioner</source>
        <translation>CP52.05 failure in positioner</translation>
    </message>
    <message>
        <source>C-parameters destroyed</source>
        <translation>C-parameters destroyed</translation>
    </message>
    <message>
        <source>Drive X not ready</source>
        <translation>Drive X not ready</translation>
    </message>
    <message>
        <source>No regulator enable Z</source>
        <translation>No regulator enable Z</translation>
    </message>
    <message>
        <source>No answer from encoder slot 1</source>
        <translation>No answer from encoder slot 1</translation>
    </message>
    <message>
        <source>No link with PLC</source>
        <translation>No link with PLC</translation>
    </message>
    <message>
        <source>Encoder channel 1 broken (Z)</source>
        <translation>Encoder channel 1 broken (Z)</translation>
    </message>
    <message>
        <source>Encoder channel 2 broken (Z)</source>
        <translation>Encoder channel 2 broken (Z)</translation>
    </message>
    <message>
        <source>DAC limit exceeded (Z)</source>
        <translation>DAC limit exceeded (Z)</translation>
    </message>
    <message>
        <source>Max. following error Z in motion</source>
        <translation>Max. following error Z in motion</translation>
    </message>
    <message>
        <source>Position/clamp check Z</source>
        <translation>Position/clamp check Z</translation>
    </message>
    <message>
        <source>No link with panel</source>
        <translation>No link with panel</translation>
    </message>
    <message>
        <source>Limit switch Z "-"</source>
        <translation>Limit switch Z "-"</translation>
    </message>
    <message>
        <source>Limit switch Z "+"</source>
        <translation>Limit switch Z "+"</translation>
    </message>
    <message>
        <source>Software limit switch (Z)</source>
        <translation>Software limit switch (Z)</translation>
    </message>
    <message>
        <source>Encoder ratio error (Z)</source>
        <translation>Encoder ratio error (Z)</translation>
    </message>
    <message>
        <source>Positioner RAM/ROM failure</source>
        <translation>Positioner RAM/ROM failure</translation>
    </message>
    <message>
        <source>Control program destroyed</source>
        <translation>Control program destroyed</translation>
    </message>
    <message>
        <source>Drive Z not ready</source>
        <translation>Drive Z not ready</translation>
    </message>
    <message>
        <source>X coordinate setting</source>
        <translation>X coordinate setting</translation>
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
        <translation>X/end of L</translation>
    </message>
    <message>
        <source>N encoder error</source>
        <translation>N encoder error</translation>
    </message>
    <message>
        <source>N DAC error</source>
        <translation>N DAC error</translation>
    </message>
    <message>
        <source>N handwheel error</source>
        <translation>N handwheel error</translation>
    </message>
    <message>
        <source>Home switch not left</source>
        <translation>Home switch not left</translation>
    </message>
    <message>
        <source>No "0" mark</source>
        <translation>No "0" mark</translation>
    </message>
    <message>
        <source>Not homed</source>
        <translation>Not homed</translation>
    </message>
    <message>
        <source>Wheel D &gt; Dmax</source>
        <translation>Wheel D &gt; Dmax</translation>
    </message>
    <message>
        <source>Wheel D &lt; Dmin</source>
        <translation>Wheel D &lt; Dmin</translation>
    </message>
    <message>
        <source>L missing</source>
        <translation>L missing</translation>
    </message>
    <message>
        <source>Overflow</source>
        <translation>Overflow</translation>
    </message>
    <message>
        <source>G?</source>
        <translation>G?</translation>
    </message>
    <message>
        <source>Nesting depth L</source>
        <translation>Nesting depth L</translation>
    </message>
    <message>
        <source>Z coordinate setting</source>
        <translation>Z coordinate setting</translation>
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
        <translation>Z/end of L</translation>
    </message>
    <message>
        <source>Jump error</source>
        <translation>Jump error</translation>
    </message>
    <message>
        <source>Duplicate frame numbers</source>
        <translation>Duplicate frame numbers</translation>
    </message>
    <message>
        <source>PLC I/O module failure</source>
        <translation>PLC I/O module failure</translation>
    </message>
    <message>
        <source>Encoder check X</source>
        <translation>Encoder check X</translation>
    </message>
    <message>
        <source>Encoder check Z</source>
        <translation>Encoder check Z</translation>
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
        <translation>automatic</translation>
    </message>
    <message>
        <source>manual</source>
        <translation>manual</translation>
    </message>
    <message>
        <source>reference point</source>
        <translation>reference point</translation>
    </message>
    <message>
        <source>presets</source>
        <translation>presets</translation>
    </message>
    <message>
        <source>machine constants</source>
        <translation>machine constants</translation>
    </message>
    <message>
        <source>program editing</source>
        <translation>program editing</translation>
    </message>
    <message>
        <source>data control</source>
        <translation>data control</translation>
    </message>
    <message>
        <source>turning</source>
        <translation>turning</translation>
    </message>
    <message>
        <source>facing</source>
        <translation>facing</translation>
    </message>
    <message>
        <source>grooving</source>
        <translation>grooving</translation>
    </message>
    <message>
        <source>boring</source>
        <translation>boring</translation>
    </message>
    <message>
        <source>drill</source>
        <translation>drill</translation>
    </message>
    <message>
        <source>threading</source>
        <translation>threading</translation>
    </message>
    <message>
        <source>coordinates and offsets</source>
        <translation>coordinates and offsets</translation>
    </message>
    <message>
        <source>initial position</source>
        <translation>initial position</translation>
    </message>
    <message>
        <source>adjustment</source>
        <translation>adjustment</translation>
    </message>
    <message>
        <source>dressing</source>
        <translation>dressing</translation>
    </message>
    <message>
        <source>grinding wheel</source>
        <translation>grinding wheel</translation>
    </message>
    <message>
        <source>diamond</source>
        <translation>diamond</translation>
    </message>
    <message>
        <source>oscillation</source>
        <translation>oscillation</translation>
    </message>
    <message>
        <source>speeds</source>
        <translation>speeds</translation>
    </message>
    <message>
        <source>axial orientation</source>
        <translation>axial orientation</translation>
    </message>
</context>
<context>
    <name>k528::studio::CompletionTexts</name>
    <message>
        <source>%1 (axis %2)</source>
        <translation>%1 (axis %2)</translation>
    </message>
    <message>
        <source>end of program</source>
        <translation>end of program</translation>
    </message>
    <message>
        <source>end of subprogram</source>
        <translation>end of subprogram</translation>
    </message>
    <message>
        <source>user parameter</source>
        <translation>user parameter</translation>
    </message>
    <message>
        <source>reserved</source>
        <translation>reserved</translation>
    </message>
    <message>
        <source>reserved (read only)</source>
        <translation>reserved (read only)</translation>
    </message>
    <message>
        <source>%1 (read only)</source>
        <translation>%1 (read only)</translation>
    </message>
    <message>
        <source>program %1</source>
        <translation>program %1</translation>
    </message>
    <message>
        <source>stop until CYCLE START</source>
        <translation>stop until CYCLE START</translation>
    </message>
</context>
<context>
    <name>k528::studio::ConflictDialog</name>
    <message>
        <source>Changed on another PC — %1</source>
        <translation>Changed on another PC — %1</translation>
    </message>
    <message>
        <source>C%1 = %2 was applied to the controller but not kept in the database: %3

Your change was based on revision %4; revision %5 is the newest now.</source>
        <translation>C%1 = %2 was applied to the controller but not kept in the database: %3

Your change was based on revision %4; revision %5 is the newest now.</translation>
    </message>
    <message>
        <source>Show the differences</source>
        <translation>Show the differences</translation>
    </message>
    <message>
        <source>Apply my change on top</source>
        <translation>Apply my change on top</translation>
    </message>
    <message>
        <source>Do not keep it</source>
        <translation>Do not keep it</translation>
    </message>
</context>
<context>
    <name>k528::studio::ConstantsEditor</name>
    <message>
        <source>No C-parameter %1 (1..152)</source>
        <translation>No C-parameter %1 (1..152)</translation>
    </message>
</context>
<context>
    <name>k528::studio::ConstantsFollow</name>
    <message>
        <source>Not kept in the database: %1</source>
        <translation>Not kept in the database: %1</translation>
    </message>
    <message>
        <source>the controller on the link keeps its own constants until they are pushed to it</source>
        <translation>the controller on the link keeps its own constants until they are pushed to it</translation>
    </message>
    <message>
        <source>the simulated controller did not take it now: %1</source>
        <translation>the simulated controller did not take it now: %1</translation>
    </message>
    <message>
        <source>the constants shown are this revision's</source>
        <translation>the constants shown are this revision's</translation>
    </message>
    <message>
        <source>Database %1: the machine %2 is not read from it: %3</source>
        <translation>Database %1: the machine %2 is not read from it: %3</translation>
    </message>
    <message>
        <source>Database %1 has no machine %2: the constants shown stay as they were; the first change kept creates the machine there</source>
        <translation>Database %1 has no machine %2: the constants shown stay as they were; the first change kept creates the machine there</translation>
    </message>
    <message>
        <source>Database %1: %2 is at revision %3 there; the controller on the link keeps its own constants until they are pushed to it</source>
        <translation>Database %1: %2 is at revision %3 there; the controller on the link keeps its own constants until they are pushed to it</translation>
    </message>
    <message>
        <source>Database %1: the constants shown are those of revision %2 of %3</source>
        <translation>Database %1: the constants shown are those of revision %2 of %3</translation>
    </message>
    <message>
        <source>Database %1: revision %2 of %3 has other constants; the simulated controller did not take them now: %4</source>
        <translation>Database %1: revision %2 of %3 has other constants; the simulated controller did not take them now: %4</translation>
    </message>
</context>
<context>
    <name>k528::studio::ConstantsLock</name>
    <message>
        <source>Name the class the constants are locked for</source>
        <translation>Name the class the constants are locked for</translation>
    </message>
    <message>
        <source>The machine constants are locked by the trainer for the class «%1»: they cannot be changed until the trainer unlocks them (Training course, Class tab)</source>
        <translation>The machine constants are locked by the trainer for the class «%1»: they cannot be changed until the trainer unlocks them (Training course, Class tab)</translation>
    </message>
</context>
<context>
    <name>k528::studio::ConstantsModel</name>
    <message>
        <source>No.</source>
        <translation>No.</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Axis</translation>
    </message>
    <message>
        <source>Panel name</source>
        <translation>Panel name</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Meaning</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <source>Range</source>
        <translation>Range</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Value</translation>
    </message>
    <message>
        <source>The value means</source>
        <translation>The value means</translation>
    </message>
    <message>
        <source>C%1: «%2» is not a whole number</source>
        <translation>C%1: «%2» is not a whole number</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Address</translation>
    </message>
    <message>
        <source>Where the constant lives in the positioner's memory, as table E.1 prints it: the word Z…, its bit or byte</source>
        <translation>Where the constant lives in the positioner's memory, as table E.1 prints it: the word Z…, its bit or byte</translation>
    </message>
</context>
<context>
    <name>k528::studio::ConstantsPane</name>
    <message>
        <source>«%1» is not a whole number</source>
        <translation>«%1» is not a whole number</translation>
    </message>
    <message>
        <source>Machine constants</source>
        <translation>Machine constants</translation>
    </message>
    <message>
        <source>Applied to the controller, but not kept in the database: %1</source>
        <translation>Applied to the controller, but not kept in the database: %1</translation>
    </message>
    <message>
        <source>%1 — kept as revision %2 of %3</source>
        <translation>%1 — kept as revision %2 of %3</translation>
    </message>
    <message>
        <source>Search: number, panel name, meaning, unit, address</source>
        <translation>Search: number, panel name, meaning, unit, address</translation>
    </message>
    <message>
        <source>All axes</source>
        <translation>All axes</translation>
    </message>
    <message>
        <source>Axis X</source>
        <translation>Axis X</translation>
    </message>
    <message>
        <source>Axis Z</source>
        <translation>Axis Z</translation>
    </message>
    <message>
        <source>Common</source>
        <translation>Common</translation>
    </message>
    <message>
        <source>Hide reserved</source>
        <translation>Hide reserved</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Undo</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Redo</translation>
    </message>
    <message>
        <source>History...</source>
        <translation>History...</translation>
    </message>
    <message>
        <source>Every revision that changed the selected constant</source>
        <translation>Every revision that changed the selected constant</translation>
    </message>
    <message>
        <source>Compare revisions...</source>
        <translation>Compare revisions...</translation>
    </message>
    <message>
        <source>Import...</source>
        <translation>Import...</translation>
    </message>
    <message>
        <source>A machine file (.k528m) or the constants as CSV, checked as «k528 db import» checks them</source>
        <translation>A machine file (.k528m) or the constants as CSV, checked as «k528 db import» checks them</translation>
    </message>
    <message>
        <source>Export...</source>
        <translation>Export...</translation>
    </message>
    <message>
        <source>Calculator...</source>
        <translation>Calculator...</translation>
    </message>
    <message>
        <source>why the next change is made (kept with its revision)</source>
        <translation>why the next change is made (kept with its revision)</translation>
    </message>
    <message>
        <source>Select a constant first</source>
        <translation>Select a constant first</translation>
    </message>
    <message>
        <source>Import machine constants</source>
        <translation>Import machine constants</translation>
    </message>
    <message>
        <source>Machine files (*.k528m);;Constants as CSV (*.csv);;All files (*)</source>
        <translation>Machine files (*.k528m);;Constants as CSV (*.csv);;All files (*)</translation>
    </message>
    <message>
        <source>Export machine constants</source>
        <translation>Export machine constants</translation>
    </message>
    <message>
        <source>Machine files (*.k528m);;Constants as CSV (*.csv)</source>
        <translation>Machine files (*.k528m);;Constants as CSV (*.csv)</translation>
    </message>
    <message>
        <source>Another operation is under way</source>
        <translation>Another operation is under way</translation>
    </message>
    <message>
        <source>interrupted</source>
        <translation>interrupted</translation>
    </message>
    <message>
        <source>Importing %1</source>
        <translation>Importing %1</translation>
    </message>
    <message>
        <source>%1 imported: revision %2 of %3 (%4 changes)</source>
        <translation>%1 imported: revision %2 of %3 (%4 changes)</translation>
    </message>
    <message>
        <source>Nothing was imported: %1</source>
        <translation>Nothing was imported: %1</translation>
    </message>
    <message>
        <source>the controller did not take them: %1</source>
        <translation>the controller did not take them: %1</translation>
    </message>
    <message>
        <source>Exporting %1</source>
        <translation>Exporting %1</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>cannot write %1: %2</translation>
    </message>
    <message>
        <source>The constants written to %1</source>
        <translation>The constants written to %1</translation>
    </message>
    <message>
        <source>Nothing was exported: %1</source>
        <translation>Nothing was exported: %1</translation>
    </message>
    <message>
        <source>Changes: %1</source>
        <translation>Changes: %1</translation>
    </message>
    <message>
        <source>sending them to the controller...</source>
        <translation>sending them to the controller...</translation>
    </message>
    <message>
        <source>The trainer has unlocked the machine constants</source>
        <translation>The trainer has unlocked the machine constants</translation>
    </message>
    <message>
        <source>Cutting data...</source>
        <translation>Cutting data...</translation>
    </message>
    <message>
        <source>Spindle speed from the cutting speed and the diameter, feed per minute, the grinding wheel's surface speed from R207</source>
        <translation>Spindle speed from the cutting speed and the diameter, feed per minute, the grinding wheel's surface speed from R207</translation>
    </message>
    <message>
        <source>The constants of the controller on the line, read every 10 s.</source>
        <translation>The constants of the controller on the line, read every 10 s.</translation>
    </message>
    <message>
        <source>A change is written to it at once and kept in the database.</source>
        <translation>A change is written to it at once and kept in the database.</translation>
    </message>
</context>
<context>
    <name>k528::studio::Controller</name>
    <message>
        <source>The controller has not answered since %1: the values shown are its last, stale; the line is tried again by itself</source>
        <translation>The controller has not answered since %1: the values shown are its last, stale; the line is tried again by itself</translation>
    </message>
</context>
<context>
    <name>k528::studio::ControllerDock</name>
    <message>
        <source>Controller</source>
        <translation>Controller</translation>
    </message>
    <message>
        <source>&amp;Controller</source>
        <translation>&amp;Controller</translation>
    </message>
    <message>
        <source>&amp;Connect to the controller</source>
        <translation>&amp;Connect to the controller</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Disconnect</translation>
    </message>
    <message>
        <source>&amp;Pull into the database</source>
        <translation>&amp;Pull into the database</translation>
    </message>
    <message>
        <source>Push a &amp;file...</source>
        <translation>Push a &amp;file...</translation>
    </message>
    <message>
        <source>Push a database &amp;machine</source>
        <translation>Push a database &amp;machine</translation>
    </message>
    <message>
        <source>Line (RS485, Modbus RTU)</source>
        <translation>Line (RS485, Modbus RTU)</translation>
    </message>
    <message>
        <source>Live monitor</source>
        <translation>Live monitor</translation>
    </message>
    <message>
        <source>Plugin</source>
        <translation>Plugin</translation>
    </message>
    <message>
        <source>Port</source>
        <translation>Port</translation>
    </message>
    <message>
        <source>Baud</source>
        <translation>Baud</translation>
    </message>
    <message>
        <source>Parity</source>
        <translation>Parity</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Address</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>even</source>
        <translation>even</translation>
    </message>
    <message>
        <source>odd</source>
        <translation>odd</translation>
    </message>
    <message>
        <source>Ports</source>
        <translation>Ports</translation>
    </message>
    <message>
        <source>Pull into the database</source>
        <translation>Pull into the database</translation>
    </message>
    <message>
        <source>Push a file...</source>
        <translation>Push a file...</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Disconnect</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Connect</translation>
    </message>
    <message>
        <source>No controller-link plugin was found (searched: %1). %2</source>
        <translation>No controller-link plugin was found (searched: %1). %2</translation>
    </message>
    <message>
        <source>Choose the serial port the controller is on.</source>
        <translation>Choose the serial port the controller is on.</translation>
    </message>
    <message>
        <source>No connection on %1: %2</source>
        <translation>No connection on %1: %2</translation>
    </message>
    <message>
        <source>Connected: %1</source>
        <translation>Connected: %1</translation>
    </message>
    <message>
        <source>memory read</source>
        <translation>memory read</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>stopped</translation>
    </message>
    <message>
        <source>The push did not start: the controller's memory could not be read (%1); nothing was sent</source>
        <translation>The push did not start: the controller's memory could not be read (%1); nothing was sent</translation>
    </message>
    <message>
        <source>Pull failed: %1</source>
        <translation>Pull failed: %1</translation>
    </message>
    <message>
        <source>Pulled, but not kept in the database: %1</source>
        <translation>Pulled, but not kept in the database: %1</translation>
    </message>
    <message>
        <source>Pulled %1 programs; the database already holds this memory of %2 (revision %3)</source>
        <translation>Pulled %1 programs; the database already holds this memory of %2 (revision %3)</translation>
    </message>
    <message>
        <source>Pulled %1 programs into %2, revision %3 (%4 changes)</source>
        <translation>Pulled %1 programs into %2, revision %3 (%4 changes)</translation>
    </message>
    <message>
        <source>pushed</source>
        <translation>pushed</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>nothing</translation>
    </message>
    <message>
        <source>Pushed %1: written and verified %2</source>
        <translation>Pushed %1: written and verified %2</translation>
    </message>
    <message>
        <source>Push of %1 stopped: %2. Written and verified before: %3</source>
        <translation>Push of %1 stopped: %2. Written and verified before: %3</translation>
    </message>
    <message>
        <source>Connecting to %1...</source>
        <translation>Connecting to %1...</translation>
    </message>
    <message>
        <source>Disconnected</source>
        <translation>Disconnected</translation>
    </message>
    <message>
        <source>Pulling the controller's memory...</source>
        <translation>Pulling the controller's memory...</translation>
    </message>
    <message>
        <source>Push a machine file</source>
        <translation>Push a machine file</translation>
    </message>
    <message>
        <source>Machine files (*.k528m *.txt);;All files (*)</source>
        <translation>Machine files (*.k528m *.txt);;All files (*)</translation>
    </message>
    <message>
        <source>%1 cannot be pushed: %2; nothing was sent</source>
        <translation>%1 cannot be pushed: %2; nothing was sent</translation>
    </message>
    <message>
        <source>The machine %1 cannot be loaded: %2</source>
        <translation>The machine %1 cannot be loaded: %2</translation>
    </message>
    <message>
        <source>Reading the controller's memory to show what %1 changes...</source>
        <translation>Reading the controller's memory to show what %1 changes...</translation>
    </message>
    <message>
        <source>Push</source>
        <translation>Push</translation>
    </message>
    <message>
        <source>Pushing %1...</source>
        <translation>Pushing %1...</translation>
    </message>
    <message>
        <source>Push of %1 not started; nothing was sent</source>
        <translation>Push of %1 not started; nothing was sent</translation>
    </message>
    <message>
        <source>Check what %1 changes, then push.</source>
        <translation>Check what %1 changes, then push.</translation>
    </message>
    <message>
        <source>Cancelling at the next exchange...</source>
        <translation>Cancelling at the next exchange...</translation>
    </message>
    <message>
        <source>power-on</source>
        <translation>power-on</translation>
    </message>
    <message>
        <source>, running</source>
        <translation>, running</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Mode</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>L%1, frame N%2</source>
        <translation>L%1, frame N%2</translation>
    </message>
    <message>
        <source>Override</source>
        <translation>Override</translation>
    </message>
    <message>
        <source>%1 mm (machine %2), following error %3 mm, %4</source>
        <translation>%1 mm (machine %2), following error %3 mm, %4</translation>
    </message>
    <message>
        <source>homed</source>
        <translation>homed</translation>
    </message>
    <message>
        <source>not homed</source>
        <translation>not homed</translation>
    </message>
    <message>
        <source>Alarms</source>
        <translation>Alarms</translation>
    </message>
    <message>
        <source>K LEDs</source>
        <translation>K LEDs</translation>
    </message>
    <message>
        <source>Machine messages</source>
        <translation>Machine messages</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Message</translation>
    </message>
    <message>
        <source>Programs</source>
        <translation>Programs</translation>
    </message>
    <message>
        <source>Clear the C area (all constants 0)...</source>
        <translation>Clear the C area (all constants 0)...</translation>
    </message>
    <message>
        <source>Clear the R area (all R-parameters 0)...</source>
        <translation>Clear the R area (all R-parameters 0)...</translation>
    </message>
    <message>
        <source>Frame log...</source>
        <translation>Frame log...</translation>
    </message>
    <message>
        <source>Save every frame of the line (time, direction, bytes, CRC) to a file</source>
        <translation>Save every frame of the line (time, direction, bytes, CRC) to a file</translation>
    </message>
    <message>
        <source>Show it on every view of the window</source>
        <translation>Show it on every view of the window</translation>
    </message>
    <message>
        <source>Push %1</source>
        <translation>Push %1</translation>
    </message>
    <message>
        <source>Save the frame log</source>
        <translation>Save the frame log</translation>
    </message>
    <message>
        <source>Text (*.txt);;All files (*)</source>
        <translation>Text (*.txt);;All files (*)</translation>
    </message>
    <message>
        <source>The frame log was not saved: %1</source>
        <translation>The frame log was not saved: %1</translation>
    </message>
    <message>
        <source>The frame log saved to %1 (%2 frames)</source>
        <translation>The frame log saved to %1 (%2 frames)</translation>
    </message>
    <message>
        <source>the C area</source>
        <translation>the C area</translation>
    </message>
    <message>
        <source>the R area</source>
        <translation>the R area</translation>
    </message>
    <message>
        <source>%1 was not cleared: %2</source>
        <translation>%1 was not cleared: %2</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Clear</translation>
    </message>
    <message>
        <source>Clear %1 of %2? Every value becomes 0; the database keeps what it had.</source>
        <translation>Clear %1 of %2? Every value becomes 0; the database keeps what it had.</translation>
    </message>
    <message>
        <source>%1 cleared</source>
        <translation>%1 cleared</translation>
    </message>
    <message>
        <source>%1: %2 answers, %3 timeouts, %4 CRC errors, %5 bad replies, %6 exceptions%7, %8 retries; round trip median %9 ms, p95 %10 ms; line busy %11 %</source>
        <translation>%1: %2 answers, %3 timeouts, %4 CRC errors, %5 bad replies, %6 exceptions%7, %8 retries; round trip median %9 ms, p95 %10 ms; line busy %11 %</translation>
    </message>
    <message>
        <source>Why: %1</source>
        <translation>Why: %1</translation>
    </message>
    <message>
        <source>No machine of the database has a line</source>
        <translation>No machine of the database has a line</translation>
    </message>
    <message>
        <source>Connect to a database &amp;machine</source>
        <translation>Connect to a database &amp;machine</translation>
    </message>
    <message>
        <source>Line (Modbus TCP)</source>
        <translation>Line (Modbus TCP)</translation>
    </message>
    <message>
        <source>Host:port</source>
        <translation>Host:port</translation>
    </message>
    <message>
        <source>Unit id</source>
        <translation>Unit id</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Machine</translation>
    </message>
    <message>
        <source>(the line below)</source>
        <translation>(the line below)</translation>
    </message>
    <message>
        <source>The machines of the database that keep their controller's line</source>
        <translation>The machines of the database that keep their controller's line</translation>
    </message>
    <message>
        <source>List the system's serial ports and the database's machines again</source>
        <translation>List the system's serial ports and the database's machines again</translation>
    </message>
    <message>
        <source>Enter the gateway's HOST:PORT.</source>
        <translation>Enter the gateway's HOST:PORT.</translation>
    </message>
    <message>
        <source>Choose a machine of the database, or the controller's port (or HOST:PORT for Modbus TCP), speed, parity and address, then Connect.</source>
        <translation>Choose a machine of the database, or the controller's port (or HOST:PORT for Modbus TCP), speed, parity and address, then Connect.</translation>
    </message>
</context>
<context>
    <name>k528::studio::CoreTexts</name>
    <message>
        <source>cannot read the file: %1</source>
        <translation>cannot read the file: %1</translation>
    </message>
    <message>
        <source>cannot create the file</source>
        <translation>cannot create the file</translation>
    </message>
    <message>
        <source>cannot write the file</source>
        <translation>cannot write the file</translation>
    </message>
    <message>
        <source>not valid UTF-8</source>
        <translation>not valid UTF-8</translation>
    </message>
    <message>
        <source>column %1: U+FEFF (byte-order mark), an invisible character; a byte-order mark may stand only at the very start of the file (files joined with `cat`?) — remove it</source>
        <translation>column %1: U+FEFF (byte-order mark), an invisible character; a byte-order mark may stand only at the very start of the file (files joined with `cat`?) — remove it</translation>
    </message>
    <message>
        <source>%1 is given twice (first on line %2)</source>
        <translation>%1 is given twice (first on line %2)</translation>
    </message>
    <message>
        <source>section header without ']': %1</source>
        <translation>section header without ']': %1</translation>
    </message>
    <message>
        <source>[end program] without [program N]</source>
        <translation>[end program] without [program N]</translation>
    </message>
    <message>
        <source>unknown section [%1] (known: machine, c, r, program N, messages, plc-messages, simulation)</source>
        <translation>unknown section [%1] (known: machine, c, r, program N, messages, plc-messages, simulation)</translation>
    </message>
    <message>
        <source>[program N]: N must be a number 1..99, not '%1'</source>
        <translation>[program N]: N must be a number 1..99, not '%1'</translation>
    </message>
    <message>
        <source>program %1 is empty</source>
        <translation>program %1 is empty</translation>
    </message>
    <message>
        <source>a program line may not start with '[' (missing [end program] for program %1 of line %2?)</source>
        <translation>a program line may not start with '[' (missing [end program] for program %1 of line %2?)</translation>
    </message>
    <message>
        <source>program %1 has no [end program]</source>
        <translation>program %1 has no [end program]</translation>
    </message>
    <message>
        <source>line outside any section: %1</source>
        <translation>line outside any section: %1</translation>
    </message>
    <message>
        <source>expected key=value: %1</source>
        <translation>expected key=value: %1</translation>
    </message>
    <message>
        <source>unknown key '%1' in [machine] (format, name, title)</source>
        <translation>unknown key '%1' in [machine] (format, name, title)</translation>
    </message>
    <message>
        <source>format: '%1' is not a number</source>
        <translation>format: '%1' is not a number</translation>
    </message>
    <message>
        <source>format %1 is not one this program reads (%2)</source>
        <translation>format %1 is not one this program reads (%2)</translation>
    </message>
    <message>
        <source>unknown key '%1' in [c] (C001..C152)</source>
        <translation>unknown key '%1' in [c] (C001..C152)</translation>
    </message>
    <message>
        <source>unknown key '%1' in [r] (R0..R299)</source>
        <translation>unknown key '%1' in [r] (R0..R299)</translation>
    </message>
    <message>
        <source>%1: '%2' is not a whole number</source>
        <translation>%1: '%2' is not a whole number</translation>
    </message>
    <message>
        <source>expected #k=text in [messages], not '%1'</source>
        <translation>expected #k=text in [messages], not '%1'</translation>
    </message>
    <message>
        <source>message number %1 is outside #1..#99</source>
        <translation>message number %1 is outside #1..#99</translation>
    </message>
    <message>
        <source>expected A01..A32, W01..W32 or S01..S16 in [plc-messages], not '%1'</source>
        <translation>expected A01..A32, W01..W32 or S01..S16 in [plc-messages], not '%1'</translation>
    </message>
    <message>
        <source>PLC message '%1': the number must be 1..%2</source>
        <translation>PLC message '%1': the number must be 1..%2</translation>
    </message>
    <message>
        <source>no [machine] section</source>
        <translation>no [machine] section</translation>
    </message>
    <message>
        <source>[machine] has no format=%1</source>
        <translation>[machine] has no format=%1</translation>
    </message>
    <message>
        <source>[machine] has no name=</source>
        <translation>[machine] has no name=</translation>
    </message>
    <message>
        <source>no [c] section (the 152 machine constants)</source>
        <translation>no [c] section (the 152 machine constants)</translation>
    </message>
    <message>
        <source>[c] lacks %1 (all 152 are required)</source>
        <translation>[c] lacks %1 (all 152 are required)</translation>
    </message>
    <message>
        <source>[c] lacks %1 and %2 more (all 152 are required)</source>
        <translation>[c] lacks %1 and %2 more (all 152 are required)</translation>
    </message>
    <message>
        <source>no built-in profile of this name (built-in: %1)</source>
        <translation>no built-in profile of this name (built-in: %1)</translation>
    </message>
    <message>
        <source>no profile given (built-in: %1)</source>
        <translation>no profile given (built-in: %1)</translation>
    </message>
    <message>
        <source>neither a built-in profile (%1) nor a machine file</source>
        <translation>neither a built-in profile (%1) nor a machine file</translation>
    </message>
    <message>
        <source>the first line must be the header '%1'</source>
        <translation>the first line must be the header '%1'</translation>
    </message>
    <message>
        <source>expected 5 fields (number;axis;name;value;unit), found %1</source>
        <translation>expected 5 fields (number;axis;name;value;unit), found %1</translation>
    </message>
    <message>
        <source>number '%1' is not a C-parameter 1..152</source>
        <translation>number '%1' is not a C-parameter 1..152</translation>
    </message>
    <message>
        <source>%1 belongs to axis '%2', the row says '%3'</source>
        <translation>%1 belongs to axis '%2', the row says '%3'</translation>
    </message>
    <message>
        <source>%1 is given twice</source>
        <translation>%1 is given twice</translation>
    </message>
    <message>
        <source>%1: value '%2' is not a whole number</source>
        <translation>%1: value '%2' is not a whole number</translation>
    </message>
    <message>
        <source>empty: no header line</source>
        <translation>empty: no header line</translation>
    </message>
    <message>
        <source>%1 is missing (all 152 are required)</source>
        <translation>%1 is missing (all 152 are required)</translation>
    </message>
    <message>
        <source>a quoted field is not closed</source>
        <translation>a quoted field is not closed</translation>
    </message>
    <message>
        <source>text after a closing quote</source>
        <translation>text after a closing quote</translation>
    </message>
    <message>
        <source>name is empty</source>
        <translation>name is empty</translation>
    </message>
    <message>
        <source>name longer than 64 characters</source>
        <translation>name longer than 64 characters</translation>
    </message>
    <message>
        <source>name '%1' does not start with a-z or 0-9</source>
        <translation>name '%1' does not start with a-z or 0-9</translation>
    </message>
    <message>
        <source>name '%1' has a character other than a-z, 0-9, '-', '_', '.'</source>
        <translation>name '%1' has a character other than a-z, 0-9, '-', '_', '.'</translation>
    </message>
    <message>
        <source>title: %1</source>
        <translation>title: %1</translation>
    </message>
    <message>
        <source>text is empty</source>
        <translation>text is empty</translation>
    </message>
    <message>
        <source>text is not valid UTF-8</source>
        <translation>text is not valid UTF-8</translation>
    </message>
    <message>
        <source>text has a control character or line break</source>
        <translation>text has a control character or line break</translation>
    </message>
    <message>
        <source>text has %1 characters, more than %2</source>
        <translation>text has %1 characters, more than %2</translation>
    </message>
    <message>
        <source>text ends with a blank</source>
        <translation>text ends with a blank</translation>
    </message>
    <message>
        <source>text starts with a blank</source>
        <translation>text starts with a blank</translation>
    </message>
    <message>
        <source>no C-parameter %1 (1..152)</source>
        <translation>no C-parameter %1 (1..152)</translation>
    </message>
    <message>
        <source>%1 = %2 is outside the range %3 of «%4»</source>
        <translation>%1 = %2 is outside the range %3 of «%4»</translation>
    </message>
    <message>
        <source>no R-parameter %1 (0..299)</source>
        <translation>no R-parameter %1 (0..299)</translation>
    </message>
    <message>
        <source>R%1 is read-only (R232..R262): it cannot be preset</source>
        <translation>R%1 is read-only (R232..R262): it cannot be preset</translation>
    </message>
    <message>
        <source>R%1 = %2 is outside the 32-bit range</source>
        <translation>R%1 = %2 is outside the 32-bit range</translation>
    </message>
    <message>
        <source>program number %1 is outside 1..99</source>
        <translation>program number %1 is outside 1..99</translation>
    </message>
    <message>
        <source>program L%1: empty</source>
        <translation>program L%1: empty</translation>
    </message>
    <message>
        <source>program L%1: not valid UTF-8</source>
        <translation>program L%1: not valid UTF-8</translation>
    </message>
    <message>
        <source>program L%1: the text does not end with a line break</source>
        <translation>program L%1: the text does not end with a line break</translation>
    </message>
    <message>
        <source>program L%1: carriage return in the text (lines end with LF)</source>
        <translation>program L%1: carriage return in the text (lines end with LF)</translation>
    </message>
    <message>
        <source>program L%1: line %2 starts with '[' (reserved for machine-file sections)</source>
        <translation>program L%1: line %2 starts with '[' (reserved for machine-file sections)</translation>
    </message>
    <message>
        <source>program L%1: line %2 is the header of program L%3 (one program per entry)</source>
        <translation>program L%1: line %2 is the header of program L%3 (one program per entry)</translation>
    </message>
    <message>
        <source>program L%1: line %2: %MESSAGES belongs to the machine file's [messages] section</source>
        <translation>program L%1: line %2: %MESSAGES belongs to the machine file's [messages] section</translation>
    </message>
    <message>
        <source>program L%1: only blank lines</source>
        <translation>program L%1: only blank lines</translation>
    </message>
    <message>
        <source>technological message number %1 is outside 1..99</source>
        <translation>technological message number %1 is outside 1..99</translation>
    </message>
    <message>
        <source>message #%1: %2</source>
        <translation>message #%1: %2</translation>
    </message>
    <message>
        <source>PLC message %1 is outside 1..%2</source>
        <translation>PLC message %1 is outside 1..%2</translation>
    </message>
    <message>
        <source>PLC message %1: %2</source>
        <translation>PLC message %1: %2</translation>
    </message>
    <message>
        <source>simulation: %1</source>
        <translation>simulation: %1</translation>
    </message>
    <message>
        <source>simulation %1: %2</source>
        <translation>simulation %1: %2</translation>
    </message>
    <message>
        <source>empty key</source>
        <translation>empty key</translation>
    </message>
    <message>
        <source>key longer than 64 characters</source>
        <translation>key longer than 64 characters</translation>
    </message>
    <message>
        <source>key '%1' does not start with a letter a-z</source>
        <translation>key '%1' does not start with a letter a-z</translation>
    </message>
    <message>
        <source>key '%1' has a character other than a-z, 0-9, '_', '.'</source>
        <translation>key '%1' has a character other than a-z, 0-9, '_', '.'</translation>
    </message>
    <message>
        <source>value is not valid UTF-8</source>
        <translation>value is not valid UTF-8</translation>
    </message>
    <message>
        <source>value longer than 200 characters</source>
        <translation>value longer than 200 characters</translation>
    </message>
    <message>
        <source>value spans lines</source>
        <translation>value spans lines</translation>
    </message>
    <message>
        <source>value has a control character</source>
        <translation>value has a control character</translation>
    </message>
    <message>
        <source>value has a ';' (starts a comment in machine files)</source>
        <translation>value has a ';' (starts a comment in machine files)</translation>
    </message>
    <message>
        <source>value starts or ends with a blank</source>
        <translation>value starts or ends with a blank</translation>
    </message>
    <message>
        <source>value %1 is outside %2..%3</source>
        <translation>value %1 is outside %2..%3</translation>
    </message>
    <message>
        <source>value '%1' is not a whole number</source>
        <translation>value '%1' is not a whole number</translation>
    </message>
    <message>
        <source>value '%1' is not a number</source>
        <translation>value '%1' is not a number</translation>
    </message>
    <message>
        <source>value '%1' is not true/false</source>
        <translation>value '%1' is not true/false</translation>
    </message>
    <message>
        <source>%1</source>
        <translation>%1</translation>
    </message>
    <message>
        <source>'%1' is not a tool kind (turning, facing, grooving, boring, drill, threading)</source>
        <translation>'%1' is not a tool kind (turning, facing, grooving, boring, drill, threading)</translation>
    </message>
    <message>
        <source>'%1' is not one of +z+x, -z+x, +z-x, -z-x</source>
        <translation>'%1' is not one of +z+x, -z+x, +z-x, -z-x</translation>
    </message>
    <message>
        <source>needs 0..50 mm</source>
        <translation>needs 0..50 mm</translation>
    </message>
    <message>
        <source>needs more than 0, at most 1000 mm</source>
        <translation>needs more than 0, at most 1000 mm</translation>
    </message>
    <message>
        <source>needs 0..100 mm (0: no limit)</source>
        <translation>needs 0..100 mm (0: no limit)</translation>
    </message>
    <message>
        <source>needs a user R-parameter 0..148 (X there, Z in the next)</source>
        <translation>needs a user R-parameter 0..148 (X there, Z in the next)</translation>
    </message>
    <message>
        <source>a tool key is tool.&lt;station 1..8&gt;.&lt;key&gt;</source>
        <translation>a tool key is tool.&lt;station 1..8&gt;.&lt;key&gt;</translation>
    </message>
    <message>
        <source>'%1' is not a key of a tool</source>
        <translation>'%1' is not a key of a tool</translation>
    </message>
    <message>
        <source>the tool of station %1 has no kind (tool.%1.kind)</source>
        <translation>the tool of station %1 has no kind (tool.%1.kind)</translation>
    </message>
    <message>
        <source>%1, line %2: %3</source>
        <translation>%1, line %2: %3</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source> (message %1)</source>
        <translation> (message %1)</translation>
    </message>
    <message>
        <source>%1 cannot be read: %2</source>
        <translation>%1 cannot be read: %2</translation>
    </message>
    <message>
        <source>Vmax must be a positive number</source>
        <translation>Vmax must be a positive number</translation>
    </message>
    <message>
        <source>the run-up time must be a positive number</source>
        <translation>the run-up time must be a positive number</translation>
    </message>
    <message>
        <source>the braking distance must be a positive number</source>
        <translation>the braking distance must be a positive number</translation>
    </message>
    <message>
        <source>the acceleration must be a positive number</source>
        <translation>the acceleration must be a positive number</translation>
    </message>
    <message>
        <source>Umax must be a positive number</source>
        <translation>Umax must be a positive number</translation>
    </message>
    <message>
        <source>Kv must be a positive number</source>
        <translation>Kv must be a positive number</translation>
    </message>
    <message>
        <source>the screw lead must be a positive number</source>
        <translation>the screw lead must be a positive number</translation>
    </message>
    <message>
        <source>the gear ratio must be a positive number</source>
        <translation>the gear ratio must be a positive number</translation>
    </message>
    <message>
        <source>the encoder must have at least one line</source>
        <translation>the encoder must have at least one line</translation>
    </message>
    <message>
        <source>the screw lead %1 mm is not a whole number of discretes (%2 mm)</source>
        <translation>the screw lead %1 mm is not a whole number of discretes (%2 mm)</translation>
    </message>
    <message>
        <source>the gear ratio %1 is not a fraction with a denominator up to 100000</source>
        <translation>the gear ratio %1 is not a fraction with a denominator up to 100000</translation>
    </message>
    <message>
        <source>a speed must be zero or positive</source>
        <translation>a speed must be zero or positive</translation>
    </message>
    <message>
        <source>the fastest feed %1 mm/min is above what the drive reaches at DAC MAX (%2 mm/min)</source>
        <translation>the fastest feed %1 mm/min is above what the drive reaches at DAC MAX (%2 mm/min)</translation>
    </message>
    <message>
        <source>the cutting speed must be a positive number</source>
        <translation>the cutting speed must be a positive number</translation>
    </message>
    <message>
        <source>the diameter must be a positive number</source>
        <translation>the diameter must be a positive number</translation>
    </message>
    <message>
        <source>the spindle speed must be a positive number</source>
        <translation>the spindle speed must be a positive number</translation>
    </message>
    <message>
        <source>the feed per revolution must be a positive number</source>
        <translation>the feed per revolution must be a positive number</translation>
    </message>
    <message>
        <source>the wheel's diameter must be a positive number</source>
        <translation>the wheel's diameter must be a positive number</translation>
    </message>
    <message>
        <source>the wheel's speed must be a positive number</source>
        <translation>the wheel's speed must be a positive number</translation>
    </message>
    <message>
        <source>the machine presets no R207 (the wheel's diameter)</source>
        <translation>the machine presets no R207 (the wheel's diameter)</translation>
    </message>
    <message>
        <source>tool %1 has no offset R-parameters (tool.%1.offset_r)</source>
        <translation>tool %1 has no offset R-parameters (tool.%1.offset_r)</translation>
    </message>
    <message>
        <source>the measured size and the drawing's must be numbers</source>
        <translation>the measured size and the drawing's must be numbers</translation>
    </message>
    <message>
        <source>R%1 would leave the R-parameter range</source>
        <translation>R%1 would leave the R-parameter range</translation>
    </message>
    <message>
        <source>no tool at station %1</source>
        <translation>no tool at station %1</translation>
    </message>
    <message>
        <source>%1 without its Russian %2 (an English text stands beside its Russian)</source>
        <translation>%1 without its Russian %2 (an English text stands beside its Russian)</translation>
    </message>
    <message>
        <source>%1 is written beside its Russian text: %2=</source>
        <translation>%1 is written beside its Russian text: %2=</translation>
    </message>
    <message>
        <source>line '%1' is not tcp://HOST:PORT/UNIT or serial:DEVICE?baud=115200&amp;parity=none&amp;address=1</source>
        <translation>line '%1' is not tcp://HOST:PORT/UNIT or serial:DEVICE?baud=115200&amp;parity=none&amp;address=1</translation>
    </message>
    <message>
        <source>line '%1': the unit id after '/' is a station address 1..247</source>
        <translation>line '%1': the unit id after '/' is a station address 1..247</translation>
    </message>
    <message>
        <source>line '%1': no HOST:PORT after tcp:// (tcp://HOST:PORT/UNIT)</source>
        <translation>line '%1': no HOST:PORT after tcp:// (tcp://HOST:PORT/UNIT)</translation>
    </message>
    <message>
        <source>line '%1': the port after the host is 1..65535</source>
        <translation>line '%1': the port after the host is 1..65535</translation>
    </message>
    <message>
        <source>line '%1': '%2' is not a host name or address</source>
        <translation>line '%1': '%2' is not a host name or address</translation>
    </message>
    <message>
        <source>line '%1': no device after serial: (serial:DEVICE?baud=115200&amp;parity=none&amp;address=1)</source>
        <translation>line '%1': no device after serial: (serial:DEVICE?baud=115200&amp;parity=none&amp;address=1)</translation>
    </message>
    <message>
        <source>line '%1': baud is a rate in bit/s, 1200..4000000</source>
        <translation>line '%1': baud is a rate in bit/s, 1200..4000000</translation>
    </message>
    <message>
        <source>line '%1': parity is none, even or odd</source>
        <translation>line '%1': parity is none, even or odd</translation>
    </message>
    <message>
        <source>line '%1': stop_bits is 1 or 2</source>
        <translation>line '%1': stop_bits is 1 or 2</translation>
    </message>
    <message>
        <source>line '%1': address is a station address 1..247</source>
        <translation>line '%1': address is a station address 1..247</translation>
    </message>
    <message>
        <source>line '%1': '%2' is not a setting of a serial line (baud, parity, stop_bits, address)</source>
        <translation>line '%1': '%2' is not a setting of a serial line (baud, parity, stop_bits, address)</translation>
    </message>
    <message>
        <source>Incomplete set of C-parameters</source>
        <translation>Incomplete set of C-parameters</translation>
    </message>
    <message>
        <source>%1 %5 = %3 is outside %4</source>
        <translation>%1 %5 = %3 is outside %4</translation>
    </message>
    <message>
        <source>Axis %1: exactly one display discrete must be set (%2), %3 set</source>
        <translation>Axis %1: exactly one display discrete must be set (%2), %3 set</translation>
    </message>
    <message>
        <source>Axis %1: L/N = %2/%3 is above 1: one encoder pulse is more than a discrete, the axis cannot position finer than a pulse</source>
        <translation>Axis %1: L/N = %2/%3 is above 1: one encoder pulse is more than a discrete, the axis cannot position finer than a pulse</translation>
    </message>
    <message>
        <source>Axis %1: DAC MAX = 0: the drive gets no voltage</source>
        <translation>Axis %1: DAC MAX = 0: the drive gets no voltage</translation>
    </message>
    <message>
        <source>Axis %1: DAC LIMIT %2 is below DAC MAX %3: message %4 at full speed</source>
        <translation>Axis %1: DAC LIMIT %2 is below DAC MAX %3: message %4 at full speed</translation>
    </message>
    <message>
        <source>Axis %1: DAC LIMIT %2 is not 15-20 %% above DAC MAX %3 (recommended %4...%5)</source>
        <translation>Axis %1: DAC LIMIT %2 is not 15-20 %% above DAC MAX %3 (recommended %4...%5)</translation>
    </message>
    <message>
        <source>Axis %1: ACCELERATION 1 = 0</source>
        <translation>Axis %1: ACCELERATION 1 = 0</translation>
    </message>
    <message>
        <source>Axis %1: %3 = 0: the axis will not move</source>
        <translation>Axis %1: %3 = 0: the axis will not move</translation>
    </message>
    <message>
        <source>Axis %1: a homing speed is zero, yet programs need the axis homed</source>
        <translation>Axis %1: a homing speed is zero, yet programs need the axis homed</translation>
    </message>
    <message>
        <source>Axis %1: F HOME CREEP is above F HOME START</source>
        <translation>Axis %1: F HOME CREEP is above F HOME START</translation>
    </message>
    <message>
        <source>Axis %1: -LIMIT %2 is not below +LIMIT %3</source>
        <translation>Axis %1: -LIMIT %2 is not below +LIMIT %3</translation>
    </message>
    <message>
        <source>Axis %1: HOME VALUE %2 is outside the soft limits %3...%4</source>
        <translation>Axis %1: HOME VALUE %2 is outside the soft limits %3...%4</translation>
    </message>
    <message>
        <source>Axis %1: function %2 is assigned to two fast inputs</source>
        <translation>Axis %1: function %2 is assigned to two fast inputs</translation>
    </message>
    <message>
        <source>No axis is present (AXIS PRESENT = 0)</source>
        <translation>No axis is present (AXIS PRESENT = 0)</translation>
    </message>
    <message>
        <source>Both encoders are on channel %1 (%4)</source>
        <translation>Both encoders are on channel %1 (%4)</translation>
    </message>
    <message>
        <source>A handwheel and an encoder are on channel %1 (%4)</source>
        <translation>A handwheel and an encoder are on channel %1 (%4)</translation>
    </message>
    <message>
        <source>Both drives are on DAC channel %1 (%4)</source>
        <translation>Both drives are on DAC channel %1 (%4)</translation>
    </message>
    <message>
        <source>Both handwheels are on channel %1</source>
        <translation>Both handwheels are on channel %1</translation>
    </message>
    <message>
        <source>Manual cycle %1: program L%2 does not exist</source>
        <translation>Manual cycle %1: program L%2 does not exist</translation>
    </message>
    <message>
        <source>Simulation setting %1 is not in the registry (a typo?)</source>
        <translation>Simulation setting %1 is not in the registry (a typo?)</translation>
    </message>
</context>
<context>
    <name>k528::studio::CuttingDataDialog</name>
    <message>
        <source>Cutting data</source>
        <translation>Cutting data</translation>
    </message>
    <message>
        <source>Spindle speed: n = 1000·v / (π·D)</source>
        <translation>Spindle speed: n = 1000·v / (π·D)</translation>
    </message>
    <message>
        <source>Cutting speed v, m/min</source>
        <translation>Cutting speed v, m/min</translation>
    </message>
    <message>
        <source>Diameter D, mm</source>
        <translation>Diameter D, mm</translation>
    </message>
    <message>
        <source>Spindle speed n</source>
        <translation>Spindle speed n</translation>
    </message>
    <message>
        <source>Feed per minute: F = f·n</source>
        <translation>Feed per minute: F = f·n</translation>
    </message>
    <message>
        <source>Feed per revolution f, mm/rev</source>
        <translation>Feed per revolution f, mm/rev</translation>
    </message>
    <message>
        <source>Feed F</source>
        <translation>Feed F</translation>
    </message>
    <message>
        <source>Grinding wheel: v = π·D·n / 60000</source>
        <translation>Grinding wheel: v = π·D·n / 60000</translation>
    </message>
    <message>
        <source>R207 wheel diameter, discretes of X</source>
        <translation>R207 wheel diameter, discretes of X</translation>
    </message>
    <message>
        <source>Wheel speed, rev/min</source>
        <translation>Wheel speed, rev/min</translation>
    </message>
    <message>
        <source>Surface speed</source>
        <translation>Surface speed</translation>
    </message>
    <message>
        <source>%1 rev/min</source>
        <translation>%1 rev/min</translation>
    </message>
    <message>
        <source>%1 mm/min at n = %2 rev/min</source>
        <translation>%1 mm/min at n = %2 rev/min</translation>
    </message>
    <message>
        <source>%1 m/s (wheel Ø%2 mm)</source>
        <translation>%1 m/s (wheel Ø%2 mm)</translation>
    </message>
    <message>
        <source>— (no wheel diameter in R207)</source>
        <translation>— (no wheel diameter in R207)</translation>
    </message>
</context>
<context>
    <name>k528::studio::CycleTimeLabel</name>
    <message>
        <source>%1 min %2 s</source>
        <translation>%1 min %2 s</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Cycle time: none while the file has errors</source>
        <translation>Cycle time: none while the file has errors</translation>
    </message>
    <message>
        <source>Cycle time: choose the machine the file is for</source>
        <translation>Cycle time: choose the machine the file is for</translation>
    </message>
    <message>
        <source>Cycle time: measuring on the simulated machine…</source>
        <translation>Cycle time: measuring on the simulated machine…</translation>
    </message>
    <message>
        <source>the run ends in an alarm</source>
        <translation>the run ends in an alarm</translation>
    </message>
    <message>
        <source>the run does not end within an hour</source>
        <translation>the run does not end within an hour</translation>
    </message>
    <message>
        <source>the program cannot be started on this machine</source>
        <translation>the program cannot be started on this machine</translation>
    </message>
    <message>
        <source>Cycle time of L%1: %2 (%3)</source>
        <translation>Cycle time of L%1: %2 (%3)</translation>
    </message>
    <message>
        <source>Cycle time of L%1: none, %2 (%3)</source>
        <translation>Cycle time of L%1: none, %2 (%3)</translation>
    </message>
</context>
<context>
    <name>k528::studio::DatabaseTexts</name>
    <message>
        <source>no machine "%1" in %2 (machines: %3)</source>
        <translation>no machine "%1" in %2 (machines: %3)</translation>
    </message>
    <message>
        <source>no machine "%1" in %2 (machines: none)</source>
        <translation>no machine "%1" in %2 (machines: none)</translation>
    </message>
    <message>
        <source>a machine named %1 already exists in %2</source>
        <translation>a machine named %1 already exists in %2</translation>
    </message>
    <message>
        <source>cannot rename %1 to %2: a machine of that name exists</source>
        <translation>cannot rename %1 to %2: a machine of that name exists</translation>
    </message>
    <message>
        <source>machine %1: the machine constants are locked by the trainer for the class «%2» (setting %3): %4 not changed; nothing was written (the trainer unlocks them first: k528 db set %1 %3=)</source>
        <translation>machine %1: the machine constants are locked by the trainer for the class «%2» (setting %3): %4 not changed; nothing was written (the trainer unlocks them first: k528 db set %1 %3=)</translation>
    </message>
    <message>
        <source>machine %1 has revisions 1..%2; there is no revision %3</source>
        <translation>machine %1 has revisions 1..%2; there is no revision %3</translation>
    </message>
    <message>
        <source>machine %1 is at revision %2, not %3</source>
        <translation>machine %1 is at revision %2, not %3</translation>
    </message>
    <message>
        <source>machine %1 is at revision %2 (changed by %3 at %4), not %5 as read: load it again and repeat the change</source>
        <translation>machine %1 is at revision %2 (changed by %3 at %4), not %5 as read: load it again and repeat the change</translation>
    </message>
    <message>
        <source>the author's name is %1 bytes long; a name has at most %2 (UTF-8); nothing was written</source>
        <translation>the author's name is %1 bytes long; a name has at most %2 (UTF-8); nothing was written</translation>
    </message>
    <message>
        <source>machine %1 revision %2 in %3: history entry %4 %5 of revision %6 cannot be read</source>
        <translation>machine %1 revision %2 in %3: history entry %4 %5 of revision %6 cannot be read</translation>
    </message>
    <message>
        <source>machine %1 revision %2 in %3: the revision is missing from the revision table</source>
        <translation>machine %1 revision %2 in %3: the revision is missing from the revision table</translation>
    </message>
    <message>
        <source>machine %1 revision %2 in %3: program L%4 of revision %5 does not match its SHA-256 checksum</source>
        <translation>machine %1 revision %2 in %3: program L%4 of revision %5 does not match its SHA-256 checksum</translation>
    </message>
    <message>
        <source>machine %1: history has an unknown section %2</source>
        <translation>machine %1: history has an unknown section %2</translation>
    </message>
    <message>
        <source>machine %1: program L%2 does not match its SHA-256 checksum</source>
        <translation>machine %1: program L%2 does not match its SHA-256 checksum</translation>
    </message>
    <message>
        <source>%1: the database has no message history (schema version %2 below %3: open it once with write access to upgrade it)</source>
        <translation>%1: the database has no message history (schema version %2 below %3: open it once with write access to upgrade it)</translation>
    </message>
    <message>
        <source>%1: the database has no training attempts (schema version %2 below %3: open it once with write access to upgrade it)</source>
        <translation>%1: the database has no training attempts (schema version %2 below %3: open it once with write access to upgrade it)</translation>
    </message>
    <message>
        <source>%1: the database has no time in each state of the shop's machines (schema version %2 below %3: open it once with write access to upgrade it)</source>
        <translation>%1: the database has no time in each state of the shop's machines (schema version %2 below %3: open it once with write access to upgrade it)</translation>
    </message>
    <message>
        <source>an attempt needs its student's name; nothing was written</source>
        <translation>an attempt needs its student's name; nothing was written</translation>
    </message>
    <message>
        <source>an attempt needs its exercise; nothing was written</source>
        <translation>an attempt needs its exercise; nothing was written</translation>
    </message>
    <message>
        <source>the attempt of "%1" at "%2": a score is 0..100, not %3; nothing was written</source>
        <translation>the attempt of "%1" at "%2": a score is 0..100, not %3; nothing was written</translation>
    </message>
    <message>
        <source>the attempt of "%1" at "%2": a negative cycle time; nothing was written</source>
        <translation>the attempt of "%1" at "%2": a negative cycle time; nothing was written</translation>
    </message>
    <message>
        <source>a transfer is a push or a pull, not "%1"</source>
        <translation>a transfer is a push or a pull, not "%1"</translation>
    </message>
    <message>
        <source>a transfer's result is ok, partial or failed, not "%1"</source>
        <translation>a transfer's result is ok, partial or failed, not "%1"</translation>
    </message>
    <message>
        <source>a time in a state needs a machine, a day (YYYY-MM-DD), run, idle, alarm or offline and 0 ms or more, not '%1' '%2' '%3' %4 ms; nothing was written</source>
        <translation>a time in a state needs a machine, a day (YYYY-MM-DD), run, idle, alarm or offline and 0 ms or more, not '%1' '%2' '%3' %4 ms; nothing was written</translation>
    </message>
    <message>
        <source>machine %1 has no program L%2 (at revision %3); nothing was released</source>
        <translation>machine %1 has no program L%2 (at revision %3); nothing was released</translation>
    </message>
    <message>
        <source>program L%2 of machine %1 was never released; nothing was written</source>
        <translation>program L%2 of machine %1 was never released; nothing was written</translation>
    </message>
    <message>
        <source>program L%2 of machine %1 is withdrawn already; nothing was written</source>
        <translation>program L%2 of machine %1 is withdrawn already; nothing was written</translation>
    </message>
    <message>
        <source>%1: an SQLite database has one user, who may do everything; the roles are PostgreSQL's</source>
        <translation>%1: an SQLite database has one user, who may do everything; the roles are PostgreSQL's</translation>
    </message>
    <message>
        <source>no database location: set K528_DB, XDG_DATA_HOME or HOME</source>
        <translation>no database location: set K528_DB, XDG_DATA_HOME or HOME</translation>
    </message>
    <message>
        <source>K528_DB names a PostgreSQL database (%1), not a file</source>
        <translation>K528_DB names a PostgreSQL database (%1), not a file</translation>
    </message>
    <message>
        <source>no database at %1</source>
        <translation>no database at %1</translation>
    </message>
    <message>
        <source>no database at %1 (create one with: k528 db init --db %1)</source>
        <translation>no database at %1 (create one with: k528 db init --db %1)</translation>
    </message>
    <message>
        <source>cannot create the database %1: the folder %2 does not exist</source>
        <translation>cannot create the database %1: the folder %2 does not exist</translation>
    </message>
    <message>
        <source>%1: is a directory, not a database file</source>
        <translation>%1: is a directory, not a database file</translation>
    </message>
    <message>
        <source>%1: not an empty database (schema version %2); a copy goes only into a new or empty one</source>
        <translation>%1: not an empty database (schema version %2); a copy goes only into a new or empty one</translation>
    </message>
    <message>
        <source>not a K528 Studio database: the file has only %1 bytes, too few for an SQLite database</source>
        <translation>not a K528 Studio database: the file has only %1 bytes, too few for an SQLite database</translation>
    </message>
    <message>
        <source>not a K528 Studio database: the file does not start with the SQLite header (another kind of file, or a database whose first page is damaged)</source>
        <translation>not a K528 Studio database: the file does not start with the SQLite header (another kind of file, or a database whose first page is damaged)</translation>
    </message>
    <message>
        <source>not a K528 Studio database: it is another program's SQLite database (application_id %1, ours is %2)</source>
        <translation>not a K528 Studio database: it is another program's SQLite database (application_id %1, ours is %2)</translation>
    </message>
    <message>
        <source>not a K528 Studio database: it is another program's SQLite database (application_id %1, %2 schema objects)</source>
        <translation>not a K528 Studio database: it is another program's SQLite database (application_id %1, %2 schema objects)</translation>
    </message>
    <message>
        <source>the database has schema version %1, written by a newer K528 Studio; this program knows versions up to %2. Use the newer program</source>
        <translation>the database has schema version %1, written by a newer K528 Studio; this program knows versions up to %2. Use the newer program</translation>
    </message>
    <message>
        <source>; the file was left untouched</source>
        <translation>; the file was left untouched</translation>
    </message>
    <message>
        <source>; only the unfinished transaction in %1 was rolled back (SQLite's crash recovery of a K528 Studio database), nothing else was changed</source>
        <translation>; only the unfinished transaction in %1 was rolled back (SQLite's crash recovery of a K528 Studio database), nothing else was changed</translation>
    </message>
    <message>
        <source>%1: another process is writing to the database and kept it locked longer than the busy timeout; nothing was written, try again</source>
        <translation>%1: another process is writing to the database and kept it locked longer than the busy timeout; nothing was written, try again</translation>
    </message>
    <message>
        <source>%1 has schema version %2; a copy needs version %3 (open it once with write access to upgrade it)</source>
        <translation>%1 has schema version %2; a copy needs version %3 (open it once with write access to upgrade it)</translation>
    </message>
    <message>
        <source>a database cannot be copied into itself</source>
        <translation>a database cannot be copied into itself</translation>
    </message>
    <message>
        <source>'%1' is not ITEM=VALUE (e.g. C022=2133, R12=5, #3=TEXT, A01=TEXT)</source>
        <translation>'%1' is not ITEM=VALUE (e.g. C022=2133, R12=5, #3=TEXT, A01=TEXT)</translation>
    </message>
    <message>
        <source>%1: no such C-parameter (1..152)</source>
        <translation>%1: no such C-parameter (1..152)</translation>
    </message>
    <message>
        <source>%1: no such R-parameter (0..299)</source>
        <translation>%1: no such R-parameter (0..299)</translation>
    </message>
    <message>
        <source>%1: no such technological message (#1..#99)</source>
        <translation>%1: no such technological message (#1..#99)</translation>
    </message>
    <message>
        <source>%1: no such PLC message (%2..%3)</source>
        <translation>%1: no such PLC message (%2..%3)</translation>
    </message>
    <message>
        <source>%1: '%2' is not a whole number</source>
        <translation>%1: '%2' is not a whole number</translation>
    </message>
    <message>
        <source>'%1' is not an item: C&lt;n&gt;, R&lt;n&gt;, #&lt;n&gt;, A&lt;nn&gt;, W&lt;nn&gt;, S&lt;nn&gt;, title or a simulation key</source>
        <translation>'%1' is not an item: C&lt;n&gt;, R&lt;n&gt;, #&lt;n&gt;, A&lt;nn&gt;, W&lt;nn&gt;, S&lt;nn&gt;, title or a simulation key</translation>
    </message>
    <message>
        <source>%1 is given twice ('%2' and '%3'); give each item once</source>
        <translation>%1 is given twice ('%2' and '%3'); give each item once</translation>
    </message>
    <message>
        <source>'%1' is not a known simulation key; nothing was saved. The keys are listed in docs/profile-format.md; --allow-unknown stores it anyway</source>
        <translation>'%1' is not a known simulation key; nothing was saved. The keys are listed in docs/profile-format.md; --allow-unknown stores it anyway</translation>
    </message>
    <message>
        <source>'%1' is not a known simulation key; nothing was saved (did you mean %2?). The keys are listed in docs/profile-format.md; --allow-unknown stores it anyway</source>
        <translation>'%1' is not a known simulation key; nothing was saved (did you mean %2?). The keys are listed in docs/profile-format.md; --allow-unknown stores it anyway</translation>
    </message>
    <message>
        <source>%1 or %2</source>
        <translation>%1 or %2</translation>
    </message>
    <message>
        <source>database location "%1": empty; give a file path or a postgresql:// URI</source>
        <translation>database location "%1": empty; give a file path or a postgresql:// URI</translation>
    </message>
    <message>
        <source>database location "%1": a password does not go into a database location (every user of this PC can read a command line, and shells keep it): put it in ~/.pgpass (PGPASSFILE) or a service file (PGSERVICEFILE, postgresql://?service=NAME), or log in without one</source>
        <translation>database location "%1": a password does not go into a database location (every user of this PC can read a command line, and shells keep it): put it in ~/.pgpass (PGPASSFILE) or a service file (PGSERVICEFILE, postgresql://?service=NAME), or log in without one</translation>
    </message>
    <message>
        <source>database location "%1": sqlite: needs a file path (sqlite:/srv/k528/shop.db)</source>
        <translation>database location "%1": sqlite: needs a file path (sqlite:/srv/k528/shop.db)</translation>
    </message>
    <message>
        <source>database location "%1": unknown kind of database "%2"; K528 Studio keeps its database in SQLite (a file path or sqlite:PATH) or PostgreSQL (postgresql://…)</source>
        <translation>database location "%1": unknown kind of database "%2"; K528 Studio keeps its database in SQLite (a file path or sqlite:PATH) or PostgreSQL (postgresql://…)</translation>
    </message>
    <message>
        <source>cannot connect to the database %1: %2</source>
        <translation>cannot connect to the database %1: %2</translation>
    </message>
    <message>
        <source>the connection to the server was lost and cannot be made again</source>
        <translation>the connection to the server was lost and cannot be made again</translation>
    </message>
    <message>
        <source>cannot open: %1</source>
        <translation>cannot open: %1</translation>
    </message>
    <message>
        <source>cannot be read: %1</source>
        <translation>cannot be read: %1</translation>
    </message>
    <message>
        <source>%1: is not a regular file (a character device); a database is a regular file — give another --db path</source>
        <translation>%1: is not a regular file (a character device); a database is a regular file — give another --db path</translation>
    </message>
    <message>
        <source>%1: is not a regular file (a block device); a database is a regular file — give another --db path</source>
        <translation>%1: is not a regular file (a block device); a database is a regular file — give another --db path</translation>
    </message>
    <message>
        <source>%1: is not a regular file (a FIFO); a database is a regular file — give another --db path</source>
        <translation>%1: is not a regular file (a FIFO); a database is a regular file — give another --db path</translation>
    </message>
    <message>
        <source>%1: is not a regular file (a socket); a database is a regular file — give another --db path</source>
        <translation>%1: is not a regular file (a socket); a database is a regular file — give another --db path</translation>
    </message>
    <message>
        <source>%1: is not a regular file (not a file); a database is a regular file — give another --db path</source>
        <translation>%1: is not a regular file (not a file); a database is a regular file — give another --db path</translation>
    </message>
    <message>
        <source>cannot be read: SQLite did not open the file</source>
        <translation>cannot be read: SQLite did not open the file</translation>
    </message>
    <message>
        <source>another program kept the database locked longer than the busy timeout (%1)</source>
        <translation>another program kept the database locked longer than the busy timeout (%1)</translation>
    </message>
    <message>
        <source>cannot be read as a database (%1)</source>
        <translation>cannot be read as a database (%1)</translation>
    </message>
    <message>
        <source>the database is damaged (integrity check: %1)</source>
        <translation>the database is damaged (integrity check: %1)</translation>
    </message>
    <message>
        <source>the database is damaged (integrity check: %1 rows break foreign keys (first: %2 row %3 -&gt; %4))</source>
        <translation>the database is damaged (integrity check: %1 rows break foreign keys (first: %2 row %3 -&gt; %4))</translation>
    </message>
    <message>
        <source>K528 Studio database without a schema version</source>
        <translation>K528 Studio database without a schema version</translation>
    </message>
    <message>
        <source>not a K528 Studio database: an SQLite database without K528 Studio's application_id, with an unfinished transaction of another program (the hot journal %1, begun on a file of %2 pages), which is not ours to roll back: let that program open it first</source>
        <translation>not a K528 Studio database: an SQLite database without K528 Studio's application_id, with an unfinished transaction of another program (the hot journal %1, begun on a file of %2 pages), which is not ours to roll back: let that program open it first</translation>
    </message>
    <message>
        <source>not a K528 Studio database: an SQLite database without K528 Studio's application_id, with an unfinished transaction of another program (the hot journal %1, begun on a file of unknown size), which is not ours to roll back: let that program open it first</source>
        <translation>not a K528 Studio database: an SQLite database without K528 Studio's application_id, with an unfinished transaction of another program (the hot journal %1, begun on a file of unknown size), which is not ours to roll back: let that program open it first</translation>
    </message>
    <message>
        <source>another program wrote into the file while it was being created</source>
        <translation>another program wrote into the file while it was being created</translation>
    </message>
    <message>
        <source>cannot switch to WAL journal mode (mode "%1"): another process kept the database busy longer than the busy timeout</source>
        <translation>cannot switch to WAL journal mode (mode "%1"): another process kept the database busy longer than the busy timeout</translation>
    </message>
    <message>
        <source>the search path names no schema that exists; create it or set search_path (options=-csearch_path=…)</source>
        <translation>the search path names no schema that exists; create it or set search_path (options=-csearch_path=…)</translation>
    </message>
    <message>
        <source>not a K528 Studio database: it holds %1 tables or views of another program (no k528_schema); nothing was changed</source>
        <translation>not a K528 Studio database: it holds %1 tables or views of another program (no k528_schema); nothing was changed</translation>
    </message>
    <message>
        <source>not a K528 Studio database (k528_schema says "%1"); nothing was changed</source>
        <translation>not a K528 Studio database (k528_schema says "%1"); nothing was changed</translation>
    </message>
    <message>
        <source>the table k528_schema is empty</source>
        <translation>the table k528_schema is empty</translation>
    </message>
    <message>
        <source>no K528 Studio database at %1 (the database is empty; create one with: k528 db init --db %1)</source>
        <translation>no K528 Studio database at %1 (the database is empty; create one with: k528 db init --db %1)</translation>
    </message>
    <message>
        <source>%1: not an empty database (schema version %2); a copy goes only into an empty one</source>
        <translation>%1: not an empty database (schema version %2); a copy goes only into an empty one</translation>
    </message>
    <message>
        <source>PostgreSQL %1 is too old; K528 Studio needs version 11 or newer</source>
        <translation>PostgreSQL %1 is too old; K528 Studio needs version 11 or newer</translation>
    </message>
    <message>
        <source>the database's encoding is %1; K528 Studio keeps Russian texts and needs UTF8 (createdb --encoding=UTF8 --template=template0)</source>
        <translation>the database's encoding is %1; K528 Studio keeps Russian texts and needs UTF8 (createdb --encoding=UTF8 --template=template0)</translation>
    </message>
    <message>
        <source>%1: another session is writing to the database and kept it locked longer than the busy timeout; nothing was written, try again</source>
        <translation>%1: another session is writing to the database and kept it locked longer than the busy timeout; nothing was written, try again</translation>
    </message>
    <message>
        <source>no role "%1": the roles are trainer, technologist, operator and viewer</source>
        <translation>no role "%1": the roles are trainer, technologist, operator and viewer</translation>
    </message>
    <message>
        <source>no message run %1; nothing was written</source>
        <translation>no message run %1; nothing was written</translation>
    </message>
    <message>
        <source>the new run has no id</source>
        <translation>the new run has no id</translation>
    </message>
    <message>
        <source>another process kept the database locked longer than the busy timeout; the messages were not written</source>
        <translation>another process kept the database locked longer than the busy timeout; the messages were not written</translation>
    </message>
    <message>
        <source>message event %1 of run %2: acknowledged without saying how</source>
        <translation>message event %1 of run %2: acknowledged without saying how</translation>
    </message>
    <message>
        <source>message event %1 of run %2: no such message was raised</source>
        <translation>message event %1 of run %2: no such message was raised</translation>
    </message>
    <message>
        <source>message history row %1: unknown source "%2"</source>
        <translation>message history row %1: unknown source "%2"</translation>
    </message>
    <message>
        <source>; none of the batch's %1 events was written</source>
        <translation>; none of the batch's %1 events was written</translation>
    </message>
    <message>
        <source>machine %1: a push takes released programs only; not released as they are:</source>
        <translation>machine %1: a push takes released programs only; not released as they are:</translation>
    </message>
    <message>
        <source>L%1: not in the database, nothing of it released</source>
        <translation>L%1: not in the database, nothing of it released</translation>
    </message>
    <message>
        <source>L%1: draft, nothing of it released</source>
        <translation>L%1: draft, nothing of it released</translation>
    </message>
    <message>
        <source>L%1: withdrawn, nothing of it released</source>
        <translation>L%1: withdrawn, nothing of it released</translation>
    </message>
    <message>
        <source>L%1: not the released version (revision %2)</source>
        <translation>L%1: not the released version (revision %2)</translation>
    </message>
    <message>
        <source>release them (k528 db release %1 L&lt;n&gt;), or let technologists push drafts: k528 db set %1 push.unreleased=true</source>
        <translation>release them (k528 db release %1 L&lt;n&gt;), or let technologists push drafts: k528 db set %1 push.unreleased=true</translation>
    </message>
    <message>
        <source>release them (k528 db release %1 L&lt;n&gt;), or push as a technologist (the machine allows drafts: push.unreleased)</source>
        <translation>release them (k528 db release %1 L&lt;n&gt;), or push as a technologist (the machine allows drafts: push.unreleased)</translation>
    </message>
    <message>
        <source>column %1 holds a value that is neither an integer nor a text (query: %2)</source>
        <translation>column %1 holds a value that is neither an integer nor a text (query: %2)</translation>
    </message>
    <message>
        <source>column %1 holds a value where an integer belongs: %2</source>
        <translation>column %1 holds a value where an integer belongs: %2</translation>
    </message>
    <message>
        <source>; the migration to schema version %1 failed, nothing was changed</source>
        <translation>; the migration to schema version %1 failed, nothing was changed</translation>
    </message>
    <message>
        <source>an unexpected database error (please report it): %1</source>
        <translation>an unexpected database error (please report it): %1</translation>
    </message>
    <message>
        <source>machine %1: rejected, nothing was written (%2 error):</source>
        <translation>machine %1: rejected, nothing was written (%2 error):</translation>
    </message>
    <message>
        <source>machine %1: rejected, nothing was written (%2 errors):</source>
        <translation>machine %1: rejected, nothing was written (%2 errors):</translation>
    </message>
    <message>
        <source>machine %1: rejected, nothing was written:</source>
        <translation>machine %1: rejected, nothing was written:</translation>
    </message>
    <message>
        <source>machine %1 revision %2 in %3: simulation key %4 of the stored order has no value</source>
        <translation>machine %1 revision %2 in %3: simulation key %4 of the stored order has no value</translation>
    </message>
    <message>
        <source>machine %1 revision %2 in %3: the stored order of the simulation settings does not list every key</source>
        <translation>machine %1 revision %2 in %3: the stored order of the simulation settings does not list every key</translation>
    </message>
    <message>
        <source>machine %1 in %2: C values: "%3" where integer pairs belong</source>
        <translation>machine %1 in %2: C values: "%3" where integer pairs belong</translation>
    </message>
    <message>
        <source>machine %1 in %2: C values: a number without its value</source>
        <translation>machine %1 in %2: C values: a number without its value</translation>
    </message>
    <message>
        <source>machine %1 in %2: R presets: "%3" where integer pairs belong</source>
        <translation>machine %1 in %2: R presets: "%3" where integer pairs belong</translation>
    </message>
    <message>
        <source>machine %1 in %2: R presets: a number without its value</source>
        <translation>machine %1 in %2: R presets: a number without its value</translation>
    </message>
    <message>
        <source>machine %1 in %2: C-parameter number %3 is not 1..152</source>
        <translation>machine %1 in %2: C-parameter number %3 is not 1..152</translation>
    </message>
    <message>
        <source>machine %1 in %2: %3 of the 152 C-parameter values are stored</source>
        <translation>machine %1 in %2: %3 of the 152 C-parameter values are stored</translation>
    </message>
    <message>
        <source>machine %1 in %2: program L%3 of revision %4 does not match its SHA-256 checksum (the text was altered outside K528 Studio)</source>
        <translation>machine %1 in %2: program L%3 of revision %4 does not match its SHA-256 checksum (the text was altered outside K528 Studio)</translation>
    </message>
    <message>
        <source>machine %1 in %2: unknown PLC message group %3</source>
        <translation>machine %1 in %2: unknown PLC message group %3</translation>
    </message>
    <message>
        <source>machine %1 in %2: the simulation setting %3=%4 cannot be read</source>
        <translation>machine %1 in %2: the simulation setting %3=%4 cannot be read</translation>
    </message>
    <message>
        <source>the database is read-only: %1 (%2); nothing was written</source>
        <translation>the database is read-only: %1 (%2); nothing was written</translation>
    </message>
    <message>
        <source>the database is read-only: %1 (%2); a new database cannot be created there</source>
        <translation>the database is read-only: %1 (%2); a new database cannot be created there</translation>
    </message>
    <message>
        <source>the database is read-only: %1 (%2); its schema is older than this program's and cannot be upgraded</source>
        <translation>the database is read-only: %1 (%2); its schema is older than this program's and cannot be upgraded</translation>
    </message>
    <message>
        <source>the database is read-only: %1 (%2); it has an unfinished transaction (a hot -journal) that only a user who may write the file can roll back; the file was left untouched</source>
        <translation>the database is read-only: %1 (%2); it has an unfinished transaction (a hot -journal) that only a user who may write the file can roll back; the file was left untouched</translation>
    </message>
    <message>
        <source>permission denied</source>
        <translation>permission denied</translation>
    </message>
    <message>
        <source>no permission to create files in its folder</source>
        <translation>no permission to create files in its folder</translation>
    </message>
    <message>
        <source>read-only file system</source>
        <translation>read-only file system</translation>
    </message>
    <message>
        <source>opened read-only</source>
        <translation>opened read-only</translation>
    </message>
    <message>
        <source>the database %1 refused the user %2: %4 needs %5; the user has %3; nothing was written</source>
        <translation>the database %1 refused the user %2: %4 needs %5; the user has %3; nothing was written</translation>
    </message>
    <message>
        <source>the database %1 refused the user %2: %3 needs %4; the user has no K528 Studio role; nothing was written</source>
        <translation>the database %1 refused the user %2: %3 needs %4; the user has no K528 Studio role; nothing was written</translation>
    </message>
    <message>
        <source>creating a machine</source>
        <translation>creating a machine</translation>
    </message>
    <message>
        <source>changing a machine</source>
        <translation>changing a machine</translation>
    </message>
    <message>
        <source>deleting a machine</source>
        <translation>deleting a machine</translation>
    </message>
    <message>
        <source>releasing a program</source>
        <translation>releasing a program</translation>
    </message>
    <message>
        <source>withdrawing a program</source>
        <translation>withdrawing a program</translation>
    </message>
    <message>
        <source>recording a transfer</source>
        <translation>recording a transfer</translation>
    </message>
    <message>
        <source>recording messages</source>
        <translation>recording messages</translation>
    </message>
    <message>
        <source>recording a training attempt</source>
        <translation>recording a training attempt</translation>
    </message>
    <message>
        <source>creating the database's tables</source>
        <translation>creating the database's tables</translation>
    </message>
    <message>
        <source>setting up the roles</source>
        <translation>setting up the roles</translation>
    </message>
    <message>
        <source>granting a role</source>
        <translation>granting a role</translation>
    </message>
    <message>
        <source>setting or clearing the constants lock</source>
        <translation>setting or clearing the constants lock</translation>
    </message>
    <message>
        <source>recording the machines' time in each state</source>
        <translation>recording the machines' time in each state</translation>
    </message>
    <message>
        <source>the role %1</source>
        <translation>the role %1</translation>
    </message>
    <message>
        <source>the owner of the database</source>
        <translation>the owner of the database</translation>
    </message>
    <message>
        <source>the owner of the database's tables with CREATEROLE</source>
        <translation>the owner of the database's tables with CREATEROLE</translation>
    </message>
    <message>
        <source>the role's admin (its creator, or CREATEROLE)</source>
        <translation>the role's admin (its creator, or CREATEROLE)</translation>
    </message>
    <message>
        <source>machine %1: %2</source>
        <translation>machine %1: %2</translation>
    </message>
</context>
<context>
    <name>k528::studio::DatabaseUi</name>
    <message>
        <source>Database: %1</source>
        <translation>Database: %1</translation>
    </message>
    <message>
        <source>The database %1 cannot be opened: %2</source>
        <translation>The database %1 cannot be opened: %2</translation>
    </message>
    <message>
        <source>this is not a database location (a file path, sqlite:PATH or postgresql://HOST/NAME; a password is never written in it: use ~/.pgpass or a service file)</source>
        <translation>this is not a database location (a file path, sqlite:PATH or postgresql://HOST/NAME; a password is never written in it: use ~/.pgpass or a service file)</translation>
    </message>
    <message>
        <source>it cannot be reached, read or created</source>
        <translation>it cannot be reached, read or created</translation>
    </message>
    <message>
        <source>it is not a K528 Studio database</source>
        <translation>it is not a K528 Studio database</translation>
    </message>
    <message>
        <source>it is damaged (nothing in it was changed)</source>
        <translation>it is damaged (nothing in it was changed)</translation>
    </message>
    <message>
        <source>it was written by a newer K528 Studio</source>
        <translation>it was written by a newer K528 Studio</translation>
    </message>
    <message>
        <source>another program holds it too long</source>
        <translation>another program holds it too long</translation>
    </message>
    <message>
        <source>the server refused this user</source>
        <translation>the server refused this user</translation>
    </message>
    <message>
        <source>an unexpected database error</source>
        <translation>an unexpected database error</translation>
    </message>
    <message>
        <source>The database %1 cannot be opened: %2.
Details: %3</source>
        <translation>The database %1 cannot be opened: %2.
Details: %3</translation>
    </message>
    <message>
        <source>Name a database: a file path, sqlite:PATH or postgresql://HOST/NAME.</source>
        <translation>Name a database: a file path, sqlite:PATH or postgresql://HOST/NAME.</translation>
    </message>
    <message>
        <source>K528 Studio — %1</source>
        <translation>K528 Studio — %1</translation>
    </message>
    <message>
        <source>Database</source>
        <translation>Database</translation>
    </message>
    <message>
        <source>The database of machines, programs and their history: a file on this PC (a path, or sqlite:PATH), or the shop's PostgreSQL server (postgresql://HOST/NAME, postgresql:///NAME, postgresql://?service=shop). The password is never written here: the server's password is read from ~/.pgpass (PGPASSFILE) or a service file.</source>
        <translation>The database of machines, programs and their history: a file on this PC (a path, or sqlite:PATH), or the shop's PostgreSQL server (postgresql://HOST/NAME, postgresql:///NAME, postgresql://?service=shop). The password is never written here: the server's password is read from ~/.pgpass (PGPASSFILE) or a service file.</translation>
    </message>
    <message>
        <source>File...</source>
        <translation>File...</translation>
    </message>
    <message>
        <source>Database file</source>
        <translation>Database file</translation>
    </message>
    <message>
        <source>K528 Studio databases (*.db *.sqlite);;All files (*)</source>
        <translation>K528 Studio databases (*.db *.sqlite);;All files (*)</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Open</translation>
    </message>
    <message>
        <source>%1 changed on another PC: revision %2 by %3 at %4 (%5)</source>
        <translation>%1 changed on another PC: revision %2 by %3 at %4 (%5)</translation>
    </message>
    <message>
        <source>&amp;Database...</source>
        <translation>&amp;Database...</translation>
    </message>
    <message>
        <source>Database %1 open</source>
        <translation>Database %1 open</translation>
    </message>
    <message>
        <source>Transfers</source>
        <translation>Transfers</translation>
    </message>
    <message>
        <source>every machine</source>
        <translation>every machine</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Time</translation>
    </message>
    <message>
        <source>User</source>
        <translation>User</translation>
    </message>
    <message>
        <source>PC</source>
        <translation>PC</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Machine</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Controller</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Direction</translation>
    </message>
    <message>
        <source>What moved</source>
        <translation>What moved</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Result</translation>
    </message>
    <message>
        <source>Machine:</source>
        <translation>Machine:</translation>
    </message>
    <message>
        <source>push</source>
        <translation>push</translation>
    </message>
    <message>
        <source>pull</source>
        <translation>pull</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <source>partial</source>
        <translation>partial</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>failed</translation>
    </message>
    <message>
        <source>%1 transfers</source>
        <translation>%1 transfers</translation>
    </message>
    <message>
        <source>&amp;Transfers...</source>
        <translation>&amp;Transfers...</translation>
    </message>
    <message>
        <source>The database %1 cannot be opened: %2.</source>
        <translation>The database %1 cannot be opened: %2.</translation>
    </message>
</context>
<context>
    <name>k528::studio::DebugPanel</name>
    <message>
        <source>Type an R-parameter number, R0..R299.</source>
        <translation>Type an R-parameter number, R0..R299.</translation>
    </message>
    <message>
        <source>A program is under way: stop it first.</source>
        <translation>A program is under way: stop it first.</translation>
    </message>
    <message>
        <source>Open a program file first.</source>
        <translation>Open a program file first.</translation>
    </message>
    <message>
        <source>The program under way is another file's.</source>
        <translation>The program under way is another file's.</translation>
    </message>
    <message>
        <source>R-parameters are R0..R299, not R%1.</source>
        <translation>R-parameters are R0..R299, not R%1.</translation>
    </message>
    <message>
        <source>R%1 was not set: %2</source>
        <translation>R%1 was not set: %2</translation>
    </message>
    <message>
        <source>R%1: «%2» is not a whole number.</source>
        <translation>R%1: «%2» is not a whole number.</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Run</translation>
    </message>
    <message>
        <source>Send the file and run its first program (homing as the operator would), or continue</source>
        <translation>Send the file and run its first program (homing as the operator would), or continue</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Hold</translation>
    </message>
    <message>
        <source>Continue</source>
        <translation>Continue</translation>
    </message>
    <message>
        <source>Single frame</source>
        <translation>Single frame</translation>
    </message>
    <message>
        <source>Run to cursor</source>
        <translation>Run to cursor</translation>
    </message>
    <message>
        <source>Run until the frame at the cursor, stopping before it</source>
        <translation>Run until the frame at the cursor, stopping before it</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stop</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reset</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Speed</translation>
    </message>
    <message>
        <source>fastest</source>
        <translation>fastest</translation>
    </message>
    <message>
        <source>real time</source>
        <translation>real time</translation>
    </message>
    <message>
        <source>Call stack</source>
        <translation>Call stack</translation>
    </message>
    <message>
        <source>R158</source>
        <translation>R158</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation>Frame</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Line</translation>
    </message>
    <message>
        <source>Watch</source>
        <translation>Watch</translation>
    </message>
    <message>
        <source>Add an R-parameter: R12, Enter</source>
        <translation>Add an R-parameter: R12, Enter</translation>
    </message>
    <message>
        <source>R</source>
        <translation>R</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Value</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Meaning</translation>
    </message>
    <message>
        <source>Like STOP on the machine's panel: the motion stops, CYCLE START continues</source>
        <translation>Like STOP on the machine's panel: the motion stops, CYCLE START continues</translation>
    </message>
    <message>
        <source>Like CYCLE START: continue the held program</source>
        <translation>Like CYCLE START: continue the held program</translation>
    </message>
    <message>
        <source>Stop after each frame; CYCLE START runs the next one</source>
        <translation>Stop after each frame; CYCLE START runs the next one</translation>
    </message>
    <message>
        <source>Like RESET: the program ends without continuation</source>
        <translation>Like RESET: the program ends without continuation</translation>
    </message>
    <message>
        <source>RESET and ESC: end the program and acknowledge the messages</source>
        <translation>RESET and ESC: end the program and acknowledge the messages</translation>
    </message>
    <message>
        <source>the file</source>
        <translation>the file</translation>
    </message>
    <message>
        <source>There is no frame at or after line %1.</source>
        <translation>There is no frame at or after line %1.</translation>
    </message>
    <message>
        <source>L%1 never reaches line %2: nothing to start there.</source>
        <translation>L%1 never reaches line %2: nothing to start there.</translation>
    </message>
    <message>
        <source>Line %1 runs while %2 oscillates (Gx81 up to its Gx80): start from the frame of the Gx81 or after the Gx80.</source>
        <translation>Line %1 runs while %2 oscillates (Gx81 up to its Gx80): start from the frame of the Gx81 or after the Gx80.</translation>
    </message>
    <message>
        <source>Start here</source>
        <translation>Start here</translation>
    </message>
    <message>
        <source>L%1 N%2 (line %3)</source>
        <translation>L%1 N%2 (line %3)</translation>
    </message>
    <message>
        <source>L%1 (line %2)</source>
        <translation>L%1 (line %2)</translation>
    </message>
    <message>
        <source>L%1 starts before %2 with the state the preview rebuilt. The axes go there first: X to its reference point, then Z, then X, at the rapid speed.</source>
        <translation>L%1 starts before %2 with the state the preview rebuilt. The axes go there first: X to its reference point, then Z, then X, at the rapid speed.</translation>
    </message>
    <message>
        <source>State</source>
        <translation>State</translation>
    </message>
    <message>
        <source>Modal functions</source>
        <translation>Modal functions</translation>
    </message>
    <message>
        <source>Feeds</source>
        <translation>Feeds</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>R224..R231 (coordinate components)</source>
        <translation>R224..R231 (coordinate components)</translation>
    </message>
    <message>
        <source>R-parameters the program set</source>
        <translation>R-parameters the program set</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Message</translation>
    </message>
    <message>
        <source>M functions handed to the PLC again</source>
        <translation>M functions handed to the PLC again</translation>
    </message>
    <message>
        <source>Start point %1</source>
        <translation>Start point %1</translation>
    </message>
    <message>
        <source>%1 (machine %2)</source>
        <translation>%1 (machine %2)</translation>
    </message>
    <message>
        <source>Safe path</source>
        <translation>Safe path</translation>
    </message>
    <message>
        <source>X %1, Z %2, X %3 (machine system)</source>
        <translation>X %1, Z %2, X %3 (machine system)</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warning</translation>
    </message>
    <message>
        <source>line %1 moves %2 until a signal or by handwheel: the start point takes its programmed end</source>
        <translation>line %1 moves %2 until a signal or by handwheel: the start point takes its programmed end</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Start the program before the frame at the cursor, with its state rebuilt (modal functions, R-parameters, call stack) and shown first</source>
        <translation>Start the program before the frame at the cursor, with its state rebuilt (modal functions, R-parameters, call stack) and shown first</translation>
    </message>
</context>
<context>
    <name>k528::studio::DebugSession</name>
    <message>
        <source>There is no frame at or after line %1.</source>
        <translation>There is no frame at or after line %1.</translation>
    </message>
    <message>
        <source>A program is under way: stop it first.</source>
        <translation>A program is under way: stop it first.</translation>
    </message>
    <message>
        <source>The controller holds no program L%1.</source>
        <translation>The controller holds no program L%1.</translation>
    </message>
    <message>
        <source>The emergency stop is pressed: pull it out on the machine's panel.</source>
        <translation>The emergency stop is pressed: pull it out on the machine's panel.</translation>
    </message>
    <message>
        <source>Switching the drives on…</source>
        <translation>Switching the drives on…</translation>
    </message>
    <message>
        <source>The reference-point mode was refused: %1</source>
        <translation>The reference-point mode was refused: %1</translation>
    </message>
    <message>
        <source>Reference point of %1…</source>
        <translation>Reference point of %1…</translation>
    </message>
    <message>
        <source>Program L%1 was refused: %2</source>
        <translation>Program L%1 was refused: %2</translation>
    </message>
    <message>
        <source>The machine did not get ready: the drives are off (see the machine's messages).</source>
        <translation>The machine did not get ready: the drives are off (see the machine's messages).</translation>
    </message>
    <message>
        <source>The reference-point cycle of %1 stopped with a message.</source>
        <translation>The reference-point cycle of %1 stopped with a message.</translation>
    </message>
    <message>
        <source>The reference-point cycle of %1 ended without the reference point.</source>
        <translation>The reference-point cycle of %1 ended without the reference point.</translation>
    </message>
    <message>
        <source>The reference-point cycle of %1 did not start.</source>
        <translation>The reference-point cycle of %1 did not start.</translation>
    </message>
    <message>
        <source>L%1 runs.</source>
        <translation>L%1 runs.</translation>
    </message>
    <message>
        <source>L%1 ended.</source>
        <translation>L%1 ended.</translation>
    </message>
    <message>
        <source>The program stopped with a message: %1</source>
        <translation>The program stopped with a message: %1</translation>
    </message>
    <message>
        <source>No machine</source>
        <translation>No machine</translation>
    </message>
    <message>
        <source>Starting L%1…</source>
        <translation>Starting L%1…</translation>
    </message>
    <message>
        <source>L%1 N%2 (line %3)</source>
        <translation>L%1 N%2 (line %3)</translation>
    </message>
    <message>
        <source>L%1 (line %2)</source>
        <translation>L%1 (line %2)</translation>
    </message>
    <message>
        <source>No program</source>
        <translation>No program</translation>
    </message>
    <message>
        <source>Running %1</source>
        <translation>Running %1</translation>
    </message>
    <message>
        <source>Breakpoint: before %1</source>
        <translation>Breakpoint: before %1</translation>
    </message>
    <message>
        <source>Single frame: before %1</source>
        <translation>Single frame: before %1</translation>
    </message>
    <message>
        <source>Run to cursor: before %1</source>
        <translation>Run to cursor: before %1</translation>
    </message>
    <message>
        <source>Ended at %1</source>
        <translation>Ended at %1</translation>
    </message>
    <message>
        <source>Stopped by a message at %1</source>
        <translation>Stopped by a message at %1</translation>
    </message>
    <message>
        <source>the emergency stop is pressed on the machine's panel</source>
        <translation>the emergency stop is pressed on the machine's panel</translation>
    </message>
    <message>
        <source>the positioner shows message %1: %2</source>
        <translation>the positioner shows message %1: %2</translation>
    </message>
    <message>
        <source>the PLC did not pass it on (start enable, the machine's messages)</source>
        <translation>the PLC did not pass it on (start enable, the machine's messages)</translation>
    </message>
    <message>
        <source>The machine is paused (Simulation &gt; Pause the machine): the run goes on when it runs.</source>
        <translation>The machine is paused (Simulation &gt; Pause the machine): the run goes on when it runs.</translation>
    </message>
    <message>
        <source>The machine is paused (Simulation &gt; Pause the machine): the program goes on when it runs.</source>
        <translation>The machine is paused (Simulation &gt; Pause the machine): the program goes on when it runs.</translation>
    </message>
    <message>
        <source>the K923 is in %1, not in automatic mode</source>
        <translation>the K923 is in %1, not in automatic mode</translation>
    </message>
    <message>
        <source>Automatic mode was refused: %1</source>
        <translation>Automatic mode was refused: %1</translation>
    </message>
    <message>
        <source>CYCLE START is held down on the machine's panel: release it, then Run again.</source>
        <translation>CYCLE START is held down on the machine's panel: release it, then Run again.</translation>
    </message>
    <message>
        <source>CYCLE START was not taken: %1.</source>
        <translation>CYCLE START was not taken: %1.</translation>
    </message>
    <message>
        <source>M00 at %1: CYCLE START continues</source>
        <translation>M00 at %1: CYCLE START continues</translation>
    </message>
    <message>
        <source>Held at %1: CYCLE START continues</source>
        <translation>Held at %1: CYCLE START continues</translation>
    </message>
</context>
<context>
    <name>k528::studio::DescriptionTexts</name>
    <message>
        <source>appears twice</source>
        <translation>appears twice</translation>
    </message>
    <message>
        <source>JSON syntax error: line %2, column %3</source>
        <translation>JSON syntax error: line %2, column %3</translation>
    </message>
    <message>
        <source>expected an object, found %1</source>
        <translation>expected an object, found %1</translation>
    </message>
    <message>
        <source>unknown key (known here: %1)</source>
        <translation>unknown key (known here: %1)</translation>
    </message>
    <message>
        <source>is missing</source>
        <translation>is missing</translation>
    </message>
    <message>
        <source>expected an array, found %1</source>
        <translation>expected an array, found %1</translation>
    </message>
    <message>
        <source>expected a string, found %1</source>
        <translation>expected a string, found %1</translation>
    </message>
    <message>
        <source>expected a whole number, found %1</source>
        <translation>expected a whole number, found %1</translation>
    </message>
    <message>
        <source>%1 is outside %2..%3</source>
        <translation>%1 is outside %2..%3</translation>
    </message>
    <message>
        <source>expected a number, found %1</source>
        <translation>expected a number, found %1</translation>
    </message>
    <message>
        <source>expected true or false, found %1</source>
        <translation>expected true or false, found %1</translation>
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
        <translation>a number</translation>
    </message>
    <message>
        <source>a string</source>
        <translation>a string</translation>
    </message>
    <message>
        <source>an array</source>
        <translation>an array</translation>
    </message>
    <message>
        <source>an object</source>
        <translation>an object</translation>
    </message>
    <message>
        <source>?</source>
        <translation>?</translation>
    </message>
    <message>
        <source>'%1' is not a valid name (letters, digits and '_', starting with a letter or '_', at most 40)</source>
        <translation>'%1' is not a valid name (letters, digits and '_', starting with a letter or '_', at most 40)</translation>
    </message>
    <message>
        <source>'%1' is reserved (a keyword or a built-in signal)</source>
        <translation>'%1' is reserved (a keyword or a built-in signal)</translation>
    </message>
    <message>
        <source>'%1' is reserved for the K923 keys K1..K12</source>
        <translation>'%1' is reserved for the K923 keys K1..K12</translation>
    </message>
    <message>
        <source>'%1' looks like an interface address (Z&lt;word&gt;.&lt;bit&gt;)</source>
        <translation>'%1' looks like an interface address (Z&lt;word&gt;.&lt;bit&gt;)</translation>
    </message>
    <message>
        <source>this program reads format 1</source>
        <translation>this program reads format 1</translation>
    </message>
    <message>
        <source>is empty</source>
        <translation>is empty</translation>
    </message>
    <message>
        <source>module place %1 appears twice</source>
        <translation>module place %1 appears twice</translation>
    </message>
    <message>
        <source>no module at place %1 in "modules"</source>
        <translation>no module at place %1 in "modules"</translation>
    </message>
    <message>
        <source>'%1': use "no" (normally open) or "nc" (normally closed)</source>
        <translation>'%1': use "no" (normally open) or "nc" (normally closed)</translation>
    </message>
    <message>
        <source>a timer needs exactly one of on_delay_ms, off_delay_ms, pulse_ms</source>
        <translation>a timer needs exactly one of on_delay_ms, off_delay_ms, pulse_ms</translation>
    </message>
    <message>
        <source>a delay belongs to a timer: {"timer": "name", "on_delay_ms": ..., "when": ...}</source>
        <translation>a delay belongs to a timer: {"timer": "name", "on_delay_ms": ..., "when": ...}</translation>
    </message>
    <message>
        <source>a rung has exactly one of "out", "set", "reset", "timer"</source>
        <translation>a rung has exactly one of "out", "set", "reset", "timer"</translation>
    </message>
    <message>
        <source>M%1 is described twice</source>
        <translation>M%1 is described twice</translation>
    </message>
    <message>
        <source>timeout_ms and timeout_alarm go together</source>
        <translation>timeout_ms and timeout_alarm go together</translation>
    </message>
    <message>
        <source>give either "acknowledge": true or "alarm": k (hold the frame, raise alarm k)</source>
        <translation>give either "acknowledge": true or "alarm": k (hold the frame, raise alarm k)</translation>
    </message>
    <message>
        <source>%1 % is not an override step (0 1 2 5 10 20 35 50 75 90 100)</source>
        <translation>%1 % is not an override step (0 1 2 5 10 20 35 50 75 90 100)</translation>
    </message>
    <message>
        <source>K%1 is bound twice</source>
        <translation>K%1 is bound twice</translation>
    </message>
    <message>
        <source>a key needs an action: set, reset, toggle or pulse</source>
        <translation>a key needs an action: set, reset, toggle or pulse</translation>
    </message>
    <message>
        <source>the LEDs of K%1 are described twice</source>
        <translation>the LEDs of K%1 are described twice</translation>
    </message>
    <message>
        <source>message %1 has two conditions here</source>
        <translation>message %1 has two conditions here</translation>
    </message>
    <message>
        <source>not a signal of the positioner interface (known: %1, mode, override, bits)</source>
        <translation>not a signal of the positioner interface (known: %1, mode, override, bits)</translation>
    </message>
    <message>
        <source>needs the four code bits, least significant first</source>
        <translation>needs the four code bits, least significant first</translation>
    </message>
    <message>
        <source>only the free words Z1011..Z1013 are written here; the bits of Z1000..Z1010 have names (see slot keys)</source>
        <translation>only the free words Z1011..Z1013 are written here; the bits of Z1000..Z1010 have names (see slot keys)</translation>
    </message>
    <message>
        <source>writes the same bit as %1</source>
        <translation>writes the same bit as %1</translation>
    </message>
    <message>
        <source>cannot read the file</source>
        <translation>cannot read the file</translation>
    </message>
    <message>
        <source>no such machine description (built in: %1; or give a .json file)</source>
        <translation>no such machine description (built in: %1; or give a .json file)</translation>
    </message>
    <message>
        <source>the name '%1' is already used (%2)</source>
        <translation>the name '%1' is already used (%2)</translation>
    </message>
    <message>
        <source>built in</source>
        <translation>built in</translation>
    </message>
    <message>
        <source>unknown signal '%1'</source>
        <translation>unknown signal '%1'</translation>
    </message>
    <message>
        <source>%1 is not written by the logic (only Z1000..Z1013 are; messages, LEDs and keys have their own sections)</source>
        <translation>%1 is not written by the logic (only Z1000..Z1013 are; messages, LEDs and keys have their own sections)</translation>
    </message>
    <message>
        <source>Z1000.11 (M acknowledged) is written by segment 0</source>
        <translation>Z1000.11 (M acknowledged) is written by segment 0</translation>
    </message>
    <message>
        <source>%1 is the mode code, written by positioner.mode</source>
        <translation>%1 is the mode code, written by positioner.mode</translation>
    </message>
    <message>
        <source>%1 belongs to the override code, written by positioner.override</source>
        <translation>%1 belongs to the override code, written by positioner.override</translation>
    </message>
    <message>
        <source>'%1' cannot be written: only outputs, flags and bits Z1000..Z1013 can (it is declared at %2)</source>
        <translation>'%1' cannot be written: only outputs, flags and bits Z1000..Z1013 can (it is declared at %2)</translation>
    </message>
    <message>
        <source>'%1' already has a coil (each signal has one)</source>
        <translation>'%1' already has a coil (each signal has one)</translation>
    </message>
    <message>
        <source>%1 already has a coil in the logic</source>
        <translation>%1 already has a coil in the logic</translation>
    </message>
    <message>
        <source>'%1' is pulsed by an action and also has a coil</source>
        <translation>'%1' is pulsed by an action and also has a coil</translation>
    </message>
    <message>
        <source>column %1: %3 in "%2"</source>
        <translation>column %1: %3 in "%2"</translation>
    </message>
    <message>
        <source>empty condition</source>
        <translation>empty condition</translation>
    </message>
    <message>
        <source>unexpected '%1'</source>
        <translation>unexpected '%1'</translation>
    </message>
    <message>
        <source>condition nested too deeply (more than %1 levels)</source>
        <translation>condition nested too deeply (more than %1 levels)</translation>
    </message>
    <message>
        <source>'%1' is a keyword, not a signal</source>
        <translation>'%1' is a keyword, not a signal</translation>
    </message>
    <message>
        <source>missing ')'</source>
        <translation>missing ')'</translation>
    </message>
    <message>
        <source>the condition ends too early</source>
        <translation>the condition ends too early</translation>
    </message>
    <message>
        <source>missing ')' after the signal of %1</source>
        <translation>missing ')' after the signal of %1</translation>
    </message>
    <message>
        <source>needs three values: x1, x10, x100 positions</source>
        <translation>needs three values: x1, x10, x100 positions</translation>
    </message>
    <message>
        <source>'%1': a spindle is "spindle", "wheel" or "work"</source>
        <translation>'%1': a spindle is "spindle", "wheel" or "work"</translation>
    </message>
    <message>
        <source>spindle '%1' appears twice</source>
        <translation>spindle '%1' appears twice</translation>
    </message>
    <message>
        <source>'%1': a pump is "coolant", "lube", "hydraulics" or "air"</source>
        <translation>'%1': a pump is "coolant", "lube", "hydraulics" or "air"</translation>
    </message>
    <message>
        <source>pump '%1' appears twice</source>
        <translation>pump '%1' appears twice</translation>
    </message>
    <message>
        <source>the size must be larger than the blank's bore (internal grinding)</source>
        <translation>the size must be larger than the blank's bore (internal grinding)</translation>
    </message>
    <message>
        <source>grinding needs the spindles "wheel" and "work"</source>
        <translation>grinding needs the spindles "wheel" and "work"</translation>
    </message>
    <message>
        <source>grinding needs a chuck (the ring is changed while it is open)</source>
        <translation>grinding needs a chuck (the ring is changed while it is open)</translation>
    </message>
    <message>
        <source>unknown machine signal '%1'</source>
        <translation>unknown machine signal '%1'</translation>
    </message>
    <message>
        <source>'%1' is not a sensor of this machine (%2)</source>
        <translation>'%1' is not a sensor of this machine (%2)</translation>
    </message>
    <message>
        <source>'%1' is not an actuator of this machine (%2)</source>
        <translation>'%1' is not an actuator of this machine (%2)</translation>
    </message>
    <message>
        <source>'%1' is driven by another output too</source>
        <translation>'%1' is driven by another output too</translation>
    </message>
    <message>
        <source>M%1 is not one of the description's m_functions</source>
        <translation>M%1 is not one of the description's m_functions</translation>
    </message>
    <message>
        <source>'%1' is not a spindle of the equipment</source>
        <translation>'%1' is not a spindle of the equipment</translation>
    </message>
    <message>
        <source>M%1 both starts and stops the spindle</source>
        <translation>M%1 both starts and stops the spindle</translation>
    </message>
    <message>
        <source>'%1' is not one of the spindles listed here</source>
        <translation>'%1' is not one of the spindles listed here</translation>
    </message>
    <message>
        <source>M%1 changes the tool twice</source>
        <translation>M%1 changes the tool twice</translation>
    </message>
    <message>
        <source>the equipment has no turret</source>
        <translation>the equipment has no turret</translation>
    </message>
    <message>
        <source>the turret's box needs z_min_mm &lt; z_max_mm and r_min_mm &lt; r_max_mm</source>
        <translation>the turret's box needs z_min_mm &lt; z_max_mm and r_min_mm &lt; r_max_mm</translation>
    </message>
    <message>
        <source>a signal name is missing at the end</source>
        <translation>a signal name is missing at the end</translation>
    </message>
    <message>
        <source>expected a signal name, found '%1'</source>
        <translation>expected a signal name, found '%1'</translation>
    </message>
    <message>
        <source>%1 needs a signal in parentheses: %1(name)</source>
        <translation>%1 needs a signal in parentheses: %1(name)</translation>
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
        <translation>comment not closed: no ')' before the end of the line</translation>
    </message>
    <message>
        <source>a CR without LF does not end a line: program text ends its lines with LF or CR LF; convert the file (e.g. tr '\r' '\n')</source>
        <translation>a CR without LF does not end a line: program text ends its lines with LF or CR LF; convert the file (e.g. tr '\r' '\n')</translation>
    </message>
    <message>
        <source>invalid byte sequence %1: program text must be UTF-8</source>
        <translation>invalid byte sequence %1: program text must be UTF-8</translation>
    </message>
    <message>
        <source>frames before the first %L&lt;n&gt; header belong to no program: add a header above them</source>
        <translation>frames before the first %L&lt;n&gt; header belong to no program: add a header above them</translation>
    </message>
    <message>
        <source>unknown header '%1': expected %L&lt;program number&gt; or %MESSAGES</source>
        <translation>unknown header '%1': expected %L&lt;program number&gt; or %MESSAGES</translation>
    </message>
    <message>
        <source>program header without a number: expected %L&lt;1..99&gt;</source>
        <translation>program header without a number: expected %L&lt;1..99&gt;</translation>
    </message>
    <message>
        <source>program number '%1' is not a whole number 1..99</source>
        <translation>program number '%1' is not a whole number 1..99</translation>
    </message>
    <message>
        <source>program number L%1 is outside 1..99</source>
        <translation>program number L%1 is outside 1..99</translation>
    </message>
    <message>
        <source>program L%1 is already defined on line %2</source>
        <translation>program L%1 is already defined on line %2</translation>
    </message>
    <message>
        <source>unexpected text after the program header: '%1'</source>
        <translation>unexpected text after the program header: '%1'</translation>
    </message>
    <message>
        <source>unexpected text after %MESSAGES: '%1'</source>
        <translation>unexpected text after %MESSAGES: '%1'</translation>
    </message>
    <message>
        <source>a message table line must read #&lt;1..99&gt;=&lt;text&gt;</source>
        <translation>a message table line must read #&lt;1..99&gt;=&lt;text&gt;</translation>
    </message>
    <message>
        <source>message number #%1 is outside 1..99</source>
        <translation>message number #%1 is outside 1..99</translation>
    </message>
    <message>
        <source>message #%1 is already defined on line %2</source>
        <translation>message #%1 is already defined on line %2</translation>
    </message>
    <message>
        <source>only #&lt;1..99&gt;=&lt;text&gt; lines and comments may stand in the %MESSAGES section</source>
        <translation>only #&lt;1..99&gt;=&lt;text&gt; lines and comments may stand in the %MESSAGES section</translation>
    </message>
    <message>
        <source>address %1 is not followed by a number</source>
        <translation>address %1 is not followed by a number</translation>
    </message>
    <message>
        <source>%1%2: number too large</source>
        <translation>%1%2: number too large</translation>
    </message>
    <message>
        <source>%1: '%2' is not a whole number without sign or point</source>
        <translation>%1: '%2' is not a whole number without sign or point</translation>
    </message>
    <message>
        <source>address %1 has no value: expected a number or an R-parameter</source>
        <translation>address %1 has no value: expected a number or an R-parameter</translation>
    </message>
    <message>
        <source>%1: a sign before an R-parameter is not allowed; compute R&lt;i&gt;=0-R&lt;j&gt; in a frame of its own</source>
        <translation>%1: a sign before an R-parameter is not allowed; compute R&lt;i&gt;=0-R&lt;j&gt; in a frame of its own</translation>
    </message>
    <message>
        <source>%2'%1' has more than 18 significant digits</source>
        <translation>%2'%1' has more than 18 significant digits</translation>
    </message>
    <message>
        <source>%2'%1' has more than 18 digits after the decimal point</source>
        <translation>%2'%1' has more than 18 digits after the decimal point</translation>
    </message>
    <message>
        <source>%2'%1' is not a number</source>
        <translation>%2'%1' is not a number</translation>
    </message>
    <message>
        <source>%1 value: </source>
        <translation>%1 value: </translation>
    </message>
    <message>
        <source>%1: </source>
        <translation>%1: </translation>
    </message>
    <message>
        <source>unexpected character '%1'</source>
        <translation>unexpected character '%1'</translation>
    </message>
    <message>
        <source>Cyrillic letter '%1': frame addresses are Latin letters</source>
        <translation>Cyrillic letter '%1': frame addresses are Latin letters</translation>
    </message>
    <message>
        <source>Cyrillic letter '%1': frame addresses are Latin letters (%2)</source>
        <translation>Cyrillic letter '%1': frame addresses are Latin letters (%2)</translation>
    </message>
    <message>
        <source>unknown address '%1': a frame may contain N, G, M, #, L, X, Z, FX, FZ</source>
        <translation>unknown address '%1': a frame may contain N, G, M, #, L, X, Z, FX, FZ</translation>
    </message>
    <message>
        <source>%1 is given twice in the frame</source>
        <translation>%1 is given twice in the frame</translation>
    </message>
    <message>
        <source>GOTO makes an unconditional jump frame: it holds only [/][N] GOTO &lt;frame number&gt;</source>
        <translation>GOTO makes an unconditional jump frame: it holds only [/][N] GOTO &lt;frame number&gt;</translation>
    </message>
    <message>
        <source>more than three G functions in the frame: %1 is one too many</source>
        <translation>more than three G functions in the frame: %1 is one too many</translation>
    </message>
    <message>
        <source>more than three M functions in the frame: M%1 is one too many</source>
        <translation>more than three M functions in the frame: M%1 is one too many</translation>
    </message>
    <message>
        <source>the frame number N must come first in the frame</source>
        <translation>the frame number N must come first in the frame</translation>
    </message>
    <message>
        <source>F without an axis: a bare F applies to the X or Z word directly before it; write FX or FZ</source>
        <translation>F without an axis: a bare F applies to the X or Z word directly before it; write FX or FZ</translation>
    </message>
    <message>
        <source>R-parameter outside a computational frame: write R&lt;i&gt;=... as a frame of its own, and in X, Z, FX, FZ as X=R&lt;i&gt;</source>
        <translation>R-parameter outside a computational frame: write R&lt;i&gt;=... as a frame of its own, and in X, Z, FX, FZ as X=R&lt;i&gt;</translation>
    </message>
    <message>
        <source>IF makes a conditional jump frame: it holds only [/][N] IF R&lt;i&gt;&gt;0 GOTO &lt;number&gt;</source>
        <translation>IF makes a conditional jump frame: it holds only [/][N] IF R&lt;i&gt;&gt;0 GOTO &lt;number&gt;</translation>
    </message>
    <message>
        <source>the skip flag '/' may only stand at the start of the frame</source>
        <translation>the skip flag '/' may only stand at the start of the frame</translation>
    </message>
    <message>
        <source>expected a whole number or an R-parameter</source>
        <translation>expected a whole number or an R-parameter</translation>
    </message>
    <message>
        <source>a sign before an R-parameter is not allowed: write 0-R&lt;j&gt; instead of -R&lt;j&gt;</source>
        <translation>a sign before an R-parameter is not allowed: write 0-R&lt;j&gt; instead of -R&lt;j&gt;</translation>
    </message>
    <message>
        <source>decimal point in a computational frame: R-parameters are whole numbers (discretes), '%1' is not allowed</source>
        <translation>decimal point in a computational frame: R-parameters are whole numbers (discretes), '%1' is not allowed</translation>
    </message>
    <message>
        <source>'%1' is not a number</source>
        <translation>'%1' is not a number</translation>
    </message>
    <message>
        <source>number %1 is outside the range of an R-parameter (-2147483648..2147483647)</source>
        <translation>number %1 is outside the range of an R-parameter (-2147483648..2147483647)</translation>
    </message>
    <message>
        <source>unexpected text in a computational frame: '%1'</source>
        <translation>unexpected text in a computational frame: '%1'</translation>
    </message>
    <message>
        <source>unexpected text in a conditional jump frame: '%1'</source>
        <translation>unexpected text in a conditional jump frame: '%1'</translation>
    </message>
    <message>
        <source>unexpected text in an unconditional jump frame: '%1'</source>
        <translation>unexpected text in an unconditional jump frame: '%1'</translation>
    </message>
    <message>
        <source>computational frame: '=' expected after R%1</source>
        <translation>computational frame: '=' expected after R%1</translation>
    </message>
    <message>
        <source>computational frame: expected an operation + - * / or the end of the frame, not '%1'</source>
        <translation>computational frame: expected an operation + - * / or the end of the frame, not '%1'</translation>
    </message>
    <message>
        <source>the jump target is written without N: GOTO %1</source>
        <translation>the jump target is written without N: GOTO %1</translation>
    </message>
    <message>
        <source>the jump target is written without N: GOTO &lt;frame number 1..999&gt;</source>
        <translation>the jump target is written without N: GOTO &lt;frame number 1..999&gt;</translation>
    </message>
    <message>
        <source>GOTO is not followed by a frame number</source>
        <translation>GOTO is not followed by a frame number</translation>
    </message>
    <message>
        <source>jump target '%1' is not a whole number 1..999</source>
        <translation>jump target '%1' is not a whole number 1..999</translation>
    </message>
    <message>
        <source>IF must be followed by an R-parameter: IF R&lt;i&gt;&gt;0 GOTO &lt;number&gt;</source>
        <translation>IF must be followed by an R-parameter: IF R&lt;i&gt;&gt;0 GOTO &lt;number&gt;</translation>
    </message>
    <message>
        <source>the only jump condition is %1&gt;0 (manual 2.7.1.3); reduce another condition to it with a computational frame</source>
        <translation>the only jump condition is %1&gt;0 (manual 2.7.1.3); reduce another condition to it with a computational frame</translation>
    </message>
    <message>
        <source>the condition must be followed by GOTO &lt;frame number&gt;</source>
        <translation>the condition must be followed by GOTO &lt;frame number&gt;</translation>
    </message>
    <message>
        <source>program L%1 has no frames</source>
        <translation>program L%1 has no frames</translation>
    </message>
    <message>
        <source>program L%1 has %2 frames: at most 999 are allowed; this is frame 1000</source>
        <translation>program L%1 has %2 frames: at most 999 are allowed; this is frame 1000</translation>
    </message>
    <message>
        <source>frame number N%1 is outside 1..999</source>
        <translation>frame number N%1 is outside 1..999</translation>
    </message>
    <message>
        <source>duplicate frame numbers: N%1 is already used on line %2</source>
        <translation>duplicate frame numbers: N%1 is already used on line %2</translation>
    </message>
    <message>
        <source>R-parameter R%1 does not exist: numbers are 0..299</source>
        <translation>R-parameter R%1 does not exist: numbers are 0..299</translation>
    </message>
    <message>
        <source>G?: %1 is outside 0..299</source>
        <translation>G?: %1 is outside 0..299</translation>
    </message>
    <message>
        <source>G?: %1 is not a G function of table 5</source>
        <translation>G?: %1 is not a G function of table 5</translation>
    </message>
    <message>
        <source>G?: %1 and %2 are both of group %3: a frame may hold one function of a group</source>
        <translation>G?: %1 and %2 are both of group %3: a frame may hold one function of a group</translation>
    </message>
    <message>
        <source>X value: the dwell time G04 X%1 is negative</source>
        <translation>X value: the dwell time G04 X%1 is negative</translation>
    </message>
    <message>
        <source>X value: the dwell X%1 s is longer than 9999.999 s</source>
        <translation>X value: the dwell X%1 s is longer than 9999.999 s</translation>
    </message>
    <message>
        <source>%1 value: %1%2 is outside ±9999.999 mm</source>
        <translation>%1 value: %1%2 is outside ±9999.999 mm</translation>
    </message>
    <message>
        <source>feed %1%2 is outside 0.001..10000 mm/min</source>
        <translation>feed %1%2 is outside 0.001..10000 mm/min</translation>
    </message>
    <message>
        <source>G04/X/Z: Z is given %2 with the dwell G04; the time goes in X only</source>
        <translation>G04/X/Z: Z is given %2 with the dwell G04; the time goes in X only</translation>
    </message>
    <message>
        <source>G04/L: subprogram %1 is called %2 with the dwell G04</source>
        <translation>G04/L: subprogram %1 is called %2 with the dwell G04</translation>
    </message>
    <message>
        <source>X/L: X is given %2 that calls subprogram %1</source>
        <translation>X/L: X is given %2 that calls subprogram %1</translation>
    </message>
    <message>
        <source>Z/L: Z is given %2 that calls subprogram %1</source>
        <translation>Z/L: Z is given %2 that calls subprogram %1</translation>
    </message>
    <message>
        <source>X/M17: X is given %2 that ends the subprogram with M17</source>
        <translation>X/M17: X is given %2 that ends the subprogram with M17</translation>
    </message>
    <message>
        <source>Z/M17: Z is given %2 that ends the subprogram with M17</source>
        <translation>Z/M17: Z is given %2 that ends the subprogram with M17</translation>
    </message>
    <message>
        <source>M30/L: end of program M30 and a call of %1 %2</source>
        <translation>M30/L: end of program M30 and a call of %1 %2</translation>
    </message>
    <message>
        <source>M2/L: end of program M02 and a call of %1 %2</source>
        <translation>M2/L: end of program M02 and a call of %1 %2</translation>
    </message>
    <message>
        <source>M17/L: end of subprogram M17 and a call of %1 %2</source>
        <translation>M17/L: end of subprogram M17 and a call of %1 %2</translation>
    </message>
    <message>
        <source>M30/M17: end of program M30 and end of subprogram M17 %2</source>
        <translation>M30/M17: end of program M30 and end of subprogram M17 %2</translation>
    </message>
    <message>
        <source>M2/M17: end of program M02 and end of subprogram M17 %2</source>
        <translation>M2/M17: end of program M02 and end of subprogram M17 %2</translation>
    </message>
    <message>
        <source>X/end of L: the last frame of subprogram %1 has no M17 and gives X</source>
        <translation>X/end of L: the last frame of subprogram %1 has no M17 and gives X</translation>
    </message>
    <message>
        <source>Z/end of L: the last frame of subprogram %1 has no M17 and gives Z</source>
        <translation>Z/end of L: the last frame of subprogram %1 has no M17 and gives Z</translation>
    </message>
    <message>
        <source>in the frame</source>
        <translation>in the frame</translation>
    </message>
    <message>
        <source>in frame N%1</source>
        <translation>in frame N%1</translation>
    </message>
    <message>
        <source>G04 without X: no dwell time is given (e.g. G04 X20.5 is 20.5 s)</source>
        <translation>G04 without X: no dwell time is given (e.g. G04 X20.5 is 20.5 s)</translation>
    </message>
    <message>
        <source>%1 without %2: no position to set is given (e.g. %1 %212.324)</source>
        <translation>%1 without %2: no position to set is given (e.g. %1 %212.324)</translation>
    </message>
    <message>
        <source>%1 without %2: no oscillation stroke is given (e.g. %1 %2=-30.5 F%2=100)</source>
        <translation>%1 without %2: no oscillation stroke is given (e.g. %1 %2=-30.5 F%2=100)</translation>
    </message>
    <message>
        <source>%1 without %2: there is no motion of axis %2 for signal %3 to interrupt</source>
        <translation>%1 without %2: there is no motion of axis %2 for signal %3 to interrupt</translation>
    </message>
    <message>
        <source>M%1: M function number outside 0..99</source>
        <translation>M%1: M function number outside 0..99</translation>
    </message>
    <message>
        <source>M%1 twice in the frame: the PLC gets it twice</source>
        <translation>M%1 twice in the frame: the PLC gets it twice</translation>
    </message>
    <message>
        <source>#%1: technological message number outside 1..99</source>
        <translation>#%1: technological message number outside 1..99</translation>
    </message>
    <message>
        <source>message #%1 is not in the message table: LCD line 2 will be blank</source>
        <translation>message #%1 is not in the message table: LCD line 2 will be blank</translation>
    </message>
    <message>
        <source>L%1: called program number outside 1..99</source>
        <translation>L%1: called program number outside 1..99</translation>
    </message>
    <message>
        <source>L missing: there is no program L%1</source>
        <translation>L missing: there is no program L%1</translation>
    </message>
    <message>
        <source>R%1 is read only (R232..R262, appendix Л): it cannot be written</source>
        <translation>R%1 is read only (R232..R262, appendix Л): it cannot be written</translation>
    </message>
    <message>
        <source>overflow: division by zero</source>
        <translation>overflow: division by zero</translation>
    </message>
    <message>
        <source>overflow: the result %1 is outside -2147483648..2147483647</source>
        <translation>overflow: the result %1 is outside -2147483648..2147483647</translation>
    </message>
    <message>
        <source>jump error: frame number %1 is outside 1..999</source>
        <translation>jump error: frame number %1 is outside 1..999</translation>
    </message>
    <message>
        <source>jump error: there is no frame N%1 in program L%2</source>
        <translation>jump error: there is no frame N%1 in program L%2</translation>
    </message>
    <message>
        <source>the frame on line %1 is never executed: an unconditional jump or an end of program precedes, and no jump leads here</source>
        <translation>the frame on line %1 is never executed: an unconditional jump or an end of program precedes, and no jump leads here</translation>
    </message>
    <message>
        <source>the frames on lines %1-%2 are never executed: an unconditional jump or an end of program precedes, and no jump leads here</source>
        <translation>the frames on lines %1-%2 are never executed: an unconditional jump or an end of program precedes, and no jump leads here</translation>
    </message>
    <message>
        <source>subprogram nesting: calls go round in a circle %2; unless a condition breaks it, nesting exceeds the limit of %1</source>
        <translation>subprogram nesting: calls go round in a circle %2; unless a condition breaks it, nesting exceeds the limit of %1</translation>
    </message>
    <message>
        <source>subprogram nesting: the call chain %3 nests %1 levels deep, the limit is %2</source>
        <translation>subprogram nesting: the call chain %3 nests %1 levels deep, the limit is %2</translation>
    </message>
    <message>
        <source>L%1-&gt;%2</source>
        <translation>L%1-&gt;%2</translation>
    </message>
    <message>
        <source>L%1</source>
        <translation>L%1</translation>
    </message>
    <message>
        <source>%1: this machine has no %2 axis (C-parameter НАЛИЧ.ОСИ = 0)</source>
        <translation>%1: this machine has no %2 axis (C-parameter НАЛИЧ.ОСИ = 0)</translation>
    </message>
    <message>
        <source>software limit (%2): %2%3%5%6 is beyond the + limit %4 mm</source>
        <translation>software limit (%2): %2%3%5%6 is beyond the + limit %4 mm</translation>
    </message>
    <message>
        <source>software limit (%2): %2%3%5%6 is beyond the - limit %4 mm</source>
        <translation>software limit (%2): %2%3%5%6 is beyond the - limit %4 mm</translation>
    </message>
    <message>
        <source> (diameter)</source>
        <translation> (diameter)</translation>
    </message>
    <message>
        <source>, %1 mm in the machine system,</source>
        <translation>, %1 mm in the machine system,</translation>
    </message>
    <message>
        <source>%1%2: the discrete of axis %1 is %3 mm, the value is rounded to %4</source>
        <translation>%1%2: the discrete of axis %1 is %3 mm, the value is rounded to %4</translation>
    </message>
    <message>
        <source>F%1%2: the discrete of axis %1 is %3 mm, the feed is rounded to %4</source>
        <translation>F%1%2: the discrete of axis %1 is %3 mm, the feed is rounded to %4</translation>
    </message>
    <message>
        <source>F%1%2 is above the axis' maximum program feed F УСК.АВТ. (%3 mm/min)</source>
        <translation>F%1%2 is above the axis' maximum program feed F УСК.АВТ. (%3 mm/min)</translation>
    </message>
    <message>
        <source>message #%1 is longer than 20 characters (%2): the display shows 20</source>
        <translation>message #%1 is longer than 20 characters (%2): the display shows 20</translation>
    </message>
    <message>
        <source>control character in the text of message #%1</source>
        <translation>control character in the text of message #%1</translation>
    </message>
    <message>
        <source>character '%1' in message #%2 may not show on the K923 (Latin, Cyrillic, digits and ASCII signs)</source>
        <translation>character '%1' in message #%2 may not show on the K923 (Latin, Cyrillic, digits and ASCII signs)</translation>
    </message>
    <message>
        <source>the file holds no program (not a single frame)</source>
        <translation>the file holds no program (not a single frame)</translation>
    </message>
    <message>
        <source>a jump target is a frame number 1..999, not %1</source>
        <translation>a jump target is a frame number 1..999, not %1</translation>
    </message>
    <message>
        <source>at most 3 G and 3 M functions in a frame</source>
        <translation>at most 3 G and 3 M functions in a frame</translation>
    </message>
    <message>
        <source>the signal number is 1..4</source>
        <translation>the signal number is 1..4</translation>
    </message>
    <message>
        <source>%1:%2: %3: %4</source>
        <translation>%1:%2: %3: %4</translation>
    </message>
    <message>
        <source>error</source>
        <translation>error</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>warning</translation>
    </message>
</context>
<context>
    <name>k528::studio::DiffDialog</name>
    <message>
        <source>Compare revisions — %1</source>
        <translation>Compare revisions — %1</translation>
    </message>
    <message>
        <source>the controller now</source>
        <translation>the controller now</translation>
    </message>
    <message>
        <source>Compare</source>
        <translation>Compare</translation>
    </message>
    <message>
        <source>Revision</source>
        <translation>Revision</translation>
    </message>
    <message>
        <source>The revisions cannot be compared: %1</source>
        <translation>The revisions cannot be compared: %1</translation>
    </message>
    <message>
        <source>(no difference)</source>
        <translation>(no difference)</translation>
    </message>
</context>
<context>
    <name>k528::studio::EditorMenu</name>
    <message>
        <source>&amp;Editor</source>
        <translation>&amp;Editor</translation>
    </message>
    <message>
        <source>Refactor</source>
        <translation>Refactor</translation>
    </message>
    <message>
        <source>Renumber frames…</source>
        <translation>Renumber frames…</translation>
    </message>
    <message>
        <source>Move or copy a program…</source>
        <translation>Move or copy a program…</translation>
    </message>
    <message>
        <source>Format the file</source>
        <translation>Format the file</translation>
    </message>
    <message>
        <source>Listing</source>
        <translation>Listing</translation>
    </message>
    <message>
        <source>Print…</source>
        <translation>Print…</translation>
    </message>
    <message>
        <source>Export PDF…</source>
        <translation>Export PDF…</translation>
    </message>
    <message>
        <source>Setup sheet</source>
        <translation>Setup sheet</translation>
    </message>
    <message>
        <source>Print preview…</source>
        <translation>Print preview…</translation>
    </message>
    <message>
        <source>The setup sheet of this file on its machine: the blank, the tools with their offsets, the programs with their cycle times, the R-parameters to preset</source>
        <translation>The setup sheet of this file on its machine: the blank, the tools with their offsets, the programs with their cycle times, the R-parameters to preset</translation>
    </message>
    <message>
        <source>Teach-in</source>
        <translation>Teach-in</translation>
    </message>
    <message>
        <source>Insert the controller's position as a frame</source>
        <translation>Insert the controller's position as a frame</translation>
    </message>
    <message>
        <source>The position the viewed controller's axes are at (current coordinates, as its panel shows them) as a frame after the cursor's line</source>
        <translation>The position the viewed controller's axes are at (current coordinates, as its panel shows them) as a frame after the cursor's line</translation>
    </message>
    <message>
        <source>Position into an R-parameter</source>
        <translation>Position into an R-parameter</translation>
    </message>
    <message>
        <source>Machine of this file</source>
        <translation>Machine of this file</translation>
    </message>
    <message>
        <source>Machine: %1</source>
        <translation>Machine: %1</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>The machine this file is checked for: its limits, feeds and axes</source>
        <translation>The machine this file is checked for: its limits, feeds and axes</translation>
    </message>
    <message>
        <source>Open from the database…</source>
        <translation>Open from the database…</translation>
    </message>
    <message>
        <source>The programs and messages of a machine of the database; saving writes its next revision</source>
        <translation>The programs and messages of a machine of the database; saving writes its next revision</translation>
    </message>
    <message>
        <source>No file is open</source>
        <translation>No file is open</translation>
    </message>
    <message>
        <source>The workstation's machine (%1)</source>
        <translation>The workstation's machine (%1)</translation>
    </message>
    <message>
        <source>The workstation's machine (none)</source>
        <translation>The workstation's machine (none)</translation>
    </message>
    <message>
        <source>None: the language only</source>
        <translation>None: the language only</translation>
    </message>
</context>
<context>
    <name>k528::studio::EditorTab</name>
    <message>
        <source>Unsaved changes</source>
        <translation>Unsaved changes</translation>
    </message>
    <message>
        <source>%1 has unsaved changes. Save them?</source>
        <translation>%1 has unsaved changes. Save them?</translation>
    </message>
    <message>
        <source>Open program</source>
        <translation>Open program</translation>
    </message>
    <message>
        <source>K528 programs (*.k528 *.txt);;All files (*)</source>
        <translation>K528 programs (*.k528 *.txt);;All files (*)</translation>
    </message>
    <message>
        <source>%1 cannot be written: %2</source>
        <translation>%1 cannot be written: %2</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Saved %1</translation>
    </message>
    <message>
        <source>Save program as</source>
        <translation>Save program as</translation>
    </message>
    <message>
        <source>File changed on disk</source>
        <translation>File changed on disk</translation>
    </message>
    <message>
        <source>%1 was changed on disk. Reload it and lose your changes?</source>
        <translation>%1 was changed on disk. Reload it and lose your changes?</translation>
    </message>
    <message>
        <source>Reloaded %1</source>
        <translation>Reloaded %1</translation>
    </message>
    <message>
        <source>Sent %1 to the controller</source>
        <translation>Sent %1 to the controller</translation>
    </message>
    <message>
        <source>error</source>
        <translation>error</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>warning</translation>
    </message>
    <message>
        <source>Errors: %1, warnings: %2</source>
        <translation>Errors: %1, warnings: %2</translation>
    </message>
    <message>
        <source>untitled %1</source>
        <translation>untitled %1</translation>
    </message>
    <message>
        <source>New</source>
        <translation>New</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Open…</translation>
    </message>
    <message>
        <source>Recent</source>
        <translation>Recent</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Save</translation>
    </message>
    <message>
        <source>Save as…</source>
        <translation>Save as…</translation>
    </message>
    <message>
        <source>Check for the machine</source>
        <translation>Check for the machine</translation>
    </message>
    <message>
        <source>Also check the machine's software limits, feeds and axes</source>
        <translation>Also check the machine's software limits, feeds and axes</translation>
    </message>
    <message>
        <source>Send to the controller</source>
        <translation>Send to the controller</translation>
    </message>
    <message>
        <source>Master…</source>
        <translation>Master…</translation>
    </message>
    <message>
        <source>Build or edit the frame at the cursor</source>
        <translation>Build or edit the frame at the cursor</translation>
    </message>
    <message>
        <source>Programs</source>
        <translation>Programs</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>Severity</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Line</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Message</translation>
    </message>
    <message>
        <source>The machine %1 cannot be loaded: %2</source>
        <translation>The machine %1 cannot be loaded: %2</translation>
    </message>
    <message>
        <source>%1 (database, revision %2)</source>
        <translation>%1 (database, revision %2)</translation>
    </message>
    <message>
        <source>Opened the programs of %1, revision %2</source>
        <translation>Opened the programs of %1, revision %2</translation>
    </message>
    <message>
        <source>The database has no machines</source>
        <translation>The database has no machines</translation>
    </message>
    <message>
        <source>Open from the database</source>
        <translation>Open from the database</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Machine</translation>
    </message>
    <message>
        <source>%1 saved as revision %2</source>
        <translation>%1 saved as revision %2</translation>
    </message>
    <message>
        <source>%1: the database already holds these programs (revision %2)</source>
        <translation>%1: the database already holds these programs (revision %2)</translation>
    </message>
    <message>
        <source>%1 is the database this window uses: it is not opened as a program</source>
        <translation>%1 is the database this window uses: it is not opened as a program</translation>
    </message>
    <message>
        <source>%1 is the database this window uses: a program is not written over it</source>
        <translation>%1 is the database this window uses: a program is not written over it</translation>
    </message>
    <message>
        <source>OK replaces line %1: %2</source>
        <translation>OK replaces line %1: %2</translation>
    </message>
    <message>
        <source>OK replaces line %1: %2
Its comment stays: %3</source>
        <translation>OK replaces line %1: %2
Its comment stays: %3</translation>
    </message>
    <message>
        <source>OK inserts a new line after line %1.</source>
        <translation>OK inserts a new line after line %1.</translation>
    </message>
    <message>
        <source>Line %1 replaced by the master</source>
        <translation>Line %1 replaced by the master</translation>
    </message>
    <message>
        <source>Line %1 replaced by the master; its comment kept</source>
        <translation>Line %1 replaced by the master; its comment kept</translation>
    </message>
    <message>
        <source>There is no sample program %1</source>
        <translation>There is no sample program %1</translation>
    </message>
    <message>
        <source>%1 (sample)</source>
        <translation>%1 (sample)</translation>
    </message>
    <message>
        <source>The controller is busy with a transfer: send again when it has ended</source>
        <translation>The controller is busy with a transfer: send again when it has ended</translation>
    </message>
    <message>
        <source>Reading the controller's memory to show what %1 changes...</source>
        <translation>Reading the controller's memory to show what %1 changes...</translation>
    </message>
    <message>
        <source>%1 was not sent: the controller's memory could not be read (%2)</source>
        <translation>%1 was not sent: the controller's memory could not be read (%2)</translation>
    </message>
    <message>
        <source>Send %1</source>
        <translation>Send %1</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Send</translation>
    </message>
    <message>
        <source>%1 not sent; nothing changed</source>
        <translation>%1 not sent; nothing changed</translation>
    </message>
    <message>
        <source>Sending %1 to the controller...</source>
        <translation>Sending %1 to the controller...</translation>
    </message>
    <message>
        <source>Sent %1 to the controller, with warnings: %2</source>
        <translation>Sent %1 to the controller, with warnings: %2</translation>
    </message>
    <message>
        <source>%1 was not sent: %2</source>
        <translation>%1 was not sent: %2</translation>
    </message>
    <message>
        <source>The controller is busy with a transfer: open again when it has ended</source>
        <translation>The controller is busy with a transfer: open again when it has ended</translation>
    </message>
    <message>
        <source>Reading the programs of the controller...</source>
        <translation>Reading the programs of the controller...</translation>
    </message>
    <message>
        <source>The programs of the controller could not be read: %1</source>
        <translation>The programs of the controller could not be read: %1</translation>
    </message>
    <message>
        <source>Opened the %1 programs of the controller (%2)</source>
        <translation>Opened the %1 programs of the controller (%2)</translation>
    </message>
    <message>
        <source>The file's programs and messages into the controller shown, after a preview of what changes</source>
        <translation>The file's programs and messages into the controller shown, after a preview of what changes</translation>
    </message>
    <message>
        <source>Open from the controller</source>
        <translation>Open from the controller</translation>
    </message>
    <message>
        <source>The programs and messages of the controller shown as a new file</source>
        <translation>The programs and messages of the controller shown as a new file</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>Code</translation>
    </message>
</context>
<context>
    <name>k528::studio::FrameMaster</name>
    <message>
        <source>Frame master</source>
        <translation>Frame master</translation>
    </message>
    <message>
        <source>ISO motion frame</source>
        <translation>ISO motion frame</translation>
    </message>
    <message>
        <source>Dwell (G4)</source>
        <translation>Dwell (G4)</translation>
    </message>
    <message>
        <source>Subprogram call (L)</source>
        <translation>Subprogram call (L)</translation>
    </message>
    <message>
        <source>Oscillation start/stop</source>
        <translation>Oscillation start/stop</translation>
    </message>
    <message>
        <source>Move until signal</source>
        <translation>Move until signal</translation>
    </message>
    <message>
        <source>Computational frame</source>
        <translation>Computational frame</translation>
    </message>
    <message>
        <source>Conditional jump (IF … GOTO)</source>
        <translation>Conditional jump (IF … GOTO)</translation>
    </message>
    <message>
        <source>Unconditional jump (GOTO)</source>
        <translation>Unconditional jump (GOTO)</translation>
    </message>
    <message>
        <source>Technological message</source>
        <translation>Technological message</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Kind</translation>
    </message>
    <message>
        <source>Skip flag «/» (the frame is not executed)</source>
        <translation>Skip flag «/» (the frame is not executed)</translation>
    </message>
    <message>
        <source>1..999, empty = none</source>
        <translation>1..999, empty = none</translation>
    </message>
    <message>
        <source>Frame number N</source>
        <translation>Frame number N</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Axis</translation>
    </message>
    <message>
        <source>Operation</source>
        <translation>Operation</translation>
    </message>
    <message>
        <source>G-functions (up to 3)</source>
        <translation>G-functions (up to 3)</translation>
    </message>
    <message>
        <source>M-functions (up to 3)</source>
        <translation>M-functions (up to 3)</translation>
    </message>
    <message>
        <source>Message #</source>
        <translation>Message #</translation>
    </message>
    <message>
        <source>Call program L</source>
        <translation>Call program L</translation>
    </message>
    <message>
        <source>X, mm (or R…)</source>
        <translation>X, mm (or R…)</translation>
    </message>
    <message>
        <source>FX, mm/min (or R…)</source>
        <translation>FX, mm/min (or R…)</translation>
    </message>
    <message>
        <source>Z, mm (or R…)</source>
        <translation>Z, mm (or R…)</translation>
    </message>
    <message>
        <source>FZ, mm/min (or R…)</source>
        <translation>FZ, mm/min (or R…)</translation>
    </message>
    <message>
        <source>Dwell, s</source>
        <translation>Dwell, s</translation>
    </message>
    <message>
        <source>Program 1..99</source>
        <translation>Program 1..99</translation>
    </message>
    <message>
        <source>Start (1) / stop (0)</source>
        <translation>Start (1) / stop (0)</translation>
    </message>
    <message>
        <source>Stroke, mm</source>
        <translation>Stroke, mm</translation>
    </message>
    <message>
        <source>Speed, mm/min</source>
        <translation>Speed, mm/min</translation>
    </message>
    <message>
        <source>Axis (X or Z)</source>
        <translation>Axis (X or Z)</translation>
    </message>
    <message>
        <source>Signal 1..4</source>
        <translation>Signal 1..4</translation>
    </message>
    <message>
        <source>Target, mm</source>
        <translation>Target, mm</translation>
    </message>
    <message>
        <source>Feed, mm/min</source>
        <translation>Feed, mm/min</translation>
    </message>
    <message>
        <source>Result R</source>
        <translation>Result R</translation>
    </message>
    <message>
        <source>Condition R (&gt; 0)</source>
        <translation>Condition R (&gt; 0)</translation>
    </message>
    <message>
        <source>Jump to frame N</source>
        <translation>Jump to frame N</translation>
    </message>
    <message>
        <source>Message number 1..99</source>
        <translation>Message number 1..99</translation>
    </message>
    <message>
        <source>Text (20 characters)</source>
        <translation>Text (20 characters)</translation>
    </message>
    <message>
        <source>%1: «%2» is not a number or R-parameter</source>
        <translation>%1: «%2» is not a number or R-parameter</translation>
    </message>
    <message>
        <source>%1: «%2» is not a whole number</source>
        <translation>%1: «%2» is not a whole number</translation>
    </message>
    <message>
        <source>N: «%1» is not a whole number</source>
        <translation>N: «%1» is not a whole number</translation>
    </message>
    <message>
        <source>G: a list of numbers, e.g. «1 90»</source>
        <translation>G: a list of numbers, e.g. «1 90»</translation>
    </message>
    <message>
        <source>M: a list of numbers, e.g. «3 8»</source>
        <translation>M: a list of numbers, e.g. «3 8»</translation>
    </message>
    <message>
        <source>R: the number of the R-parameter tested</source>
        <translation>R: the number of the R-parameter tested</translation>
    </message>
    <message>
        <source>Operand 1 (number or R…)</source>
        <translation>Operand 1 (number or R…)</translation>
    </message>
    <message>
        <source>Operand 2 (number or R…)</source>
        <translation>Operand 2 (number or R…)</translation>
    </message>
    <message>
        <source>Operand 1: a whole number or R…</source>
        <translation>Operand 1: a whole number or R…</translation>
    </message>
    <message>
        <source>Operand 2: a whole number or R…</source>
        <translation>Operand 2: a whole number or R…</translation>
    </message>
    <message>
        <source>Result: the number of the R-parameter written</source>
        <translation>Result: the number of the R-parameter written</translation>
    </message>
</context>
<context>
    <name>k528::studio::HistoryDialog</name>
    <message>
        <source>History of %1 %2 — %3</source>
        <translation>History of %1 %2 — %3</translation>
    </message>
    <message>
        <source>Revision</source>
        <translation>Revision</translation>
    </message>
    <message>
        <source>When</source>
        <translation>When</translation>
    </message>
    <message>
        <source>Who</source>
        <translation>Who</translation>
    </message>
    <message>
        <source>Before</source>
        <translation>Before</translation>
    </message>
    <message>
        <source>After</source>
        <translation>After</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Note</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(none)</translation>
    </message>
    <message>
        <source>No revision of %1 changed this constant.</source>
        <translation>No revision of %1 changed this constant.</translation>
    </message>
    <message>
        <source>Revisions that changed this constant: %1 (newest first).</source>
        <translation>Revisions that changed this constant: %1 (newest first).</translation>
    </message>
    <message>
        <source>The history cannot be read: %1</source>
        <translation>The history cannot be read: %1</translation>
    </message>
</context>
<context>
    <name>k528::studio::HistoryModel</name>
    <message>
        <source>Positioner</source>
        <translation>Positioner</translation>
    </message>
    <message>
        <source>PLC alarm</source>
        <translation>PLC alarm</translation>
    </message>
    <message>
        <source>PLC system</source>
        <translation>PLC system</translation>
    </message>
    <message>
        <source>PLC work</source>
        <translation>PLC work</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>ESC</source>
        <translation>ESC</translation>
    </message>
    <message>
        <source>ESC from the history dock</source>
        <translation>ESC from the history dock</translation>
    </message>
    <message>
        <source>acknowledge signal Z1000.7</source>
        <translation>acknowledge signal Z1000.7</translation>
    </message>
    <message>
        <source>reset Z1000.5</source>
        <translation>reset Z1000.5</translation>
    </message>
    <message>
        <source>L%1, line %2</source>
        <translation>L%1, line %2</translation>
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
        <translation>not yet</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Time</translation>
    </message>
    <message>
        <source>Machine time</source>
        <translation>Machine time</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Source</translation>
    </message>
    <message>
        <source>No.</source>
        <translation>No.</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Message</translation>
    </message>
    <message>
        <source>Cause gone</source>
        <translation>Cause gone</translation>
    </message>
    <message>
        <source>Acknowledged</source>
        <translation>Acknowledged</translation>
    </message>
</context>
<context>
    <name>k528::studio::HistoryView</name>
    <message>
        <source>Export the message history</source>
        <translation>Export the message history</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>The messages could not be written (they are kept and written later): %1</source>
        <translation>The messages could not be written (they are kept and written later): %1</translation>
    </message>
    <message>
        <source>No message history: %1</source>
        <translation>No message history: %1</translation>
    </message>
    <message>
        <source>%1 messages (%2 loaded); %3 waiting for acknowledgement. Database: %4</source>
        <translation>%1 messages (%2 loaded); %3 waiting for acknowledgement. Database: %4</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Cannot write %1: %2</translation>
    </message>
    <message>
        <source>The export was cancelled; %1 was left as it was.</source>
        <translation>The export was cancelled; %1 was left as it was.</translation>
    </message>
    <message>
        <source>Exporting the message history…</source>
        <translation>Exporting the message history…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <source>%1 messages exported to %2</source>
        <translation>%1 messages exported to %2</translation>
    </message>
    <message>
        <source>Search</source>
        <translation>Search</translation>
    </message>
    <message>
        <source>text or number, e.g. 37 or A03</source>
        <translation>text or number, e.g. 37 or A03</translation>
    </message>
    <message>
        <source>All sources</source>
        <translation>All sources</translation>
    </message>
    <message>
        <source>Not acknowledged</source>
        <translation>Not acknowledged</translation>
    </message>
    <message>
        <source>All machines</source>
        <translation>All machines</translation>
    </message>
    <message>
        <source>Acknowledge (ESC)</source>
        <translation>Acknowledge (ESC)</translation>
    </message>
    <message>
        <source>Acknowledges the current messages as ESC on the K923 does (C123 reset, C124 faults, C125 system messages)</source>
        <translation>Acknowledges the current messages as ESC on the K923 does (C123 reset, C124 faults, C125 system messages)</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>Export CSV…</translation>
    </message>
    <message>
        <source>Message history</source>
        <translation>Message history</translation>
    </message>
    <message>
        <source>A real controller's messages are acknowledged on its own K923 (ESC): the link carries no keys</source>
        <translation>A real controller's messages are acknowledged on its own K923 (ESC): the link carries no keys</translation>
    </message>
    <message>
        <source>The messages of the controller on the line, recorded as they are read (every %1 ms) with this PC's time; they are acknowledged on its own K923.</source>
        <translation>The messages of the controller on the line, recorded as they are read (every %1 ms) with this PC's time; they are acknowledged on its own K923.</translation>
    </message>
    <message>
        <source>Cannot export to %1: %2</source>
        <translation>Cannot export to %1: %2</translation>
    </message>
</context>
<context>
    <name>k528::studio::K923Keys</name>
    <message>
        <source>Mode AUTOMATIC: the machine works by the control program.</source>
        <translation>Mode AUTOMATIC: the machine works by the control program.</translation>
    </message>
    <message>
        <source>Mode MANUAL: the machine's push-buttons and handwheels move the axes; R-parameters can be edited.</source>
        <translation>Mode MANUAL: the machine's push-buttons and handwheels move the axes; R-parameters can be edited.</translation>
    </message>
    <message>
        <source>Mode REFERENCE POINT: the homing cycle ties the axes to the machine.</source>
        <translation>Mode REFERENCE POINT: the homing cycle ties the axes to the machine.</translation>
    </message>
    <message>
        <source>Mode PRESETS: technological parameters of the machine in groups.</source>
        <translation>Mode PRESETS: technological parameters of the machine in groups.</translation>
    </message>
    <message>
        <source>Mode MACHINE CONSTANTS: editing the C-parameters (password).</source>
        <translation>Mode MACHINE CONSTANTS: editing the C-parameters (password).</translation>
    </message>
    <message>
        <source>Mode PROGRAM EDITING: editing the control programs (password).</source>
        <translation>Mode PROGRAM EDITING: editing the control programs (password).</translation>
    </message>
    <message>
        <source>Mode DATA MANAGEMENT: clearing memory and working with the PC (password).</source>
        <translation>Mode DATA MANAGEMENT: clearing memory and working with the PC (password).</translation>
    </message>
    <message>
        <source>Mode key F8: the K528-05 has no eighth mode.</source>
        <translation>Mode key F8: the K528-05 has no eighth mode.</translation>
    </message>
    <message>
        <source>The key opens the main screen of the mode.</source>
        <translation>The key opens the main screen of the mode.</translation>
    </message>
    <message>
        <source>Machine function key K%1. The PLC program of the machine gives it its function: pressing sets Z1300.%2. Its LED is green by Z1906.%2, red by Z1907.%2, amber by both.</source>
        <translation>Machine function key K%1. The PLC program of the machine gives it its function: pressing sets Z1300.%2. Its LED is green by Z1906.%2, red by Z1907.%2, amber by both.</translation>
    </message>
    <message>
        <source>Feed override key L%1: selects the override whose code machine constant C%2 holds (codes 0–10 = 0…100 %). Its LED shows the override key in effect.</source>
        <translation>Feed override key L%1: selects the override whose code machine constant C%2 holds (codes 0–10 = 0…100 %). Its LED shows the override key in effect.</translation>
    </message>
    <message>
        <source>Digit %1.</source>
        <translation>Digit %1.</translation>
    </message>
    <message>
        <source>Moves the marker up to the previous parameter or line.</source>
        <translation>Moves the marker up to the previous parameter or line.</translation>
    </message>
    <message>
        <source>Moves the marker down to the next parameter or line.</source>
        <translation>Moves the marker down to the next parameter or line.</translation>
    </message>
    <message>
        <source>Moves the marker left; in the axis screens, to the other axis.</source>
        <translation>Moves the marker left; in the axis screens, to the other axis.</translation>
    </message>
    <message>
        <source>Moves the marker right; in the axis screens, to the other axis.</source>
        <translation>Moves the marker right; in the axis screens, to the other axis.</translation>
    </message>
    <message>
        <source>Pages through the screens of the current mode.</source>
        <translation>Pages through the screens of the current mode.</translation>
    </message>
    <message>
        <source>Enters the service screens (messages, faults, system, diagnostics) and returns from them.</source>
        <translation>Enters the service screens (messages, faults, system, diagnostics) and returns from them.</translation>
    </message>
    <message>
        <source>As the machine constants set it: cancels editing a parameter, resets the system, acknowledges error and fault messages.</source>
        <translation>As the machine constants set it: cancels editing a parameter, resets the system, acknowledges error and fault messages.</translation>
    </message>
    <message>
        <source>Switches keys with two functions to their second one: press SHIFT, then the key. The LED shows SHIFT engaged; pressing SHIFT again releases it.</source>
        <translation>Switches keys with two functions to their second one: press SHIFT, then the key. The LED shows SHIFT engaged; pressing SHIFT again releases it.</translation>
    </message>
    <message>
        <source>Goes to choosing a parameter by its number, and back.</source>
        <translation>Goes to choosing a parameter by its number, and back.</translation>
    </message>
    <message>
        <source>Enters the number of the program for automatic mode; in the program editor, inserts a computing or jump frame.</source>
        <translation>Enters the number of the program for automatic mode; in the program editor, inserts a computing or jump frame.</translation>
    </message>
    <message>
        <source>Inserts a new standard frame after the current one (program editor).</source>
        <translation>Inserts a new standard frame after the current one (program editor).</translation>
    </message>
    <message>
        <source>Deletes a program, a frame or the value of a parameter.</source>
        <translation>Deletes a program, a frame or the value of a parameter.</translation>
    </message>
    <message>
        <source>Enters the typed value.</source>
        <translation>Enters the typed value.</translation>
    </message>
    <message>
        <source>Decimal point.</source>
        <translation>Decimal point.</translation>
    </message>
    <message>
        <source>Addition.</source>
        <translation>Addition.</translation>
    </message>
    <message>
        <source>Subtraction; the minus sign.</source>
        <translation>Subtraction; the minus sign.</translation>
    </message>
    <message>
        <source>Multiplication.</source>
        <translation>Multiplication.</translation>
    </message>
    <message>
        <source>Division.</source>
        <translation>Division.</translation>
    </message>
    <message>
        <source>Assigns the result.</source>
        <translation>Assigns the result.</translation>
    </message>
    <message>
        <source>Types the letter R (R-parameters).</source>
        <translation>Types the letter R (R-parameters).</translation>
    </message>
    <message>
        <source>Sets or clears the skip mark «/» of a frame (program editor).</source>
        <translation>Sets or clears the skip mark «/» of a frame (program editor).</translation>
    </message>
    <message>
        <source>SHIFT+▲: three lines up; in the program editor, the previous frame.</source>
        <translation>SHIFT+▲: three lines up; in the program editor, the previous frame.</translation>
    </message>
    <message>
        <source>SHIFT+▼: three lines down; in the program editor, the next frame.</source>
        <translation>SHIFT+▼: three lines down; in the program editor, the next frame.</translation>
    </message>
    <message>
        <source>%1 (latches like a click); or hold Shift with the other key</source>
        <translation>%1 (latches like a click); or hold Shift with the other key</translation>
    </message>
    <message>
        <source>PC keyboard:</source>
        <translation>PC keyboard:</translation>
    </message>
</context>
<context>
    <name>k528::studio::K923Widget</name>
    <message>
        <source>Keyboard map…</source>
        <translation>Keyboard map…</translation>
    </message>
    <message>
        <source>Copy the LCD text</source>
        <translation>Copy the LCD text</translation>
    </message>
    <message>
        <source>LCD: yellow-green backlight</source>
        <translation>LCD: yellow-green backlight</translation>
    </message>
    <message>
        <source>LCD: blue backlight</source>
        <translation>LCD: blue backlight</translation>
    </message>
    <message>
        <source>The K923 operator panel. Click it to work it from the PC keyboard too (each key's tooltip names its PC key; Tab leaves the panel). Right-click for the keyboard map.</source>
        <translation>The K923 operator panel. Click it to work it from the PC keyboard too (each key's tooltip names its PC key; Tab leaves the panel). Right-click for the keyboard map.</translation>
    </message>
    <message>
        <source>K923 operator panel</source>
        <translation>K923 operator panel</translation>
    </message>
</context>
<context>
    <name>k528::studio::KeyboardMapDialog</name>
    <message>
        <source>K923 keyboard map</source>
        <translation>K923 keyboard map</translation>
    </message>
    <message>
        <source>The PC keyboard works the panel while the panel has the focus: click the panel (a ring shows round it) or reach it with Tab; Tab leaves it again. Shift held with a PC key that is not a character gives SHIFT+key; S latches the panel's SHIFT for the next key, as a click on SHIFT does. Letters work in the Russian layout too.</source>
        <translation>The PC keyboard works the panel while the panel has the focus: click the panel (a ring shows round it) or reach it with Tab; Tab leaves it again. Shift held with a PC key that is not a character gives SHIFT+key; S latches the panel's SHIFT for the next key, as a click on SHIFT does. Letters work in the Russian layout too.</translation>
    </message>
    <message>
        <source>Panel key</source>
        <translation>Panel key</translation>
    </message>
    <message>
        <source>PC keyboard</source>
        <translation>PC keyboard</translation>
    </message>
    <message>
        <source>Function</source>
        <translation>Function</translation>
    </message>
</context>
<context>
    <name>k528::studio::LinkController</name>
    <message>
        <source>cancelled; nothing was kept</source>
        <translation>cancelled; nothing was kept</translation>
    </message>
    <message>
        <source>C-parameters</source>
        <translation>C-parameters</translation>
    </message>
    <message>
        <source>messages</source>
        <translation>messages</translation>
    </message>
    <message>
        <source>cancelled; the program being sent was not committed</source>
        <translation>cancelled; the program being sent was not committed</translation>
    </message>
    <message>
        <source>%1, address %2, %3 bit/s</source>
        <translation>%1, address %2, %3 bit/s</translation>
    </message>
    <message>
        <source>R-parameters</source>
        <translation>R-parameters</translation>
    </message>
    <message>
        <source>the controller is not connected</source>
        <translation>the controller is not connected</translation>
    </message>
    <message>
        <source>cancelled; what was not committed is as it was</source>
        <translation>cancelled; what was not committed is as it was</translation>
    </message>
    <message>
        <source>the link's map carries no LCD text, no keys, no DAC or servo-tick data</source>
        <translation>the link's map carries no LCD text, no keys, no DAC or servo-tick data</translation>
    </message>
    <message>
        <source>a transfer is under way on the line</source>
        <translation>a transfer is under way on the line</translation>
    </message>
    <message>
        <source>R%1 is the positioner's own: the PC does not write it (it writes %2)</source>
        <translation>R%1 is the positioner's own: the PC does not write it (it writes %2)</translation>
    </message>
    <message>
        <source>R%1 is read only over the link: the PC writes %2</source>
        <translation>R%1 is read only over the link: the PC writes %2</translation>
    </message>
    <message>
        <source>C%1 has no address in the positioner (table Е.1): it is not written</source>
        <translation>C%1 has no address in the positioner (table Е.1): it is not written</translation>
    </message>
    <message>
        <source>power-on</source>
        <translation>power-on</translation>
    </message>
    <message>
        <source>the controller is in F7 УПРАВЛЕНИЕ ДАННЫМИ but not on «РАБОТА С ПЭВМ»: choose it in its menu on the K923</source>
        <translation>the controller is in F7 УПРАВЛЕНИЕ ДАННЫМИ but not on «РАБОТА С ПЭВМ»: choose it in its menu on the K923</translation>
    </message>
    <message>
        <source>the controller is not in F7 «РАБОТА С ПЭВМ» (mode %1 now): press F7 (УПРАВЛЕНИЕ ДАННЫМИ) on its K923 and choose «РАБОТА С ПЭВМ»</source>
        <translation>the controller is not in F7 «РАБОТА С ПЭВМ» (mode %1 now): press F7 (УПРАВЛЕНИЕ ДАННЫМИ) on its K923 and choose «РАБОТА С ПЭВМ»</translation>
    </message>
    <message>
        <source>%1: the controller is not connected</source>
        <translation>%1: the controller is not connected</translation>
    </message>
    <message>
        <source>clear C</source>
        <translation>clear C</translation>
    </message>
    <message>
        <source>clear R</source>
        <translation>clear R</translation>
    </message>
    <message>
        <source>On record: transfer %1 in %2</source>
        <translation>On record: transfer %1 in %2</translation>
    </message>
    <message>
        <source>The transfer is not on record: %1</source>
        <translation>The transfer is not on record: %1</translation>
    </message>
    <message>
        <source>program %1</source>
        <translation>program %1</translation>
    </message>
    <message>
        <source>draft</source>
        <translation>draft</translation>
    </message>
    <message>
        <source>withdrawn</source>
        <translation>withdrawn</translation>
    </message>
    <message>
        <source>released</source>
        <translation>released</translation>
    </message>
    <message>
        <source>L%1: %2, not the released version: its released version (revision %3) is sent</source>
        <translation>L%1: %2, not the released version: its released version (revision %3) is sent</translation>
    </message>
    <message>
        <source>L%1: %2, never released: not sent</source>
        <translation>L%1: %2, never released: not sent</translation>
    </message>
    <message>
        <source>L%1: not in the database: not sent</source>
        <translation>L%1: not in the database: not sent</translation>
    </message>
    <message>
        <source>The push did not start: %1; nothing was sent</source>
        <translation>The push did not start: %1; nothing was sent</translation>
    </message>
    <message>
        <source>%1, unit %2 (Modbus TCP)</source>
        <translation>%1, unit %2 (Modbus TCP)</translation>
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
        <translation>exception 01: the controller does not know this function</translation>
    </message>
    <message>
        <source>exception 02: a register outside the controller's map (or a read-only one written)</source>
        <translation>exception 02: a register outside the controller's map (or a read-only one written)</translation>
    </message>
    <message>
        <source>exception 03: a value outside its range; nothing of the request was written</source>
        <translation>exception 03: a value outside its range; nothing of the request was written</translation>
    </message>
    <message>
        <source>exception 06: the controller is not in F7 «РАБОТА С ПЭВМ» (УПРАВЛЕНИЕ ДАННЫМИ): select it on the K923 to write</source>
        <translation>exception 06: the controller is not in F7 «РАБОТА С ПЭВМ» (УПРАВЛЕНИЕ ДАННЫМИ): select it on the K923 to write</translation>
    </message>
    <message>
        <source>exception %1</source>
        <translation>exception %1</translation>
    </message>
    <message>
        <source>idle (the transfer)</source>
        <translation>idle</translation>
    </message>
    <message>
        <source>ready (the transfer)</source>
        <translation>ready</translation>
    </message>
    <message>
        <source>committed</source>
        <translation>committed</translation>
    </message>
    <message>
        <source>the controller is not in F7 «РАБОТА С ПЭВМ»</source>
        <translation>the controller is not in F7 «РАБОТА С ПЭВМ»</translation>
    </message>
    <message>
        <source>no such program in the controller</source>
        <translation>no such program in the controller</translation>
    </message>
    <message>
        <source>the controller refused the text</source>
        <translation>the controller refused the text</translation>
    </message>
    <message>
        <source>CRC or length mismatch: the text arrived damaged and was not stored</source>
        <translation>CRC or length mismatch: the text arrived damaged and was not stored</translation>
    </message>
    <message>
        <source>the controller's memory is full</source>
        <translation>the controller's memory is full</translation>
    </message>
    <message>
        <source>status %1</source>
        <translation>status %1</translation>
    </message>
    <message>
        <source>reading registers %1</source>
        <translation>reading registers %1</translation>
    </message>
    <message>
        <source>writing registers %1</source>
        <translation>writing registers %1</translation>
    </message>
    <message>
        <source>echo</source>
        <translation>echo</translation>
    </message>
    <message>
        <source>diagnostics %1</source>
        <translation>diagnostics %1</translation>
    </message>
    <message>
        <source>server id</source>
        <translation>server id</translation>
    </message>
    <message>
        <source>%1: the controller does not answer (%2 attempts)</source>
        <translation>%1: the controller does not answer (%2 attempts)</translation>
    </message>
    <message>
        <source>%1: the controller does not answer (1 attempt)</source>
        <translation>%1: the controller does not answer (1 attempt)</translation>
    </message>
    <message>
        <source>%1: the controller does not answer (%2 attempts, last: %3)</source>
        <translation>%1: the controller does not answer (%2 attempts, last: %3)</translation>
    </message>
    <message>
        <source>%1: the controller does not answer (1 attempt, last: %2)</source>
        <translation>%1: the controller does not answer (1 attempt, last: %2)</translation>
    </message>
    <message>
        <source>timeout</source>
        <translation>timeout</translation>
    </message>
    <message>
        <source>CRC error</source>
        <translation>CRC error</translation>
    </message>
    <message>
        <source>the port is closed</source>
        <translation>the port is closed</translation>
    </message>
    <message>
        <source>the connection is closed</source>
        <translation>the connection is closed</translation>
    </message>
    <message>
        <source>the echo differs</source>
        <translation>the echo differs</translation>
    </message>
    <message>
        <source>an empty answer</source>
        <translation>an empty answer</translation>
    </message>
    <message>
        <source>the port is closed and does not open again: %1</source>
        <translation>the port is closed and does not open again: %1</translation>
    </message>
    <message>
        <source>the port failed: %1</source>
        <translation>the port failed: %1</translation>
    </message>
    <message>
        <source>the connection is closed and does not open again: %1</source>
        <translation>the connection is closed and does not open again: %1</translation>
    </message>
    <message>
        <source>the connection failed: %1</source>
        <translation>the connection failed: %1</translation>
    </message>
    <message>
        <source>%1 (a damaged frame)</source>
        <translation>%1</translation>
    </message>
    <message>
        <source>%1 (an answer that does not fit)</source>
        <translation>%1</translation>
    </message>
    <message>
        <source>%1 (no answer)</source>
        <translation>%1</translation>
    </message>
    <message>
        <source>connection refused</source>
        <translation>connection refused</translation>
    </message>
    <message>
        <source>the other end closed the connection</source>
        <translation>the other end closed the connection</translation>
    </message>
    <message>
        <source>host not found</source>
        <translation>host not found</translation>
    </message>
    <message>
        <source>no connection within %1 ms</source>
        <translation>no connection within %1 ms</translation>
    </message>
    <message>
        <source>the socket timed out</source>
        <translation>the socket timed out</translation>
    </message>
    <message>
        <source>the network is unreachable</source>
        <translation>the network is unreachable</translation>
    </message>
    <message>
        <source>access to the socket denied</source>
        <translation>access to the socket denied</translation>
    </message>
    <message>
        <source>the address is in use</source>
        <translation>the address is in use</translation>
    </message>
    <message>
        <source>socket error: %1</source>
        <translation>socket error: %1</translation>
    </message>
    <message>
        <source>no such port</source>
        <translation>no such port</translation>
    </message>
    <message>
        <source>permission denied (or another program holds the port)</source>
        <translation>permission denied (or another program holds the port)</translation>
    </message>
    <message>
        <source>the port is already open</source>
        <translation>the port is already open</translation>
    </message>
    <message>
        <source>the port does not take these settings</source>
        <translation>the port does not take these settings</translation>
    </message>
    <message>
        <source>the port is gone (unplugged?)</source>
        <translation>the port is gone (unplugged?)</translation>
    </message>
    <message>
        <source>the port failed to read or write</source>
        <translation>the port failed to read or write</translation>
    </message>
    <message>
        <source>the port timed out</source>
        <translation>the port timed out</translation>
    </message>
    <message>
        <source>the port is not open</source>
        <translation>the port is not open</translation>
    </message>
    <message>
        <source>port error: %1</source>
        <translation>port error: %1</translation>
    </message>
    <message>
        <source>'%1' is not HOST:PORT (a port 1..65535)</source>
        <translation>'%1' is not HOST:PORT (a port 1..65535)</translation>
    </message>
    <message>
        <source>the controller is in F7 УПРАВЛЕНИЕ ДАННЫМИ but not on «РАБОТА С ПЭВМ»: choose «РАБОТА С ПЭВМ» in its menu on the K923 (▲ ▼, ENTER), then %1 again; nothing was sent</source>
        <translation>the controller is in F7 УПРАВЛЕНИЕ ДАННЫМИ but not on «РАБОТА С ПЭВМ»: choose «РАБОТА С ПЭВМ» in its menu on the K923 (▲ ▼, ENTER), then %1 again; nothing was sent</translation>
    </message>
    <message>
        <source>the controller is not in F7 «РАБОТА С ПЭВМ» (mode F%2 now): press F7 (УПРАВЛЕНИЕ ДАННЫМИ) on the K923 and choose «РАБОТА С ПЭВМ», then %1 again; nothing was sent</source>
        <translation>the controller is not in F7 «РАБОТА С ПЭВМ» (mode F%2 now): press F7 (УПРАВЛЕНИЕ ДАННЫМИ) on the K923 and choose «РАБОТА С ПЭВМ», then %1 again; nothing was sent</translation>
    </message>
    <message>
        <source>the controller is not in F7 «РАБОТА С ПЭВМ» (powering on): press F7 (УПРАВЛЕНИЕ ДАННЫМИ) on the K923 and choose «РАБОТА С ПЭВМ», then %1 again; nothing was sent</source>
        <translation>the controller is not in F7 «РАБОТА С ПЭВМ» (powering on): press F7 (УПРАВЛЕНИЕ ДАННЫМИ) on the K923 and choose «РАБОТА С ПЭВМ», then %1 again; nothing was sent</translation>
    </message>
    <message>
        <source>push (the action to repeat)</source>
        <translation>push</translation>
    </message>
    <message>
        <source>clear C (the action to repeat)</source>
        <translation>clear C</translation>
    </message>
    <message>
        <source>clear R (the action to repeat)</source>
        <translation>clear R</translation>
    </message>
    <message>
        <source>set %1 (the action to repeat)</source>
        <translation>set %1</translation>
    </message>
    <message>
        <source>C-parameters</source>
        <translation>C-parameters</translation>
    </message>
    <message>
        <source>R-parameters</source>
        <translation>R-parameters</translation>
    </message>
    <message>
        <source>R-parameters (%1)</source>
        <translation>R-parameters (%1)</translation>
    </message>
    <message>
        <source>messages</source>
        <translation>messages</translation>
    </message>
    <message>
        <source>program %1</source>
        <translation>program %1</translation>
    </message>
    <message>
        <source>clear C</source>
        <translation>clear C</translation>
    </message>
    <message>
        <source>clear R</source>
        <translation>clear R</translation>
    </message>
    <message>
        <source>clear C: the C block does not read back as zeros</source>
        <translation>clear C: the C block does not read back as zeros</translation>
    </message>
    <message>
        <source>the controller announces a text of %1 bytes</source>
        <translation>the controller announces a text of %1 bytes</translation>
    </message>
    <message>
        <source>the text read does not match its CRC-32</source>
        <translation>the text read does not match its CRC-32</translation>
    </message>
    <message>
        <source>%1 at line %2</source>
        <translation>%1 at line %2</translation>
    </message>
    <message>
        <source>the map's window does not follow its offset</source>
        <translation>the map's window does not follow its offset</translation>
    </message>
    <message>
        <source>%1: the text read back differs from the text sent</source>
        <translation>%1: the text read back differs from the text sent</translation>
    </message>
    <message>
        <source>%1: the controller refused the block</source>
        <translation>%1: the controller refused the block</translation>
    </message>
    <message>
        <source>%1: the controller refused the block at C%2</source>
        <translation>%1: the controller refused the block at C%2</translation>
    </message>
    <message>
        <source>%1: the values read back differ from those sent</source>
        <translation>%1: the values read back differ from those sent</translation>
    </message>
    <message>
        <source>C%1 has no address in the positioner (table Е.1): it cannot be written</source>
        <translation>C%1 has no address in the positioner (table Е.1): it cannot be written</translation>
    </message>
    <message>
        <source>C%1 = %2: the controller refused the value (outside table Е.1)</source>
        <translation>C%1 = %2: the controller refused the value (outside table Е.1)</translation>
    </message>
    <message>
        <source>%1: the controller does not read back what was written</source>
        <translation>%1: the controller does not read back what was written</translation>
    </message>
    <message>
        <source>R%1 is read only over the link (the PC writes %2)</source>
        <translation>R%1 is read only over the link (the PC writes %2)</translation>
    </message>
    <message>
        <source>R%1 = %2 is outside 32 bits</source>
        <translation>R%1 = %2 is outside 32 bits</translation>
    </message>
    <message>
        <source>%1; nothing was sent</source>
        <translation>%1; nothing was sent</translation>
    </message>
    <message>
        <source>C%1 (%2): %3 (table Е.1)</source>
        <translation>C%1 (%2): %3 (table Е.1)</translation>
    </message>
    <message>
        <source>R%1 is outside the 32-bit range</source>
        <translation>R%1 is outside the 32-bit range</translation>
    </message>
    <message>
        <source>program %1, line %2: %3</source>
        <translation>program %1, line %2: %3</translation>
    </message>
    <message>
        <source>program %1 does not hold exactly that program</source>
        <translation>program %1 does not hold exactly that program</translation>
    </message>
    <message>
        <source>program %1: %2</source>
        <translation>program %1: %2</translation>
    </message>
    <message>
        <source>%1:%2: %3</source>
        <translation>%1:%2: %3</translation>
    </message>
    <message>
        <source>%1 holds no program (%L) and no %MESSAGES</source>
        <translation>%1 holds no program (%L) and no %MESSAGES</translation>
    </message>
    <message>
        <source>%1: the text before the first %L header belongs to no program</source>
        <translation>%1: the text before the first %L header belongs to no program</translation>
    </message>
    <message>
        <source>%1:%2: %3 (checked against the controller's constants and programs)</source>
        <translation>%1:%2: %3 (checked against the controller's constants and programs)</translation>
    </message>
    <message>
        <source>new: %1</source>
        <translation>new: %1</translation>
    </message>
    <message>
        <source>in doubt (the line broke while it was committed; pull to see): %1</source>
        <translation>in doubt (the line broke while it was committed; pull to see): %1</translation>
    </message>
    <message>
        <source>as they were: %1</source>
        <translation>as they were: %1</translation>
    </message>
    <message>
        <source>%1 answer</source>
        <translation>%1 answer</translation>
    </message>
    <message>
        <source>%1 answers</source>
        <translation>%1 answers</translation>
    </message>
    <message>
        <source>%1 timeout</source>
        <translation>%1 timeout</translation>
    </message>
    <message>
        <source>%1 timeouts</source>
        <translation>%1 timeouts</translation>
    </message>
    <message>
        <source>%1 CRC error</source>
        <translation>%1 CRC error</translation>
    </message>
    <message>
        <source>%1 CRC errors</source>
        <translation>%1 CRC errors</translation>
    </message>
    <message>
        <source>%1 bad reply</source>
        <translation>%1 bad reply</translation>
    </message>
    <message>
        <source>%1 bad replies</source>
        <translation>%1 bad replies</translation>
    </message>
    <message>
        <source>%1 exception</source>
        <translation>%1 exception</translation>
    </message>
    <message>
        <source>%1 exceptions</source>
        <translation>%1 exceptions</translation>
    </message>
    <message>
        <source>%1 retry</source>
        <translation>%1 retry</translation>
    </message>
    <message>
        <source>%1 retries</source>
        <translation>%1 retries</translation>
    </message>
    <message>
        <source>%1 request sent again in halves</source>
        <translation>%1 request sent again in halves</translation>
    </message>
    <message>
        <source>%1 requests sent again in halves</source>
        <translation>%1 requests sent again in halves</translation>
    </message>
    <message>
        <source>; round trip median %1 ms, p95 %2 ms</source>
        <translation>; round trip median %1 ms, p95 %2 ms</translation>
    </message>
    <message>
        <source>cancelled by the user</source>
        <translation>cancelled by the user</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>closed</translation>
    </message>
    <message>
        <source>address %1: %2</source>
        <translation>address %1: %2</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>no answer</translation>
    </message>
    <message>
        <source>a damaged answer (another baud rate or parity?)</source>
        <translation>a damaged answer (another baud rate or parity?)</translation>
    </message>
    <message>
        <source>echo ok</source>
        <translation>echo ok</translation>
    </message>
    <message>
        <source>exception %1 to the echo</source>
        <translation>exception %1 to the echo</translation>
    </message>
    <message>
        <source>, running (the server id says)</source>
        <translation>, running</translation>
    </message>
    <message>
        <source>; no server id (FC 17)</source>
        <translation>; no server id (FC 17)</translation>
    </message>
    <message>
        <source>; K528-05 map: mode F%1</source>
        <translation>; K528-05 map: mode F%1</translation>
    </message>
    <message>
        <source>, program %1</source>
        <translation>, program %1</translation>
    </message>
    <message>
        <source>, %1 programs</source>
        <translation>, %1 programs</translation>
    </message>
    <message>
        <source>, alarms</source>
        <translation>, alarms</translation>
    </message>
    <message>
        <source>; round trip %1 ms</source>
        <translation>; round trip %1 ms</translation>
    </message>
    <message>
        <source>; server id %1</source>
        <translation>; server id %1</translation>
    </message>
    <message>
        <source>cannot connect to %1: %2</source>
        <translation>cannot connect to %1: %2</translation>
    </message>
</context>
<context>
    <name>k528::studio::ListingActions</name>
    <message>
        <source>Listing of %1 pages written to %2</source>
        <translation>Listing of %1 pages written to %2</translation>
    </message>
    <message>
        <source>Export the listing</source>
        <translation>Export the listing</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Printed %1 pages</source>
        <translation>Printed %1 pages</translation>
    </message>
    <message>
        <source>The listing could not be printed</source>
        <translation>The listing could not be printed</translation>
    </message>
</context>
<context>
    <name>k528::studio::MachinePanelWidget</name>
    <message>
        <source>SPINDLE</source>
        <translation>SPINDLE</translation>
    </message>
    <message>
        <source>COOLANT</source>
        <translation>COOLANT</translation>
    </message>
    <message>
        <source>LIMIT</source>
        <translation>LIMIT</translation>
    </message>
    <message>
        <source>HOMED</source>
        <translation>HOMED</translation>
    </message>
    <message>
        <source>DOOR</source>
        <translation>DOOR</translation>
    </message>
    <message>
        <source>CLAMPED</source>
        <translation>CLAMPED</translation>
    </message>
    <message>
        <source>ALARM</source>
        <translation>ALARM</translation>
    </message>
    <message>
        <source>LUBE</source>
        <translation>LUBE</translation>
    </message>
    <message>
        <source>WHEEL</source>
        <translation>WHEEL</translation>
    </message>
    <message>
        <source>GAUGE</source>
        <translation>GAUGE</translation>
    </message>
    <message>
        <source>TURRET</source>
        <translation>TURRET</translation>
    </message>
    <message>
        <source>HYDRAUL.</source>
        <translation>HYDRAUL.</translation>
    </message>
    <message>
        <source>MACHINE CONTROL PANEL</source>
        <translation>MACHINE CONTROL PANEL</translation>
    </message>
    <message>
        <source>EMERGENCY STOP</source>
        <translation>EMERGENCY STOP</translation>
    </message>
    <message>
        <source>DRIVES ON</source>
        <translation>DRIVES ON</translation>
    </message>
    <message>
        <source>RESET</source>
        <translation>RESET</translation>
    </message>
    <message>
        <source>CYCLE START</source>
        <translation>CYCLE START</translation>
    </message>
    <message>
        <source>STOP</source>
        <translation>STOP</translation>
    </message>
    <message>
        <source>Rapid traverse: hold with a jog button</source>
        <translation>Rapid traverse: hold with a jog button</translation>
    </message>
    <message>
        <source>Jog X+ (hold)</source>
        <translation>Jog X+ (hold)</translation>
    </message>
    <message>
        <source>Jog X- (hold)</source>
        <translation>Jog X- (hold)</translation>
    </message>
    <message>
        <source>Jog Z+ (hold)</source>
        <translation>Jog Z+ (hold)</translation>
    </message>
    <message>
        <source>Jog Z- (hold)</source>
        <translation>Jog Z- (hold)</translation>
    </message>
    <message>
        <source>JOG</source>
        <translation>JOG</translation>
    </message>
    <message>
        <source>HANDWHEEL</source>
        <translation>HANDWHEEL</translation>
    </message>
    <message>
        <source>AXIS</source>
        <translation>AXIS</translation>
    </message>
    <message>
        <source>STEP</source>
        <translation>STEP</translation>
    </message>
    <message>
        <source>Drag round or turn the mouse wheel: one detent is one step</source>
        <translation>Drag round or turn the mouse wheel: one detent is one step</translation>
    </message>
    <message>
        <source>FEED OVERRIDE %</source>
        <translation>FEED OVERRIDE %</translation>
    </message>
    <message>
        <source>K923: the panel's L1..L4 keys set the override</source>
        <translation>K923: the panel's L1..L4 keys set the override</translation>
    </message>
    <message>
        <source>CHUCK</source>
        <translation>CHUCK</translation>
    </message>
    <message>
        <source>NEW WHEEL</source>
        <translation>NEW WHEEL</translation>
    </message>
    <message>
        <source>Per detent: %1 / %2 / %3 mm</source>
        <translation>Per detent: %1 / %2 / %3 mm</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Spindle</translation>
    </message>
    <message>
        <source>Wheel</source>
        <translation>Wheel</translation>
    </message>
    <message>
        <source>Work</source>
        <translation>Work</translation>
    </message>
    <message>
        <source>rpm</source>
        <translation>rpm</translation>
    </message>
    <message>
        <source>Tool %1</source>
        <translation>Tool %1</translation>
    </message>
    <message>
        <source>Gauge: bore %1 / %2 mm, wheel %3 mm</source>
        <translation>Gauge: bore %1 / %2 mm, wheel %3 mm</translation>
    </message>
    <message>
        <source> in </source>
        <translation> in </translation>
    </message>
    <message>
        <source> touch </source>
        <translation> touch </translation>
    </message>
    <message>
        <source> rough </source>
        <translation> rough </translation>
    </message>
    <message>
        <source> finish </source>
        <translation> finish </translation>
    </message>
    <message>
        <source> size</source>
        <translation> size</translation>
    </message>
</context>
<context>
    <name>k528::studio::MachineSource</name>
    <message>
        <source>The machine database is not used: %1</source>
        <translation>The machine database is not used: %1</translation>
    </message>
    <message>
        <source>database %1</source>
        <translation>database %1</translation>
    </message>
    <message>
        <source>built-in</source>
        <translation>built-in</translation>
    </message>
    <message>
        <source>not in the database %1</source>
        <translation>not in the database %1</translation>
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
        <translation>revision %1 by %2 at %3: %4
</translation>
    </message>
</context>
<context>
    <name>k528::studio::MainWindow</name>
    <message>
        <source>About K528 Studio</source>
        <translation>About K528 Studio</translation>
    </message>
    <message>
        <source>&lt;h3&gt;K528 Studio %1&lt;/h3&gt;&lt;p&gt;Workstation for the Konstar K528-05 two-axis positioning controller and its K923 operator panel.&lt;/p&gt;&lt;p&gt;Licence: GNU GPL version 3 or later.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;K528 Studio %1&lt;/h3&gt;&lt;p&gt;Workstation for the Konstar K528-05 two-axis positioning controller and its K923 operator panel.&lt;/p&gt;&lt;p&gt;Licence: GNU GPL version 3 or later.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quit</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;View</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Language</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Help</translation>
    </message>
    <message>
        <source>&amp;About K528 Studio</source>
        <translation>&amp;About K528 Studio</translation>
    </message>
    <message>
        <source>K923 operator panel</source>
        <translation>K923 operator panel</translation>
    </message>
    <message>
        <source>Machine control panel</source>
        <translation>Machine control panel</translation>
    </message>
    <message>
        <source>Messages</source>
        <translation>Messages</translation>
    </message>
    <message>
        <source>Axes and signals</source>
        <translation>Axes and signals</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Ready</translation>
    </message>
    <message>
        <source>Machine time %1:%2:%3</source>
        <translation>Machine time %1:%2:%3</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <source>&amp;Pause the machine</source>
        <translation>&amp;Pause the machine</translation>
    </message>
    <message>
        <source>&amp;Speed</source>
        <translation>&amp;Speed</translation>
    </message>
    <message>
        <source>&amp;Faults for training</source>
        <translation>&amp;Faults for training</translation>
    </message>
    <message>
        <source>&amp;Clear all faults</source>
        <translation>&amp;Clear all faults</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Machine</translation>
    </message>
    <message>
        <source>The machine %1 cannot be loaded: %2</source>
        <translation>The machine %1 cannot be loaded: %2</translation>
    </message>
    <message>
        <source>&amp;Machine</source>
        <translation>&amp;Machine</translation>
    </message>
    <message>
        <source>Machine: %1</source>
        <translation>Machine: %1</translation>
    </message>
    <message>
        <source>Machine: %1 (%2)</source>
        <translation>Machine: %1 (%2)</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>Load programs</source>
        <translation>Load programs</translation>
    </message>
    <message>
        <source>K528 programs (*.k528 *.txt);;All files (*)</source>
        <translation>K528 programs (*.k528 *.txt);;All files (*)</translation>
    </message>
    <message>
        <source>Loaded %1 from %2</source>
        <translation>Loaded %1 from %2</translation>
    </message>
    <message>
        <source>Loaded %1 from %2, with warnings.</source>
        <translation>Loaded %1 from %2, with warnings.</translation>
    </message>
    <message>
        <source>&amp;Load programs...</source>
        <translation>&amp;Load programs...</translation>
    </message>
    <message>
        <source>Keep in the database</source>
        <translation>Keep in the database</translation>
    </message>
    <message>
        <source>The memory of %1 was not kept: %2</source>
        <translation>The memory of %1 was not kept: %2</translation>
    </message>
    <message>
        <source>%1: the database already holds this memory (revision %2)</source>
        <translation>%1: the database already holds this memory (revision %2)</translation>
    </message>
    <message>
        <source>%1 kept in the database as revision %2 (%3 changes)</source>
        <translation>%1 kept in the database as revision %2 (%3 changes)</translation>
    </message>
    <message>
        <source>&amp;Keep the controller's memory in the database</source>
        <translation>&amp;Keep the controller's memory in the database</translation>
    </message>
    <message>
        <source>Editor</source>
        <translation>Editor</translation>
    </message>
    <message>
        <source>The controller on the link takes no keys: press them on its own K923</source>
        <translation>The controller on the link takes no keys: press them on its own K923</translation>
    </message>
    <message>
        <source>Debugger</source>
        <translation>Debugger</translation>
    </message>
    <message>
        <source>This control panel is the simulated machine's: the controller on the line is worked from its own machine's panel (its state is in the other views).</source>
        <translation>This control panel is the simulated machine's: the controller on the line is worked from its own machine's panel (its state is in the other views).</translation>
    </message>
    <message>
        <source>The debugger steps programs on the simulated machine; the controller on the line runs them itself. Show the simulation again (Controller dock) to debug.</source>
        <translation>The debugger steps programs on the simulated machine; the controller on the line runs them itself. Show the simulation again (Controller dock) to debug.</translation>
    </message>
    <message>
        <source>Reading the controller's memory to keep it in the database...</source>
        <translation>Reading the controller's memory to keep it in the database...</translation>
    </message>
    <message>
        <source> — stale since %1</source>
        <translation> — stale since %1</translation>
    </message>
    <message>
        <source>K923: LEDs only (no LCD text or keys over the link)</source>
        <translation>K923: LEDs only (no LCD text or keys over the link)</translation>
    </message>
    <message>
        <source>The controller on the line: its K LEDs and override as it shows them; its LCD text and keys are not on the link — use its own K923</source>
        <translation>The controller on the line: its K LEDs and override as it shows them; its LCD text and keys are not on the link — use its own K923</translation>
    </message>
    <message>
        <source>The database %1 has no machine %2: it runs as it was loaded; File &gt; Machine offers this database's machines</source>
        <translation>The database %1 has no machine %2: it runs as it was loaded; File &gt; Machine offers this database's machines</translation>
    </message>
    <message>
        <source>Shop</source>
        <translation>Shop</translation>
    </message>
</context>
<context>
    <name>k528::studio::MessagesView</name>
    <message>
        <source>Source</source>
        <translation>Source</translation>
    </message>
    <message>
        <source>No.</source>
        <translation>No.</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Message</translation>
    </message>
    <message>
        <source>State</source>
        <translation>State</translation>
    </message>
    <message>
        <source> (L%1, line %2)</source>
        <translation> (L%1, line %2)</translation>
    </message>
    <message>
        <source>Positioner</source>
        <translation>Positioner</translation>
    </message>
    <message>
        <source>active</source>
        <translation>active</translation>
    </message>
    <message>
        <source>PLC system</source>
        <translation>PLC system</translation>
    </message>
    <message>
        <source>PLC alarm</source>
        <translation>PLC alarm</translation>
    </message>
    <message>
        <source>PLC</source>
        <translation>PLC</translation>
    </message>
    <message>
        <source>information</source>
        <translation>information</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>No alarms.</source>
        <translation>No alarms.</translation>
    </message>
    <message>
        <source>Alarms: %1. Acknowledge with RESET on the machine panel or ESC on the K923 once the cause is gone.</source>
        <translation>Alarms: %1. Acknowledge with RESET on the machine panel or ESC on the K923 once the cause is gone.</translation>
    </message>
    <message>
        <source>waits for acknowledgement</source>
        <translation>waits for acknowledgement</translation>
    </message>
</context>
<context>
    <name>k528::studio::ParameterTablePane</name>
    <message>
        <source>Note:</source>
        <translation>Note:</translation>
    </message>
    <message>
        <source>They cannot be changed now: %1.</source>
        <translation>They cannot be changed now: %1.</translation>
    </message>
</context>
<context>
    <name>k528::studio::ProblemsModel</name>
    <message>
        <source>The rule of the prove-out the frame breaks (the blank, the chuck, the tools): %1</source>
        <translation>A rule of the prove-out (the program against the blank, the chuck and the tools): %1</translation>
    </message>
</context>
<context>
    <name>k528::studio::ProgramMonitor</name>
    <message>
        <source>ready</source>
        <translation>ready</translation>
    </message>
    <message>
        <source>running</source>
        <translation>running</translation>
    </message>
    <message>
        <source>dwell</source>
        <translation>dwell</translation>
    </message>
    <message>
        <source>waiting for the PLC (M)</source>
        <translation>waiting for the PLC (M)</translation>
    </message>
    <message>
        <source>M00: waiting for START</source>
        <translation>M00: waiting for START</translation>
    </message>
    <message>
        <source>interrupted: START continues</source>
        <translation>interrupted: START continues</translation>
    </message>
    <message>
        <source>ended</source>
        <translation>ended</translation>
    </message>
    <message>
        <source>stopped by a message: START begins again</source>
        <translation>stopped by a message: START begins again</translation>
    </message>
    <message>
        <source>Follow the controller</source>
        <translation>Follow the controller</translation>
    </message>
    <message>
        <source>L%1: %2</source>
        <translation>L%1: %2</translation>
    </message>
    <message>
        <source>no program</source>
        <translation>no program</translation>
    </message>
    <message>
        <source>, frame N%1</source>
        <translation>, frame N%1</translation>
    </message>
</context>
<context>
    <name>k528::studio::ProgramReleases</name>
    <message>
        <source>Note (why, what was checked):</source>
        <translation>Note (why, what was checked):</translation>
    </message>
    <message>
        <source>draft</source>
        <translation>draft</translation>
    </message>
    <message>
        <source>released</source>
        <translation>released</translation>
    </message>
    <message>
        <source>withdrawn</source>
        <translation>withdrawn</translation>
    </message>
    <message>
        <source>Release states of %1 cannot be read: %2</source>
        <translation>Release states of %1 cannot be read: %2</translation>
    </message>
    <message>
        <source>Released as of revision %1 by %2 at %3</source>
        <translation>Released as of revision %1 by %2 at %3</translation>
    </message>
    <message>
        <source>Changed since its release: revision %1 is released (by %2 at %3) and a push takes that one</source>
        <translation>Changed since its release: revision %1 is released (by %2 at %3) and a push takes that one</translation>
    </message>
    <message>
        <source>Deleted from the machine since its release (by %1 at %2)</source>
        <translation>Deleted from the machine since its release (by %1 at %2)</translation>
    </message>
    <message>
        <source>Withdrawn by %1 at %2 (revision %3 was released)</source>
        <translation>Withdrawn by %1 at %2 (revision %3 was released)</translation>
    </message>
    <message>
        <source>Note: %1</source>
        <translation>Note: %1</translation>
    </message>
    <message>
        <source>Never released: a push to a controller does not take it</source>
        <translation>Never released: a push to a controller does not take it</translation>
    </message>
    <message>
        <source>Release L%1 of %2</source>
        <translation>Release L%1 of %2</translation>
    </message>
    <message>
        <source>Withdraw L%1 of %2</source>
        <translation>Withdraw L%1 of %2</translation>
    </message>
    <message>
        <source>L%1 is no longer a program of %2: there is nothing to release</source>
        <translation>L%1 is no longer a program of %2: there is nothing to release</translation>
    </message>
    <message>
        <source>L%1 is released already (revision %2)</source>
        <translation>L%1 is released already (revision %2)</translation>
    </message>
    <message>
        <source>Released L%1 of %2 as of revision %3 by %4 at %5</source>
        <translation>Released L%1 of %2 as of revision %3 by %4 at %5</translation>
    </message>
    <message>
        <source>L%1 was not released: %2</source>
        <translation>L%1 was not released: %2</translation>
    </message>
    <message>
        <source>L%1 was never released: there is nothing to withdraw</source>
        <translation>L%1 was never released: there is nothing to withdraw</translation>
    </message>
    <message>
        <source>L%1 is withdrawn already</source>
        <translation>L%1 is withdrawn already</translation>
    </message>
    <message>
        <source>Withdrew L%1 of %2 by %3 at %4</source>
        <translation>Withdrew L%1 of %2 by %3 at %4</translation>
    </message>
    <message>
        <source>L%1 was not withdrawn: %2</source>
        <translation>L%1 was not withdrawn: %2</translation>
    </message>
    <message>
        <source>Programs of %1 for the controllers</source>
        <translation>Programs of %1 for the controllers</translation>
    </message>
    <message>
        <source>State</source>
        <translation>State</translation>
    </message>
    <message>
        <source>By</source>
        <translation>By</translation>
    </message>
    <message>
        <source>Release...</source>
        <translation>Release...</translation>
    </message>
    <message>
        <source>Makes the program's current version the one a push to a controller takes (k528 db release)</source>
        <translation>Makes the program's current version the one a push to a controller takes (k528 db release)</translation>
    </message>
    <message>
        <source>Withdraw...</source>
        <translation>Withdraw...</translation>
    </message>
    <message>
        <source>Withdraws the released version: a push no longer takes it (k528 db withdraw)</source>
        <translation>Withdraws the released version: a push no longer takes it (k528 db withdraw)</translation>
    </message>
    <message>
        <source>No.</source>
        <translation>No.</translation>
    </message>
</context>
<context>
    <name>k528::studio::ProveoutPane</name>
    <message>
        <source>The blank: %1</source>
        <translation>The blank: %1</translation>
    </message>
    <message>
        <source>The file's blank: %1</source>
        <translation>The file's blank: %1</translation>
    </message>
    <message>
        <source>The machine's description: %1</source>
        <translation>The machine's description: %1</translation>
    </message>
    <message>
        <source>The machine's tools: %1</source>
        <translation>The machine's tools: %1</translation>
    </message>
    <message>
        <source>Open a program file in the editor: it is proved on the machine it is checked for.</source>
        <translation>Open a program file in the editor: it is proved on the machine it is checked for.</translation>
    </message>
    <message>
        <source>The file is checked for no machine: choose one (Editor menu) to prove it.</source>
        <translation>The file is checked for no machine: choose one (Editor menu) to prove it.</translation>
    </message>
    <message>
        <source>The file has errors (Problems): it is proved once they are fixed.</source>
        <translation>The file has errors (Problems): it is proved once they are fixed.</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Error</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warning</translation>
    </message>
    <message>
        <source>turning</source>
        <translation>turning</translation>
    </message>
    <message>
        <source>facing</source>
        <translation>facing</translation>
    </message>
    <message>
        <source>grooving</source>
        <translation>grooving</translation>
    </message>
    <message>
        <source>boring bar</source>
        <translation>boring bar</translation>
    </message>
    <message>
        <source>drill</source>
        <translation>drill</translation>
    </message>
    <message>
        <source>threading</source>
        <translation>threading</translation>
    </message>
    <message>
        <source>Nothing found.</source>
        <translation>Nothing found.</translation>
    </message>
    <message>
        <source>Errors: %1, warnings: %2.</source>
        <translation>Errors: %1, warnings: %2.</translation>
    </message>
    <message>
        <source>the blank of the file (UCG)</source>
        <translation>the blank of the file (UCG)</translation>
    </message>
    <message>
        <source>the blank</source>
        <translation>the blank</translation>
    </message>
    <message>
        <source>the chuck and the turret</source>
        <translation>the chuck and the turret</translation>
    </message>
    <message>
        <source>the spindles</source>
        <translation>the spindles</translation>
    </message>
    <message>
        <source>Proved against: %1.</source>
        <translation>Proved against: %1.</translation>
    </message>
    <message>
        <source>No blank: give one (UCG) to check the rapids against the material.</source>
        <translation>No blank: give one (UCG) to check the rapids against the material.</translation>
    </message>
    <message>
        <source>Blank (UCG)</source>
        <translation>Blank (UCG)</translation>
    </message>
    <message>
        <source>the file's own</source>
        <translation>the file's own</translation>
    </message>
    <message>
        <source>The blank as a UCG line (NC-200); empty: the UCG comment of the file</source>
        <translation>The blank as a UCG line (NC-200); empty: the UCG comment of the file</translation>
    </message>
    <message>
        <source>Prove</source>
        <translation>Prove</translation>
    </message>
    <message>
        <source>Run the file's programs in preview against the blank, the chuck, the turret and the tools of the machine</source>
        <translation>Run the file's programs in preview against the blank, the chuck, the turret and the tools of the machine</translation>
    </message>
    <message>
        <source>Prove after each change</source>
        <translation>Prove after each change</translation>
    </message>
    <message>
        <source>The machine's tools</source>
        <translation>The machine's tools</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>Severity</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation>Frame</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Line</translation>
    </message>
    <message>
        <source>Text</source>
        <translation>Text</translation>
    </message>
    <message>
        <source>Station</source>
        <translation>Station</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Tool</translation>
    </message>
    <message>
        <source>Radius, mm</source>
        <translation>Radius, mm</translation>
    </message>
    <message>
        <source>Offset X, mm</source>
        <translation>Offset X, mm</translation>
    </message>
    <message>
        <source>Offset Z, mm</source>
        <translation>Offset Z, mm</translation>
    </message>
    <message>
        <source>Offsets in</source>
        <translation>Offsets in</translation>
    </message>
    <message>
        <source>Max depth, mm</source>
        <translation>Max depth, mm</translation>
    </message>
    <message>
        <source>The tool's nose radius</source>
        <translation>The tool's nose radius</translation>
    </message>
    <message>
        <source>The deepest cut the tool takes (its cutting edge)</source>
        <translation>The deepest cut the tool takes (its cutting edge)</translation>
    </message>
    <message>
        <source>Prove-out</source>
        <translation>Prove-out</translation>
    </message>
    <message>
        <source>expected UCG</source>
        <translation>expected UCG</translation>
    </message>
    <message>
        <source>expected the type N after UCG,</source>
        <translation>expected the type N after UCG,</translation>
    </message>
    <message>
        <source>expected Z&lt;outer length&gt;Z&lt;bore length&gt;</source>
        <translation>expected Z&lt;outer length&gt;Z&lt;bore length&gt;</translation>
    </message>
    <message>
        <source>expected X&lt;outer diameter&gt;X&lt;bore diameter&gt;</source>
        <translation>expected X&lt;outer diameter&gt;X&lt;bore diameter&gt;</translation>
    </message>
    <message>
        <source>expected S&lt;outer angle&gt;S&lt;bore angle&gt;</source>
        <translation>expected S&lt;outer angle&gt;S&lt;bore angle&gt;</translation>
    </message>
    <message>
        <source>the direction is 0 or 1</source>
        <translation>the direction is 0 or 1</translation>
    </message>
    <message>
        <source>the detail is -1..-5</source>
        <translation>the detail is -1..-5</translation>
    </message>
    <message>
        <source>the blank is smaller than 0.01 mm</source>
        <translation>the blank is smaller than 0.01 mm</translation>
    </message>
    <message>
        <source>the bore length has the sign of the outer length</source>
        <translation>the bore length has the sign of the outer length</translation>
    </message>
    <message>
        <source>the bore is longer than the blank</source>
        <translation>the bore is longer than the blank</translation>
    </message>
    <message>
        <source>the bore diameter is 0..the outer diameter</source>
        <translation>the bore diameter is 0..the outer diameter</translation>
    </message>
    <message>
        <source>cone angles are within ±90°</source>
        <translation>cone angles are within ±90°</translation>
    </message>
    <message>
        <source>no UCG in the file</source>
        <translation>no UCG in the file</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Kind</translation>
    </message>
</context>
<context>
    <name>k528::studio::ProveoutTexts</name>
    <message>
        <source>A rapid (G00) enters the material of the blank: X%1 Z%2</source>
        <translation>A rapid (G00) enters the material of the blank: X%1 Z%2</translation>
    </message>
    <message>
        <source>A rapid (G00) enters the material at its dogleg: axis %3 arrives first (X%1 Z%2), although both end points are outside the blank</source>
        <translation>A rapid (G00) enters the material at its dogleg: axis %3 arrives first (X%1 Z%2), although both end points are outside the blank</translation>
    </message>
    <message>
        <source>A rapid (G00) takes the wheel into the ring's material: X%1 Z%2</source>
        <translation>A rapid (G00) takes the wheel into the ring's material: X%1 Z%2</translation>
    </message>
    <message>
        <source>Tool T%3 runs into the chuck's jaws: X%1 Z%2</source>
        <translation>Tool T%3 runs into the chuck's jaws: X%1 Z%2</translation>
    </message>
    <message>
        <source>Tool T%3 runs into the chuck's body: X%1 Z%2</source>
        <translation>Tool T%3 runs into the chuck's body: X%1 Z%2</translation>
    </message>
    <message>
        <source>The turret runs into the chuck's jaws (tool T%3 at X%1 Z%2)</source>
        <translation>The turret runs into the chuck's jaws (tool T%3 at X%1 Z%2)</translation>
    </message>
    <message>
        <source>The turret runs into the chuck's body (tool T%3 at X%1 Z%2)</source>
        <translation>The turret runs into the chuck's body (tool T%3 at X%1 Z%2)</translation>
    </message>
    <message>
        <source>A feed into the material with the spindle stopped: X%1 Z%2</source>
        <translation>A feed into the material with the spindle stopped: X%1 Z%2</translation>
    </message>
    <message>
        <source>A feed into the ring's material with the wheel stopped: X%1 Z%2</source>
        <translation>A feed into the ring's material with the wheel stopped: X%1 Z%2</translation>
    </message>
    <message>
        <source>A manual move takes the tool into the material of the blank: X%1 Z%2</source>
        <translation>A manual move takes the tool into the material of the blank: X%1 Z%2</translation>
    </message>
    <message>
        <source>A cut %1 mm deep, deeper than tool T%2 takes (%3 mm)</source>
        <translation>A cut %1 mm deep, deeper than tool T%2 takes (%3 mm)</translation>
    </message>
</context>
<context>
    <name>k528::studio::PushPreview</name>
    <message>
        <source>name</source>
        <translation>name</translation>
    </message>
    <message>
        <source>title</source>
        <translation>title</translation>
    </message>
    <message>
        <source>added</source>
        <translation>added</translation>
    </message>
    <message>
        <source>removed</source>
        <translation>removed</translation>
    </message>
    <message>
        <source>changed</source>
        <translation>changed</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(none)</translation>
    </message>
</context>
<context>
    <name>k528::studio::RParamsModel</name>
    <message>
        <source>%1 mm/min</source>
        <translation>%1 mm/min</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>user</source>
        <translation>user</translation>
    </message>
    <message>
        <source>system</source>
        <translation>system</translation>
    </message>
    <message>
        <source>read only</source>
        <translation>read only</translation>
    </message>
    <message>
        <source>reserved</source>
        <translation>reserved</translation>
    </message>
    <message>
        <source>No.</source>
        <translation>No.</translation>
    </message>
    <message>
        <source>Access</source>
        <translation>Access</translation>
    </message>
    <message>
        <source>Preset screen</source>
        <translation>Preset screen</translation>
    </message>
    <message>
        <source>Discretes</source>
        <translation>Discretes</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>Preset</source>
        <translation>Preset</translation>
    </message>
    <message>
        <source>R%1 is read only: the controller writes R232..R262</source>
        <translation>R%1 is read only: the controller writes R232..R262</translation>
    </message>
    <message>
        <source>A program is executing: R-parameters are changed when it stops, as on the K923</source>
        <translation>A program is executing: R-parameters are changed when it stops, as on the K923</translation>
    </message>
    <message>
        <source>%1 is outside the R-parameters' range -2147483648..2147483647</source>
        <translation>%1 is outside the R-parameters' range -2147483648..2147483647</translation>
    </message>
    <message>
        <source>R%1: «%2» is not a number</source>
        <translation>R%1: «%2» is not a number</translation>
    </message>
    <message>
        <source>Meaning (appendix L)</source>
        <translation>Meaning (appendix L)</translation>
    </message>
</context>
<context>
    <name>k528::studio::RParamsPane</name>
    <message>
        <source>R-parameters</source>
        <translation>R-parameters</translation>
    </message>
    <message>
        <source>The machine's presets are not read from the database: %1</source>
        <translation>The machine's presets are not read from the database: %1</translation>
    </message>
    <message>
        <source>Search: number or meaning</source>
        <translation>Search: number or meaning</translation>
    </message>
    <message>
        <source>All R0..R299</source>
        <translation>All R0..R299</translation>
    </message>
    <message>
        <source>User R0..R149</source>
        <translation>User R0..R149</translation>
    </message>
    <message>
        <source>System (writable)</source>
        <translation>System (writable)</translation>
    </message>
    <message>
        <source>Read only R232..R262</source>
        <translation>Read only R232..R262</translation>
    </message>
    <message>
        <source>With a preset</source>
        <translation>With a preset</translation>
    </message>
    <message>
        <source>Not zero</source>
        <translation>Not zero</translation>
    </message>
    <message>
        <source>Keep as preset</source>
        <translation>Keep as preset</translation>
    </message>
    <message>
        <source>The selected parameter's value becomes the machine's preset (a new revision)</source>
        <translation>The selected parameter's value becomes the machine's preset (a new revision)</translation>
    </message>
    <message>
        <source>Remove preset</source>
        <translation>Remove preset</translation>
    </message>
    <message>
        <source>Keep all as presets</source>
        <translation>Keep all as presets</translation>
    </message>
    <message>
        <source>Every writable R-parameter that is not 0 becomes a preset, as «Keep the controller's memory» does</source>
        <translation>Every writable R-parameter that is not 0 becomes a preset, as «Keep the controller's memory» does</translation>
    </message>
    <message>
        <source>Load the presets</source>
        <translation>Load the presets</translation>
    </message>
    <message>
        <source>The machine's presets into the controller</source>
        <translation>The machine's presets into the controller</translation>
    </message>
    <message>
        <source>why the presets change (kept with the revision)</source>
        <translation>why the presets change (kept with the revision)</translation>
    </message>
    <message>
        <source>No preset changes</source>
        <translation>No preset changes</translation>
    </message>
    <message>
        <source>The presets were not kept: %1</source>
        <translation>The presets were not kept: %1</translation>
    </message>
    <message>
        <source>%1 — kept as revision %2 of %3</source>
        <translation>%1 — kept as revision %2 of %3</translation>
    </message>
    <message>
        <source>Select an R-parameter first</source>
        <translation>Select an R-parameter first</translation>
    </message>
    <message>
        <source>R%1 is read only (R232..R262): it cannot be preset</source>
        <translation>R%1 is read only (R232..R262): it cannot be preset</translation>
    </message>
    <message>
        <source>The selected R-parameter has no preset</source>
        <translation>The selected R-parameter has no preset</translation>
    </message>
    <message>
        <source>Presets loaded into the controller: %1</source>
        <translation>Presets loaded into the controller: %1</translation>
    </message>
    <message>
        <source>Presets loaded into the controller: %1 of %2; R%3 not: %4</source>
        <translation>Presets loaded into the controller: %1 of %2; R%3 not: %4</translation>
    </message>
    <message>
        <source>Database %1 has no machine %2: the presets shown are those the window loaded; the first one kept creates the machine there</source>
        <translation>Database %1 has no machine %2: the presets shown are those the window loaded; the first one kept creates the machine there</translation>
    </message>
    <message>
        <source>Database %1: the presets shown are those of revision %2 of %3</source>
        <translation>Database %1: the presets shown are those of revision %2 of %3</translation>
    </message>
    <message>
        <source>Trial part...</source>
        <translation>Trial part...</translation>
    </message>
    <message>
        <source>The size measured on the trial part against the drawing: the change of the tool's offset R-parameter, kept as the machine's preset</source>
        <translation>The size measured on the trial part against the drawing: the change of the tool's offset R-parameter, kept as the machine's preset</translation>
    </message>
    <message>
        <source>Kept as revision %1; R%2 not set in the controller: %3</source>
        <translation>Kept as revision %1; R%2 not set in the controller: %3</translation>
    </message>
    <message>
        <source>The R-parameters of the controller on the line, all read every 2.5 s.</source>
        <translation>The R-parameters of the controller on the line, all read every 2.5 s.</translation>
    </message>
    <message>
        <source>R0..R231 are written to it at once (not R158, R222, R223).</source>
        <translation>R0..R231 are written to it at once (not R158, R222, R223).</translation>
    </message>
</context>
<context>
    <name>k528::studio::RefactorActions</name>
    <message>
        <source>Renumbered every program from %1 by %2</source>
        <translation>Renumbered every program from %1 by %2</translation>
    </message>
    <message>
        <source>Renumbered L%1 from %2 by %3</source>
        <translation>Renumbered L%1 from %2 by %3</translation>
    </message>
    <message>
        <source>Copied L%1 to L%2</source>
        <translation>Copied L%1 to L%2</translation>
    </message>
    <message>
        <source>Moved L%1 to L%2</source>
        <translation>Moved L%1 to L%2</translation>
    </message>
    <message>
        <source>Formatted</source>
        <translation>Formatted</translation>
    </message>
    <message>
        <source>Renumber frames</source>
        <translation>Renumber frames</translation>
    </message>
    <message>
        <source>Every program</source>
        <translation>Every program</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>First number</source>
        <translation>First number</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Step</translation>
    </message>
    <message>
        <source>The file has no program</source>
        <translation>The file has no program</translation>
    </message>
    <message>
        <source>Move or copy a program</source>
        <translation>Move or copy a program</translation>
    </message>
    <message>
        <source>Keep the program (copy)</source>
        <translation>Keep the program (copy)</translation>
    </message>
    <message>
        <source>New number</source>
        <translation>New number</translation>
    </message>
</context>
<context>
    <name>k528::studio::RefactorTexts</name>
    <message>
        <source>there is no program L%1</source>
        <translation>there is no program L%1</translation>
    </message>
    <message>
        <source>a program number is 1..99, not %1</source>
        <translation>a program number is 1..99, not %1</translation>
    </message>
    <message>
        <source>program L%1 exists already</source>
        <translation>program L%1 exists already</translation>
    </message>
    <message>
        <source>the start and step of numbering must be at least 1</source>
        <translation>the start and step of numbering must be at least 1</translation>
    </message>
    <message>
        <source>the last frame number would exceed 999 (%1 frames)</source>
        <translation>the last frame number would exceed 999 (%1 frames)</translation>
    </message>
</context>
<context>
    <name>k528::studio::RefusalTexts</name>
    <message>
        <source>F%1 selects no mode</source>
        <translation>F%1 selects no mode</translation>
    </message>
    <message>
        <source>the PLC sets the mode (Z1000.8-10 = %1)</source>
        <translation>the PLC sets the mode (Z1000.8-10 = %1)</translation>
    </message>
    <message>
        <source>override keys are L1..L4, not L%1</source>
        <translation>override keys are L1..L4, not L%1</translation>
    </message>
    <message>
        <source>program numbers are 1..99, not %1</source>
        <translation>program numbers are 1..99, not %1</translation>
    </message>
    <message>
        <source>R-parameters are R0..R299, not R%1</source>
        <translation>R-parameters are R0..R299, not R%1</translation>
    </message>
    <message>
        <source>R%1 is read only (R232..R262)</source>
        <translation>R%1 is read only (R232..R262)</translation>
    </message>
    <message>
        <source>%1 is outside -2147483648..2147483647</source>
        <translation>%1 is outside -2147483648..2147483647</translation>
    </message>
    <message>
        <source>a program is executing</source>
        <translation>a program is executing</translation>
    </message>
    <message>
        <source>a program is active (running or held)</source>
        <translation>a program is active (running or held)</translation>
    </message>
    <message>
        <source>C-parameters are 1..152, not %1</source>
        <translation>C-parameters are 1..152, not %1</translation>
    </message>
    <message>
        <source>%1 = %2 is outside the range %3 of «%4»</source>
        <translation>%1 = %2 is outside the range %3 of «%4»</translation>
    </message>
    <message>
        <source>C-parameters are edited in РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ (F5)</source>
        <translation>C-parameters are edited in РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ (F5)</translation>
    </message>
    <message>
        <source>153 values expected (C1..C152 at 1..152)</source>
        <translation>153 values expected (C1..C152 at 1..152)</translation>
    </message>
    <message>
        <source>C-parameters are loaded from the PC in УПРАВЛЕНИЕ ДАННЫМИ (F7)</source>
        <translation>C-parameters are loaded from the PC in УПРАВЛЕНИЕ ДАННЫМИ (F7)</translation>
    </message>
    <message>
        <source>memory is cleared in УПРАВЛЕНИЕ ДАННЫМИ (F7)</source>
        <translation>memory is cleared in УПРАВЛЕНИЕ ДАННЫМИ (F7)</translation>
    </message>
    <message>
        <source>axis %1 is not present</source>
        <translation>axis %1 is not present</translation>
    </message>
    <message>
        <source>the current value is set in ПРЕДУСТАНОВКИ (F4)</source>
        <translation>the current value is set in ПРЕДУСТАНОВКИ (F4)</translation>
    </message>
    <message>
        <source>the zero offset would leave the 32-bit range</source>
        <translation>the zero offset would leave the 32-bit range</translation>
    </message>
    <message>
        <source>the PLC sets the mode</source>
        <translation>the PLC sets the mode</translation>
    </message>
    <message>
        <source>not in this mode</source>
        <translation>not in this mode</translation>
    </message>
    <message>
        <source>a program is active</source>
        <translation>a program is active</translation>
    </message>
    <message>
        <source>read-only parameter</source>
        <translation>read-only parameter</translation>
    </message>
    <message>
        <source>no such parameter</source>
        <translation>no such parameter</translation>
    </message>
    <message>
        <source>value out of range</source>
        <translation>value out of range</translation>
    </message>
    <message>
        <source>no such program</source>
        <translation>no such program</translation>
    </message>
    <message>
        <source>the axis is not present</source>
        <translation>the axis is not present</translation>
    </message>
    <message>
        <source>no such key</source>
        <translation>no such key</translation>
    </message>
    <message>
        <source>the controller is off</source>
        <translation>the controller is off</translation>
    </message>
</context>
<context>
    <name>k528::studio::RevisionNotes</name>
    <message>
        <source>built-in profile %1 (first start)</source>
        <translation>built-in profile %1 (first start)</translation>
    </message>
    <message>
        <source>created</source>
        <translation>created</translation>
    </message>
    <message>
        <source>set %1</source>
        <translation>set %1</translation>
    </message>
    <message>
        <source>changed %1</source>
        <translation>changed %1</translation>
    </message>
    <message>
        <source>changed %1 and %2 more</source>
        <translation>changed %1 and %2 more</translation>
    </message>
    <message>
        <source>changed order of simulation settings</source>
        <translation>changed order of simulation settings</translation>
    </message>
    <message>
        <source>import %1</source>
        <translation>import %1</translation>
    </message>
    <message>
        <source>import %1 (K528 Studio)</source>
        <translation>import %1 (K528 Studio)</translation>
    </message>
    <message>
        <source>the machine as K528 Studio loaded it</source>
        <translation>the machine as K528 Studio loaded it</translation>
    </message>
    <message>
        <source>kept from the simulated controller's memory (K528 Studio)</source>
        <translation>kept from the simulated controller's memory (K528 Studio)</translation>
    </message>
    <message>
        <source>programs and messages from the editor (K528 Studio)</source>
        <translation>programs and messages from the editor (K528 Studio)</translation>
    </message>
    <message>
        <source>set %1 = %2 (K528 Studio)</source>
        <translation>set %1 = %2 (K528 Studio)</translation>
    </message>
    <message>
        <source>undo: %1</source>
        <translation>undo: %1</translation>
    </message>
    <message>
        <source>presets %1 (K528 Studio)</source>
        <translation>presets %1 (K528 Studio)</translation>
    </message>
    <message>
        <source>trial part: T%1 %2 measured %3 for %4: R%5 %6 -&gt; %7</source>
        <translation>trial part: T%1 %2 measured %3 for %4: R%5 %6 -&gt; %7</translation>
    </message>
    <message>
        <source>constants locked for the class %1 (trainer)</source>
        <translation>constants locked for the class %1 (trainer)</translation>
    </message>
    <message>
        <source>constants unlocked (trainer; were locked for %1)</source>
        <translation>constants unlocked (trainer; were locked for %1)</translation>
    </message>
</context>
<context>
    <name>k528::studio::RuleNames</name>
    <message>
        <source>not UTF-8</source>
        <translation>not UTF-8</translation>
    </message>
    <message>
        <source>unclosed comment</source>
        <translation>unclosed comment</translation>
    </message>
    <message>
        <source>frame syntax</source>
        <translation>frame syntax</translation>
    </message>
    <message>
        <source>Cyrillic letter</source>
        <translation>Cyrillic letter</translation>
    </message>
    <message>
        <source>unknown address</source>
        <translation>unknown address</translation>
    </message>
    <message>
        <source>word given twice</source>
        <translation>word given twice</translation>
    </message>
    <message>
        <source>too many G</source>
        <translation>too many G</translation>
    </message>
    <message>
        <source>too many M</source>
        <translation>too many M</translation>
    </message>
    <message>
        <source>F without an axis</source>
        <translation>F without an axis</translation>
    </message>
    <message>
        <source>bad number</source>
        <translation>bad number</translation>
    </message>
    <message>
        <source>point in an R frame</source>
        <translation>point in an R frame</translation>
    </message>
    <message>
        <source>number out of range</source>
        <translation>number out of range</translation>
    </message>
    <message>
        <source>jump condition</source>
        <translation>jump condition</translation>
    </message>
    <message>
        <source>bad header</source>
        <translation>bad header</translation>
    </message>
    <message>
        <source>program number</source>
        <translation>program number</translation>
    </message>
    <message>
        <source>program given twice</source>
        <translation>program given twice</translation>
    </message>
    <message>
        <source>frame outside a program</source>
        <translation>frame outside a program</translation>
    </message>
    <message>
        <source>message line</source>
        <translation>message line</translation>
    </message>
    <message>
        <source>message number</source>
        <translation>message number</translation>
    </message>
    <message>
        <source>message too long</source>
        <translation>message too long</translation>
    </message>
    <message>
        <source>message given twice</source>
        <translation>message given twice</translation>
    </message>
    <message>
        <source>control character</source>
        <translation>control character</translation>
    </message>
    <message>
        <source>K923 characters</source>
        <translation>K923 characters</translation>
    </message>
    <message>
        <source>frame number</source>
        <translation>frame number</translation>
    </message>
    <message>
        <source>frame number twice</source>
        <translation>frame number twice</translation>
    </message>
    <message>
        <source>too many frames</source>
        <translation>too many frames</translation>
    </message>
    <message>
        <source>empty program</source>
        <translation>empty program</translation>
    </message>
    <message>
        <source>no program</source>
        <translation>no program</translation>
    </message>
    <message>
        <source>coordinate range</source>
        <translation>coordinate range</translation>
    </message>
    <message>
        <source>feed range</source>
        <translation>feed range</translation>
    </message>
    <message>
        <source>unknown G</source>
        <translation>unknown G</translation>
    </message>
    <message>
        <source>G of one group</source>
        <translation>G of one group</translation>
    </message>
    <message>
        <source>M out of range</source>
        <translation>M out of range</translation>
    </message>
    <message>
        <source>M given twice</source>
        <translation>M given twice</translation>
    </message>
    <message>
        <source>message out of range</source>
        <translation>message out of range</translation>
    </message>
    <message>
        <source>message not in the table</source>
        <translation>message not in the table</translation>
    </message>
    <message>
        <source>call out of range</source>
        <translation>call out of range</translation>
    </message>
    <message>
        <source>called program missing</source>
        <translation>called program missing</translation>
    </message>
    <message>
        <source>no such R</source>
        <translation>no such R</translation>
    </message>
    <message>
        <source>read-only R</source>
        <translation>read-only R</translation>
    </message>
    <message>
        <source>division by zero</source>
        <translation>division by zero</translation>
    </message>
    <message>
        <source>R overflow</source>
        <translation>R overflow</translation>
    </message>
    <message>
        <source>jump target</source>
        <translation>jump target</translation>
    </message>
    <message>
        <source>axis with a call</source>
        <translation>axis with a call</translation>
    </message>
    <message>
        <source>axis with M17</source>
        <translation>axis with M17</translation>
    </message>
    <message>
        <source>axis at the end of L</source>
        <translation>axis at the end of L</translation>
    </message>
    <message>
        <source>two ends in a frame</source>
        <translation>two ends in a frame</translation>
    </message>
    <message>
        <source>G04 with Z</source>
        <translation>G04 with Z</translation>
    </message>
    <message>
        <source>G04 with a call</source>
        <translation>G04 with a call</translation>
    </message>
    <message>
        <source>negative dwell</source>
        <translation>negative dwell</translation>
    </message>
    <message>
        <source>G04 without time</source>
        <translation>G04 without time</translation>
    </message>
    <message>
        <source>G without its axis</source>
        <translation>G without its axis</translation>
    </message>
    <message>
        <source>unreachable frame</source>
        <translation>unreachable frame</translation>
    </message>
    <message>
        <source>calls in a circle</source>
        <translation>calls in a circle</translation>
    </message>
    <message>
        <source>nesting too deep</source>
        <translation>nesting too deep</translation>
    </message>
    <message>
        <source>no such axis</source>
        <translation>no such axis</translation>
    </message>
    <message>
        <source>software limit</source>
        <translation>software limit</translation>
    </message>
    <message>
        <source>feed above maximum</source>
        <translation>feed above maximum</translation>
    </message>
    <message>
        <source>rounded to a discrete</source>
        <translation>rounded to a discrete</translation>
    </message>
    <message>
        <source>rapid into material</source>
        <translation>rapid into material</translation>
    </message>
    <message>
        <source>tool into chuck</source>
        <translation>tool into chuck</translation>
    </message>
    <message>
        <source>turret into chuck</source>
        <translation>turret into chuck</translation>
    </message>
    <message>
        <source>feed, spindle stopped</source>
        <translation>feed, spindle stopped</translation>
    </message>
    <message>
        <source>feed, wheel stopped</source>
        <translation>feed, wheel stopped</translation>
    </message>
    <message>
        <source>cut too deep</source>
        <translation>cut too deep</translation>
    </message>
    <message>
        <source>manual move into material</source>
        <translation>manual move into material</translation>
    </message>
</context>
<context>
    <name>k528::studio::ScopeView</name>
    <message>
        <source>Export CSV</source>
        <translation>Export CSV</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Cannot write %1</source>
        <translation>Cannot write %1</translation>
    </message>
    <message>
        <source>Export PNG</source>
        <translation>Export PNG</translation>
    </message>
    <message>
        <source>PNG (*.png)</source>
        <translation>PNG (*.png)</translation>
    </message>
    <message>
        <source>%1  t = %2 s  setpoint %3 mm  position %4 mm  speed %5 mm/min  following error %6 mm  DAC %7</source>
        <translation>%1  t = %2 s  setpoint %3 mm  position %4 mm  speed %5 mm/min  following error %6 mm  DAC %7</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Window, s</source>
        <translation>Window, s</translation>
    </message>
    <message>
        <source>Fourth trace</source>
        <translation>Fourth trace</translation>
    </message>
    <message>
        <source>Speed, mm/min</source>
        <translation>Speed, mm/min</translation>
    </message>
    <message>
        <source>DAC code</source>
        <translation>DAC code</translation>
    </message>
    <message>
        <source>Trigger</source>
        <translation>Trigger</translation>
    </message>
    <message>
        <source>Free running</source>
        <translation>Free running</translation>
    </message>
    <message>
        <source>Frame start</source>
        <translation>Frame start</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <source>|Following error| over, mm</source>
        <translation>|Following error| over, mm</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>Export CSV…</translation>
    </message>
    <message>
        <source>Export PNG…</source>
        <translation>Export PNG…</translation>
    </message>
    <message>
        <source>Move the mouse over a chart to read the values.</source>
        <translation>Move the mouse over a chart to read the values.</translation>
    </message>
    <message>
        <source>Oscilloscope</source>
        <translation>Oscilloscope</translation>
    </message>
    <message>
        <source>Time before the newest sample, s</source>
        <translation>Time before the newest sample, s</translation>
    </message>
    <message>
        <source>Setpoint, mm</source>
        <translation>Setpoint, mm</translation>
    </message>
    <message>
        <source>Position, mm</source>
        <translation>Position, mm</translation>
    </message>
    <message>
        <source>Following error, mm (right scale)</source>
        <translation>Following error, mm (right scale)</translation>
    </message>
    <message>
        <source>DAC code (right scale)</source>
        <translation>DAC code (right scale)</translation>
    </message>
    <message>
        <source>Speed, mm/min (right scale)</source>
        <translation>Speed, mm/min (right scale)</translation>
    </message>
    <message>
        <source>Axis X</source>
        <translation>Axis X</translation>
    </message>
    <message>
        <source>Axis Z</source>
        <translation>Axis Z</translation>
    </message>
    <message>
        <source>Live at %1 samples a second: the link's poll of the controller's positions and following errors (the setpoint is position + error; no DAC on the link).</source>
        <translation>Live at %1 samples a second: the link's poll of the controller's positions and following errors (the setpoint is position + error; no DAC on the link).</translation>
    </message>
    <message>
        <source>Every servo tick of the simulated machine (%1 samples a second).</source>
        <translation>Every servo tick of the simulated machine (%1 samples a second).</translation>
    </message>
    <message>
        <source>The link's map carries no DAC code: the simulated machine's only</source>
        <translation>The link's map carries no DAC code: the simulated machine's only</translation>
    </message>
</context>
<context>
    <name>k528::studio::SetupSheetActions</name>
    <message>
        <source>Open a program file in the editor: its setup sheet is made on the machine it is checked for.</source>
        <translation>Open a program file in the editor: its setup sheet is made on the machine it is checked for.</translation>
    </message>
    <message>
        <source>The file is checked for no machine: choose one (Editor menu) for its setup sheet.</source>
        <translation>The file is checked for no machine: choose one (Editor menu) for its setup sheet.</translation>
    </message>
    <message>
        <source>The file has errors (Problems): its setup sheet is made once they are fixed.</source>
        <translation>The file has errors (Problems): its setup sheet is made once they are fixed.</translation>
    </message>
    <message>
        <source>The setup sheet cannot be made: %1</source>
        <translation>The setup sheet cannot be made: %1</translation>
    </message>
    <message>
        <source>Setup sheet written to %1</source>
        <translation>Setup sheet written to %1</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Cannot write %1: %2</translation>
    </message>
    <message>
        <source>Export the setup sheet</source>
        <translation>Export the setup sheet</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Setup sheet</source>
        <translation>Setup sheet</translation>
    </message>
    <message>
        <source>Setup sheet: %1</source>
        <translation>Setup sheet: %1</translation>
    </message>
</context>
<context>
    <name>k528::studio::ShopDatabase</name>
    <message>
        <source>The database %1 failed: %2.</source>
        <translation>The database %1 failed: %2.</translation>
    </message>
    <message>
        <source>The database %1 failed: %2.
Details: %3</source>
        <translation>The database %1 failed: %2.
Details: %3</translation>
    </message>
</context>
<context>
    <name>k528::studio::ShopTile</name>
    <message>
        <source>Mode %1</source>
        <translation>Mode %1</translation>
    </message>
    <message>
        <source>, running</source>
        <translation>, running</translation>
    </message>
    <message>
        <source>Program L%1, frame N%2</source>
        <translation>Program L%1, frame N%2</translation>
    </message>
    <message>
        <source>No program</source>
        <translation>No program</translation>
    </message>
    <message>
        <source>Alarm (no number)</source>
        <translation>Alarm (no number)</translation>
    </message>
    <message>
        <source>The line does not answer</source>
        <translation>The line does not answer</translation>
    </message>
    <message>
        <source>Last answer at %1</source>
        <translation>Last answer at %1</translation>
    </message>
    <message>
        <source>No answer yet</source>
        <translation>No answer yet</translation>
    </message>
    <message>
        <source>Polling...</source>
        <translation>Polling...</translation>
    </message>
    <message>
        <source>No transfer on record</source>
        <translation>No transfer on record</translation>
    </message>
    <message>
        <source>Last transfer: %1</source>
        <translation>Last transfer: %1</translation>
    </message>
    <message>
        <source>Click: show this machine's controller on every view of the window</source>
        <translation>Click: show this machine's controller on every view of the window</translation>
    </message>
    <message>
        <source>%1 in this state, since %2</source>
        <translation>%1 in this state, since %2</translation>
    </message>
</context>
<context>
    <name>k528::studio::ShopView</name>
    <message>
        <source>run</source>
        <translation>run</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>idle</translation>
    </message>
    <message>
        <source>alarm</source>
        <translation>alarm</translation>
    </message>
    <message>
        <source>offline</source>
        <translation>offline</translation>
    </message>
    <message>
        <source>%1 d %2:%3</source>
        <translation>%1 d %2:%3</translation>
    </message>
    <message>
        <source>alarm %1</source>
        <translation>alarm %1</translation>
    </message>
    <message>
        <source>power-on</source>
        <translation>power-on</translation>
    </message>
    <message>
        <source>Reload</source>
        <translation>Reload</translation>
    </message>
    <message>
        <source>Read the database's machines and their lines again</source>
        <translation>Read the database's machines and their lines again</translation>
    </message>
    <message>
        <source>Alarms raised and cleared</source>
        <translation>Alarms raised and cleared</translation>
    </message>
    <message>
        <source>Today: minutes in each state</source>
        <translation>Today: minutes in each state</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Time</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Machine</translation>
    </message>
    <message>
        <source>Event</source>
        <translation>Event</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <source>minutes</source>
        <translation>minutes</translation>
    </message>
    <message>
        <source>The database cannot be read: %1</source>
        <translation>The database cannot be read: %1</translation>
    </message>
    <message>
        <source>No machine of the database %1 keeps its controller's line: set a machine's line (Modbus TCP or serial) in the database to see it here.</source>
        <translation>No machine of the database %1 keeps its controller's line: set a machine's line (Modbus TCP or serial) in the database to see it here.</translation>
    </message>
    <message>
        <source>Machines of the database %1 on their lines: %2; each line polled every %3 ms</source>
        <translation>Machines of the database %1 on their lines: %2; each line polled every %3 ms</translation>
    </message>
    <message>
        <source>push</source>
        <translation>push</translation>
    </message>
    <message>
        <source>pull</source>
        <translation>pull</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <source>partial</source>
        <translation>partial</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>failed</translation>
    </message>
    <message>
        <source>%1 %2, %3</source>
        <translation>%1 %2, %3</translation>
    </message>
    <message>
        <source>The machines cannot be polled: %1</source>
        <translation>The machines cannot be polled: %1</translation>
    </message>
    <message>
        <source>raised</source>
        <translation>raised</translation>
    </message>
    <message>
        <source>cleared</source>
        <translation>cleared</translation>
    </message>
    <message>
        <source>The controller of %1 cannot be shown now: the Controller dock's line is busy</source>
        <translation>The controller of %1 cannot be shown now: the Controller dock's line is busy</translation>
    </message>
    <message>
        <source>Connecting to the controller of %1...</source>
        <translation>Connecting to the controller of %1...</translation>
    </message>
    <message>
        <source>Publish to MQTT</source>
        <translation>Publish to MQTT</translation>
    </message>
    <message>
        <source>Every machine's state (retained) and each alarm raised or cleared to the MQTT broker, in the topics of k528 shop publish (k528/&lt;machine&gt;/state, k528/&lt;machine&gt;/alarms); the machines are polled while this is on, whatever page is shown</source>
        <translation>Every machine's state (retained) and each alarm raised or cleared to the MQTT broker, in the topics of k528 shop publish (k528/&lt;machine&gt;/state, k528/&lt;machine&gt;/alarms); the machines are polled while this is on, whatever page is shown</translation>
    </message>
    <message>
        <source>Broker</source>
        <translation>Broker</translation>
    </message>
    <message>
        <source>Connecting to the broker...</source>
        <translation>Connecting to the broker...</translation>
    </message>
    <message>
        <source>Publishing as %1</source>
        <translation>Publishing as %1</translation>
    </message>
    <message>
        <source>Not publishing: the broker cannot be reached (see the tool tip)</source>
        <translation>Not publishing: the broker cannot be reached (see the tool tip)</translation>
    </message>
</context>
<context>
    <name>k528::studio::SimulatedController</name>
    <message>
        <source>simulated %1</source>
        <translation>simulated %1</translation>
    </message>
</context>
<context>
    <name>k528::studio::SystemTexts</name>
    <message>
        <source>cannot open %1: %2</source>
        <translation>cannot open %1: %2</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>cannot read %1: %2</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>cannot write %1: %2</translation>
    </message>
    <message>
        <source>cannot read standard input: %1</source>
        <translation>cannot read standard input: %1</translation>
    </message>
    <message>
        <source>cannot write standard output: %1</source>
        <translation>cannot write standard output: %1</translation>
    </message>
    <message>
        <source>it is a directory</source>
        <translation>it is a directory</translation>
    </message>
    <message>
        <source>it is %1, not a regular file (k528 reads program and machine files only)</source>
        <translation>it is %1, not a regular file (k528 reads program and machine files only)</translation>
    </message>
    <message>
        <source>a directory</source>
        <translation>a directory</translation>
    </message>
    <message>
        <source>a character device</source>
        <translation>a character device</translation>
    </message>
    <message>
        <source>a block device</source>
        <translation>a block device</translation>
    </message>
    <message>
        <source>a FIFO (named pipe)</source>
        <translation>a FIFO (named pipe)</translation>
    </message>
    <message>
        <source>a socket</source>
        <translation>a socket</translation>
    </message>
    <message>
        <source>a special file</source>
        <translation>a special file</translation>
    </message>
    <message>
        <source>it is larger than %1 MiB, the most k528 reads (a K528-05 holds at most 99 programs of 999 frames, about 3 MB of text)</source>
        <translation>it is larger than %1 MiB, the most k528 reads (a K528-05 holds at most 99 programs of 999 frames, about 3 MB of text)</translation>
    </message>
    <message>
        <source>not enough memory</source>
        <translation>not enough memory</translation>
    </message>
    <message>
        <source>it is a directory; give a file name</source>
        <translation>it is a directory; give a file name</translation>
    </message>
    <message>
        <source>it is not a regular file, a FIFO or a character device</source>
        <translation>it is not a regular file, a FIFO or a character device</translation>
    </message>
    <message>
        <source>cannot create a file in its folder %1: %2</source>
        <translation>cannot create a file in its folder %1: %2</translation>
    </message>
    <message>
        <source>it is not open</source>
        <translation>it is not open</translation>
    </message>
    <message>
        <source>a write failed</source>
        <translation>a write failed</translation>
    </message>
    <message>
        <source>'%1' is not mqtt://HOST[:PORT] (plain MQTT; TLS is not supported)</source>
        <translation>'%1' is not mqtt://HOST[:PORT] (plain MQTT; TLS is not supported)</translation>
    </message>
    <message>
        <source>'%1': the port is 1..65535</source>
        <translation>'%1': the port is 1..65535</translation>
    </message>
    <message>
        <source>'%1': no host name or address after mqtt://</source>
        <translation>'%1': no host name or address after mqtt://</translation>
    </message>
    <message>
        <source>Operation not permitted</source>
        <translation>Operation not permitted</translation>
    </message>
    <message>
        <source>No such file or directory</source>
        <translation>No such file or directory</translation>
    </message>
    <message>
        <source>Interrupted system call</source>
        <translation>Interrupted system call</translation>
    </message>
    <message>
        <source>Input/output error</source>
        <translation>Input/output error</translation>
    </message>
    <message>
        <source>No such device or address</source>
        <translation>No such device or address</translation>
    </message>
    <message>
        <source>Bad file descriptor</source>
        <translation>Bad file descriptor</translation>
    </message>
    <message>
        <source>Resource temporarily unavailable</source>
        <translation>Resource temporarily unavailable</translation>
    </message>
    <message>
        <source>Cannot allocate memory</source>
        <translation>Cannot allocate memory</translation>
    </message>
    <message>
        <source>Permission denied</source>
        <translation>Permission denied</translation>
    </message>
    <message>
        <source>Device or resource busy</source>
        <translation>Device or resource busy</translation>
    </message>
    <message>
        <source>File exists</source>
        <translation>File exists</translation>
    </message>
    <message>
        <source>Invalid cross-device link</source>
        <translation>Invalid cross-device link</translation>
    </message>
    <message>
        <source>No such device</source>
        <translation>No such device</translation>
    </message>
    <message>
        <source>Not a directory</source>
        <translation>Not a directory</translation>
    </message>
    <message>
        <source>Is a directory</source>
        <translation>Is a directory</translation>
    </message>
    <message>
        <source>Invalid argument</source>
        <translation>Invalid argument</translation>
    </message>
    <message>
        <source>Too many open files in system</source>
        <translation>Too many open files in system</translation>
    </message>
    <message>
        <source>Too many open files</source>
        <translation>Too many open files</translation>
    </message>
    <message>
        <source>Text file busy</source>
        <translation>Text file busy</translation>
    </message>
    <message>
        <source>File too large</source>
        <translation>File too large</translation>
    </message>
    <message>
        <source>No space left on device</source>
        <translation>No space left on device</translation>
    </message>
    <message>
        <source>Illegal seek</source>
        <translation>Illegal seek</translation>
    </message>
    <message>
        <source>Read-only file system</source>
        <translation>Read-only file system</translation>
    </message>
    <message>
        <source>Too many links</source>
        <translation>Too many links</translation>
    </message>
    <message>
        <source>Broken pipe</source>
        <translation>Broken pipe</translation>
    </message>
    <message>
        <source>File name too long</source>
        <translation>File name too long</translation>
    </message>
    <message>
        <source>Too many levels of symbolic links</source>
        <translation>Too many levels of symbolic links</translation>
    </message>
    <message>
        <source>Directory not empty</source>
        <translation>Directory not empty</translation>
    </message>
    <message>
        <source>Disk quota exceeded</source>
        <translation>Disk quota exceeded</translation>
    </message>
    <message>
        <source>Stale file handle</source>
        <translation>Stale file handle</translation>
    </message>
    <message>
        <source>Value too large for defined data type</source>
        <translation>Value too large for defined data type</translation>
    </message>
    <message>
        <source>Operation not supported</source>
        <translation>Operation not supported</translation>
    </message>
    <message>
        <source>Connection refused</source>
        <translation>Connection refused</translation>
    </message>
    <message>
        <source>Connection timed out</source>
        <translation>Connection timed out</translation>
    </message>
    <message>
        <source>%2 (error %1)</source>
        <translation>%2 (error %1)</translation>
    </message>
</context>
<context>
    <name>k528::studio::TeachIn</name>
    <message>
        <source>Open a program file in the editor to teach a position into it</source>
        <translation>Open a program file in the editor to teach a position into it</translation>
    </message>
    <message>
        <source>No controller is viewed: no position to teach</source>
        <translation>No controller is viewed: no position to teach</translation>
    </message>
    <message>
        <source>The viewed controller has no axes: no position to teach</source>
        <translation>The viewed controller has no axes: no position to teach</translation>
    </message>
    <message>
        <source>Taught: %1</source>
        <translation>Taught: %1</translation>
    </message>
    <message>
        <source>The viewed controller has no axis %1</source>
        <translation>The viewed controller has no axis %1</translation>
    </message>
    <message>
        <source>Taught: %1 (%2 mm)</source>
        <translation>Taught: %1 (%2 mm)</translation>
    </message>
</context>
<context>
    <name>k528::studio::TrainingPane</name>
    <message>
        <source>Nothing is machined in this exercise</source>
        <translation>Nothing is machined in this exercise</translation>
    </message>
    <message>
        <source>Exercise:</source>
        <translation>Exercise:</translation>
    </message>
    <message>
        <source>Student:</source>
        <translation>Student:</translation>
    </message>
    <message>
        <source>the student's name</source>
        <translation>the student's name</translation>
    </message>
    <message>
        <source>Grade the editor's program</source>
        <translation>Grade the editor's program</translation>
    </message>
    <message>
        <source>Runs the editor's program on a simulated machine of its own as the operator would and grades the part</source>
        <translation>Runs the editor's program on a simulated machine of its own as the operator would and grades the part</translation>
    </message>
    <message>
        <source>Grade a file…</source>
        <translation>Grade a file…</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>Export CSV</translation>
    </message>
    <message>
        <source>Task</source>
        <translation>Task</translation>
    </message>
    <message>
        <source>Attempt</source>
        <translation>Attempt</translation>
    </message>
    <message>
        <source>Class</source>
        <translation>Class</translation>
    </message>
    <message>
        <source>Student</source>
        <translation>Student</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Exercise</translation>
    </message>
    <message>
        <source>Score</source>
        <translation>Score</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Result</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Time</translation>
    </message>
    <message>
        <source>passed</source>
        <translation>passed</translation>
    </message>
    <message>
        <source>not passed</source>
        <translation>not passed</translation>
    </message>
    <message>
        <source>Cycle time at most %1 s</source>
        <translation>Cycle time at most %1 s</translation>
    </message>
    <message>
        <source>The drawing: the half profile below, black; its tolerance limits dashed</source>
        <translation>The drawing: the half profile below, black; its tolerance limits dashed</translation>
    </message>
    <message>
        <source>The drawing: bore Ø%1, %2/%3 mm</source>
        <translation>The drawing: bore Ø%1, %2/%3 mm</translation>
    </message>
    <message>
        <source>The drawing: the part the reference program makes, ±%1 mm</source>
        <translation>The drawing: the part the reference program makes, ±%1 mm</translation>
    </message>
    <message>
        <source>Hint:</source>
        <translation>Hint:</translation>
    </message>
    <message>
        <source>No attempt graded yet: write the program in the editor, then «Grade the editor's program»</source>
        <translation>No attempt graded yet: write the program in the editor, then «Grade the editor's program»</translation>
    </message>
    <message>
        <source>%1: %2/100, %3</source>
        <translation>%1: %2/100, %3</translation>
    </message>
    <message>
        <source>cycle time %1 s</source>
        <translation>cycle time %1 s</translation>
    </message>
    <message>
        <source>(limit %1 s)</source>
        <translation>(limit %1 s)</translation>
    </message>
    <message>
        <source>line %1 «%2»: %3</source>
        <translation>line %1 «%2»: %3</translation>
    </message>
    <message>
        <source>No deductions</source>
        <translation>No deductions</translation>
    </message>
    <message>
        <source>The editor holds no program: open the student's file in the editor or use «Grade a file…»</source>
        <translation>The editor holds no program: open the student's file in the editor or use «Grade a file…»</translation>
    </message>
    <message>
        <source>the editor's program</source>
        <translation>the editor's program</translation>
    </message>
    <message>
        <source>The student's program</source>
        <translation>The student's program</translation>
    </message>
    <message>
        <source>K528 programs (*.k528 *.txt);;All files (*)</source>
        <translation>K528 programs (*.k528 *.txt);;All files (*)</translation>
    </message>
    <message>
        <source>Training</source>
        <translation>Training</translation>
    </message>
    <message>
        <source>Grading: the program runs on the simulated machine…</source>
        <translation>Grading: the program runs on the simulated machine…</translation>
    </message>
    <message>
        <source>The attempt could not be graded: %1</source>
        <translation>The attempt could not be graded: %1</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Cannot write %1: %2</translation>
    </message>
    <message>
        <source>Training course</source>
        <translation>Training course</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Refresh</translation>
    </message>
    <message>
        <source>Reads the class's attempts from the database again</source>
        <translation>Reads the class's attempts from the database again</translation>
    </message>
    <message>
        <source>Not kept in the database: %1</source>
        <translation>Not kept in the database: %1</translation>
    </message>
    <message>
        <source>The database cannot be read: only this session's attempts are listed (%1)</source>
        <translation>The database cannot be read: only this session's attempts are listed (%1)</translation>
    </message>
    <message>
        <source>Export PDF</source>
        <translation>Export PDF</translation>
    </message>
    <message>
        <source>The class report as PDF: each attempt with its score and deductions</source>
        <translation>The class report as PDF: each attempt with its score and deductions</translation>
    </message>
    <message>
        <source>Training course: class report</source>
        <translation>Training course: class report</translation>
    </message>
    <message>
        <source>Attempts: %1; printed %2</source>
        <translation>Attempts: %1; printed %2</translation>
    </message>
    <message>
        <source>File</source>
        <translation>File</translation>
    </message>
    <message>
        <source>Cycle time, s</source>
        <translation>Cycle time, s</translation>
    </message>
    <message>
        <source>Deductions</source>
        <translation>Deductions</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Lock the constants…</source>
        <translation>Lock the constants…</translation>
    </message>
    <message>
        <source>Unlock the constants</source>
        <translation>Unlock the constants</translation>
    </message>
    <message>
        <source>Lets the machine constants be changed again</source>
        <translation>Lets the machine constants be changed again</translation>
    </message>
    <message>
        <source>The machine constants are locked for the class «%1»</source>
        <translation>The machine constants are locked for the class «%1»</translation>
    </message>
    <message>
        <source>Locks the machine constants for a class: the constants dock and the K923 refuse changes until you unlock them (kept in the database)</source>
        <translation>Locks the machine constants for a class: the constants dock and the K923 refuse changes until you unlock them (kept in the database)</translation>
    </message>
    <message>
        <source>The machine constants may be changed</source>
        <translation>The machine constants may be changed</translation>
    </message>
    <message>
        <source>No machine</source>
        <translation>No machine</translation>
    </message>
    <message>
        <source>Lock the machine constants</source>
        <translation>Lock the machine constants</translation>
    </message>
    <message>
        <source>The class the constants are locked for:</source>
        <translation>The class the constants are locked for:</translation>
    </message>
</context>
<context>
    <name>k528::studio::TrialPartDialog</name>
    <message>
        <source>Trial part: correct a tool's offset</source>
        <translation>Trial part: correct a tool's offset</translation>
    </message>
    <message>
        <source>X: a diameter</source>
        <translation>X: a diameter</translation>
    </message>
    <message>
        <source>Z: a length</source>
        <translation>Z: a length</translation>
    </message>
    <message>
        <source>X of this machine shows a diameter: the offset changes by the diameter's error.</source>
        <translation>X of this machine shows a diameter: the offset changes by the diameter's error.</translation>
    </message>
    <message>
        <source>X of this machine shows a radius: the offset changes by half the diameter's error.</source>
        <translation>X of this machine shows a radius: the offset changes by half the diameter's error.</translation>
    </message>
    <message>
        <source>A size that came out larger than the drawing's was cut with too large an offset: the new offset is the old one minus the error.</source>
        <translation>A size that came out larger than the drawing's was cut with too large an offset: the new offset is the old one minus the error.</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Tool</translation>
    </message>
    <message>
        <source>Measured on</source>
        <translation>Measured on</translation>
    </message>
    <message>
        <source>Measured, mm</source>
        <translation>Measured, mm</translation>
    </message>
    <message>
        <source>Drawing, mm</source>
        <translation>Drawing, mm</translation>
    </message>
    <message>
        <source>Keep as the preset</source>
        <translation>Keep as the preset</translation>
    </message>
    <message>
        <source>The new offset becomes the machine's preset (its next revision in the database, the measurement as its note) and goes into the controller</source>
        <translation>The new offset becomes the machine's preset (its next revision in the database, the measurement as its note) and goes into the controller</translation>
    </message>
    <message>
        <source>The machine's tools are not described (tool.N.* of its settings).</source>
        <translation>The machine's tools are not described (tool.N.* of its settings).</translation>
    </message>
    <message>
        <source>Error %1 mm: R%2 %3 → %4 (offset %5 mm)</source>
        <translation>Error %1 mm: R%2 %3 → %4 (offset %5 mm)</translation>
    </message>
    <message>
        <source>Enter the size measured on the trial part and the drawing's size.</source>
        <translation>Enter the size measured on the trial part and the drawing's size.</translation>
    </message>
</context>
<context>
    <name>k528::studio::Workspaces</name>
    <message>
        <source>&amp;Workspace</source>
        <translation>&amp;Workspace</translation>
    </message>
    <message>
        <source>&amp;Reset layout</source>
        <translation>&amp;Reset layout</translation>
    </message>
    <message>
        <source>The current workspace's docks where they were at first</source>
        <translation>The current workspace's docks where they were at first</translation>
    </message>
    <message>
        <source>Workspace: the window arranged for its user</source>
        <translation>Workspace: the window arranged for its user</translation>
    </message>
    <message>
        <source>Operator</source>
        <translation>Operator</translation>
    </message>
    <message>
        <source>At the machine: the K923, the machine's panel, the program being run, the messages and the axes</source>
        <translation>At the machine: the K923, the machine's panel, the program being run, the messages and the axes</translation>
    </message>
    <message>
        <source>Technologist</source>
        <translation>Technologist</translation>
    </message>
    <message>
        <source>Programs: the editor with its problems and outline, the backplot; the debugger and the controller from the View menu</source>
        <translation>Programs: the editor with its problems and outline, the backplot; the debugger and the controller from the View menu</translation>
    </message>
    <message>
        <source>Training</source>
        <translation>Training</translation>
    </message>
    <message>
        <source>Learning the machine: the machine's panel, the K923, the backplot and the oscilloscope</source>
        <translation>Learning the machine: the machine's panel, the K923, the backplot and the oscilloscope</translation>
    </message>
    <message>
        <source>Shop</source>
        <translation>Shop</translation>
    </message>
    <message>
        <source>The shop floor: a tile per machine of the database on its line, the alarms as they come, today's time in each state; the controller of the machine clicked beside it</source>
        <translation>The shop floor: a tile per machine of the database on its line, the alarms as they come, today's time in each state; the controller of the machine clicked beside it</translation>
    </message>
</context>
<context>
    <name>k528::studio::backplot::BackplotDock</name>
    <message>
        <source>Backplot</source>
        <translation>Backplot</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>Programmed path</source>
        <translation>Programmed path</translation>
    </message>
    <message>
        <source>Simulate run</source>
        <translation>Simulate run</translation>
    </message>
    <message>
        <source>Run the program on the simulated machine and overlay the actual path, coloured by following error</source>
        <translation>Run the program on the simulated machine and overlay the actual path, coloured by following error</translation>
    </message>
    <message>
        <source>Blank (UCG)</source>
        <translation>Blank (UCG)</translation>
    </message>
    <message>
        <source>The backplot needs OpenGL (an X display)</source>
        <translation>The backplot needs OpenGL (an X display)</translation>
    </message>
    <message>
        <source>Follow the machine</source>
        <translation>Follow the machine</translation>
    </message>
    <message>
        <source>The actual path grows from the controller's live positions, read %1 times a second; a program's path once its text is read from the controller.</source>
        <translation>The actual path grows from the controller's live positions, read %1 times a second; a program's path once its text is read from the controller.</translation>
    </message>
    <message>
        <source>Reading L%1 from the controller for its path...</source>
        <translation>Reading L%1 from the controller for its path...</translation>
    </message>
    <message>
        <source>While the controller shown runs a program, its path grows here live</source>
        <translation>While the controller shown runs a program, its path grows here live</translation>
    </message>
</context>
<context>
    <name>k528::studio::backplot::BackplotWidget</name>
    <message>
        <source>Fit</source>
        <translation>Fit</translation>
    </message>
    <message>
        <source>Show the whole path (middle button pans, the wheel zooms)</source>
        <translation>Show the whole path (middle button pans, the wheel zooms)</translation>
    </message>
    <message>
        <source>XZ view</source>
        <translation>XZ view</translation>
    </message>
    <message>
        <source>3D view</source>
        <translation>3D view</translation>
    </message>
    <message>
        <source>fastest</source>
        <translation>fastest</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Play</translation>
    </message>
    <message>
        <source>Previous frame</source>
        <translation>Previous frame</translation>
    </message>
    <message>
        <source>Next frame</source>
        <translation>Next frame</translation>
    </message>
    <message>
        <source>Beyond the software limits</source>
        <translation>Beyond the software limits</translation>
    </message>
    <message>
        <source>Click a segment to find its frame</source>
        <translation>Click a segment to find its frame</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>line %1</translation>
    </message>
    <message>
        <source>L%1 N%2, line %3</source>
        <translation>L%1 N%2, line %3</translation>
    </message>
    <message>
        <source>No segment here</source>
        <translation>No segment here</translation>
    </message>
    <message>
        <source>%1 segments</source>
        <translation>%1 segments</translation>
    </message>
    <message>
        <source>X ⌀ diameter</source>
        <translation>X ⌀ diameter</translation>
    </message>
    <message>
        <source>X radius</source>
        <translation>X radius</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <source>Stop computing the path (the view keeps what it shows)</source>
        <translation>Stop computing the path (the view keeps what it shows)</translation>
    </message>
    <message>
        <source>L%1: computing the path… %2 frames</source>
        <translation>L%1: computing the path… %2 frames</translation>
    </message>
    <message>
        <source>L%1: cutting the blank… %2 of %3 moves</source>
        <translation>L%1: cutting the blank… %2 of %3 moves</translation>
    </message>
    <message>
        <source>L%1 does not end within %2 frames (an endless loop?): the path shows those frames</source>
        <translation>L%1 does not end within %2 frames (an endless loop?): the path shows those frames</translation>
    </message>
    <message>
        <source>L%1: the path was not computed (cancelled)</source>
        <translation>L%1: the path was not computed (cancelled)</translation>
    </message>
    <message>
        <source>L%1: simulating the run…</source>
        <translation>L%1: simulating the run…</translation>
    </message>
    <message>
        <source>µm</source>
        <translation>µm</translation>
    </message>
</context>
<context>
    <name>k528::studio::backplot::VtkGlWidget</name>
    <message>
        <source>No OpenGL context for the backplot</source>
        <translation>No OpenGL context for the backplot</translation>
    </message>
</context>
</TS>