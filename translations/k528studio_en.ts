<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
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
    <name>k528::studio</name>
    <message>
        <source>%1 cannot be read: %2</source>
        <translation>%1 cannot be read: %2</translation>
    </message>
    <message>
        <source>%1 has errors: nothing was loaded.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>%1 holds no program.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>A program is running: stop it (RESET) before loading programs.</source>
        <translation type="unfinished" />
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
        <translation type="unfinished" />
    </message>
    <message>
        <source>Machine, mm</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Rest, mm</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Feed, mm/min</source>
        <translation>Feed, mm/min</translation>
    </message>
    <message>
        <source>Error, µm</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>DAC</source>
        <translation>DAC</translation>
    </message>
    <message>
        <source>Volts</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source> (dia.)</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>absent</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>homing</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>homed</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>not homed</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>loop closed</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>loop open</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>moving</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>in position</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>cam</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>limit +</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>limit -</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>fault %1</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Z1000 PLC→</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>E-stop released</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>feed enable</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>start enable</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>start</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>stop</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>reset</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>data hold</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>acknowledge</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>M done</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>mode %1</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Z2000 →PLC</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>ready</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>running</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>interrupted</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>end/reset</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>dwell</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>M00</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>override 0%</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>change wheel</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Z2001</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>M strobe</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>M code %1</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>cycle %1</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>regulator</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>feed</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>jog +</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>jog -</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>rapid</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>loop</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>loop error</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>fast inputs </source>
        <translation type="unfinished" />
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
        <source>%1 cannot be read: %2</source>
        <translation>%1 cannot be read: %2</translation>
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
        <source>No.</source>
        <translation>No.</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Message</translation>
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
        <source>Operand a (number or R…)</source>
        <translation>Operand a (number or R…)</translation>
    </message>
    <message>
        <source>Operand b (number or R…)</source>
        <translation>Operand b (number or R…)</translation>
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
        <source>a: a whole number or R…</source>
        <translation>a: a whole number or R…</translation>
    </message>
    <message>
        <source>b: a whole number or R…</source>
        <translation>b: a whole number or R…</translation>
    </message>
    <message>
        <source>R: the number of the R-parameter written</source>
        <translation>R: the number of the R-parameter written</translation>
    </message>
    <message>
        <source>R: the number of the R-parameter tested</source>
        <translation>R: the number of the R-parameter tested</translation>
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
</context>
<context>
    <name>k528::studio::K923Keys</name>
    <message>
        <source>Mode AUTOMATIC: the machine works by the control program.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Mode MANUAL: the machine's push-buttons and handwheels move the axes; R-parameters can be edited.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Mode REFERENCE POINT: the homing cycle ties the axes to the machine.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Mode PRESETS: technological parameters of the machine in groups.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Mode MACHINE CONSTANTS: editing the C-parameters (password).</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Mode PROGRAM EDITING: editing the control programs (password).</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Mode DATA MANAGEMENT: clearing memory and working with the PC (password).</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Mode key F8: the K528-05 has no eighth mode.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>The key opens the main screen of the mode.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Machine function key K%1. The PLC program of the machine gives it its function: pressing sets Z1300.%2. Its LED is green by Z1906.%2, red by Z1907.%2, amber by both.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Feed override key L%1: selects the override whose code machine constant C%2 holds (codes 0–10 = 0…100 %). Its LED shows the override key in effect.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Digit %1.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Moves the marker up to the previous parameter or line.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Moves the marker down to the next parameter or line.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Moves the marker left; in the axis screens, to the other axis.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Moves the marker right; in the axis screens, to the other axis.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Pages through the screens of the current mode.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Enters the service screens (messages, faults, system, diagnostics) and returns from them.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>As the machine constants set it: cancels editing a parameter, resets the system, acknowledges error and fault messages.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Switches keys with two functions to their second one: press SHIFT, then the key. The LED shows SHIFT engaged; pressing SHIFT again releases it.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Goes to choosing a parameter by its number, and back.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Enters the number of the program for automatic mode; in the program editor, inserts a computing or jump frame.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Inserts a new standard frame after the current one (program editor).</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Deletes a program, a frame or the value of a parameter.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Enters the typed value.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Decimal point.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Addition.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Subtraction; the minus sign.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Multiplication.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Division.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Assigns the result.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Types the letter R (R-parameters).</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Sets or clears the skip mark «/» of a frame (program editor).</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>SHIFT+▲: three lines up; in the program editor, the previous frame.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>SHIFT+▼: three lines down; in the program editor, the next frame.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>%1 (latches like a click); or hold Shift with the other key</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>PC keyboard:</source>
        <translation type="unfinished" />
    </message>
</context>
<context>
    <name>k528::studio::K923Widget</name>
    <message>
        <source>Keyboard map…</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Copy the LCD text</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>LCD: yellow-green backlight</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>LCD: blue backlight</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>The K923 operator panel. Click it to work it from the PC keyboard too (each key's tooltip names its PC key; Tab leaves the panel). Right-click for the keyboard map.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>K923 operator panel</source>
        <translation type="unfinished" />
    </message>
</context>
<context>
    <name>k528::studio::KeyboardMapDialog</name>
    <message>
        <source>K923 keyboard map</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>The PC keyboard works the panel while the panel has the focus: click the panel (a ring shows round it) or reach it with Tab; Tab leaves it again. Shift held with a PC key that is not a character gives SHIFT+key; S latches the panel's SHIFT for the next key, as a click on SHIFT does. Letters work in the Russian layout too.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Panel key</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>PC keyboard</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Function</source>
        <translation type="unfinished" />
    </message>
</context>
<context>
    <name>k528::studio::MachinePanelWidget</name>
    <message>
        <source>SPINDLE</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>COOLANT</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>LIMIT</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>HOMED</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>DOOR</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>CLAMPED</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>ALARM</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>LUBE</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>WHEEL</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>GAUGE</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>TURRET</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>HYDRAUL.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>MACHINE CONTROL PANEL</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>EMERGENCY STOP</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>DRIVES ON</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>RESET</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>CYCLE START</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>STOP</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Rapid traverse: hold with a jog button</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Jog X+ (hold)</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Jog X- (hold)</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Jog Z+ (hold)</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Jog Z- (hold)</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>JOG</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>HANDWHEEL</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>AXIS</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>STEP</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Drag round or turn the mouse wheel: one detent is one step</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>FEED OVERRIDE %</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>K923: the panel's L1..L4 keys set the override</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>CHUCK</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>NEW WHEEL</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Per detent: %1 / %2 / %3 mm</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Spindle</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Wheel</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Work</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>rpm</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Tool %1</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Gauge: bore %1 / %2 mm, wheel %3 mm</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source> in </source>
        <translation type="unfinished" />
    </message>
    <message>
        <source> touch </source>
        <translation type="unfinished" />
    </message>
    <message>
        <source> rough </source>
        <translation type="unfinished" />
    </message>
    <message>
        <source> finish </source>
        <translation type="unfinished" />
    </message>
    <message>
        <source> size</source>
        <translation type="unfinished" />
    </message>
</context>
<context>
    <name>k528::studio::MachineSource</name>
    <message>
        <source>The machine database is not used: %1</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>database %1</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>built-in</source>
        <translation type="unfinished" />
    </message>
</context>
<context>
    <name>k528::studio::MainWindow</name>
    <message>
        <source>About K528 Studio</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>&lt;h3&gt;K528 Studio %1&lt;/h3&gt;&lt;p&gt;Workstation for the Konstar K528-05 two-axis positioning controller and its K923 operator panel.&lt;/p&gt;&lt;p&gt;Licence: GNU GPL version 3 or later.&lt;/p&gt;</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>K528 Studio</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>&amp;Language</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>&amp;About K528 Studio</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>K923 operator panel</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Machine control panel</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Messages</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Axes and signals</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Ready</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Machine time %1:%2:%3</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>&amp;Pause the machine</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>&amp;Speed</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>&amp;Faults for training</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>&amp;Clear all faults</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Machine</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>The machine %1 cannot be loaded: %2</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>&amp;Machine</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Machine: %1</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Machine: %1 (%2)</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>Load programs</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>K528 programs (*.k528 *.txt);;All files (*)</source>
        <translation>K528 programs (*.k528 *.txt);;All files (*)</translation>
    </message>
    <message>
        <source>Loaded %1 from %2</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Loaded %1 from %2, with warnings.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>&amp;Load programs...</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Keep in the database</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>The memory of %1 was not kept: %2</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>%1: the database already holds this memory (revision %2)</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>%1 kept in the database as revision %2 (%3 changes)</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>&amp;Keep the controller's memory in the database</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Editor</source>
        <translation>Editor</translation>
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
        <translation type="unfinished" />
    </message>
    <message>
        <source> (L%1, line %2)</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Positioner</source>
        <translation>Positioner</translation>
    </message>
    <message>
        <source>active</source>
        <translation type="unfinished" />
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
        <translation type="unfinished" />
    </message>
    <message>
        <source>information</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>No alarms.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Alarms: %1. Acknowledge with RESET on the machine panel or ESC on the K923 once the cause is gone.</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>waits for acknowledgement</source>
        <translation type="unfinished" />
    </message>
</context>
<context>
    <name>k528::studio::ProgramMonitor</name>
    <message>
        <source>ready</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>running</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>dwell</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>waiting for the PLC (M)</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>M00: waiting for START</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>interrupted: START continues</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>ended</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>stopped by a message: START begins again</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>Follow the controller</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>L%1: %2</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>no program</source>
        <translation type="unfinished" />
    </message>
    <message>
        <source>, frame N%1</source>
        <translation type="unfinished" />
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
        <source>Axis X</source>
        <translation>Axis X</translation>
    </message>
    <message>
        <source>Axis Z</source>
        <translation>Axis Z</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>Error, mm</source>
        <translation>Error, mm</translation>
    </message>
    <message>
        <source>DAC</source>
        <translation>DAC</translation>
    </message>
    <message>
        <source>mm/min</source>
        <translation>mm/min</translation>
    </message>
    <message>
        <source>Setpoint</source>
        <translation>Setpoint</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Following error</source>
        <translation>Following error</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Speed</translation>
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
</context>
</TS>